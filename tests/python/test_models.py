"""The catalogue and Brdf on arrays: the CLI's numbers, array = per-pair, sampling by chi^2."""

import numpy as np
import pytest
from scipy import stats

import brdfkit
from conftest import random_directions, run_cli, unit


def test_catalogue_is_the_clis():
    cli = run_cli("models", "--json")
    assert [m.name for m in brdfkit.models()] == [m["name"] for m in cli]
    for m, c in zip(brdfkit.models(), cli):
        assert m.params == c["params"], m.name
        assert m.description == c["description"]


@pytest.mark.parametrize("model,params", [
    ("cook-torrance-ggx", {"alpha": 0.3, "ks": (0.2, 0.5, 0.9)}),
    ("ward", {}),
    ("lambert+blinn-phong", {"2.ks": 0.4}),
])
def test_eval_matches_the_cli(model, params):
    b = brdfkit.Brdf(model, params)
    args = []
    for k, v in params.items():
        args += ["--param", f"{k}={','.join(map(str, v)) if isinstance(v, tuple) else v}"]
    for wi, wo in [((30, 0), (40, 180)), ((0, 0), (75, 20)), ((60, 45), (60, 225))]:
        cli = run_cli("eval", model, *args, "--wi", "%g,%g" % wi, "--wo", "%g,%g" % wo, "--json")
        np.testing.assert_allclose(b.eval(unit(*wi), unit(*wo)), cli["rho"], rtol=1e-12, atol=0)


def test_array_eval_equals_per_pair_eval(rng):
    b = brdfkit.Brdf("cook-torrance-beckmann", alpha=0.25, kd=(0.1, 0.3, 0.5))
    wi, wo = random_directions(rng, 3000), random_directions(rng, 3000)  # several blocks of 1024
    whole = b.eval(wi, wo)
    assert whole.shape == (3000, 3)
    per_pair = np.array([b.eval(wi[k], wo[k]) for k in range(len(wi))])
    np.testing.assert_array_equal(whole, per_pair)
    # A single row is used for every row of the other argument.
    np.testing.assert_array_equal(b.eval(wi[5], wo), np.array([b.eval(wi[5], w) for w in wo]))


def test_reciprocity_through_python(rng):
    b = brdfkit.Brdf("cook-torrance-ggx", alpha=0.2)
    wi, wo = random_directions(rng, 500), random_directions(rng, 500)
    np.testing.assert_allclose(b.eval(wi, wo), b.eval(wo, wi), rtol=1e-12)


def chi2_of_sampler(b, wo, n, rng, bins=(10, 20)):
    """Pearson chi^2 of the sampler's draws over (cos theta, phi) bins against the pdf integrated
    over each bin (midpoint rule on a 16 x 16 sub-grid); bins expecting < 5 draws are pooled."""
    u = rng.random((n, 3))
    wi, valid = b.sample(wo, u)
    wi = wi[valid]
    nt, nphi = bins
    cos_t = wi[:, 2]
    phi = np.mod(np.arctan2(wi[:, 1], wi[:, 0]), 2 * np.pi)
    observed, _, _ = np.histogram2d(cos_t, phi, bins=[nt, nphi], range=[[0, 1], [0, 2 * np.pi]])
    sub = 16
    c = (np.arange(nt * sub) + 0.5) / (nt * sub)
    p = (np.arange(nphi * sub) + 0.5) / (nphi * sub) * 2 * np.pi
    cc, pp = np.meshgrid(c, p, indexing="ij")
    s = np.sqrt(1 - cc * cc)
    dirs = np.stack([s * np.cos(pp), s * np.sin(pp), cc], axis=-1).reshape(-1, 3)
    dens = b.pdf(wo, dirs).reshape(nt * sub, nphi * sub)
    cell = (1.0 / (nt * sub)) * (2 * np.pi / (nphi * sub))  # d(cos theta) d(phi) = solid angle
    expected = n * dens.reshape(nt, sub, nphi, sub).sum(axis=(1, 3)) * cell
    order = np.argsort(expected, axis=None)
    o, e = observed.ravel()[order], expected.ravel()[order]
    # Pool the smallest expectations into one bin until it reaches 5.
    k = np.searchsorted(np.cumsum(e), 5.0) + 1
    o = np.concatenate([[o[:k].sum()], o[k:]])
    e = np.concatenate([[e[:k].sum()], e[k:]])
    chi2 = ((o - e) ** 2 / e).sum()
    dof = len(o) - 1
    return stats.chi2.sf(chi2, dof), expected.sum() / n, valid.mean()


