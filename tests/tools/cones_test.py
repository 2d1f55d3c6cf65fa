#!/usr/bin/python3
"""Test of tools/cones and of the retinal-irradiance chain, on spectral EXRs eyetrace renders.

  tests/tools/cones_test.py EYETRACE_BINARY SCRATCH_DIR

The scenes emit a known spectral radiance s(lambda) in W m^-2 sr^-1 nm^-1: a table given as
"spectrum L" with "float scale" = its luminance in eyetrace's normalisation (Y relative to the
equal-energy spectrum, computed here from the CIE 1931 rows of src/core/cie_tables.cpp), the
recipe of docs/spectral.md. Pixels are independent (the "independent" sampler), so the spread of
per-pixel values gives the standard error (SE) of an image mean.

1. A pinhole looking at a diffuse emitter that fills the view, 60 buckets of 5 nm:
   a. the tool's per-pixel L, M, S equal sum_b value_b * W_b, with W_b integrated here
      independently (numpy trapezoid at 0.01 nm of the interpolated table), to 1e-5;
   b. their image means equal the exact integrals of s times the Stockman & Sharpe
      fundamentals over 400-700 nm within 4 SE plus the (computed) bucket quantisation error.
2. The Navarro eye (2 mm pupil, 4 degree field) in a uniform sky of radiance s:
   a. the header's factors are n'(centre)^2 / C with its own C and indices;
   b. n'_ref^2 / C matches the paraxial retinal irradiance per unit radiance, pi r_EP^2 P^2
      (entrance pupil radius and power from `eyetrace optics --json`), within 0.5 % (the real
      cone's sin^2 against the paraxial tan^2 alone accounts for ~0.3 %);
   c. the image mean of every bucket is the mean of s over the bucket (the camera's weight is
      normalised so that a uniform scene reads its radiance at the image centre) within 4 SE
      plus 0.3 % (relative illumination 2 degrees off axis);
   d. --write-irradiance writes the buckets times the factors, and --irradiance gives L, M, S
      in W m^-2 matching sum_b factor_b * mean_b(s) * W_b within 4 SE plus 0.3 %.
3. Errors: an RGB EXR (no spectral channels) and --irradiance without factors exit 1 naming
   the file; --help exits 0.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CONES = os.path.join(ROOT, "tools", "cones")
TABLE = os.path.join(ROOT, "data", "color", "linss2_10e_1.csv")

# The test spectrum (W m^-2 sr^-1 nm^-1): knots on the 5 nm grid, constant beyond the ends.
S_LAMBDA = np.array([380, 400, 450, 500, 550, 600, 650, 700, 780], dtype=float)
S_VALUE = np.array([0.3, 0.4, 1.6, 0.5, 0.9, 2.0, 1.2, 0.6, 0.2])

failures = []


def check(ok, message):
    print(("ok   " if ok else "FAIL ") + message)
    if not ok:
        failures.append(message)


def s_of(lam):
    return np.interp(lam, S_LAMBDA, S_VALUE)


def luminance_scale():
    """Y of s as eyetrace computes it: sum over the CIE rows of s * ybar / sum of ybar."""
    text = open(os.path.join(ROOT, "src", "core", "cie_tables.cpp")).read()
    rows = [(float(m.group(1)), float(m.group(2)))
            for m in re.finditer(r"\{(\d+), [-\d.e]+, ([-\d.e]+), [-\d.e]+,", text)]
    lam, ybar = np.array(rows).T
    assert len(lam) == 81 and lam[0] == 380 and lam[-1] == 780, "cie_tables.cpp rows not found"
    return float((s_of(lam) * ybar).sum() / ybar.sum())


def pairs():
    return " ".join(f"{l:g} {v:g}" for l, v in zip(S_LAMBDA, S_VALUE))


def run(cmd, expect=0):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != expect:
        sys.exit(f"cones test: FAIL: {' '.join(cmd)} exited {r.returncode} (expected {expect}):\n{r.stdout}\n{r.stderr}")
    return r


def read_exr(path):
    inp = oiio.ImageInput.open(path)
    if inp is None:
        sys.exit(f"cones test: FAIL: cannot read {path}: {oiio.geterror()}")
    spec = inp.spec()
    px = np.asarray(inp.read_image(oiio.FLOAT), dtype=np.float64).reshape(spec.height, spec.width, spec.nchannels)
    attrs = {a.name: a.value for a in spec.extra_attribs}
    inp.close()
    return px, list(spec.channelnames), attrs


def fundamentals():
    t = np.loadtxt(TABLE, delimiter=",", skiprows=1)
    return t[:, 0], t[:, 1:4].T


def integrate(f, lo, hi, step=0.01):
    n = int(round((hi - lo) / step))
    x = np.linspace(lo, hi, n + 1)
    return np.trapz(f(x), x)


def weights(edges):
    lam, curves = fundamentals()
    return np.array([[integrate(lambda x, c=c: np.interp(x, lam, c, left=0, right=0), edges[b], edges[b + 1])
                      for b in range(len(edges) - 1)] for c in curves])


def mean_and_se(v):
    """Image mean and its standard error, per trailing channel, from (H, W, C) values."""
    flat = v.reshape(-1, v.shape[-1])
    return flat.mean(axis=0), flat.std(axis=0, ddof=1) / math.sqrt(flat.shape[0])


def render(eyetrace, scratch, name, text):
    scene = os.path.join(scratch, name + ".pbrt")
    with open(scene, "w") as f:
        f.write(text)
    out = os.path.join(scratch, name + ".exr")
    run([eyetrace, "render", "-q", scene, "-o", out, "--threads", "2", "--stats", out + ".json"])
    return out


def test_pinhole(eyetrace, scratch, scale):
    nb, lo, hi = 60, 400.0, 700.0
    exr = render(eyetrace, scratch, "pinhole", f"""LookAt 0 0 -3  0 0 0  0 1 0
