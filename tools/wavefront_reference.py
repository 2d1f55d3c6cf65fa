#!/usr/bin/python3
"""Independent wavefront reference for the schematic eyes: OPD over the pupil, its RMS and
peak-to-valley, OSA/ANSI Zernike coefficients and the refraction they give.

Written from the shared eye-model reference (eye-models.json) alone, with the real-ray tracer of
tools/reference_trace.py (closed-form conic intersection, vector Snell's law, the eye as traced
there); none of eyetrace's code or data files is read. tests/optics/wavefront_test.cpp runs
eyetrace's optics::trace_wavefront on the same cases and compares.

  /usr/bin/python3 tools/wavefront_reference.py --output tests/data/optics/wavefront_reference.json

Needs Python 3 and numpy (Debian python3-numpy) only.

The construction (the one eyetrace documents in src/optics/wavefront.h, written again here):
object at infinity in the direction of the field angle w (rays (0, -sin w, cos w)); the chief ray
aimed (2-D Newton, reference_trace.aim) at the centre of the stop; the pupil a disc of the given
radius on a plane perpendicular to the axis in object space, centred on the chief ray (for
parallel rays the plane's position does not matter), sampled at the centres of a grid x grid
lattice of cells inside the disc; the stop opened (it does not clip: the disc is the pupil),
every other edge as reference_trace.py has it. Each ray's optical path from the plane through the
chief ray's start perpendicular to the beam to the last refracting surface, then along the
image-space line to the reference sphere: centred on the chief ray's retina point, through the
chief ray's crossing of the paraxial exit-pupil plane (computed here with y-nu matrices from the
stop), the crossing nearer the pupil. OPD = chief ray's path - ray's path. Pupil coordinates in
the ANSI Z80.28 axes: x_osa = -x, y_osa = y, normalised by the radius. Zernike polynomials from
the standard's formula (Thibos et al. 2002), fitted by numpy's least squares (SVD). RMS: from the
coefficients (root sum of squares of j >= 1) and from the samples (standard deviation). Refraction:
least squares M = -4 sqrt3 c(2,0) / r^2, J0 = -2 sqrt6 c(2,2) / r^2, J45 = -2 sqrt6 c(2,-2) / r^2
and paraxial curvature M = (-4 sqrt3 c20 + 12 sqrt5 c40 - 24 sqrt7 c60) / r^2,
J0 = (-2 sqrt6 c22 + 6 sqrt10 c42 - 12 sqrt14 c62) / r^2 (Thibos, Hong, Bradley & Applegate 2004).
"""
import argparse
import datetime
import hashlib
import json
import math
import os
import platform
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reference_trace as rt  # noqa: E402

STATES = ["gullstrand_relaxed", "legrand_relaxed", "kooijman", "navarro_relaxed", "navarro_wu2011_relaxed",
          "escudero_sanz", "arizona_relaxed", "navarro_D4"]
CASES = [(0.0, 3.0), (0.0, 2.0), (20.0, 2.0)]  # (field deg, entrance-pupil radius mm)
GRID = 64
ORDER = 6
START_Z = -3.0


def zernike_index(j):
    n = 0
    while (n + 1) * (n + 2) // 2 <= j:
        n += 1
    return n, 2 * j - n * (n + 2)


