#!/usr/bin/env python3
"""Seed corpus of the fuzz targets (fuzz/fuzz_*.cpp): tiny synthetic files per format, made up here
so no measured data is copied. Usage: make_corpus.py OUT_DIR  (writes OUT_DIR/<target>/<seed>).

The seeds are valid, or one field away from valid, so the fuzzer starts past the first checks.
Layouts: MERL (measured/merl.h; the fuzz_merl input byte 0 picks raw file or patched full-size
file), RGL tensor_file (measured/rgl_tensor.cpp reader: magic, version 1.0, field table, data),
Cornell (measured/cornell.h), ALTA slice (measured/alta_slice.h), saved fit (fit/fit_record.cpp
to_json), published fits (models/published_fits.h), command-line arguments (NUL-separated).
"""
import json
import math
import os
import struct
import sys

# ---------------------------------------------------------------------------------------------
# MERL: fuzz_merl.cpp's input format.

MERL_DIMS = struct.pack("<3i", 90, 90, 180)
MERL_VALUES = 3 * 90 * 90 * 180


def merl_record(index, value):
    return struct.pack("<Id", index % MERL_VALUES, value)


def merl_seeds():
    yield "raw-header-only", b"\x00" + MERL_DIMS
    yield "raw-truncated", b"\x00" + MERL_DIMS + struct.pack("<4d", 0.5, 1.0, -1.0, 2.0)
    yield "raw-bad-dims", b"\x00" + struct.pack("<3i", 90, 90, 360) + struct.pack("<d", 1.0)
    yield "measured-plain", b"\x01\x00"
    yield "measured-patched", b"\x01\x00" + merl_record(7, 0.25) + merl_record(1458000 + 7, -1.0) + merl_record(4373999, 3e3)
    yield "measured-one-byte-long", b"\x01\x08" + merl_record(0, 1.5)
    yield "unmeasured-one-cell", b"\x02\x00" + b"".join(merl_record(k * 1458000 + 12345, 0.5) for k in range(3))
    yield "unmeasured-plain", b"\x02\x00"


# ---------------------------------------------------------------------------------------------
# RGL tensor_file: magic "tensor_file\0", version 1.0, uint32 field count, per field (uint16 name
# length, name, uint16 ndim, uint8 type, uint64 offset, uint64 shape[ndim]), then the data.

UINT8, FLOAT32 = 1, 10


def tensor_file(fields):
    """fields: list of (name, type, shape, payload bytes); the data follow the header in order."""
    def header(offsets):
        h = bytearray(b"tensor_file\0" + bytes([1, 0]) + struct.pack("<I", len(fields)))
        for (name, typ, shape, _), off in zip(fields, offsets):
            h += struct.pack("<H", len(name)) + name.encode() + struct.pack("<HBQ", len(shape), typ, off)
            h += b"".join(struct.pack("<Q", s) for s in shape)
        return bytes(h)

    pos = len(header([0] * len(fields)))  # the header's size does not depend on the offsets
    offsets = []
    for _, _, _, payload in fields:
        offsets.append(pos)
        pos += len(payload)
    return header(offsets) + b"".join(payload for _, _, _, payload in fields)


def f32(values):
    return struct.pack("<%df" % len(values), *values)


def rgl_fields(nt=2, n=3, spectral=False, jacobian=1):
    theta = [i * (math.pi / 2) / nt for i in range(nt)]  # [0, π/2)
    cells = n * n
    vndf = [1.0 + 0.1 * ((i * 7) % 5) for i in range(nt * cells)]
    lum = [0.2 + 0.05 * (i % 4) for i in range(nt * cells)]
    fields = [
        ("theta_i", FLOAT32, [nt], f32(theta)),
        ("phi_i", FLOAT32, [1], f32([0.0])),
        ("sigma", FLOAT32, [n, n], f32([1.0 + 0.01 * i for i in range(cells)])),
        ("ndf", FLOAT32, [n, n], f32([2.0 - 0.1 * i for i in range(cells)])),
        ("vndf", FLOAT32, [1, nt, n, n], f32(vndf)),
        ("luminance", FLOAT32, [1, nt, n, n], f32(lum)),
        ("jacobian", UINT8, [1], bytes([jacobian])),
        ("description", UINT8, [9], b"synthetic"),
    ]
    if spectral:
        wl = [450.0, 550.0, 650.0]
        fields.append(("wavelengths", FLOAT32, [3], f32(wl)))
        fields.append(("spectra", FLOAT32, [1, nt, 3, n, n], f32([0.3 + 0.01 * (i % 9) for i in range(nt * 3 * cells)])))
    else:
        fields.append(("rgb", FLOAT32, [1, nt, 3, n, n], f32([0.1 * ((i % 5) - 1) for i in range(nt * 3 * cells)])))
    return fields


