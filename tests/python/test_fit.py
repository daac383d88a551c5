"""brdfkit.fit / error / load_fit / published / export / render give the CLI's numbers and files."""

import json
import os

import numpy as np
import pytest

import brdfkit
from conftest import data_file, run_cli, unit


def same_numbers(a, b, path=""):
    """JSON documents equal, numbers to 1e-12 relative (timings excepted)."""
    if isinstance(a, dict):
        assert set(a) == set(b), path
        for k in a:
            if k != "seconds":
                same_numbers(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            same_numbers(x, y, f"{path}[{i}]")
    elif isinstance(a, float) or isinstance(b, float):
        assert a == pytest.approx(b, rel=1e-12, abs=1e-300), path
    else:
        assert a == b, path


@pytest.mark.parametrize("model,settings,args", [
    ("cook-torrance-ggx", {"procedure": "ngan"}, ["--procedure", "ngan"]),
    ("ward", {"metric": "low-e2", "starts": 3, "seed": 5}, ["--metric", "low-e2", "--starts", "3", "--seed", "5"]),
    ("cook-torrance-ggx", {"bounds": {"alpha": (0.3, 0.4)}}, ["--bounds", "alpha=0.3:0.4"]),
])
def test_fit_is_the_clis(tmp_path, model, settings, args):
    file = data_file("cornell", "krylon_blue.brdf")
    fit = brdfkit.fit(file, model, **settings)
    run_cli("fit", file, "--model", model, *args, "-o", tmp_path / "cli.json")
    cli = json.loads((tmp_path / "cli.json").read_text())
    same_numbers(json.loads(fit.to_json()), cli)
    assert fit.metrics[fit.fit_metric] == pytest.approx(cli["metrics"][fit.fit_metric], rel=1e-12)


def test_fit_on_rgl_and_error_are_the_clis(tmp_path):
    data = brdfkit.load(data_file("rgl", "paper_white_rgb.bsdf"))
    fit = brdfkit.fit(data, "cook-torrance-ggx", coarsen=4, report=["ngan", "low-e2"])
    assert set(fit.metrics) == {"ngan", "low-e2"}
    fit.save(tmp_path / "fit.json")
    cli = run_cli("error", data.path, "--params", tmp_path / "fit.json", "--json")
    errors = brdfkit.error(data, fit)
    assert set(errors) == set(cli["metrics"])
    for k, v in cli["metrics"].items():
        assert errors[k] == pytest.approx(v, rel=1e-12) if v is not None else errors[k] is None
    assert errors["ngan"] == pytest.approx(fit.metrics["ngan"], rel=1e-12)


def test_json_round_trip(tmp_path):
    fit = brdfkit.fit(data_file("cornell", "acryl_blue.brdf"), "blinn-phong")
    again = brdfkit.Fit.from_json(fit.to_json())
    assert again.to_json() == fit.to_json()
    assert again.brdf.params == fit.brdf.params
    fit.save(tmp_path / "f.json")
    assert brdfkit.load_fit(tmp_path / "f.json").to_json() == fit.to_json()
    doc = json.loads(fit.to_json())
    doc["model"] = "no-such-model"
    with pytest.raises(ValueError, match="no-such-model"):
        brdfkit.Fit.from_json(json.dumps(doc))


def test_settings_are_named_in_errors():
    file = data_file("cornell", "acryl_blue.brdf")
    with pytest.raises(brdfkit.SettingError, match="starts"):
        brdfkit.fit(file, "ward", starts=0)
    with pytest.raises(ValueError, match="procedure"):
        brdfkit.fit(file, "ward", procedure="no-such-procedure")
    with pytest.raises(brdfkit.SettingError, match="bounds.*no parameter 'alpa'"):
        brdfkit.fit(file, "ward", bounds={"alpa": (0.1, 0.2)})
    with pytest.raises(brdfkit.SettingError, match="bounds.*domain"):
        brdfkit.fit(file, "ward", bounds={"alpha": (0.0, 0.2)})
    with pytest.raises(TypeError, match="no_such_setting"):
        brdfkit.fit(file, "ward", no_such_setting=1)


def test_published_fit_error_is_the_clis():
    published = data_file("published-fits", "bagher2012-sgd.json")
    if not os.path.exists(published):
        pytest.skip(f"{published} is absent")
    brdf = brdfkit.published(published, "alum-bronze")
    cli = run_cli("eval", "--params", published, "--material", "alum-bronze", "--wi", "20,0", "--wo", "30,180",
                  "--json")
    assert brdf.model.name == cli["model"]
    np.testing.assert_allclose(brdf.eval(unit(20, 0), unit(30, 180)), cli["rho"], rtol=1e-12)
    with pytest.raises(ValueError, match="no-such-material"):
        brdfkit.published(published, "no-such-material")


def test_export_writes_the_clis_files(tmp_path):
    fit = brdfkit.fit(data_file("cornell", "garnet_red.brdf"), "pbrt-mix-diffuse-conductor")
    fit.save(tmp_path / "fit.json")
    r = brdfkit.export(fit, "pbrt-v4", tmp_path / "py.pbrt")
    run_cli("export", tmp_path / "fit.json", "--to", "pbrt-v4", "-o", tmp_path / "cli.pbrt")
    assert r["files"] and all(os.path.exists(f) for f in r["files"])
    py_text = (tmp_path / "py.pbrt").read_text().replace("py_scene", "X")
    cli_text = (tmp_path / "cli.pbrt").read_text().replace("cli_scene", "X")
    assert py_text == cli_text


def test_render_gives_the_clis_numbers(tmp_path):
    data = brdfkit.load(data_file("rgl", "paper_white_rgb.bsdf"))
    fit = brdfkit.fit(data, "lambert", coarsen=4)
    fit.save(tmp_path / "fit.json")
    r = brdfkit.render([data, fit], tmp_path / "py.png", env_constant=1.0, lights=[(30, 45, 2)], size=24, spp=4)
    run_cli("render", data.path, tmp_path / "fit.json", "--env-constant", "1", "--light", "30,45,2", "--size", "24",
            "--spp", "4", "-q", "-o", tmp_path / "cli.png")
    cli = json.loads((tmp_path / "cli.json").read_text())
    assert r["images"][0].shape == (24, 24, 3) and r["delta_e"][1].shape == (24, 24)
    assert r["errors"][0] is None
    assert r["errors"][1]["rmse"] == pytest.approx(cli["columns"][1]["image_rmse"], rel=1e-12)
    assert r["errors"][1]["mean_delta_e"] == pytest.approx(cli["columns"][1]["mean_delta_e2000"], rel=1e-12)
    assert os.path.exists(tmp_path / "py.exr")
