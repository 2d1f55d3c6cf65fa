"""The chromatic figure of tools/figures: coloured letters seen through the dispersive Navarro eye.

The scene (scenes/chromatic.pbrt, written by tools/make_textures from the layout below) has a
column of three letters at each field angle of FIELDS_DEG along the horizontal meridian: blue
above, white on the meridian, red below, each on black. The relaxed Navarro eye is rendered
dispersive and monochromatic at MONO_NM, at each of PUPILS_MM, with a spectral film whose
buckets are centred on the two wavelengths TCA_NM at which `eyetrace optics --json` is asked
for the transverse chromatic aberration (TCA).

The fringe is measured as the radial offset between the white letter's image at the short and
at the long wavelength: the difference of the letter's centroids in the two buckets. A centroid
is linear in the image, so for a locally shift-invariant blur it is the object's centroid plus
the point spread function's, whatever the blur's width and shape; the difference between two
wavelengths is then exactly the optics' `centroid_tca_arcmin` (the real-ray spots' centroids),
with nothing to fit. The background is black, so pixels outside the letter add no noise, and
the centroid averages every edge of the letter (robust to colour noise). The same offset
between the image's B and R channels is the fringe one sees in the sRGB image; it is reported
beside, not compared: those channels weigh broad bands of wavelengths, some negatively (sRGB's
colour matching functions have negative lobes), so they have no single wavelength whose TCA
they should show.
"""
import csv
import functools
import math
import os
from typing import NamedTuple

import numpy as np

import figure_metrics as fm
import image_files

FIELDS_DEG = (0.0, 10.0, 20.0, 30.0)  # horizontal field angles of the letter columns
PUPILS_MM = (3.0, 6.0)
MONO_NM = 555.0  # the monochromatic comparison (near the photopic peak)
DISTANCE_M = 10.0  # the letters' distance (as the far wall of scenes/peripheral.pbrt)
LETTER = "H"  # straight strokes: every edge lies across the radial direction or along it
LETTER_DEG = 2.0  # side of each letter's square, degrees of visual angle
ROW_DEG = 3.5  # vertical distance between the letters of a column
# (texture name, linear sRGB reflectance of the letter, elevation in degrees)
COLOURS = (("blue", (0.0, 0.0, 1.0), ROW_DEG), ("white", (1.0, 1.0, 1.0), 0.0), ("red", (1.0, 0.0, 0.0), -ROW_DEG))
# Black border around each letter's square inside its measuring window. The window must hold
# the whole blurred letter, or the centroid loses part of the spot: at 30 deg and 6 mm the 450 nm
# image has a flare towards the fovea reaching 1.4 deg beyond the letter's edge, so the radial
# (horizontal) border is wide; vertically the next letter of the column bounds it.
RADIAL_MARGIN_DEG = 3.0
TANGENTIAL_MARGIN_DEG = 0.75
EDGE_BAND_DEG = 0.25  # the window's outermost band, whose share of the light must be negligible
# The TCA's two wavelengths (those `eyetrace optics` uses by default), given to it explicitly so
# that the film's buckets and the optics speak of the same pair.
TCA_NM = (450.0, 650.0)
# Width of the spectral film's buckets, one centred on each TCA wavelength: wide, for the
# samples they collect; the TCA varies smoothly enough with wavelength that a bucket's mean
# offset is its centre's (1/lambda^2 averaged over 425-475 nm differs from 1/450^2 by 0.3%).
BUCKET_NM = 50.0
AGREEMENT = 0.05  # a fringe agrees with the TCA within its noise (tolerance()) or this fraction of it
MAX_EDGE_LIGHT = 0.01  # of a bucket's light in a window's outer EDGE_BAND_DEG
# Pixel pitch and samples per pixel (spp: dispersive eye, mono_spp: monochromatic) of each
# tools/figures quality. The dispersive eye's samples cost more (with the scene's box filter it
# traces a path per wavelength, docs/spectral.md), so preview gives it 32 spp to stay within the
# ~60 s the figure may add to tools/figures; its fringe sigma there is 0.08 arcmin at 3 mm
# against 0.15 for the monochromatic eye at 16 spp (docs/figures.md).
QUALITY = {
    "smoke": dict(arcmin_per_px=6.0, spp=16, mono_spp=4),
    "preview": dict(arcmin_per_px=2.0, spp=32, mono_spp=16),
    "paper": dict(arcmin_per_px=1.0, spp=256, mono_spp=64),
}


def texture_name(colour):
    return f"letter-{colour}.png"


