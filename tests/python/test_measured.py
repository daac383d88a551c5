"""Measured files from Python: the CLI's values, array = per-pair, info and albedo, bad input."""

import numpy as np
import pytest

import brdfkit
from conftest import data_file, random_directions, run_cli, unit


def rgl():
    return data_file("rgl", "paper_white_rgb.bsdf")


def test_eval_matches_the_cli():
    d = brdfkit.load(rgl())
    assert d.format == "rgl"
    for wi, wo in [((30, 0), (40, 180)), ((10, 50), (70, 300))]:
        cli = run_cli("eval", rgl(), "--wi", "%g,%g" % wi, "--wo", "%g,%g" % wo, "--json")
        np.testing.assert_allclose(d.eval(unit(*wi), unit(*wo)), cli["rho"], rtol=1e-12, atol=0)


def test_array_eval_equals_per_pair_eval(rng):
    d = brdfkit.load(rgl())
    wi, wo = random_directions(rng, 200), random_directions(rng, 200)
    whole = d.eval(wi, wo)
    assert whole.shape == (200, 3) and np.isfinite(whole).all()
    np.testing.assert_array_equal(whole, np.array([d.eval(wi[k], wo[k]) for k in range(200)]))


def test_scattered_samples_answer_no_pair():
    d = brdfkit.load(data_file("cornell", "garnet_red.brdf"))
    assert np.isnan(d.eval(unit(30, 0), unit(30, 180))).all()
    with pytest.raises(ValueError, match="garnet_red.brdf"):
        d.albedo(0.1)
    assert d.info()["albedo_method"] == "samples"


def test_info_is_the_clis():
    d = brdfkit.load(rgl())
    cli = run_cli("info", rgl(), "--json")
    assert d.info() == cli["files"][0]
    np.testing.assert_allclose(d.albedo(np.radians(30.0)), d.info()["albedo"][3]["rgb"], rtol=1e-12)


def test_bad_files_raise_naming_the_file(tmp_path):
    with pytest.raises(FileNotFoundError, match="missing.binary"):
        brdfkit.load(tmp_path / "missing.binary")
    bad = tmp_path / "truncated.binary"
    bad.write_bytes(b"\x5a\x00\x00\x00\x5a\x00\x00\x00\xb4\x00\x00\x00" + b"\x00" * 100)
    with pytest.raises(ValueError, match="truncated.binary"):
        brdfkit.load(bad)
    with pytest.raises(brdfkit.InputError):
        brdfkit.load(bad)


@pytest.mark.parametrize("wi,message", [
    (np.zeros((4, 2)), "wi: expected 3 columns"),
    (np.zeros((2, 2, 3)), "wi: expected an array of shape"),
    (np.array([[0.0, 0.0, np.nan]]), r"wi\[0\]: is not finite"),
    (np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 2.0]]), r"wi\[1\]: is not a unit vector"),
])
def test_bad_arrays_raise_value_errors(wi, message):
    d = brdfkit.load(rgl())
    with pytest.raises(ValueError, match=message):
        d.eval(wi, unit(0, 0))


def test_dtypes_and_strides_are_converted(rng):
    d = brdfkit.load(rgl())
    wi = random_directions(rng, 50)
    wo = random_directions(rng, 50)
    reference = d.eval(wi, wo)
    # float32 (unit within float32's precision), Fortran order, a strided view, lists.
    f32 = d.eval(wi.astype(np.float32), wo)
    assert np.isfinite(f32).all()
    np.testing.assert_array_equal(d.eval(np.asfortranarray(wi), wo), reference)
    wide = np.zeros((50, 6))
    wide[:, ::2] = wi
    np.testing.assert_array_equal(d.eval(wide[:, ::2], wo), reference)
    np.testing.assert_array_equal(d.eval(wi.tolist(), wo), reference)
    with pytest.raises(TypeError):
        d.eval(np.array([["a", "b", "c"]]), wo)
    with pytest.raises(ValueError, match="2 rows and 3 rows"):
        d.eval(wi[:2], wo[:3])


def test_convert_writes_what_the_cli_writes(tmp_path):
    # A measured file to RGL and MERL, and a Brdf to RGL: the files read back with the source's values.
    d = brdfkit.load(rgl())
    brdfkit.convert(d, tmp_path / "paper.binary")
    merl = brdfkit.load(tmp_path / "paper.binary")
    wi, wo = unit(30, 0), unit(40, 180)
    np.testing.assert_allclose(merl.eval(wi, wo), d.eval(wi, wo), rtol=0.05)
    ward = brdfkit.Brdf("ward", kd=0.3, ks=0.2, alpha=0.15)
    brdfkit.convert(ward, tmp_path / "ward.bsdf", theta_i=10, grid=24, description="ward")
    back = brdfkit.load(tmp_path / "ward.bsdf")
    assert back.format == "rgl" and "10 theta_i x 24x24" in back.dimensions
    np.testing.assert_allclose(back.eval(wi, wo), ward.eval(wi, wo), rtol=0.02)
    with pytest.raises(ValueError, match="extension"):
        brdfkit.convert(ward, tmp_path / "ward.txt")
    assert not (tmp_path / "ward.txt").exists()


def test_convert_writes_anisotropic_sources_as_anisotropic_files(tmp_path):
    # The layout follows the probed symmetry; dropping the anisotropy warns.
    lobe = brdfkit.Brdf("cook-torrance-ggx-aniso", kd=0.1, ks=0.9, alpha_x=0.15, alpha_y=0.3, phi_t=0.7, F0=0.5)
    written = brdfkit.convert(lobe, tmp_path / "aniso.bsdf", theta_i=9, grid=24)
    assert written == "anisotropic RGL tensor_file (13 phi_i nodes over 1/2 of the azimuths)"
    back = brdfkit.load(tmp_path / "aniso.bsdf")
    assert "13 phi_i (anisotropic, 1/2 of the azimuths) x 9 theta_i x 24x24" in back.dimensions
    for phi in (20, 110, 200, 290):  # folded by a half turn where sin(phi) > 0
        wi, wo = unit(35, phi), unit(40, phi + 150)
        np.testing.assert_allclose(back.eval(wi, wo), lobe.eval(wi, wo), rtol=0.05)
    with pytest.warns(UserWarning, match="a MERL table is isotropic"):
        assert brdfkit.convert(lobe, tmp_path / "aniso.binary") == "MERL"
