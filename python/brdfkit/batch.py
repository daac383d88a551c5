"""Batches of fits on any executor: in this process, a thread pool, or a Dask cluster.

``fit_all`` writes exactly what ``brdfkit fit-all`` writes into ``out_dir`` (one JSON per fit,
summary.csv, table.txt) through the same library code: each fit is one task that claims its
result file, fits and saves it (src/brdfkit/fit/batch/fit_batch.h), so tasks can run in other
processes or on other machines that see ``out_dir`` (a shared file system), several batches
(Python or ``fit-all``) may share ``out_dir``, a rerun skips the fits already saved, and a task
lost with its worker is simply run again by the executor.

In process (default; each fit is itself parallel)::

    summary = brdfkit.batch.fit_all(["../shared/data/cornell"], ["ward", "cook-torrance-ggx"], "fits")

On a Dask cluster (Debian's python3-distributed; a LocalCluster here, or Dask's own SSH,
Kubernetes or Slurm deployments)::

    from dask.distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        summary = brdfkit.batch.fit_all(inputs, models, "fits", executor=client.get_executor())
"""

import concurrent.futures as _futures
import os as _os
import sys as _sys
import time as _time

from . import _brdfkit
from ._brdfkit import FitSettings, OutputError

__all__ = ["fit_all", "DEFAULT_REPORT"]

# `brdfkit fit-all --report`'s default.
DEFAULT_REPORT = ("ngan", "bagher", "low-e1", "low-e2")


def _fit_task(material, file, model, out_dir, settings, report):
    """One fit of a batch under the claim protocol; runs in whichever process the executor picks."""
    return _brdfkit._run_batch_fit(material, file, model, out_dir, FitSettings(**settings), report)


def _stderr(line):
    print(line, file=_sys.stderr, flush=True)


def _as_executor(executor):
    if executor is None or isinstance(executor, _futures.Executor):
        return executor
    # A dask.distributed.Client is not itself a concurrent.futures.Executor; its executor is.
    if hasattr(executor, "get_executor"):
        return executor.get_executor()
    raise TypeError(f"executor: expected a concurrent.futures.Executor or a Dask Client, got {type(executor).__name__}")


def _row_without_fit(material, model, status, reason):
    """The row of a fit no task saved: 'unfinished' (never run) or 'failed' (its task was lost)."""
    return {"material": material, "model": model, "status": status, "reason": reason, "json": "",
            "metrics": [], "seconds": 0.0, "iterations": 0, "converged": False}


class _Run:
    """The tasks of one batch and their rows, in fit-all's order (material-major)."""

    def __init__(self, inputs, models, out_dir, settings, report, executor, log, metric):
        self.inputs, self.models, self.out_dir = inputs, models, out_dir
        self.settings, self.report, self.executor, self.log, self.metric = settings, report, executor, log, metric
        self.rows = [None] * (len(inputs) * len(models))
        self.done = 0

    def args(self, k):
        material, file = self.inputs[k // len(self.models)]
        return material, file, self.models[k % len(self.models)], self.out_dir, self.settings, self.report

    def run(self, ks, last_try):
        """Runs tasks ks; returns the indices whose claim another process held."""
        elsewhere = []
        if self.executor is None:
            for k in ks:
                self.finish(k, _fit_task(*self.args(k)), last_try, elsewhere)
            return elsewhere
        pending = {self.executor.submit(_fit_task, *self.args(k)): k for k in ks}
        try:
            while pending:
                finished, _ = _futures.wait(list(pending), return_when=_futures.FIRST_COMPLETED)
                for f in finished:
                    k = pending.pop(f)
                    try:
                        row = f.result()
                    except OutputError:
                        raise
                    except Exception as e:  # the task itself was lost (e.g. its worker died too often)
                        material, _, model, *_ = self.args(k)
                        row = _row_without_fit(material, model, "failed", f"{type(e).__name__}: {e}")
                    self.finish(k, row, last_try, elsewhere)
        finally:
            for f in pending:
                f.cancel()
        return elsewhere

    def finish(self, k, row, last_try, elsewhere):
        self.rows[k] = row
        if row["status"] == "running elsewhere" and not last_try:
            elsewhere.append(k)
            self.log(f"{row['material']} {row['model']}: claimed by another process; tried again after the others")
            return
        self.done += 1
        self.log(_brdfkit._progress_line(row, self.metric, self.done, len(self.rows)))


def fit_all(inputs, models="single-lobe", out_dir="results/fits", *, report=DEFAULT_REPORT, compare=None,
            executor=None, log=_stderr, **settings) -> dict:
    """Fits every material x model and writes what `brdfkit fit-all INPUTS --models ... -o OUT_DIR` writes.

    inputs: measured files and/or folders (every measured file in a folder, sorted), a path or a
    list. models: a list of names, or fit-all's spec ('single-lobe', 'all', 'a,b,c'). report: the
    metric ids every row and JSON carries (the fitting metric first), or 'all'. compare: a
    published-fits file whose fits are listed beside. settings: brdfkit.FitSettings' keyword
    arguments (procedure, metric, starts, seed, ...). executor: None runs the fits one after the
    other in this process; any concurrent.futures.Executor runs each fit as one of its tasks (a
    ThreadPoolExecutor; a Dask client's get_executor(), or the Client itself, spreads them over
    its workers, which must see out_dir). log: called with one line per finished fit and the total.

    Returns the summary (what `fit-all --json` prints): rows with each fit's status ('fitted',
    'resumed', 'failed', 'running elsewhere', 'unfinished'), metrics, seconds and reason. A rerun
    keeps the fits already saved; a KeyboardInterrupt starts no further task, writes the summary
    with the rest 'unfinished', and is raised again. OSError (OutputError) when a result cannot
    be written; ValueError for bad inputs or settings, before anything runs.
    """
    paths = [_os.fspath(inputs)] if isinstance(inputs, (str, bytes, _os.PathLike)) else [_os.fspath(i) for i in inputs]
    pairs = _brdfkit._batch_inputs(paths)
    names = _brdfkit._batch_models(models if isinstance(models, str) else ",".join(models))
    report_spec = report if report == "all" else ",".join(report)
    fit_settings = FitSettings(**settings)
    metric = _brdfkit._batch_check(fit_settings, report_spec, compare or "", names)
    out_dir = _os.fspath(out_dir)
    _os.makedirs(out_dir, exist_ok=True)
    started = _time.monotonic()
    run = _Run(pairs, names, out_dir, settings, report_spec, _as_executor(executor), log, metric)
    interrupted = False
    try:
        again = run.run(range(len(run.rows)), last_try=False)
        # A fit another process held is tried once more after the others, as fit-all does.
        run.run(again, last_try=True)
    except KeyboardInterrupt:
        interrupted = True
    rows = [row or _row_without_fit(pairs[k // len(names)][0], names[k % len(names)], "unfinished",
                                    "the batch was interrupted before this fit started")
            for k, row in enumerate(run.rows)]
    summary = _brdfkit._summarize_batch(pairs, names, out_dir, fit_settings, report_spec, compare or "", rows,
                                        interrupted, _time.monotonic() - started, log)
    if interrupted:
        raise KeyboardInterrupt
    return summary