def scene_text():
    """scenes/chromatic.pbrt: each letter a square facing the eye, LETTER_DEG wide, at its field
    angle and elevation, DISTANCE_M away; one distant light from behind the eye (no shading
    noise), as in scenes/peripheral.pbrt. Nothing else: every other ray leaves the scene (black)."""
    half = DISTANCE_M * math.tan(math.radians(LETTER_DEG / 2))
    lines = [
        "# The chromatic figure of tools/figures (written by tools/make_textures from",
        "# tools/chromatic_figure.py: edit the layout there and rerun it). Metres; the eye sits at the",
        "# origin looking down +z, y up; tools/figures supplies the camera and the film.",
        f"# Letters '{LETTER}' ({LETTER_DEG:g} deg squares, {DISTANCE_M:g} m away) at horizontal field angles "
        + ", ".join(f"{f:g}" for f in FIELDS_DEG) + " deg:",
        "# " + ", ".join(f"{c} at {e:+g} deg elevation" for c, _, e in COLOURS) + ", each on black.",
        film_text(),
        'Sampler "zsobol" "integer pixelsamples" 16',
        'Integrator "direct"',
        'PixelFilter "box"',
        "",
        "WorldBegin",
        "",
        'LightSource "distant" "point3 from" [0 0 0] "point3 to" [0.2 -0.35 1] "rgb L" [3.14159 3.14159 3.14159]',
    ]
    for colour, _, _ in COLOURS:
        lines.append(f'Texture "{colour}" "spectrum" "imagemap" "string filename" "textures/{texture_name(colour)}"')
    for field in FIELDS_DEG:
        for colour, _, elevation in COLOURS:
            lines += letter_text(colour, field, elevation, half)
    return "\n".join(lines) + "\n"


def film_text():
    """A spectral film whose equal buckets have one centred on each TCA wavelength."""
    n = round((TCA_NM[1] - TCA_NM[0]) / BUCKET_NM) + 1
    lo, hi = TCA_NM[0] - BUCKET_NM / 2, TCA_NM[1] + BUCKET_NM / 2
    return (f'Film "spectral" "integer nbuckets" {n} "float lambdamin" {lo:g} "float lambdamax" {hi:g}'
            ' "string filename" "chromatic.exr"')


def letter_text(colour, field_deg, elevation_deg, half_m):
    """One letter square, turned to face the eye: rotated about x by the elevation, then about y
    by the field angle, then moved along that direction to DISTANCE_M."""
    az, el = math.radians(field_deg), math.radians(elevation_deg)
    p = DISTANCE_M * np.array([math.cos(el) * math.sin(az), math.sin(el), math.cos(el) * math.cos(az)])
    s = f"{half_m:.5f}"
    return [
        f"AttributeBegin  # {colour}, field {field_deg:g} deg, elevation {elevation_deg:+g} deg",
        f"  Translate {p[0]:.5f} {p[1]:.5f} {p[2]:.5f}",
        f"  Rotate {field_deg:g} 0 1 0",
        f"  Rotate {-elevation_deg:g} 1 0 0",
        f'  Material "diffuse" "texture reflectance" "{colour}"',
        f'  Shape "bilinearmesh" "point3 P" [-{s} -{s} 0  {s} -{s} 0  -{s} {s} 0  {s} {s} 0]',
        '    "point2 uv" [0 0  1 0  0 1  1 1]',
        "AttributeEnd",
    ]


# --- Rendering ---------------------------------------------------------------------------------

class Geometry(NamedTuple):
    """The image of a quality: the eye camera's vertical field of view (degrees; pixels are
    linear in visual angle, pitch fov / height on both axes), the full image's size, and the
    first column rendered (--crop keeps the columns from the 0 deg letter outwards)."""
    fov_deg: float
    width: int
    height: int
    first_column: int

    def render_options(self):
        # A crop's first column is ceil(width * x0) (pbrt's cropwindow); half a pixel below it
        # makes that exactly first_column whatever the rounding of the fraction.
        x0 = (self.first_column - 0.5) / self.width
        return ["--resolution", f"{self.width}x{self.height}", "--crop", f"{x0:.9f},1,0,1"]


def geometry(quality):
    pitch = QUALITY[quality]["arcmin_per_px"] / 60.0
    half_x, half_y = window_half_deg()
    height = round(2 * (ROW_DEG + half_y) / pitch)
    half_width = round((max(FIELDS_DEG) + half_x) / pitch)
    return Geometry(height * pitch, 2 * half_width, height, half_width - round(half_x / pitch))


def window_half_deg():
    """Half the width and height of a letter's measuring window, degrees."""
    return LETTER_DEG / 2 + RADIAL_MARGIN_DEG, LETTER_DEG / 2 + TANGENTIAL_MARGIN_DEG