Camera "perspective" "float fov" 10
Film "spectral" "integer xresolution" 32 "integer yresolution" 32 "integer nbuckets" {nb}
Sampler "independent" "integer pixelsamples" 64
Integrator "path" "integer maxdepth" 1
PixelFilter "box"
WorldBegin
AreaLightSource "diffuse" "spectrum L" [{pairs()}] "float scale" {scale:.9g}
Shape "sphere" "float radius" 1
""")
    px, names, _ = read_exr(exr)
    check(names[:4] == ["R", "G", "B", "S0.402,500nm"] and len(names) == 3 + nb,
          f"pinhole: channels R, G, B, S0.402,500nm ... ({len(names)} channels)")
    buckets = px[:, :, 3:]
    edges = lo + (hi - lo) * np.arange(nb + 1) / nb
    prefix = os.path.join(scratch, "pinhole-lms")
    r = run(["/usr/bin/python3", CONES, exr, "--out", prefix])
    print(r.stdout)
    lms, lms_names, attrs = read_exr(prefix + ".exr")
    check(lms_names == ["L", "M", "S"] and attrs.get("eyetrace:units") == "W m^-2 sr^-1",
          "pinhole: the tool writes channels L, M, S in W m^-2 sr^-1")
    check(os.path.getsize(prefix + ".png") > 1000, "pinhole: the PNG panel is written")

    w = weights(edges)
    mine = np.einsum("hwb,cb->hwc", buckets, w)
    rel = np.abs(lms - mine).max() / np.abs(mine).max()
    check(rel < 1e-5, f"pinhole: per-pixel L, M, S = sum_b value_b W_b (largest difference {rel:.2e} of the maximum)")

    lam, curves = fundamentals()
    exact = np.array([integrate(lambda x, c=c: s_of(x) * np.interp(x, lam, c, left=0, right=0), lo, hi)
                      for c in curves])
    bucket_means = np.array([integrate(s_of, edges[b], edges[b + 1]) / (edges[b + 1] - edges[b]) for b in range(nb)])
    quantisation = np.abs(w @ bucket_means - exact)
    mean, se = mean_and_se(lms)
    for c, cone in enumerate("LMS"):
        tol = 4 * se[c] + quantisation[c] + 1e-4 * exact[c]
        check(abs(mean[c] - exact[c]) <= tol and se[c] < 0.01 * exact[c],
              f"pinhole: {cone} = {mean[c]:.5g} vs integral of s * {cone.lower()}bar over 400-700 nm {exact[c]:.5g} "
              f"(SE {se[c]:.2g}, bucket quantisation {quantisation[c]:.2g})")
    return exr


def test_eye(eyetrace, scratch, scale):
    nb, lo, hi = 15, 400.0, 700.0
    camera = 'Camera "navarro" "float fov" 4 "float pupildiameter" 2 "float wavelength" 589.3'  # monochromatic at the reference wavelength (the paraxial check is there)
    exr = render(eyetrace, scratch, "eye", f"""LookAt 0 0 0  0 0 1  0 1 0
{camera}
Film "spectral" "integer xresolution" 32 "integer yresolution" 32 "integer nbuckets" {nb}
Sampler "independent" "integer pixelsamples" 128
PixelFilter "box"
WorldBegin
LightSource "infinite" "spectrum L" [{pairs()}] "float scale" {scale:.9g}
""")
    px, names, attrs = read_exr(exr)
    buckets = px[:, :, 3:]
    edges = lo + (hi - lo) * np.arange(nb + 1) / nb
    centres = 0.5 * (edges[1:] + edges[:-1])
    factors = np.array([float(v) for v in attrs["eyetrace:retinal_irradiance_factors"].split()])
    index = np.array([float(v) for v in attrs["eyetrace:image_medium_index"].split()])
    c_norm = float(attrs["eyetrace:camera_weight_normalisation"])
    check(attrs.get("eyetrace:image_medium") == "vitreous", "eye: the image medium is the vitreous")
    check(np.allclose(factors, index ** 2 / c_norm, rtol=1e-7), "eye: factors = n'(centre)^2 / C")
    stats = json.load(open(exr + ".json"))["film"]["retinal_irradiance"]
    check(np.allclose(stats["factor_sr"], factors, rtol=1e-8) and np.allclose(stats["bucket_centres_nm"], centres),
          "eye: --stats holds the same factors and bucket centres")

    optics = json.loads(run([eyetrace, "optics", "--camera", camera, "--json"]).stdout)
    r_ep = optics["entrance_pupil"]["diameter_mm"] / 2
    power = optics["power_diopters"] / 1000.0  # 1/mm
    n_ref = next(m["index_reference"] for m in optics["dispersion"]["media"] if m["medium"] == "vitreous")
    paraxial = math.pi * r_ep ** 2 * power ** 2
    at_ref = factors * (n_ref / index) ** 2
    worst = np.abs(at_ref / paraxial - 1).max()
    check(worst < 0.005, f"eye: n'_ref^2 / C = {at_ref.mean():.6g} sr vs paraxial pi r_EP^2 P^2 = {paraxial:.6g} sr "
                         f"(worst bucket {100 * worst:.2f} %)")

    mean, se = mean_and_se(buckets)
    s_means = np.array([integrate(s_of, edges[b], edges[b + 1]) / (edges[b + 1] - edges[b]) for b in range(nb)])
    bad = [b for b in range(nb) if not abs(mean[b] - s_means[b]) <= 4 * se[b] + 0.003 * s_means[b]]
    check(not bad and (se / s_means).max() < 0.015,
          f"eye: every bucket's image mean is the scene's radiance over the bucket (worst "
          f"{np.abs(mean / s_means - 1).max() * 100:.2f} %, largest SE {100 * (se / s_means).max():.2f} %; failing: {bad})")

    irr_path = os.path.join(scratch, "eye-irradiance.exr")
    prefix = os.path.join(scratch, "eye-lms")
    r = run(["/usr/bin/python3", CONES, exr, "--irradiance", "--write-irradiance", irr_path, "--out", prefix])
    print(r.stdout)
    irr, irr_names, irr_attrs = read_exr(irr_path)
    check(irr_names == names[3:] and irr_attrs.get("eyetrace:units") == "W m^-2 nm^-1",
          "eye: the irradiance EXR has the spectral channels, in W m^-2 nm^-1")
    check(np.allclose(irr, (buckets * factors).astype(np.float32), rtol=1e-6, atol=0),
          "eye: irradiance = bucket value x factor")
    lms, _, lms_attrs = read_exr(prefix + ".exr")
    expected = weights(edges) @ (factors * s_means)
    mean, se = mean_and_se(lms)
    for c, cone in enumerate("LMS"):
        check(abs(mean[c] - expected[c]) <= 4 * se[c] + 0.003 * expected[c] and lms_attrs["eyetrace:units"] == "W m^-2",
              f"eye: retinal {cone} = {mean[c]:.5g} W m^-2 vs {expected[c]:.5g} (SE {se[c]:.2g})")


def test_errors(eyetrace, scratch, pinhole_exr):
    rgb = os.path.join(scratch, "rgb.exr")
    scene = os.path.join(scratch, "rgb.pbrt")
    with open(scene, "w") as f:
        f.write('Film "rgb" "integer xresolution" 4 "integer yresolution" 4\nWorldBegin\n'
                'LightSource "infinite" "rgb L" [1 1 1]\n')
    run([eyetrace, "render", "-q", scene, "-o", rgb])
    r = run(["/usr/bin/python3", CONES, rgb], expect=1)
    check(f'"{rgb}" has no spectral channels (channels: R, G, B)' in r.stderr, "errors: an RGB EXR is refused by name")
    r = run(["/usr/bin/python3", CONES, pinhole_exr, "--irradiance", "--no-png",
             "--out", os.path.join(scratch, "never")], expect=1)
    check("has no retinal irradiance factors" in r.stderr and not os.path.exists(os.path.join(scratch, "never.exr")),
          "errors: --irradiance without factors (a pinhole render) is refused and writes nothing")
    r = run(["/usr/bin/python3", CONES, "--help"])
    check("Stockman" in r.stdout or "cone" in r.stdout, "errors: --help exits 0")


def main():
    eyetrace, scratch = sys.argv[1], sys.argv[2]
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    scale = luminance_scale()
    print(f"luminance scale of the test spectrum: {scale:.9g}")
    pinhole = test_pinhole(eyetrace, scratch, scale)
    test_eye(eyetrace, scratch, scale)
    test_errors(eyetrace, scratch, pinhole)
    if failures:
        sys.exit(f"cones test: {len(failures)} check(s) failed")
    print("cones test: all checks passed")


if __name__ == "__main__":
    main()
