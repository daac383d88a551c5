"""Shared fixtures of the Python module's tests: the CLI built beside the module (to compare
with), the shared measurements (skipped with a reason when absent) and a scratch folder."""

import json
import os
import subprocess

import numpy as np
import pytest

CLI = os.environ.get("BRDFKIT_CLI", "")
DATA = os.environ.get("BRDFKIT_TEST_DATA_DIR", os.path.join(os.path.dirname(__file__), "../../../shared/data"))


def run_cli(*args, check=True):
    """Runs the brdfkit CLI; returns its stdout (JSON parsed when the command printed JSON)."""
    if not CLI:
        pytest.skip("BRDFKIT_CLI is not set (ctest sets it)")
    r = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    if check and r.returncode != 0:
        raise AssertionError(f"brdfkit {' '.join(map(str, args))} exited {r.returncode}: {r.stderr}")
    return json.loads(r.stdout) if "--json" in args else r


def data_file(*parts):
    path = os.path.join(DATA, *parts)
    if not os.path.exists(path):
        pytest.skip(f"{path} is absent (the shared measurements are not beside the repository)")
    return path


def unit(theta_deg, phi_deg):
    """The CLI's (theta, phi) in degrees as a unit vector (apps/brdfkit/cmd_eval.cpp)."""
    t, p = np.radians(theta_deg), np.radians(phi_deg)
    return np.array([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)])


def random_directions(rng, n):
    """Unit vectors on the upper hemisphere, uniformly in solid angle."""
    z = rng.uniform(0.02, 1.0, n)
    phi = rng.uniform(0, 2 * np.pi, n)
    r = np.sqrt(1 - z * z)
    return np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=1)


@pytest.fixture
def rng():
    return np.random.default_rng(7)