def camera_text(fov_deg, pupil_mm, wavelength_nm=None):
    """The relaxed Navarro eye: dispersive, or monochromatic at wavelength_nm. The dispersive eye
    traces each wavelength's own path: in about the time of the default spectral MIS it halves
    the fringes' sigma (0.08 and 0.18 arcmin against 0.18 and 0.31 at 3 and 6 mm, preview,
    2026-11-28), since every wavelength's image of an edge is then a stratified sample of it."""
    if wavelength_nm is None:
        return (f'Camera "navarro" "float fov" {fov_deg:.9g} "float pupildiameter" {pupil_mm:g}'
                ' "string dispersionsampling" "paths"')
    return (f'Camera "navarro" "float fov" {fov_deg:.9g} "float pupildiameter" {pupil_mm:g}'
            f' "float wavelength" {wavelength_nm:g}')


class Panel(NamedTuple):
    name: str
    camera: str
    label: str
    pupil_mm: float
    mono_nm: object  # None: dispersive
    spp: int


def panels(quality):
    """Every render: the dispersive and the monochromatic eye at each pupil."""
    q, fov = QUALITY[quality], geometry(quality).fov_deg
    out = []
    for mono in (None, MONO_NM):
        for pupil in PUPILS_MM:
            suffix = "" if mono is None else f"-{mono:g}nm"
            label = f"{pupil:g} mm pupil, " + ("dispersive" if mono is None else f"monochromatic {mono:g} nm")
            out.append(Panel(f"chromatic-{pupil:g}mm{suffix}", camera_text(fov, pupil, mono), label, pupil, mono,
                             q["spp"] if mono is None else q["mono_spp"]))
    return out


# --- Measurement -------------------------------------------------------------------------------

def bucket_channel(nm):
    """pbrt-v4's name of the spectral bucket centred at nm ("S0.450,000nm")."""
    return "S0." + f"{nm:.3f}".replace(".", ",") + "nm"


def letter_mask(ax, ay, field_deg, inset_deg=0.0):
    """The measured letter's window: the white letter's square (it holds every wavelength; on
    the meridian, so its radial direction is horizontal) and its black margin, shrunk by
    inset_deg on every side."""
    half_x, half_y = window_half_deg()
    return (np.abs(ax - field_deg) <= half_x - inset_deg) & (np.abs(ay) <= half_y - inset_deg)


def edge_light(image, ax, ay, field_deg):
    """The share of a window's light in its outermost EDGE_BAND_DEG: near 0 when the window
    holds the whole blurred letter and no light of its neighbours."""
    whole = image[letter_mask(ax, ay, field_deg)].sum()
    return float(1 - image[letter_mask(ax, ay, field_deg, EDGE_BAND_DEG)].sum() / whole)


def centroid_deg(image, ax, mask):
    """Horizontal centroid (degrees) of an image's light within mask: for a blur that does not
    change across the letter, the object's centroid plus the point spread function's."""
    w = image[mask]
    return float((ax[mask] * w).sum() / w.sum())


def fringes(channels, ax, ay, rows=None):
    """{field: (short - long bucket offset, B - R offset, edge light)}, offsets in arcmin along
    the radial direction (horizontal: the measured letters lie on the horizontal meridian,
    outwards to +x), signed as the optics' tca_arcmin (the short wavelength's image minus the
    long one's); edge light the larger of the two buckets' edge_light. rows: a mask that keeps
    part of each window (default: all of it)."""
    short, long_ = (channels[bucket_channel(nm)] for nm in TCA_NM)
    out = {}
    for f in FIELDS_DEG:
        m = letter_mask(ax, ay, f) & (True if rows is None else rows)
        out[f] = (60 * (centroid_deg(short, ax, m) - centroid_deg(long_, ax, m)),
                  60 * (centroid_deg(channels["B"], ax, m) - centroid_deg(channels["R"], ax, m)),
                  max(edge_light(short, ax, ay, f), edge_light(long_, ax, ay, f)))
    return out


class Fringe(NamedTuple):
    """One letter's measured fringe (arcmin): the TCA buckets' offset and its sampling sigma, the
    sRGB B - R offset, the share of light at the window's edge, and the optics' TCA (centroid of
    the real-ray spots, and chief ray)."""
    field_deg: float
    measured: float
    sigma: float
    srgb: float
    edge_light: float
    centroid_tca: float
    chief_tca: float


