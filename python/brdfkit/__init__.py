"""brdfkit: fit analytic BRDF models to measured reflectance, measure the fits, sample, render, export.

The same library as the `brdfkit` command line, on numpy arrays::

    import numpy as np, brdfkit
    data = brdfkit.load("../shared/data/rgl/aniso_brushed_aluminium_1_rgb.bsdf")
    fit = brdfkit.fit(data, "cook-torrance-ggx", procedure="ngan")
    fit.metrics["ngan"], fit.brdf.params
    brdfkit.error(data, fit)["low-e2"]

Conventions (DESIGN.md): directions are unit vectors in the local frame (z = normal), arrays of
shape (n, 3); wi points towards the light, wo towards the viewer; rho is in 1/sr and excludes the
cosine. Errors: ValueError (brdfkit.InputError; brdfkit.SettingError for a keyword argument) with
the library's one-line message naming the file, field or parameter; FileNotFoundError for a
missing file; OSError (brdfkit.OutputError) for an output that cannot be written; RuntimeError
(brdfkit.FitError) for a fit with no finite start. Long calls release the GIL.
"""

import os as _os
import warnings as _warnings

from . import _brdfkit
from ._brdfkit import (  # noqa: F401  (the public classes and functions documented in the extension)
    Brdf,
    Fit,
    FitError,
    FitSettings,
    InputError,
    MerlTable,
    Measured,
    Model,
    OutputError,
    SettingError,
    load_fit,
    model,
    models,
    published,
    tabulate as _tabulate,
)

__version__ = _brdfkit.__version__
__all__ = [
    "Brdf", "Fit", "FitError", "FitSettings", "InputError", "MerlTable", "Measured", "Model", "OutputError",
    "SettingError", "convert", "error", "export", "fit", "load", "load_fit", "model", "models", "published",
    "render", "tabulate", "batch",
]


def _require_file(path, what="file"):
    path = _os.fspath(path)
    if not _os.path.exists(path):
        raise FileNotFoundError(f"{path}: no such {what}")
    return path


def _brdf_of(x):
    if isinstance(x, Fit):
        return x.brdf
    if isinstance(x, Brdf):
        return x
    raise TypeError(f"expected a brdfkit.Brdf or brdfkit.Fit, got {type(x).__name__}")


def _model_of(m):
    return model(m) if isinstance(m, str) else m


def load(path) -> Measured:
    """Reads a measured BRDF file: MERL .binary, RGL .bsdf, Cornell .brdf or ALTA .alta (by content).

    Returns a Measured with eval(wi, wo), albedo(theta_i) and info(). FileNotFoundError when the
    file does not exist; ValueError naming the file and the problem when it cannot be read.
    """
    return Measured(_require_file(path))


def fit(data, model, *, report=None, progress=None, **settings) -> Fit:
    """Fits `model` to measured `data`, as `brdfkit fit DATA --model MODEL ...` does (same numbers).

    data: a Measured (brdfkit.load) or a path. model: a name ('cook-torrance-ggx', 'lambert+ward')
    or a Model. settings: the keyword arguments of brdfkit.FitSettings, named as the command
    line's flags without dashes: procedure ('ngan', 'bagher', 'low-e1', 'low-e2', 'hp-2step',
    'hp-1step'; None: a plain fit under `metric`), metric, per_channel_shape, coarsen, threshold,
    starts, seed, max_iterations, coarse_to_fine, scan_start, bounds ({'alpha': (0.001, 3.0)}: the
    search box of a parameter instead of the model's). report: the metric ids to report
    (None: every metric). progress: called with each line the procedure logs.

    Returns a Fit: model, brdf (the fitted Brdf; brdf.params the values), metrics, iterations,
    seconds, converged, to_json() (the file `brdfkit fit -o` writes), save(path).
    ValueError naming a bad setting; RuntimeError (FitError) when no start is finite.
    """
    if not isinstance(data, Measured):
        data = load(data)
    s = FitSettings(**settings)
    return _brdfkit._fit(data, _model_of(model), s, ",".join(report or []), progress)


def error(data, fit, *, metric=None, coarsen=None) -> dict:
    """The error metrics of a fit (a Fit, or any Brdf) on measured data, as `brdfkit error` computes them.

    metric: a list of metric ids (None: every metric). coarsen: grid coarsening (None: the fit's,
    else 1). Returns {metric id: value, or None where the data cannot answer the metric}. Warns
    (UserWarning) when the data are not the file the fit was made on.
    """
    if not isinstance(data, Measured):
        data = load(data)
    if isinstance(fit, Fit):
        if fit.data_sha256 and fit.data_sha256 != data.sha256:
            import warnings
            warnings.warn(f"{data.path} is not the file this fit was made on "
                          f"(sha256 {data.sha256} != {fit.data_sha256})", stacklevel=2)
        if coarsen is None:
            coarsen = fit.coarsen
    return _brdfkit._error(data, _brdf_of(fit), ",".join(metric or []), 1 if coarsen is None else coarsen)


