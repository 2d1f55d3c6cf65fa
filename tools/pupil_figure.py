"""The pupil figure of tools/figures: one letter chart through the Navarro eye at five pupils.

What a person sees depends on the pupil in two opposite ways: diffraction blurs more as the
pupil shrinks (the Airy pattern's size goes as wavelength / diameter), the eye's aberrations
blur more as it grows. Only a render with both shows the sharpest image at an intermediate
pupil, near 2-3 mm, as measured in human eyes (Campbell & Green 1965; Artal & Navarro 1994).

The scene (scenes/acuity.pbrt, written by tools/make_textures from the layout below) is an
acuity chart of Sloan letters from 10 to 3.2 arcmin tall (20/40 to 20/13), 1.2 degrees wide,
DISTANCE_M away on the visual axis. It is rendered through the relaxed Navarro eye at each of
PUPILS_MM, monochromatic at WAVELENGTH_NM (so that the eye's chromatic aberration does not
enter: this figure is about diffraction against monochromatic aberrations), with diffraction
on, and through a pinhole camera as the perfect image.

The measurement is the image's own modulation transfer: in a band of spatial frequencies, the
square root of the eye image's power spectrum over the pinhole image's (both windowed alike,
the sampling noise's power subtracted, estimated from the difference of each panel's two
independent halves). For a blur that does not change across the chart's 1.2 degrees this is
the eye's MTF averaged over the band's orientations, the quantity `eyetrace optics --wave`
computes from the wavefront, independently of the renderer. The plot shows both against the
pupil, with the optics' Strehl ratio.
"""
import csv
import math
import os
from typing import NamedTuple

import numpy as np

import figure_metrics as fm
import image_files

PUPILS_MM = (1.0, 2.0, 3.0, 5.0, 7.0)
# The models' design wavelength, at which the relaxed Navarro eye is emmetropic (at 555 nm its
# chromatic aberration makes it 0.17 D myopic, a defocus that would dominate every pupil).
WAVELENGTH_NM = 589.3
DISTANCE_M = 100.0  # far: 0.01 D of defocus for the relaxed eye, negligible at every pupil
CHART_DEG = 1.2  # the chart's side; the image shows its central FOV_DEG
FOV_DEG = 1.0
TEXTURE = "acuity-chart.png"
TEXTURE_PX = 2048  # 0.035 arcmin per texel: far finer than any image detail
# Letter heights in arcmin, one row each (0.1 log units apart from 10 to 3.2: 20/40 to 20/13).
LETTER_ARCMIN = tuple(10.0 * 10 ** (-0.1 * k) for k in range(6))
BANDS_CPD = ((7.5, 12.5), (17.5, 22.5), (27.5, 32.5), (37.5, 42.5))  # measured bands; centres below
CLAIM_CPD = 30.0
# How well the rendered MTF must match the optics' in the claim: the render samples the wave
# PSF from a table interpolated over field and wavelength (docs/wave-optics.md gives its
# encircled-energy agreement, 4 %), and a band average of the MTF is not its value at the
# centre; 0.05 in MTF covers both.
AGREEMENT = 0.05

QUALITY = {
    "smoke": dict(px=96, spp=16),
    "preview": dict(px=240, spp=64),
    "paper": dict(px=480, spp=256),
}


def scene_text():
    half = DISTANCE_M * math.tan(math.radians(CHART_DEG / 2))
    return f"""# The pupil figure of tools/figures (written by tools/make_textures from
# tools/pupil_figure.py: edit the layout there and rerun it). Metres; the eye sits at the origin
# looking down +z, y up; tools/figures supplies the camera and the film.
# An acuity chart {CHART_DEG:g} deg wide, {DISTANCE_M:g} m away on the visual axis.
Film "rgb" "string filename" "acuity.exr"
Sampler "zsobol" "integer pixelsamples" 16
Integrator "direct"
PixelFilter "box"

WorldBegin

LightSource "distant" "point3 from" [0 0 0] "point3 to" [0 0 1] "rgb L" [3.14159 3.14159 3.14159]
Texture "chart" "spectrum" "imagemap" "string filename" "textures/{TEXTURE}"
AttributeBegin
  Translate 0 0 {DISTANCE_M:g}
  Material "diffuse" "texture reflectance" "chart"
  Shape "bilinearmesh" "point3 P" [{-half:.6f} {-half:.6f} 0  {half:.6f} {-half:.6f} 0  {-half:.6f} {half:.6f} 0  {half:.6f} {half:.6f} 0]
    "point2 uv" [0 0  1 0  0 1  1 1]
AttributeEnd
"""


ROW_PITCH = 1.5  # row spacing / letter height
LETTER_PITCH = 1.6  # letter spacing / letter height
VIEW_FRACTION = 0.8  # of the chart's width the rows fill: all within the image's FOV_DEG