def measure(halves, ax, ay, tca):
    """Fringes of one panel from its two half-sample renders (channel dicts); tca: {field:
    (centroid, chief)}. The panel's value is that of the mean of the halves.

    Its sampling sigma comes from four sub-estimates per field: each half's fringe measured on
    the window's upper and on its lower half (the letter is symmetric about the meridian, so both
    halves see the same fringe). Their scatter about their mean, pooled over the fields (3 degrees
    of freedom each), is that of one sub-estimate, which holds a quarter of the light and samples:
    the panel's sigma is half of it."""
    mean = {k: 0.5 * (halves[0][k] + halves[1][k]) for k in halves[0]}
    value = fringes(mean, ax, ay)
    subs = [fringes(h, ax, ay, part) for h in halves for part in (ay > 0, ay <= 0)]
    scatter = [s[f][0] - np.mean([t[f][0] for t in subs]) for f in FIELDS_DEG for s in subs]
    sigma = float(np.sqrt(np.sum(np.square(scatter)) / sigma_dof()) / 2)
    return [Fringe(f, value[f][0], sigma, value[f][1], value[f][2], *tca[f]) for f in FIELDS_DEG]


def sigma_dof():
    """Degrees of freedom of a panel's sigma: 4 sub-estimates, less their mean, per field."""
    return 3 * len(FIELDS_DEG)


def t_threshold(dof, p_two_sided=0.0027):
    """|t| that Student's t with dof degrees of freedom exceeds with probability p_two_sided:
    what 3 sigma (p = 0.0027 for a known sigma) becomes when sigma is itself estimated from dof
    squares. Its density integrated numerically (the tail beyond 60 is below 1e-6 for dof >= 4)."""
    x = np.linspace(0.0, 60.0, 600001)
    pdf = (1 + x * x / dof) ** (-(dof + 1) / 2)
    cdf = np.concatenate([[0.0], np.cumsum(0.5 * (pdf[1:] + pdf[:-1]) * np.diff(x))])
    beyond = 1 - cdf / cdf[-1]  # P(|t| > x)
    return float(np.interp(-p_two_sided, -beyond, x))


def pixel_angles(quality, shape):
    """Visual angles (degrees) of the rendered pixels: the full image's, cropped as rendered."""
    g = geometry(quality)
    ax, ay = fm.pixel_angles((g.height, g.width), "navarro", g.fov_deg)
    ax, ay = ax[:, g.first_column:], ay[:, g.first_column:]
    if ax.shape != shape:
        raise SystemExit(f"figures: chromatic render is {shape}, expected {ax.shape} for {quality} quality")
    return ax, ay


def optics_fields(tca_json):
    """{field: (centroid_tca_arcmin, tca_arcmin)} from `eyetrace optics --json`'s tca object."""
    pair = [tca_json["short_wavelength_nm"], tca_json["long_wavelength_nm"]]
    if list(TCA_NM) != pair:
        raise SystemExit(f"figures: optics TCA is for {pair} nm, the film's buckets for {list(TCA_NM)} nm")
    return {round(f["field_deg"], 6): (f["centroid_tca_arcmin"], f["tca_arcmin"]) for f in tca_json["fields"]}


# --- Report ------------------------------------------------------------------------------------

def report(out_dir, quality, chosen, optics_tca):
    """Measures the chosen panels (Panel list), writes chromatic.csv and chromatic.png, prints
    the table and the claims. optics_tca(pupil_mm) -> `eyetrace optics --json`'s tca object."""
    optics_tca = functools.lru_cache(maxsize=None)(optics_tca)  # one optics run per pupil
    results = []
    for p in chosen:
        halves = [image_files.read_channels(h, "figures") for h in fm.half_paths(out_dir, p.name)]
        ax, ay = pixel_angles(quality, halves[0]["R"].shape)
        results.append((p, measure(halves, ax, ay, optics_fields(optics_tca(p.pupil_mm)))))
        rgb = np.stack([0.5 * (halves[0][c] + halves[1][c]) for c in "RGB"], axis=-1)
        letters_strip(rgb, ax, os.path.join(out_dir, p.name + "-letters.png"))
    write_csv(results, os.path.join(out_dir, "chromatic.csv"))
    print_table(results)
    fm.montage([os.path.join(out_dir, p.name + "-letters.png") for p, _ in results], [p.label for p, _ in results],
               os.path.join(out_dir, "chromatic.png"),
               "Relaxed Navarro eye: blue, white, red letters at " + ", ".join(f"{f:g}" for f in FIELDS_DEG) + " deg",
               cols=min(len(results), len(PUPILS_MM)), tile_inches=(4.2, 3.5))
    return check_claims(results)