def rgl_seeds():
    yield "rgb-2x3", tensor_file(rgl_fields())
    yield "rgb-3x4-no-jacobian", tensor_file(rgl_fields(nt=3, n=4, jacobian=0))
    yield "spectral-2x2", tensor_file(rgl_fields(n=2, spectral=True))
    bad = rgl_fields()
    bad[0] = ("theta_i", FLOAT32, [2], f32([0.5, 0.25]))  # not increasing
    yield "theta-decreasing", tensor_file(bad)
    yield "magic-only", b"tensor_file\0\x01\x00\x00\x00\x00\x00"


# ---------------------------------------------------------------------------------------------
# Cornell: '#' comments, CRLF, the wavelength count, the wavelengths, then θi φi θs φs values.

def cornell_seeds():
    head = "# num wls\r\n3\r\n\r\n# wls\r\n450 550\r\n650\r\n\r\n# theta i, phi i, theta s, phi_s, values\r\n"
    rows = []
    for ti in (0.0, 0.5236):
        for k, ts in enumerate((0.0, 0.45, 0.9, 1.3)):
            rows.append("%.6f 0.000000 %.6f %.6f %.6f %.6f %.6f" % (ti, ts, -0.3 * k, 0.02 + 0.01 * k, 0.03, -0.001))
    yield "three-wavelengths", (head + "\r\n".join(rows) + "\r\n").encode()
    yield "lf-one-sample", b"1\n550\n0.1 0 0.2 -1.0 0.05\n"
    yield "header-only", b"# nothing measured\n2\n500 600\n"


# ---------------------------------------------------------------------------------------------
# ALTA θd = 0 slice.

def alta_seeds():
    head = "# synthetic slice\n#DIM 1 3\n#PARAM_IN  COS_TH\n#PARAM_OUT RGB_COLOR\n"
    rows = ["%.15g\t%.15g\t%.15g\t%.15g\t" % (c, 0.1 + c, 0.08, 0.06) for c in (0.2, 0.6, 0.9, 0.99, 1.0)]
    yield "five-rows", (head + "\n".join(rows) + "\n").encode()
    yield "one-row-crlf", (head.replace("\n", "\r\n") + "0.5 1 2 3\r\n").encode()
    yield "missing-param-out", b"#DIM 1 3\n#PARAM_IN COS_TH\n0.5 1 2 3\n"


# ---------------------------------------------------------------------------------------------
# Saved fits, as fit/fit_record.cpp to_json writes them (model parameters from models/*.h).

def fit_record(model, params, shape="shared", extra=None):
    doc = {
        "format": "brdfkit-fit",
        "brdfkit_version": "0.1.0",
        "model": model,
        "shape": shape,
        "params": [{"name": n, "scope": s, "values": v} for n, s, v in params],
        "data": {"file": "synthetic.binary", "sha256": "0" * 64},
        "fit": {"metric": "ngan", "starts": 1, "seed": 1, "iterations": 12, "seconds": 0.5, "converged": True,
                "message": "synthetic"},
        "grid_coarsen": 1,
        "metrics": {"ngan": 0.125, "low-e1": None},
        "metric_notes": {"low-e1": "not computed"},
    }
    doc.update(extra or {})
    return json.dumps(doc, indent=2).encode()