@pytest.mark.parametrize("model,params", [
    ("cook-torrance-ggx", {"alpha": 0.3}),
    ("ward", {"alpha": 0.2}),
    ("lambert", {}),
])
def test_sample_and_pdf_pass_chi2(model, params, rng):
    b = brdfkit.Brdf(model, params)
    wo = unit(40, 30)
    p_value, integral, accepted = chi2_of_sampler(b, wo, 200_000, rng)
    assert p_value > 1e-3, (model, p_value)
    # The pdf integrates over the hemisphere to the share of draws that land above it.
    assert integral == pytest.approx(accepted, abs=0.01)


def test_chi2_rejects_a_wrong_pdf(rng):
    """The test above can fail: draws of one model scored against another's pdf."""
    class Mismatch:
        def __init__(self):
            self.draw = brdfkit.Brdf("cook-torrance-ggx", alpha=0.3)
            self.density = brdfkit.Brdf("cook-torrance-ggx", alpha=0.4)

        def sample(self, wo, u):
            return self.draw.sample(wo, u)

        def pdf(self, wo, wi):
            return self.density.pdf(wo, wi)

    p_value, _, _ = chi2_of_sampler(Mismatch(), unit(40, 30), 200_000, rng)
    assert p_value < 1e-6


def test_albedo_of_lambert_is_kd():
    b = brdfkit.Brdf("lambert", kd=(0.2, 0.5, 0.8))
    np.testing.assert_allclose(b.albedo([0.0, 0.7, 1.2]), [[0.2, 0.5, 0.8]] * 3, rtol=2e-3)
    assert b.albedo(0.3).shape == (3,)


def test_tabulate_writes_the_clis_file(tmp_path):
    b = brdfkit.Brdf("cook-torrance-ggx", alpha=0.2)
    t = brdfkit.tabulate(b)
    t.save(tmp_path / "py.binary")
    run_cli("tabulate", "cook-torrance-ggx", "--param", "alpha=0.2", "-o", tmp_path / "cli.binary")
    assert (tmp_path / "py.binary").read_bytes() == (tmp_path / "cli.binary").read_bytes()
    assert t.cells_written + t.cells_below_horizon == 90 * 90 * 180


def test_parameters_by_name_and_channel():
    b = brdfkit.Brdf(brdfkit.model("cook-torrance-ggx"), {"kd": (0.1, 0.2, 0.3)}, alpha=0.4)
    assert b.params["alpha"] == 0.4 and b.params["kd"] == (0.1, 0.2, 0.3)
    with pytest.raises(ValueError, match="parameter 'alpha'.*shared"):
        brdfkit.Brdf("cook-torrance-ggx", alpha=(0.1, 0.2, 0.3))
    with pytest.raises(ValueError, match="parameter 'nope'.*unknown"):
        brdfkit.Brdf("cook-torrance-ggx", nope=1)
    with pytest.raises(ValueError, match="parameter 'alpha'.*outside"):
        brdfkit.Brdf("cook-torrance-ggx", alpha=5)
    with pytest.raises(ValueError, match="unknown-model"):
        brdfkit.model("unknown-model")


def test_sample_checks_its_random_numbers():
    b = brdfkit.Brdf("cook-torrance-ggx")
    with pytest.raises(ValueError, match=r"u\[1\]: 1 is not in \[0, 1\)"):
        b.sample(unit(10, 0), [[0.5, 0.5, 0.5], [0.5, 1.0, 0.2]])
    with pytest.raises(ValueError, match=r"u\[0\]: is not finite"):
        b.sample(unit(10, 0), [np.nan, 0.5, 0.5])
    with pytest.raises(ValueError, match="u: expected 3 columns"):
        b.sample(unit(10, 0), [[0.5, 0.5]])
    wi, valid = b.sample(unit(10, 0), np.full((4, 3), 0.25))
    assert wi.shape == (4, 3) and valid.dtype == bool and valid.all()