def letters_strip(rgb, ax, path):
    """The columns around each field's letters side by side (the black between them left out),
    parted by a grey line, as 8-bit sRGB."""
    half = LETTER_DEG / 2 + TANGENTIAL_MARGIN_DEG
    parts = []
    for f in FIELDS_DEG:
        cols = np.abs(ax[0] - f) <= half
        parts += [rgb[:, cols], np.full((rgb.shape[0], 2, 3), 0.2)]
    fm.write_png(np.concatenate(parts[:-1], axis=1), path)


def ratio(f):
    return f.measured / f.centroid_tca if abs(f.centroid_tca) > 0 else float("nan")


def write_csv(results, path):
    with open(path, "w", newline="") as out:
        w = csv.writer(out)
        w.writerow(["panel", "pupil_mm", "wavelength_nm", "field_deg", "fringe_arcmin", "fringe_sigma_arcmin",
                    "srgb_fringe_arcmin", "edge_light", "centroid_tca_arcmin", "chief_tca_arcmin", "ratio"])
        for p, fringes_ in results:
            for f in fringes_:
                w.writerow([p.name, p.pupil_mm, "dispersive" if p.mono_nm is None else p.mono_nm, f.field_deg,
                            f"{f.measured:.3f}", f"{f.sigma:.3f}", f"{f.srgb:.3f}", f"{f.edge_light:.2e}",
                            f"{f.centroid_tca:.3f}", f"{f.chief_tca:.3f}", f"{ratio(f):.3f}"])


def print_table(results):
    print(f"Chromatic figure: fringe = centroid of the white letter at {TCA_NM[0]:g} nm minus at {TCA_NM[1]:g} nm "
          "(arcmin, radial; sigma from the halves' sub-windows), against the optics' TCA (centroid of the real-ray spots)")
    print("  panel                  field  fringe (sigma)    B-R sRGB  optics TCA  ratio")
    for p, fringes_ in results:
        for f in fringes_:
            print(f"  {p.name:22s} {f.field_deg:4g}  {f.measured:7.2f} ({f.sigma:.2f})  {f.srgb:8.2f}  "
                  f"{f.centroid_tca:10.2f}  {ratio(f):5.2f}")


def tolerance(f, tca):
    """What a fringe may differ by from what it should be: the 3-sigma-equivalent sampling noise
    (t_threshold sigmas), or AGREEMENT of the TCA if larger (the centroid is exact up to the
    blur's change across the letter and the buckets' width, both far below it)."""
    return max(t_threshold(sigma_dof()) * f.sigma, AGREEMENT * abs(tca))


def check_claims(results):
    """Prints whether the window held each letter, the dispersive fringes are the TCA and the
    monochromatic eye shows none. Returns the verdicts."""
    verdicts = {}

    def say(claim, holds, detail):
        verdicts[claim] = holds
        print(f"  [{'HOLDS' if holds else 'DOES NOT HOLD'}] {claim}: {detail}")

    z = t_threshold(sigma_dof())
    disp = [(p, f) for p, fs in results if p.mono_nm is None for f in fs]
    mono = [(p, f) for p, fs in results if p.mono_nm is not None for f in fs]
    window = max(f.edge_light for _, fs in results for f in fs)
    say("every window holds its whole blurred letter", window < MAX_EDGE_LIGHT,
        f"largest share of a bucket's light in a window's outer {EDGE_BAND_DEG:g} deg: {window:.1e}")
    if disp:
        say(f"the dispersive eye's fringes are the optics' TCA (within {z:.2f} sigma or {100 * AGREEMENT:g}%)",
            all(abs(f.measured - f.centroid_tca) <= tolerance(f, f.centroid_tca) for _, f in disp),
            "; ".join(f"{p.pupil_mm:g} mm {f.field_deg:g} deg {f.measured:.2f} vs {f.centroid_tca:.2f}"
                      for p, f in disp))
    if mono:
        # The measurement can tell only if the dispersive fringes stand out of the noise too.
        zs = [abs(f.measured) / f.sigma for _, f in disp if f.field_deg > 0]
        told = f"; dispersive fringes off axis {min(zs):.0f}-{max(zs):.0f} sigma from 0" if zs else ""
        say(f"the monochromatic {MONO_NM:g} nm eye shows no fringe (within {z:.2f} sigma or {100 * AGREEMENT:g}% of "
            "the TCA)" + (f", the dispersive one does (over {z:.2f} sigma)" if zs else ""),
            all(abs(f.measured) <= tolerance(f, f.centroid_tca) for _, f in mono) and all(v > z for v in zs),
            "; ".join(f"{p.pupil_mm:g} mm {f.field_deg:g} deg {f.measured:.2f} (sigma {f.sigma:.2f})" for p, f in mono)
            + told)
    return verdicts
