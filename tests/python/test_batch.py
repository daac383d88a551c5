"""brdfkit.batch.fit_all writes what `brdfkit fit-all` writes, in process and on a Dask cluster,
survives a worker killed mid-fit, and resumes."""

import csv
import json
import os
import signal
import threading

import pytest

import brdfkit
from conftest import data_file, run_cli

MODELS = ["lambert", "ward", "cook-torrance-ggx"]
# Enough random starts that a fit lasts about a second: a worker can be killed while it fits.
SETTINGS = {"starts": 1000, "seed": 3}


def cornell():
    return os.path.dirname(data_file("cornell", "garnet_red.brdf"))


def without_timings(doc):
    if isinstance(doc, dict):
        return {k: without_timings(v) for k, v in doc.items() if k != "seconds"}
    if isinstance(doc, list):
        return [without_timings(v) for v in doc]
    return doc


def summary_rows(folder):
    with open(os.path.join(folder, "summary.csv")) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r.pop("seconds")
    return rows


def fits(folder):
    """Every saved fit (material/model.json) without timings; and any stray file (temporaries)."""
    out, stray = {}, []
    for material in sorted(os.listdir(folder)):
        path = os.path.join(folder, material)
        if not os.path.isdir(path) or material.startswith("."):
            continue
        for name in sorted(os.listdir(path)):
            if name.endswith(".json"):
                with open(os.path.join(path, name)) as f:
                    out[f"{material}/{name}"] = without_timings(json.load(f))
            else:
                stray.append(f"{material}/{name}")
    return out, stray


@pytest.fixture(scope="module")
def cli_batch(tmp_path_factory):
    out = tmp_path_factory.mktemp("cli")
    run_cli("fit-all", cornell(), "--models", ",".join(MODELS), "--starts", SETTINGS["starts"], "--seed",
            SETTINGS["seed"], "-o", out)
    return str(out)


def assert_same_as_cli(folder, cli_folder):
    ours, stray = fits(folder)
    theirs, _ = fits(cli_folder)
    assert not stray
    assert set(ours) == set(theirs) and len(ours) == 9
    for k in ours:
        # Files name their data file and folder the same way; only timings may differ.
        assert ours[k] == theirs[k], k
    assert summary_rows(folder) == summary_rows(cli_folder)
    with open(os.path.join(folder, "table.txt")) as a, open(os.path.join(cli_folder, "table.txt")) as b:
        assert a.read() == b.read()


def test_in_process_batch_writes_what_fit_all_writes(tmp_path, cli_batch):
    lines = []
    summary = brdfkit.batch.fit_all(cornell(), MODELS, tmp_path, log=lines.append, **SETTINGS)
    assert [r["status"] for r in summary["rows"]] == ["fitted"] * 9
    assert_same_as_cli(tmp_path, cli_batch)
    assert lines[0].startswith("[1/9] acryl_blue lambert: ngan ")
    assert lines[-1].startswith("fit-all: 9 fits: 9 fitted")
    # A rerun fits nothing.
    again = brdfkit.batch.fit_all(cornell(), MODELS, tmp_path, log=lambda line: None, **SETTINGS)
    assert [r["status"] for r in again["rows"]] == ["resumed"] * 9


def test_bad_batch_input_raises_before_any_fit(tmp_path):
    with pytest.raises(ValueError, match="no-such-folder"):
        brdfkit.batch.fit_all(tmp_path / "no-such-folder", MODELS, tmp_path / "out")
    with pytest.raises(ValueError, match="no-such-model"):
        brdfkit.batch.fit_all(cornell(), ["no-such-model"], tmp_path / "out")
    with pytest.raises(brdfkit.SettingError, match="bounds.*'alpa'"):
        brdfkit.batch.fit_all(cornell(), ["ward", "lambert"], tmp_path / "out", bounds={"alpa": (0.1, 0.2)})
    assert not (tmp_path / "out").exists() or not os.listdir(tmp_path / "out")


def test_dask_cluster_survives_a_killed_worker(tmp_path, cli_batch):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=50) as cluster, distributed.Client(cluster) as client:
        pids = client.run(os.getpid)  # worker address -> pid
        killed = {}
        lock = threading.Lock()

        def log(line):
            # After the first fit ends, kill a worker that is fitting at that moment.
            with lock:
                if killed or not line.startswith("["):
                    return
                busy = [w for w, tasks in client.processing().items() if tasks]
                if busy:
                    killed[busy[0]] = pids[busy[0]]
                    os.kill(pids[busy[0]], signal.SIGKILL)

        summary = brdfkit.batch.fit_all(cornell(), MODELS, tmp_path, executor=client, log=log, **SETTINGS)
    assert killed, "no worker was busy when the first fit ended"
    statuses = [r["status"] for r in summary["rows"]]
    assert statuses.count("fitted") + statuses.count("resumed") == 9, summary["rows"]
    assert len({(r["material"], r["model"]) for r in summary["rows"]}) == 9
    assert_same_as_cli(tmp_path, cli_batch)
    # A rerun skips every finished fit.
    again = brdfkit.batch.fit_all(cornell(), MODELS, tmp_path, log=lambda line: None, **SETTINGS)
    assert [r["status"] for r in again["rows"]] == ["resumed"] * 9
