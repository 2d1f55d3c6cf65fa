#!/usr/bin/python3
"""optiland_eyes.py DIR/eyes_mtf.csv: the MTF, RMS wavefront and Strehl ratio of the Navarro, Le Grand,
Gullstrand and Kooijman schematic eyes computed with Optiland (an independent optical design code,
https://github.com/HarrisonKramer/optiland, 0.6.0), for eyetrace's comparison
(tests/optics/optiland_comparison_test.cpp, docs/wavefront.md). Run with Optiland on PYTHONPATH:

    PYTHONPATH=/work/oracles/optiland /usr/bin/python3 tools/oracles/optiland_eyes.py \
        tests/data/optiland/eyes_mtf.csv

(and beside it navarro_6mm_zernike.csv: Navarro's c(2,0), c(4,0), c(6,0) over a 6 mm pupil.)
Each eye is built in Optiland from its published prescription (radii, conics, thicknesses and the
indices at 589.3 nm; the same numbers as eyetrace's data/eyes files, typed in here from the
sources cited below), object at infinity, the aperture an entrance-pupil diameter (EPD) of 3 or
5 mm, fields 0 and 20 degrees, 589.3 nm, the image surface the model's retina (a sphere, or
Gullstrand's plane). No surface clips (Optiland's default): the pupil is the paraxial
entrance-pupil disc, as in eyetrace's wavefront analysis without clip_at_stop. The disc is
centred, as eyetrace's, on the ray through the centre of the stop (found here by secant steps on
Optiland's trace; Optiland's own chief ray, through the paraxial entrance pupil's centre, misses
the stop's centre by 8 um at 20 degrees); the tilt-free RMS on Optiland's own disc is recorded
beside it (rms_no_tilt_paraxial_centre_waves: 0 to 1.1 % smaller at 20 degrees, the coma of the
disc moved by 10 um).

What is taken from Optiland: its real-ray trace and its optical path difference (OPD) map, with
its "chief_ray" reference (a sphere centred on the chief ray's image point on the image surface,
through the axial exit-pupil point), sampled on its "uniform" grid of normalised entrance-pupil
coordinates (N x N points from -1 to 1, inside the unit disc). Its own FFT Strehl ratio (the PSF
at the chief ray's image over the diffraction-limited peak) is recorded as well.

Why the MTF is computed here from the OPD map and not taken from Optiland's FFTMTF: that one is in
cycles per mm on a flat image plane with one working F-number for both directions, while vision
science (and eyetrace) states the MTF in cycles per degree of visual angle in object space: the
autocorrelation of the pupil function P = exp(2 pi i W) over the entrance pupil at a shear of
lambda x frequency (cycles per radian). Sagittally (x, across the meridian) the shear is
lambda f; tangentially (y) lambda f / cos(field): a tilt a of the incoming beam changes the phase
across the entrance-pupil plane by 2 pi a cos(field) y / lambda (the pupil seen from the object is
foreshortened in the meridian). The autocorrelation is computed by FFT (zero-padded, so it does
not wrap), normalised by its value at zero shear, and interpolated linearly between whole-sample
shears.

Sources of the prescriptions: Navarro, Santamaria & Bescos, JOSA A 2(8):1273 (1985), relaxed, with
the cornea index 1.376 and vitreous 16.40398 mm (Atchison & Smith 2000) and a retina of radius
-12 mm (Escudero-Sanz & Navarro, JOSA A 16:1881, 1999); Le Grand's full theoretical eye (Le Grand
& El Hage 1980, as tabulated by Atchison & Smith, Optics of the Human Eye, 2000, Table A1), retina
-13.4 mm; Gullstrand's exact (number 1) eye, relaxed (Gullstrand 1909; Atchison & Smith Table
A1), flat image plane; Kooijman's eye (Kooijman, JOSA 73:1544, 1983), conic corneas and lens,
retina -10.8 mm.
"""
import csv
import math
import subprocess
import sys

import numpy as np

import optiland
from optiland import optic
from optiland.distribution import UniformDistribution
from optiland.materials import IdealMaterial
from optiland.psf import FFTPSF
from optiland.wavefront import OPD

WAVELENGTH_UM = 0.5893
GRID = 257  # points across the pupil (odd: one on the axis)
FREQS_CPD = [5, 10, 20, 30, 40, 60]

