#!/usr/bin/env python3
"""Throughput of Brdf.eval from Python against the C++ Model::eval_batch on the same pairs.

Measures the seconds (best of 5) to evaluate RGB on 10^6 direction pairs (uniform on the upper
hemisphere, seeded) from Python (brdfkit.Brdf.eval on (n, 3) arrays: checks, conversion to
structure of arrays in blocks, eval_batch per channel, one core) and in C++
(bench/eval_pairs_baseline.cpp: eval_batch per channel on the whole structure of arrays, one
core), for each model named, and prints the ratio. Target (the Python issue): ratio <= 1.5.

Reproduce: PYTHONPATH=build/python python3 bench/python_eval.py [MODEL ...]
           (default models: cook-torrance-ggx lambert ward; build/ built by scripts/build.sh)
"""
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "build", "python"))
import brdfkit  # noqa: E402

N = 1_000_000


def directions(rng, n):
    z = rng.uniform(0.0, 1.0, n)
    phi = rng.uniform(0, 2 * np.pi, n)
    r = np.sqrt(1 - z * z)
    return np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=1)


def main(models):
    rng = np.random.default_rng(1)
    wi, wo = directions(rng, N), directions(rng, N)
    baseline = os.path.join(ROOT, "build", "bench", "eval_pairs_baseline")
    with tempfile.NamedTemporaryFile(suffix=".f64") as f:
        np.concatenate([wi, wo], axis=1).astype(np.float64).tofile(f.name)
        print(f"{'model':<28}{'python s':>10}{'c++ s':>10}{'ratio':>8}  (10^6 pairs, RGB, best of 5, one core)")
        worst = 0
        for name in models:
            b = brdfkit.Brdf(name)
            best = min(timed(b.eval, wi, wo) for _ in range(5))
            cpp = float(subprocess.run([baseline, f.name, str(N), name], check=True, capture_output=True,
                                       text=True).stdout.split()[0])
            worst = max(worst, best / cpp)
            print(f"{name:<28}{best:>10.4f}{cpp:>10.4f}{best / cpp:>8.2f}")
    print(f"worst ratio {worst:.2f} (target <= 1.5)")


def timed(fn, *args):
    t0 = time.perf_counter()
    fn(*args)
    return time.perf_counter() - t0


if __name__ == "__main__":
    main(sys.argv[1:] or ["cook-torrance-ggx", "lambert", "ward"])