def chart_rows(rng, letters):
    """(height as a fraction of the chart, letters) per row: each row as many letters as fit in
    VIEW_FRACTION of the chart's width, LETTER_PITCH letter heights apart."""
    rows = []
    for arcmin in LETTER_ARCMIN:
        size = arcmin / 60.0 / CHART_DEG
        n = max(1, int(VIEW_FRACTION / (LETTER_PITCH * size)))
        rows.append((size, "".join(rng.choice(list(letters)) for _ in range(n))))
    return rows


def camera_text(pupil_mm):
    return (f'Camera "navarro" "float fov" {FOV_DEG:g} "float pupildiameter" {pupil_mm:g} '
            f'"float wavelength" {WAVELENGTH_NM:g} "bool diffraction" true')


REFERENCE_CAMERA = f'Camera "pinhole" "float fov" {FOV_DEG:g}'


class Panel(NamedTuple):
    name: str
    camera: str
    label: str
    pupil_mm: float  # 0 for the pinhole reference
    spp: int


def render_options(quality):
    px = QUALITY[quality]["px"]
    return ["--resolution", f"{px}x{px}"]


def panels(quality):
    spp = QUALITY[quality]["spp"]
    out = [Panel(f"pupil-{p:g}mm", camera_text(p), f"{p:g} mm pupil", p, spp) for p in PUPILS_MM]
    return out + [Panel("pupil-reference", REFERENCE_CAMERA, "pinhole (perfect image)", 0.0, spp)]


# --- Measurement -------------------------------------------------------------------------------

def spectra(halves):
    """Power spectrum of the panel (mean of its halves' luminance, Hann-windowed) and of its
    sampling noise (a quarter of the halves' difference's), and the frequency of every bin in
    cycles per degree."""
    ya, yb = (fm.luminance(h) for h in halves)
    n = ya.shape[0]
    w = np.outer(np.hanning(n), np.hanning(n))
    mean = 0.5 * (ya + yb)
    power = np.abs(np.fft.fft2((mean - mean.mean()) * w)) ** 2
    noise = np.abs(np.fft.fft2((ya - yb) * w)) ** 2 / 4.0
    f = np.fft.fftfreq(n, d=FOV_DEG / n)  # cycles per degree
    fx, fy = np.meshgrid(f, f)
    return power, noise, np.hypot(fx, fy)


class Transfer(NamedTuple):
    band: tuple
    mtf: float
    sigma: float  # standard deviation of mtf from the sampling noise of both images


def window_correlation(n):
    """How much more a sum of Hann-windowed power over a block of bins varies than a sum of as
    many independent bins: the window spreads each frequency over neighbouring bins, whose
    powers then correlate. Per dimension sum_k |c_k|^2 = n sum w^4 / (sum w^2)^2 (35/18 for
    Hann), squared for the two dimensions."""
    h = np.hanning(n)
    return float(n * (h ** 4).sum() / (h ** 2).sum() ** 2) ** 2


def band_signal(spectrum, m):
    """The band's signal power (power minus the noise's estimate) and its variance: per bin the
    noise adds N^2 (an exponential's variance; the subtracted estimate as much again) and the
    cross term 2 Re(S conj(noise)) adds 2 S N; neighbouring bins correlate (window_correlation)."""
    p, n, _ = spectrum
    s = np.maximum(p[m] - n[m], 0.0)
    var = float((2.0 * s * n[m] + 2.0 * n[m] ** 2).sum()) * window_correlation(p.shape[0])
    return float((p[m] - n[m]).sum()), var


def band_transfer(eye, ref, band):
    """sqrt(sum (P_eye - N_eye) / sum (P_ref - N_ref)) over the band's bins."""
    m = (eye[2] >= band[0]) & (eye[2] < band[1])
    se, ve = band_signal(eye, m)
    sr, vr = band_signal(ref, m)
    if not sr > 0.0:
        return Transfer(band, float("nan"), float("nan"))  # the pinhole image has no power there
    if not se > 0.0:  # the eye's power is all noise: 0, uncertain by the noise's own scatter
        return Transfer(band, 0.0, math.sqrt(math.sqrt(ve) / sr))
    mtf = math.sqrt(se / sr)
    return Transfer(band, mtf, 0.5 * mtf * math.sqrt(ve / se ** 2 + vr / sr ** 2))


def optics_freqs(pupil_mm):
    """The band centres below the pupil's diffraction cut-off, for `eyetrace optics --freqs`
    (which refuses frequencies beyond it: the MTF is exactly 0 there). The cut-off is D / lambda
    for the entrance pupil D, about 1.13 times the iris for the Navarro eye (taken as 1.1 here,
    which only keeps a frequency out that lies within 3 % of the cut-off)."""
    cutoff = 1.1 * pupil_mm * 1e-3 / (WAVELENGTH_NM * 1e-9) * math.pi / 180.0
    return [0.5 * (a + b) for a, b in BANDS_CPD if 0.5 * (a + b) < cutoff]


def optics_mtf(wave, freq):
    """The optics' MTF at freq (cycles/deg), the mean of tangential and sagittal (on axis they
    are one); 0 at frequencies the report left out (beyond the cut-off)."""
    for m in wave["mtf"]:
        if abs(m["freq_cpd"] - freq) < 1e-9:
            return 0.5 * (m["tangential"] + m["sagittal"])
    return 0.0