# (radius mm or inf, conic, thickness mm to the next surface, index after, is_stop)
EYES = {
    "navarro": ([(7.72, -0.26, 0.55, 1.376, False), (6.5, 0.0, 3.05, 1.3374, False),
                 (math.inf, 0.0, 0.0, 1.3374, True), (10.2, -3.1316, 4.0, 1.42, False),
                 (-6.0, -1.0, 16.40398, 1.336, False)], -12.0),
    "legrand": ([(7.8, 0.0, 0.55, 1.3771, False), (6.5, 0.0, 3.05, 1.3374, False),
                 (math.inf, 0.0, 0.0, 1.3374, True), (10.2, 0.0, 4.0, 1.42, False),
                 (-6.0, 0.0, 16.59655, 1.336, False)], -13.4),
    "gullstrand": ([(7.7, 0.0, 0.5, 1.376, False), (6.8, 0.0, 3.1, 1.336, False),
                    (math.inf, 0.0, 0.0, 1.336, True), (10.0, 0.0, 0.546, 1.386, False),
                    (7.911, 0.0, 2.419, 1.406, False), (-5.76, 0.0, 0.635, 1.386, False),
                    (-6.0, 0.0, 17.185, 1.336, False)], math.inf),
    "kooijman": ([(7.8, -0.25, 0.55, 1.3771, False), (6.5, -0.25, 3.05, 1.3374, False),
                  (math.inf, 0.0, 0.0, 1.3374, True), (10.2, -3.06, 4.0, 1.42, False),
                  (-6.0, -1.0, 16.59655, 1.336, False)], -10.8),
}


def build(name, epd_mm):
    surfaces, retina = EYES[name]
    lens = optic.Optic()
    lens.surfaces.add(index=0, radius=math.inf, thickness=math.inf)
    for i, (radius, conic, thickness, n, stop) in enumerate(surfaces, start=1):
        lens.surfaces.add(index=i, radius=radius, conic=conic, thickness=thickness, is_stop=stop,
                          material=IdealMaterial(n=n))
    lens.surfaces.add(index=len(surfaces) + 1, radius=retina, material=IdealMaterial(n=surfaces[-1][3]))
    lens.set_aperture(aperture_type="EPD", value=epd_mm)
    lens.fields.set_type(field_type="angle")
    lens.fields.add(y=0.0)
    lens.fields.add(y=20.0)
    lens.wavelengths.add(value=WAVELENGTH_UM, is_primary=True)
    return lens


def stop_height(lens, hy, py):
    """Height (mm) at the stop (surface 3) of the ray of field hy through pupil point (0, py)."""
    lens.trace_generic(0.0, hy, 0.0, py, WAVELENGTH_UM)
    return float(optiland.backend.to_numpy(lens.surfaces.y[3])[0])


def real_chief_py(lens, hy):
    """The normalised pupil coordinate Py of the ray through the centre of the stop (secant steps).
    Optiland's chief ray is the ray through the paraxial entrance pupil's centre (Py = 0); off axis
    the cornea's pupil aberration makes it miss the stop's centre (by 8 um at 20 degrees in these
    eyes). eyetrace centres its disc on the ray through the stop's centre."""
    h = 0.01
    slope = (stop_height(lens, hy, h) - stop_height(lens, hy, 0.0)) / h
    py = 0.0
    for _ in range(4):
        py -= stop_height(lens, hy, py) / slope
    return py


def pupil_function(lens, hy, centre_py):
    """exp(2 pi i W) on the GRID x GRID normalised entrance-pupil grid (0 outside) centred on
    Py = centre_py, and W and the points of the disc."""
    grid = UniformDistribution()
    grid.generate_points(GRID)
    grid.y = grid.y + centre_py
    opd = OPD(lens, field=(0.0, hy), wavelength=WAVELENGTH_UM, distribution=grid, strategy="chief_ray")
    data = opd.get_data((0.0, hy), WAVELENGTH_UM)
    w = np.asarray(optiland.backend.to_numpy(data.opd), dtype=float)
    ok = np.asarray(optiland.backend.to_numpy(data.intensity)) > 0
    x = np.asarray(optiland.backend.to_numpy(grid.x), dtype=float)
    y = np.asarray(optiland.backend.to_numpy(grid.y), dtype=float) - centre_py
    ix = np.rint((x + 1.0) * 0.5 * (GRID - 1)).astype(int)
    iy = np.rint((y + 1.0) * 0.5 * (GRID - 1)).astype(int)
    p = np.zeros((GRID, GRID), dtype=complex)
    p[iy[ok], ix[ok]] = np.exp(2j * np.pi * w[ok])
    return p, w[ok], x[ok], y[ok], int((~ok).sum())


def autocorrelation(p):
    n = 1
    while n < 2 * GRID:
        n *= 2
    f = np.fft.fft2(p, s=(n, n))
    a = np.fft.ifft2(np.abs(f) ** 2)
    return a / a[0, 0], n


def mtf_at(a, n, shear_samples, along_y):
    """|autocorrelation| at a fractional shear along one axis, linear between whole samples."""
    k = int(math.floor(shear_samples))
    t = shear_samples - k
    value = lambda j: abs(a[j % n, 0]) if along_y else abs(a[0, j % n])
    if k + 1 >= GRID:
        return 0.0
    return (1.0 - t) * value(k) + t * value(k + 1)


