"""The clinical figure of tools/figures: one scene through a person's eye and its corrections.

The figure scene (scenes/peripheral.pbrt: letter charts at 0.25, 1 and 4 m, a far wall at 10 m)
through the Navarro eye at a 4 mm pupil, monochromatic at its design wavelength (589.3 nm,
where the relaxed eye is emmetropic), as five people: an emmetrope; a -3 D axial myope
uncorrected (far point 0.33 m: the 0.25 m chart is nearly sharp, the wall is not); the same
myope with spectacles of -3.11 D at 12 mm (the vertex-distance formula F / (1 - d F)) and with a
-3 D contact lens; and an astigmat whose cornea has -1.50 D of cylinder at axis 90. Under each
panel, the refraction `eyetrace optics` reports for that eye (sphere / cylinder x axis, at the
first vertex, which for the corrected eyes is the correcting lens's front).

Measured on the far wall (|horizontal angle| < 10 deg, the band where only the wall is seen):
the luminance's gradient energy along x (what vertical edges give) and along y (horizontal
edges), each against the emmetrope's, with the sampling noise's share removed
(figure_metrics.PanelEnergy). The claims: the corrections restore the wall to the emmetrope's
sharpness, the uncorrected myope loses most of it, and the astigmat blurs vertical edges
(its horizontal meridian is the 1.50 D too strong one) more than horizontal ones.
"""
import csv
import os
from typing import NamedTuple

import numpy as np

import figure_metrics as fm
import image_files

PUPIL_MM = 4.0
WAVELENGTH_NM = 589.3
WALL_HALF_WIDTH_DEG = 10.0
# (name, label, the eye's camera parameters)
EYES = (
    ("clinical-emmetrope", "emmetrope", ""),
    ("clinical-myope", "-3 D myope", '"float refractiveerror" -3'),
    ("clinical-spectacles", "-3 D, spectacles -3.11 D", '"float refractiveerror" -3 "float spectaclesphere" -3.112'),
    ("clinical-contact", "-3 D, contact lens -3 D", '"float refractiveerror" -3 "float contactlens" -3'),
    ("clinical-astigmat", "cornea -1.50 x 90", '"float cylinder" -1.5 "float axis" 90'),
)
# Claims' thresholds: a correction keeps at least CORRECTED of the emmetrope's gradient energy
# (the spectacle lens's own aberrations and the eye's changed length leave a little less); the
# uncorrected myope at most UNCORRECTED; the astigmat's x/y ratio at most ASTIGMATIC.
CORRECTED, UNCORRECTED, ASTIGMATIC = 0.8, 0.3, 0.7


class Panel(NamedTuple):
    name: str
    camera: str
    label: str
    spp: int


def camera_text(params):
    return (f'Camera "navarro" "float fov" {fm.FOV:g} "float pupildiameter" {PUPIL_MM:g} '
            f'"float wavelength" {WAVELENGTH_NM:g} {params}').strip()


def panels(spp):
    return [Panel(name, camera_text(params), label, spp) for name, label, params in EYES]


def refraction_text(report):
    return (f"{report['sphere_diopters']:+.2f} / {report['cylinder_diopters']:+.2f} x {report['axis_deg']:.0f}")


def directional_energy(halves, mask):
    """Gradient energy along x and along y of the panel (mean of halves), noise share removed."""
    ya, yb = (fm.luminance(h) for h in halves)
    out = []
    for axis in (1, 0):
        d = lambda y: np.diff(y, axis=axis)[: mask.shape[0] - (axis == 0), : mask.shape[1] - (axis == 1)]
        m = mask[: mask.shape[0] - (axis == 0), : mask.shape[1] - (axis == 1)]
        mean, noise = d(0.5 * (ya + yb)) ** 2, d(ya - yb) ** 2 / 4.0
        out.append(float(mean[m].mean() - noise[m].mean()))
    return out


