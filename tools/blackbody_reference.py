#!/usr/bin/python3
"""The linear sRGB of a blackbody of luminance 1, computed from Planck's law, the CIE 1931 2-degree
colour-matching functions and the sRGB matrix of IEC 61966-2-1, with nothing of eyetrace's code:
the reference tests/render/colour_fidelity_test.cpp and tests/materials/spectrum_test.cpp hold the
renderer to (docs/spectral.md, "A 6504 K blackbody is not white").

  /usr/bin/python3 tools/blackbody_reference.py [--kelvin 6504] [--cmf FILE.csv]

The colour-matching functions are the CIE 15 5 nm abridgement, 380-780 nm, read as published data
from the table in src/core/cie_tables.cpp (the numbers only: its columns lambda, x, y, z); --cmf
takes any other tabulation instead (a CSV with a header row and columns wavelength, x, y, z, e.g.
the CIE's 1 nm table, 360-830 nm). Between rows the table is interpolated linearly and it is 0
outside them; the integrals of Planck's law times the interpolated functions are taken by the
trapezoidal rule on a 0.01 nm grid (converged to 1e-9). The spectrum is scaled to Y = 1 (the
luminance of the renderer's lights) and taken to linear sRGB by the IEC 61966-2-1 matrix, whose
white is D65 at (x, y) = (0.3127, 0.3290).

Prints, for each temperature: the chromaticity (x, y), the CIE 1960 (u, v) distance from D65's
white point, and the linear sRGB (R, G, B).
"""
import argparse
import os
import re
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# CODATA 2018 (exact in the SI since 2019).
H = 6.62607015e-34  # J s
C = 299792458.0  # m / s
KB = 1.380649e-23  # J / K

# IEC 61966-2-1:1999, XYZ (Y = 1 for white) to linear sRGB.
XYZ_TO_SRGB = np.array([[3.2406, -1.5372, -0.4986],
                        [-0.9689, 1.8758, 0.0415],
                        [0.0557, -0.2040, 1.0570]])
D65_XY = (0.3127, 0.3290)


def planck(lambda_nm, kelvin):
    """Spectral radiance, W m^-2 sr^-1 m^-1 (the scale cancels in the luminance normalisation)."""
    lam = lambda_nm * 1e-9
    return 2.0 * H * C * C / (lam ** 5 * np.expm1(H * C / (lam * KB * kelvin)))


def cie_tables_cpp():
    """The lambda, x, y, z columns of the rows of src/core/cie_tables.cpp ({380, 0.001368, ...})."""
    text = open(os.path.join(ROOT, "src", "core", "cie_tables.cpp")).read()
    rows = re.findall(r"\{(\d+), ([-\d.e]+), ([-\d.e]+), ([-\d.e]+),", text)
    return np.array([[float(v) for v in r] for r in rows])


def csv_table(path):
    data = np.genfromtxt(path, delimiter=",", skip_header=1)
    return data[:, :4]


def uv(x, y):
    d = -2.0 * x + 12.0 * y + 3.0
    return np.array([4.0 * x / d, 6.0 * y / d])


def blackbody_srgb(table, kelvin):
    grid = np.arange(table[0, 0], table[-1, 0] + 1e-9, 0.01)
    spd = planck(grid, kelvin)
    trapezoid = getattr(np, "trapezoid", None) or np.trapz  # renamed in numpy 2
    xyz = np.array([trapezoid(spd * np.interp(grid, table[:, 0], table[:, c]), grid) for c in (1, 2, 3)])
    xyz /= xyz[1]
    xy = xyz[:2] / xyz.sum()
    return xy, np.linalg.norm(uv(*xy) - uv(*D65_XY)), XYZ_TO_SRGB @ xyz


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--kelvin", type=float, nargs="+", default=[6504.0])
    ap.add_argument("--cmf", help="CSV of wavelength, x, y, z (default: the CIE 15 5 nm rows)")
    args = ap.parse_args()
    table = csv_table(args.cmf) if args.cmf else cie_tables_cpp()
    print(f"colour-matching functions: {args.cmf or 'src/core/cie_tables.cpp'}, "
          f"{len(table)} rows, {table[0, 0]:g}-{table[-1, 0]:g} nm")
    for k in args.kelvin:
        xy, duv, rgb = blackbody_srgb(table, k)
        print(f"{k:g} K: xy ({xy[0]:.5f}, {xy[1]:.5f}), duv from D65 {duv:.5f}, "
              f"linear sRGB ({rgb[0]:.5f}, {rgb[1]:.5f}, {rgb[2]:.5f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