def zernike(j, x, y):
    n, m = zernike_index(j)
    rho, theta = np.hypot(x, y), np.arctan2(y, x)
    am = abs(m)
    radial = sum((-1) ** s * math.factorial(n - s) /
                 (math.factorial(s) * math.factorial((n + am) // 2 - s) * math.factorial((n - am) // 2 - s)) *
                 rho ** (n - 2 * s) for s in range((n - am) // 2 + 1))
    norm = math.sqrt((2.0 if m != 0 else 1.0) * (n + 1))
    return norm * radial * (np.cos(m * theta) if m >= 0 else np.sin(am * theta))


def exit_pupil_z(seq, stop):
    """Where a paraxial ray from the stop centre, continued in image space, crosses the axis."""
    y, nu, z, n = 0.0, 1.0, seq[stop]["z"], seq[stop]["n_after"]
    last = len(seq) - 2
    for s in seq[stop + 1:last + 1]:
        y += (s["z"] - z) * nu / n
        nu -= y * (s["n_after"] - n) * s["c"]
        z, n = s["z"], s["n_after"]
    return z - y * n / nu


def path(seq, o, d, reference):
    """(optical path to the last refracting surface, its point, image-space direction, retina point)."""
    hits = rt.trace(seq, o, d)
    last = len(seq) - 2
    length = float(np.dot(hits[0][0] - reference, d))  # object space is air
    for i in range(last):
        length += seq[i]["n_after"] * float(np.linalg.norm(hits[i + 1][0] - hits[i][0]))
    return length, hits[last][0], hits[last][1], hits[-1][0]


def analyse(seq, stop, wavelength, field, radius):
    d0 = np.array([0.0, -math.sin(math.radians(field)), math.cos(math.radians(field))])

    def make(u):
        return np.array([u[0], u[1], START_Z]), d0

    guess = -d0[:2] / d0[2] * (seq[stop]["z"] - START_Z)
    o_chief, _, miss = rt.aim(seq, stop, np.zeros(2), make, guess)
    assert miss < 1e-10
    n_image = seq[-2]["n_after"]
    L, P, dd, C = path(seq, o_chief, d0, o_chief)
    s_pupil = (exit_pupil_z(seq, stop) - P[2]) / dd[2]
    R = float(np.linalg.norm(P + s_pupil * dd - C))
    L_chief = L + n_image * s_pupil
    points, opd = [], []
    for i in range(GRID):
        for j in range(GRID):
            u = np.array([-1.0 + (i + 0.5) * 2.0 / GRID, -1.0 + (j + 0.5) * 2.0 / GRID])
            if u @ u > 1.0:
                continue
            o = o_chief + np.array([radius * u[0], radius * u[1], 0.0])  # parallel rays: a translation
            L, P, dd, _ = path(seq, o, d0, o_chief)
            oc = P - C
            b = float(oc @ dd)
            t = -b - math.sqrt(b * b - (float(oc @ oc) - R * R))
            points.append((-u[0], u[1]))
            opd.append(L_chief - (L + n_image * t))
    pts = np.array(points)
    w_um = np.array(opd) * 1000.0
    terms = (ORDER + 1) * (ORDER + 2) // 2
    A = np.stack([zernike(j, pts[:, 0], pts[:, 1]) for j in range(terms)], axis=1)
    c, *_ = np.linalg.lstsq(A, w_um, rcond=None)
    wave_um = wavelength * 1e-3
    r2 = radius * radius
    return dict(
        field_deg=field, pupil_radius_mm=radius, wavelength_nm=wavelength, grid=GRID, order=ORDER,
        rays=len(opd), reference_radius_mm=R, image_point_mm=[float(v) for v in C],
        rms_waves=float(math.sqrt(float(np.sum(c[1:] ** 2))) / wave_um),
        rms_sampled_waves=float(np.std(w_um) / wave_um), pv_waves=float((w_um.max() - w_um.min()) / wave_um),
        zernike_um=[float(v) for v in c],
        least_squares_M_D=float(-4 * math.sqrt(3) * c[4] / r2),
        least_squares_J0_D=float(-2 * math.sqrt(6) * c[5] / r2),
        paraxial_M_D=float((-4 * math.sqrt(3) * c[4] + 12 * math.sqrt(5) * c[12] - 24 * math.sqrt(7) * c[24]) / r2),
        paraxial_J0_D=float((-2 * math.sqrt(6) * c[5] + 6 * math.sqrt(10) * c[13] - 12 * math.sqrt(14) * c[25]) / r2))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--input", default=rt.DEFAULT_INPUT)
    ap.add_argument("--output", default="-")
    args = ap.parse_args()
    raw = open(args.input, "rb").read()
    src = json.loads(raw)
    rt.PUPIL_DIAMETER_MM = 20.0  # the stop opened: the disc is the pupil
    out = []
    for state_id, key, description, preset, builder in rt.states(src):
        if state_id not in STATES:
            continue
        seq = rt.build(*builder())
        stop = next(i for i, s in enumerate(seq) if s["role"] == "stop")
        wavelength, _ = rt.wavelength_of(src["models"][key])
        cases = [analyse(seq, stop, wavelength, f, r) for f, r in CASES]
        out.append(dict(id=state_id, state=description, eyetrace_preset=preset, cases=cases))
    doc = dict(provenance=dict(
        what="independent wavefront analysis (OPD, RMS, PV, OSA Zernike to order 6, refraction) of the eyes of "
             "eye-models.json",
        command="/usr/bin/python3 tools/wavefront_reference.py " + " ".join(sys.argv[1:]),
        input=os.path.basename(args.input), input_sha256=hashlib.sha256(raw).hexdigest(), generated=datetime.date.today().isoformat(),
        python=platform.python_version(), numpy=np.__version__), states=out)
    text = json.dumps(doc, indent=1)
    if args.output == "-":
        print(text)
    else:
        open(args.output, "w").write(text + "\n")


if __name__ == "__main__":
    main()