def report(out_dir, chosen, optics_wave):
    """Measures the chosen panels, writes pupil.csv, pupil.png (montage), pupil-mtf.png (plot);
    prints the table and the claims. optics_wave(pupil_mm) -> the wave object (field 0) of
    `eyetrace optics --json --wave`."""
    by_name = {p.name: p for p in chosen}
    if "pupil-reference" not in by_name:
        return {}
    read = lambda name: [image_files.read_rgb(h, "figures") for h in fm.half_paths(out_dir, name)]
    ref = spectra(read("pupil-reference"))
    rows = []
    for p in (p for p in chosen if p.pupil_mm > 0):
        eye = spectra(read(p.name))
        wave = optics_wave(p.pupil_mm)
        for band in BANDS_CPD:
            t = band_transfer(eye, ref, band)
            centre = 0.5 * (band[0] + band[1])
            rows.append(dict(pupil_mm=p.pupil_mm, freq_cpd=centre, rendered_mtf=t.mtf, sigma=t.sigma,
                             optics_mtf=optics_mtf(wave, centre), strehl=wave["strehl"]))
    write_csv(rows, os.path.join(out_dir, "pupil.csv"))
    print_table(rows)
    eyes = [p for p in chosen if p.pupil_mm > 0] + [by_name["pupil-reference"]]
    fm.montage([os.path.join(out_dir, p.name + ".png") for p in eyes], [p.label for p in eyes],
               os.path.join(out_dir, "pupil.png"),
               f"Relaxed Navarro eye, {WAVELENGTH_NM:g} nm, with diffraction: an acuity chart (20/40 to 20/13) "
               f"at {DISTANCE_M:g} m", cols=3, tile_inches=(3.6, 3.9))
    plot(rows, os.path.join(out_dir, "pupil-mtf.png"))
    return check_claims(rows)


def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4f}" if isinstance(v, float) else v) for k, v in r.items()})


def print_table(rows):
    print(f"Pupil figure: the rendered chart's MTF (band power against the pinhole's, noise removed) against "
          f"`eyetrace optics --wave` at {WAVELENGTH_NM:g} nm")
    print("  pupil  cpd   rendered (sigma)  optics  Strehl")
    for r in rows:
        print(f"  {r['pupil_mm']:4g}  {r['freq_cpd']:4g}   {r['rendered_mtf']:6.3f} ({r['sigma']:.3f})  "
              f"{r['optics_mtf']:6.3f}  {r['strehl']:6.3f}")


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    at = [r for r in rows if r["freq_cpd"] == CLAIM_CPD]
    pupils = [r["pupil_mm"] for r in at]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.errorbar(pupils, [r["rendered_mtf"] for r in at], yerr=[3 * r["sigma"] for r in at], fmt="o-",
                label=f"rendered image, MTF at {CLAIM_CPD:g} cpd")
    ax.plot(pupils, [r["optics_mtf"] for r in at], "s--", label=f"eyetrace optics: MTF at {CLAIM_CPD:g} cpd")
    ax.plot(pupils, [r["strehl"] for r in at], "^:", label="eyetrace optics: Strehl ratio")
    ax.set_xlabel("pupil diameter (mm)")
    ax.set_ylabel("MTF / Strehl ratio")
    ax.set_ylim(0, 1.05)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=9)
    ax.set_title(f"Navarro eye, {WAVELENGTH_NM:g} nm, diffraction and aberrations")
    fig.tight_layout()
    fig.savefig(path + ".tmp.png", dpi=110)
    plt.close(fig)
    os.replace(path + ".tmp.png", path)


def check_claims(rows):
    verdicts = {}

    def say(claim, holds, detail):
        verdicts[claim] = holds
        print(f"  [{'HOLDS' if holds else 'DOES NOT HOLD'}] {claim}: {detail}")

    at = sorted((r for r in rows if r["freq_cpd"] == CLAIM_CPD), key=lambda r: r["pupil_mm"])
    if len(at) < 3:
        return verdicts
    best = max(at, key=lambda r: r["rendered_mtf"])
    say(f"the sharpest image (MTF at {CLAIM_CPD:g} cpd) is at a 2-3 mm pupil", 2.0 <= best["pupil_mm"] <= 3.0,
        ", ".join(f"{r['pupil_mm']:g} mm {r['rendered_mtf']:.3f}" for r in at))
    worst = max(at, key=lambda r: abs(r["rendered_mtf"] - r["optics_mtf"]) - 3 * r["sigma"])
    holds = all(abs(r["rendered_mtf"] - r["optics_mtf"]) <= AGREEMENT + 3 * r["sigma"] for r in at)
    say(f"the rendered MTF at {CLAIM_CPD:g} cpd is the optics' (within {AGREEMENT:g} + 3 sigma)", holds,
        f"largest difference {worst['rendered_mtf'] - worst['optics_mtf']:+.3f} at {worst['pupil_mm']:g} mm "
        f"(sigma {worst['sigma']:.3f})")
    return verdicts