def tabulate(brdf, *, clamp_negative=False) -> MerlTable:
    """A Brdf (or a Fit's) on the MERL grid, as `brdfkit tabulate` writes it; .save(path) writes the .binary file.

    ValueError naming the model when the BRDF is NaN, infinite or negative in a cell
    (clamp_negative=True stores max(0, rho) for negative values instead).
    """
    return _tabulate(_brdf_of(brdf), clamp_negative)


def convert(source, output, *, theta_i=16, phi_i=0, symmetry=0, grid=0, description="") -> str:
    """Writes measured data, a Brdf or a Fit as `brdfkit convert` does: MERL .binary or RGL .bsdf by the extension.

    source: a Measured (or a path to one), a Brdf or a Fit. RGL output (Dupuy & Jakob 2018's
    parameterization, readable by Mitsuba 3's `measured`): theta_i incidence nodes from 0 to 90 deg;
    phi_i incidence azimuths (1: an isotropic file; 0: 1 for an isotropic source, 24 steps around
    the circle for an anisotropic one); symmetry 1, 2 or 4 (an anisotropic file stores all, half or
    a quarter of the azimuths; 0: as probed from the source); a grid x grid colour table per node
    (0: 64, 32 when anisotropic); the file's description. MERL cells the source has no value for are
    written as not measured. Returns what was written; a layout that drops the source's anisotropy
    or assumes a symmetry it lacks raises a UserWarning. ValueError for another extension or bad
    options; the file is written atomically.
    """
    if isinstance(source, (str, _os.PathLike)):
        source = load(source)
    if isinstance(source, Fit):
        source = source.brdf
    if not isinstance(source, (Measured, Brdf)):
        raise TypeError(f"expected a brdfkit.Measured, Brdf or Fit, or a path, got {type(source).__name__}")
    written, warned = _brdfkit._write_measured(source, _os.fspath(output), theta_i, phi_i, symmetry, grid, description)
    for text in warned:
        _warnings.warn(text, stacklevel=2)
    return written


def render(subjects, output=None, *, env=None, env_rotation=0.0, env_intensity=1.0, env_constant=None,
           lights=(), size=256, spp=64, seed=1, exposure=None, proxy="auto", progress=None) -> dict:
    """Renders spheres of measured data and fits side by side, as `brdfkit render` does (DESIGN.md section 13).

    subjects: Measured, Brdf and Fit objects in panel order; the first, when measured, is the
    reference of the error images. Light: env (an equirectangular .exr/.hdr map, turned by
    env_rotation degrees, radiance times env_intensity) or env_constant (a constant radiance),
    and lights: (theta, phi[, I]) or (theta, phi, R, G, B) tuples in degrees (theta from the
    camera axis, phi counter-clockwise from the image's right); nothing given: the built-in key +
    fill light. Measured data are sampled through the first fit (proxy='auto') or by the cosine.
    output: 'OUT.png' also writes OUT.png (panel), OUT.exr (linear) and OUT.json.

    Returns a dict: labels, images ((size, size, 3) linear radiance each), covered ((size, size)
    bool masks of the sphere), smape ((size, size, 3) or None) and delta_e ((size, size) or None)
    images against the reference, errors ({rmse, mean_smape, mean_delta_e} or None per subject),
    exposure (EV of the PNG) and summary (what OUT.json holds).
    """
    items = []
    for s in subjects:
        if isinstance(s, Measured):
            items.append((s.path, s))
        elif isinstance(s, Fit):
            items.append((f"fit of {s.data_file}" if s.data_file else s.model, s.brdf))
        elif isinstance(s, Brdf):
            items.append((s.model.name, s))
        else:
            raise TypeError(f"subjects: expected Measured, Brdf or Fit objects, got {type(s).__name__}")
    light_args = [",".join(str(float(v)) for v in light) for light in lights]
    scene = _brdfkit._SceneSettings(_require_file(env, "environment map") if env else "", float(env_rotation),
                                    float(env_intensity), env_constant, light_args)
    return _brdfkit._render(items, _os.fspath(output) if output else "", scene, size, spp, seed, exposure, proxy,
                            progress)


def export(fit, to, output) -> dict:
    """Writes a fit for a renderer, as `brdfkit export FIT --to TO -o OUTPUT` does (DESIGN.md section 14).

    to: 'gltf', 'mitsuba3', 'pbrt-v4', 'brdf-explorer' or 'glsl'. A fit in one of the target's own
    models is written exactly; any other is refitted into the target's model and the added error
    recorded. Returns {files, written (the Brdf written), provenance, refit_seconds}.
    """
    record = fit.to_json() if isinstance(fit, Fit) else None
    return _brdfkit._export(_brdf_of(fit), record, to, _os.fspath(output))


from . import batch  # noqa: E402,F401  (brdfkit.batch.fit_all)