def fit_record_seeds():
    yield "lambert", fit_record("lambert", [("kd", "per-channel", [0.5, 0.4, 0.3])])
    ward = [("kd", "per-channel", [0.2, 0.3, 0.4]), ("ks", "per-channel", [0.05, 0.06, 0.07]),
            ("alpha", "shared", [0.1, 0.1, 0.1])]
    yield "ward", fit_record("ward", ward)
    yield "ward-per-channel", fit_record("ward", ward[:2] + [("alpha", "per-channel", [0.1, 0.2, 0.3])], "per-channel")
    yield "low-smooth", fit_record("low-smooth", [("kd", "per-channel", [0.1, 0.1, 0.1]),
                                                   ("A", "per-channel", [10, 20, 30]), ("B", "shared", [1e4] * 3),
                                                   ("C", "shared", [0.7] * 3), ("eta", "shared", [1.5] * 3)])
    yield "sum", fit_record("lambert+ward", [("kd", "per-channel", [0.5, 0.4, 0.3])])


# ---------------------------------------------------------------------------------------------
# Published fits (made-up numbers in the files' layout: materials → list of lobes).

def published(lobe, params, materials=("mat-a", "mat-b")):
    doc = {"source": "synthetic", "conventions": {"formula": "rho = Lambertian + " + lobe}, "materials": {}}
    for k, m in enumerate(materials):
        doc["materials"][m] = [{"lobe": "Lambertian", "params": {"albedo": [0.05 + 0.01 * k, 0.04, 0.03]}},
                               {"lobe": lobe, "params": params}]
    return json.dumps(doc, indent=1).encode()


def published_seeds():
    yield "low-smooth", published("LowSmooth", {"A": [100.0, 80.0, 60.0], "B": 15000.0, "C": 0.6, "eta": 1.5})
    yield "ashikhmin-shirley", published("LowAshikhminShirley",
                                         {"albedo": [0.2, 0.18, 0.22], "sharpness": 6000.0, "fresnelReflectance": 1.4})
    yield "cook-torrance", published("LowCookTorrance", {"albedo": [0.05, 0.04, 0.05], "roughness": 0.02, "eta": 1.46})
    yield "microfacet", published("LowMicrofacetFit", {"A": [50.0, 40.0, 30.0], "B": 10000.0, "C": 0.8, "eta": 2.2})
    yield "bagher", published("Bagher", {"albedo": [0.03, 0.6, 0.27], "alpha": [0.015, 0.03, 0.05],
                                         "p": [0.46, 0.45, 0.53], "eta": [[6.0, 0.24, 0.58], [5.0, 0.18, 0.48]]})
    yield "unknown-lobe", published("Phong", {"n": 10})


# ---------------------------------------------------------------------------------------------
# Command-line arguments after `brdfkit`, NUL-separated (fuzz_cli_options.cpp).

def cli_seeds():
    runs = {
        "fit": ["fit", "data.binary", "-m", "ward", "-o", "out.json", "--starts", "3", "--seed", "7",
                "--max-iterations", "100", "--coarsen", "2", "--threshold", "0.01", "--metric", "low-e1"],
        "fit-procedure": ["fit", "data.binary", "-o", "o.json", "--procedure", "ngan", "--per-channel-shape"],
        "eval": ["eval", "ward", "--param", "kd=0.1,0.2,0.3", "--param", "alpha=0.2", "--param", "ks[g]=0.5",
                 "--wi", "30,0", "--wo", "45,180"],
        "eval-radians": ["eval", "lambert+ward", "--param", "kd=0.5", "--wi", "0.5,0", "--wo", "1.2,3", "--radians"],
        "tabulate": ["tabulate", "low-smooth", "--param", "B=1e4", "--param", "C=0.5", "-o", "t.binary",
                     "--clamp-negative"],
    }
    for name, args in runs.items():
        yield name, "\0".join(args).encode()


TARGETS = {
    "fuzz_merl": merl_seeds,
    "fuzz_rgl": rgl_seeds,
    "fuzz_cornell": cornell_seeds,
    "fuzz_alta": alta_seeds,
    "fuzz_fit_record": fit_record_seeds,
    "fuzz_published_fits": published_seeds,
    "fuzz_cli_options": cli_seeds,
}


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_corpus.py OUT_DIR")
    out = sys.argv[1]
    for target, seeds in TARGETS.items():
        folder = os.path.join(out, target)
        os.makedirs(folder, exist_ok=True)
        count = 0
        for name, data in seeds():
            with open(os.path.join(folder, "seed-" + name), "wb") as f:
                f.write(data)
            count += 1
        print("%-20s %d seeds" % (target, count))


if __name__ == "__main__":
    main()
