#!/usr/bin/python3
"""Smoke test of tools/figures: renders the thin-lens and Navarro panels of Figure 3 and the
chromatic figure at the smallest quality into a scratch directory and checks what the tool
promises to write.

  tests/tools/figures_smoke.py EYETRACE_BINARY SCRATCH_DIR

Checks: an EXR and a PNG per panel (and per half-sample render), the Figure 3 montage, blur.csv
and panels.csv exist; every EXR pixel is finite; blur.csv's numbers are finite; and the two
panels differ by far more than sampling noise: the RMS luminance difference between them must
exceed 3x the RMS difference sampling noise alone would give (estimated from each panel's two
independent halves), so two renders of the same camera would fail it. The chromatic figure:
its montage and chromatic.csv exist, with a finite fringe, sigma and TCA for every panel and
field, and its three claims are printed.
"""
import csv
import math
import os
import shutil
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import chromatic_figure as cf  # noqa: E402
import clinical_figure as clin  # noqa: E402
import pupil_figure as pf  # noqa: E402
import figure_metrics as fm  # noqa: E402

PANELS = ["figure3-thinlens", "figure3-navarro"]
BLOCK = 4


def block_means(y):
    h, w = y.shape[0] // BLOCK * BLOCK, y.shape[1] // BLOCK * BLOCK
    return y[:h, :w].reshape(h // BLOCK, BLOCK, w // BLOCK, BLOCK).mean(axis=(1, 3))


def fail(msg):
    sys.exit(f"figures smoke: FAIL: {msg}")


def main():
    eyetrace, scratch = sys.argv[1], sys.argv[2]
    out = os.path.join(scratch, "figures")
    shutil.rmtree(out, ignore_errors=True)  # the tool skips panels it has made: make it render
    cmd = ["/usr/bin/python3", os.path.join(ROOT, "tools", "figures"), "--quality", "smoke",
           "--panels", "thinlens,navarro,chromatic,pupil,clinical", "--out", out, "--eyetrace", eyetrace, "--threads", "2"]
    run = subprocess.run(cmd, capture_output=True, text=True)
    print(run.stdout)
    if run.returncode != 0:
        fail(f"{' '.join(cmd)} exited {run.returncode}:\n{run.stderr}")

    expected = ["figure3.png", "blur.csv", "panels.csv", "blur-vs-eccentricity.png"]
    for p in PANELS:
        expected += [p + ".exr", p + ".png"] + [os.path.relpath(h, out) for h in fm.half_paths(out, p)]
    missing = [f for f in expected
               if not (os.path.exists(os.path.join(out, f)) and os.path.getsize(os.path.join(out, f)) > 0)]
    if missing:
        fail(f"missing or empty outputs: {missing}")
    unexpected = [f for f in os.listdir(out) if f.startswith("figure4")]
    if unexpected:
        fail(f"--panels thinlens,navarro also rendered {unexpected}")

    lum, noise_var = {}, {}
    for p in PANELS:
        for path in [os.path.join(out, p + ".exr")] + fm.half_paths(out, p):
            img = fm.read_rgb(path)
            if img.shape[:2] != (80, 120):
                fail(f"{path} is {img.shape[1]}x{img.shape[0]}, not the smoke quality's 120x80")
            if not np.isfinite(img).all():
                fail(f"{path} has {np.count_nonzero(~np.isfinite(img))} non-finite values")
        y_a, y_b = (block_means(fm.luminance(fm.read_rgb(h))) for h in fm.half_paths(out, p))
        lum[p] = block_means(fm.luminance(fm.read_rgb(os.path.join(out, p + ".exr"))))
        # The panel is the mean of its halves, so its noise variance is a quarter of theirs apart.
        noise_var[p] = float(np.mean((y_a - y_b) ** 2)) / 4.0
    rms_diff = float(np.sqrt(np.mean((lum[PANELS[0]] - lum[PANELS[1]]) ** 2)))
    rms_noise = math.sqrt(noise_var[PANELS[0]] + noise_var[PANELS[1]])
    print(f"thin lens vs Navarro, {BLOCK}x{BLOCK} block means: RMS luminance difference {rms_diff:.4f}, "
          f"from noise alone {rms_noise:.4f}")
    if not rms_diff > 3.0 * rms_noise:
        fail(f"the panels differ by RMS {rms_diff:.4f}, not more than 3x noise ({rms_noise:.4f})")

    rows = list(csv.DictReader(open(os.path.join(out, "blur.csv"))))
    if {r["panel"] for r in rows} != set(PANELS):
        fail(f"blur.csv has panels {sorted({r['panel'] for r in rows})}")
    for r in rows:
        for k in ("sharpness_ratio", "noise_floor", "signal_sigma"):
            if not math.isfinite(float(r[k])):
                fail(f"blur.csv {k} = {r[k]} in {r}")
        if r["model"] == "navarro" and r["region"].startswith("far wall") \
                and not (r["rms_spot_um"] and 0 < float(r["rms_spot_um"]) < 1e4):
            fail(f"blur.csv rms_spot_um = {r['rms_spot_um']!r} in {r}")
    check_chromatic(out, run.stdout)
    check_pupil(out, run.stdout)
    check_clinical(out, run.stdout)
    print("figures smoke: OK")


def check_chromatic(out, stdout):
    for f in ["chromatic.png", "chromatic.csv"] + [p.name + ".exr" for p in cf.panels("smoke")]:
        if not os.path.exists(os.path.join(out, f)):
            fail(f"missing chromatic output {f}")
    rows = list(csv.DictReader(open(os.path.join(out, "chromatic.csv"))))
    expected = {(p.name, f) for p in cf.panels("smoke") for f in cf.FIELDS_DEG}
    if {(r["panel"], float(r["field_deg"])) for r in rows} != expected:
        fail(f"chromatic.csv rows {sorted((r['panel'], r['field_deg']) for r in rows)}")
    for r in rows:
        for k in ("fringe_arcmin", "fringe_sigma_arcmin", "centroid_tca_arcmin", "srgb_fringe_arcmin"):
            if not math.isfinite(float(r[k])):
                fail(f"chromatic.csv {k} = {r[k]} in {r}")
    claims = [line for line in stdout.splitlines() if "HOLD" in line and ("fringe" in line or "window" in line)]
    if len(claims) != 3:
        fail(f"expected the chromatic figure's 3 claims in the output, found {claims}")


def check_pupil(out, stdout):
    for f in ["pupil.png", "pupil-mtf.png", "pupil.csv"] + [p.name + ".exr" for p in pf.panels("smoke")]:
        if not os.path.exists(os.path.join(out, f)):
            fail(f"missing pupil output {f}")
    rows = list(csv.DictReader(open(os.path.join(out, "pupil.csv"))))
    expected = {(p, 0.5 * (a + b)) for p in pf.PUPILS_MM for a, b in pf.BANDS_CPD}
    if {(float(r["pupil_mm"]), float(r["freq_cpd"])) for r in rows} != expected:
        fail(f"pupil.csv rows {sorted((r['pupil_mm'], r['freq_cpd']) for r in rows)}")
    for r in rows:
        for k in ("rendered_mtf", "sigma", "optics_mtf", "strehl"):
            if not math.isfinite(float(r[k])):
                fail(f"pupil.csv {k} = {r[k]} in {r}")
    claims = [line for line in stdout.splitlines() if "HOLD" in line and "cpd" in line]
    if len(claims) != 2:
        fail(f"expected the pupil figure's 2 claims in the output, found {claims}")


def check_clinical(out, stdout):
    for f in ["clinical.png", "clinical.csv"] + [name + ".exr" for name, _, _ in clin.EYES]:
        if not os.path.exists(os.path.join(out, f)):
            fail(f"missing clinical output {f}")
    rows = list(csv.DictReader(open(os.path.join(out, "clinical.csv"))))
    if [r["panel"] for r in rows] != [name for name, _, _ in clin.EYES]:
        fail(f"clinical.csv panels {[r['panel'] for r in rows]}")
    for r in rows:
        for k in ("x_vs_emmetrope", "y_vs_emmetrope", "sphere", "cylinder", "M"):
            if not math.isfinite(float(r[k])):
                fail(f"clinical.csv {k} = {r[k]} in {r}")
    claims = [line for line in stdout.splitlines() if "HOLD" in line and ("myope" in line or "astigmat" in line
                                                                         or "spectacles" in line)]
    if len(claims) != 4:
        fail(f"expected the clinical figure's 4 claims in the output, found {claims}")


if __name__ == "__main__":
    main()