def report(out_dir, chosen, optics_report):
    """Measures the chosen panels (all of EYES needed for the claims), writes clinical.csv and
    clinical.png, prints the table and the claims. optics_report(camera) -> `eyetrace optics
    --json` of that camera."""
    rows = []
    for p in chosen:
        halves = [image_files.read_rgb(h, "figures") for h in fm.half_paths(out_dir, p.name)]
        ax, ay = fm.pixel_angles(halves[0].shape[:2], "navarro")
        mask = fm.wall_mask(ax, ay, 0.0, WALL_HALF_WIDTH_DEG)
        ex, ey = directional_energy(halves, mask)
        rx = optics_report(p.camera)
        rows.append(dict(panel=p.name, label=p.label, energy_x=ex, energy_y=ey, sphere=rx["sphere_diopters"],
                         cylinder=rx["cylinder_diopters"], axis=rx["axis_deg"], M=rx["M"]))
    ref = next((r for r in rows if r["panel"] == "clinical-emmetrope"), None)
    for r in rows:
        r["x_vs_emmetrope"] = r["energy_x"] / ref["energy_x"] if ref else float("nan")
        r["y_vs_emmetrope"] = r["energy_y"] / ref["energy_y"] if ref else float("nan")
    with open(os.path.join(out_dir, "clinical.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("Clinical figure: far-wall gradient energy along x and y against the emmetrope's; refraction from "
          "`eyetrace optics` (sphere / minus cylinder x axis, D)")
    for r in rows:
        print(f"  {r['panel']:22s} x {r['x_vs_emmetrope']:5.2f}  y {r['y_vs_emmetrope']:5.2f}   "
              f"{r['sphere']:+.2f} / {r['cylinder']:+.2f} x {r['axis']:.0f}")
    fm.montage([os.path.join(out_dir, r["panel"] + ".png") for r in rows],
               [f"{r['label']}: {r['sphere']:+.2f} / {r['cylinder']:+.2f} x {r['axis']:.0f}" for r in rows],
               os.path.join(out_dir, "clinical.png"),
               f"Navarro eye, {PUPIL_MM:g} mm pupil: a person's eye and its corrections "
               "(under each: the refraction eyetrace optics reports, sphere / cylinder x axis, D)", cols=3,
               tile_inches=(5.2, 3.95))
    return check_claims({r["panel"]: r for r in rows})


def check_claims(by):
    verdicts = {}

    def say(claim, holds, detail):
        verdicts[claim] = holds
        print(f"  [{'HOLDS' if holds else 'DOES NOT HOLD'}] {claim}: {detail}")

    if len(by) < len(EYES):
        return verdicts
    corrected = [by["clinical-spectacles"], by["clinical-contact"]]
    say("the optics find the corrected myope emmetropic (|M| < 0.05 D)", all(abs(r["M"]) < 0.05 for r in corrected),
        ", ".join(f"{r['panel']} M {r['M']:+.3f} D" for r in corrected))
    wall = lambda r: 0.5 * (r["x_vs_emmetrope"] + r["y_vs_emmetrope"])
    say(f"spectacles and contact lens restore the far wall (>= {CORRECTED:g} of the emmetrope's gradient energy)",
        all(wall(r) >= CORRECTED for r in corrected), ", ".join(f"{r['panel']} {wall(r):.2f}" for r in corrected))
    m = by["clinical-myope"]
    say(f"the uncorrected myope loses the far wall (<= {UNCORRECTED:g})", wall(m) <= UNCORRECTED, f"{wall(m):.2f}")
    a = by["clinical-astigmat"]
    ratio = a["x_vs_emmetrope"] / a["y_vs_emmetrope"]
    say(f"the astigmat (-1.50 x 90) blurs vertical edges more than horizontal ones (x/y <= {ASTIGMATIC:g})",
        ratio <= ASTIGMATIC, f"x {a['x_vs_emmetrope']:.2f}, y {a['y_vs_emmetrope']:.2f}; optics cylinder "
        f"{a['cylinder']:+.2f} x {a['axis']:.0f}")
    return verdicts