def navarro_spherical(out):
    """Navarro's OSA c(2,0), c(4,0), c(6,0) in um over a 6 mm entrance pupil on axis at 589.3 nm:
    least squares of Optiland's OPD map (on axis it is rotationally symmetric: the m = 0 terms,
    Z(n,0) = sqrt(n + 1) R_n^0(rho), ANSI Z80.28, are all it holds)."""
    lens = build("navarro", 6.0)
    _, w, x, y, _ = pupil_function(lens, 0.0, 0.0)
    rho2 = x ** 2 + y ** 2
    basis = np.stack([np.ones_like(rho2), math.sqrt(3) * (2 * rho2 - 1),
                      math.sqrt(5) * (6 * rho2 ** 2 - 6 * rho2 + 1),
                      math.sqrt(7) * (20 * rho2 ** 3 - 30 * rho2 ** 2 + 12 * rho2 - 1)], axis=1)
    c_um = np.linalg.lstsq(basis, w, rcond=None)[0] * WAVELENGTH_UM
    with open(out, "w") as f:
        f.write("# Optiland 0.6.0, tools/oracles/optiland_eyes.py: Navarro relaxed, 6 mm entrance pupil, on axis, "
                "589.3 nm, OSA Zernike um\n")
        f.write("c20_um,c40_um,c60_um\n")
        f.write(f"{c_um[1]:.6f},{c_um[2]:.6f},{c_um[3]:.6f}\n")
    print("navarro 6 mm c20 c40 c60 um:", c_um[1:])


def main(out):
    rows = []
    commit = "f854a0bf5145f7931a40a3da77191c2b3e955745 (tag v0.6.0)"
    for name in EYES:
        for epd in (3.0, 5.0):
            lens = build(name, epd)
            for field_deg, hy in ((0.0, 0.0), (20.0, 1.0)):
                centre_py = real_chief_py(lens, hy) if hy else 0.0
                p, w, x, y, lost = pupil_function(lens, hy, centre_py)
                a, n = autocorrelation(p)
                spacing_mm = epd / (GRID - 1)
                cos_f = math.cos(math.radians(field_deg))
                rms = float(np.sqrt(np.mean((w - w.mean()) ** 2)))
                # Without tilt: the residual of a least-squares plane (piston and tilt) over the
                # equal-area samples. Tilt depends on which ray is the chief ray (the image
                # point the reference sphere is centred on); the MTF does not.
                basis = np.stack([np.ones_like(x), x, y], axis=1)
                residual = w - basis @ np.linalg.lstsq(basis, w, rcond=None)[0]
                rms_no_tilt = float(np.sqrt(np.mean(residual ** 2)))
                # The same on Optiland's own disc (centred on the paraxial entrance pupil).
                _, w0, x0, y0, _ = pupil_function(lens, hy, 0.0)
                basis0 = np.stack([np.ones_like(x0), x0, y0], axis=1)
                residual0 = w0 - basis0 @ np.linalg.lstsq(basis0, w0, rcond=None)[0]
                strehl_chief = float(abs(np.mean(np.exp(2j * np.pi * w))) ** 2)
                psf = FFTPSF(lens, field=(0.0, hy), wavelength=WAVELENGTH_UM, num_rays=128, grid_size=512)
                row = {"model": name, "pupil_mm": epd, "field_deg": field_deg, "wavelength_nm": 589.3,
                       "disc_centre_mm": round(centre_py * epd / 2, 6),
                       "rms_waves": round(rms, 6), "rms_no_tilt_waves": round(rms_no_tilt, 6),
                       "rms_no_tilt_paraxial_centre_waves": round(float(np.sqrt(np.mean(residual0 ** 2))), 6),
                       "strehl_at_chief_ray": round(strehl_chief, 6),
                       "optiland_fft_strehl": round(psf.strehl_ratio(), 6), "rays_lost": lost}
                for f in FREQS_CPD:
                    per_rad = f * 180.0 / math.pi
                    shear_mm = per_rad * WAVELENGTH_UM * 1e-3
                    row[f"mtf_s_{f}"] = round(mtf_at(a, n, shear_mm / spacing_mm, False), 6)
                    row[f"mtf_t_{f}"] = round(mtf_at(a, n, shear_mm / cos_f / spacing_mm, True), 6)
                rows.append(row)
                print(name, epd, field_deg, row, flush=True)
    with open(out, "w", newline="") as f:
        f.write(f"# Optiland {optiland.__version__ if hasattr(optiland, '__version__') else '0.6.0'} "
                f"commit {commit}; tools/oracles/optiland_eyes.py; grid {GRID}; 589.3 nm\n")
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main(sys.argv[1])
    navarro_spherical(sys.argv[1].replace("eyes_mtf.csv", "navarro_6mm_zernike.csv"))
