#!/usr/bin/python3
"""realisticeye_navarro.py OPTICS.json OUTDIR: the Navarro eye as ISET3d's realisticEye camera
(pbrt-v3-spectral, scienstanford/pbrt-v3-spectral at c4d605a) reads it, for the side-by-side
comparison in bench/peer_equal_error.py (docs/performance.md, "Against ISET3d's realisticEye").

OPTICS.json is `eyetrace optics --camera 'Camera "navarro" ...' --json`: its surfaces are the
published Navarro (1985) prescription after the accommodation law, so both renderers trace the
same eye. Written to OUTDIR:
  navarro.dat     the lens file: the effective focal length, then one line per surface from the
                  scene to the retina: radiusX radiusY thickness mediumIndex semiDiameter conicX conicY
                  (mm; mediumIndex is the slot iorN of the medium after the surface).
  camera.txt      the Camera line's parameters (retina distance and radius, index spectra).

realisticEye's conventions, read from its source (cameras/realisticEye.cpp): its camera z axis
points at the scene and a surface's sag is z = c r^2 / (1 + sqrt(1 - (1+Q) c^2 r^2)) with
c = 1/radius, so a positive radius has its centre on the scene side; the optical convention
(eyetrace's, light from the scene) puts the centre of a positive radius on the retina side,
hence the sign flip. Thickness is the distance to the next surface; the last surface's must be 0,
the vitreous being the camera's "retinaDistance". A surface with both radii 0 is the aperture and
takes its semi-diameter from "pupilDiameter". The retina is a sphere of "retinaRadius" (positive,
curving towards the lens).

The index spectra: Navarro's Herzberger-type law through Le Grand's indices at 365, 486.1, 656.3
and 1014 nm (shared/optics eye-models.md 5d), shifted so that it gives the model's index at the
reference wavelength 589.3 nm (the lens's includes the accommodation term); sampled every 10 nm
from 400 to 700 nm, realisticEye's spectral range, and interpolated linearly by pbrt.

Checks before writing: the spectra at 400 and 700 nm against eyetrace's own dispersion (2e-5), and
the lens file's paraxial power, read as realisticEye reads it, against eyetrace's (1e-4 D; a radius
sign error would give -71 D instead of 61.8 D at accommodation 1).
"""
import json
import os
import sys

HERZBERGER = {  # a, b, c, d of A1..A4 (Atchison & Smith 2005, as in eye-models.md 5d)
    'A1': (0.66147196, -0.40352796, -0.28046790, 0.03385979),
    'A2': (-4.20146383, 2.73508956, 1.50543784, -0.11593235),
    'A3': (6.29834237, -4.69409935, -1.57508650, 0.10293038),
    'A4': (-1.75835059, 2.36253794, 0.35011657, -0.02085782),
}
LE_GRAND = {  # indices at 365 / 486.1 / 656.3 / 1014 nm
    'cornea': (1.3975, 1.3807, 1.37405, 1.3668),
    'aqueous': (1.3593, 1.3422, 1.3354, 1.3278),
    'lens': (1.4492, 1.4263, 1.4175, 1.4097),
    'vitreous': (1.3565, 1.3407, 1.3341, 1.3273),
}
SLOTS = ['cornea', 'aqueous', 'lens', 'vitreous']  # ior1..ior4


def herzberger(medium, wavelength_nm):
    lam = wavelength_nm / 1000.0
    big_l = 1.0 / (lam * lam - 0.028)
    weights = [a + b * lam * lam + c * big_l + d * big_l * big_l
               for a, b, c, d in (HERZBERGER[k] for k in ('A1', 'A2', 'A3', 'A4'))]
    return sum(w * n for w, n in zip(weights, LE_GRAND[medium]))


def index_spectrum(medium, reference_index, reference_nm):
    shift = reference_index - herzberger(medium, reference_nm)
    return [(w, herzberger(medium, w) + shift) for w in range(400, 701, 10)]


def lens_lines(surfaces):
    """One line per surface, scene to retina; the retina itself goes to the camera parameters."""
    lines = []
    for s in surfaces:
        if s['role'] == 'image':
            continue
        slot = SLOTS.index(s['medium']) + 1
        if s['role'] == 'stop':
            radius, conic = 0.0, 0.0  # both radii 0: the aperture (semi-diameter from pupilDiameter)
        else:
            radius, conic = -s['radius_mm'], s['conic']  # centre on the scene side is positive there
        lines.append((radius, radius, s['thickness_mm'], slot, s['semi_diameter_mm'], conic, conic))
    if lines[-1][2] != 0.0:
        raise SystemExit('the last refracting surface carries the vitreous; expected thickness 0')
    return lines


def paraxial_power(lines, index_of_slot):
    """Power in dioptres of the lens file read as realisticEye reads it (a y-nu trace of a ray parallel
    to the axis from the scene, optical radius = minus the file's): it must equal eyetrace's."""
    y, nu, n = 1.0, 0.0, 1.0  # height (mm), reduced angle, index before the surface
    for radius, _, thickness, slot, _, _, _ in lines:
        n_after = index_of_slot[slot]
        if radius != 0.0:
            nu -= y * (n_after - n) / -radius
        y += thickness * nu / n_after
        n = n_after
    return -nu * 1000.0


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    report = json.load(open(sys.argv[1]))
    outdir = sys.argv[2]
    os.makedirs(outdir, exist_ok=True)
    surfaces = report['surfaces']
    refracting = [s for s in surfaces if s['role'] != 'image']
    retina = [s for s in surfaces if s['role'] == 'image'][0]
    # The vitreous: eyetrace keeps it as the last lens surface's thickness.
    vitreous = refracting[-1]['thickness_mm']
    refracting[-1] = dict(refracting[-1], thickness_mm=0.0)
    lines = lens_lines(refracting)
    with open(os.path.join(outdir, 'navarro.dat'), 'w') as f:
        f.write('# Navarro eye from eyetrace optics --json (%s); realisticEye lens file\n' % report['source'])
        f.write('# radiusX radiusY thickness mediumIndex semiDiameter conicX conicY (mm)\n')
        f.write('%.6f\n' % report['focal_lengths_mm'][1])
        for line in lines:
            f.write('%.9f %.9f %.9f %d %.6f %.9f %.9f\n' % line)
    reference_nm = report['reference_wavelength_nm']
    media = {m['medium']: m for m in report['dispersion']['media']}
    params = ['"float retinaDistance" %.9f' % vitreous,
              '"float retinaRadius" %.6f' % abs(retina['radius_mm'])]
    for slot, medium in enumerate(SLOTS, 1):
        spectrum = index_spectrum(medium, media[medium]['index_reference'], reference_nm)
        ends = media[medium]['index_at_range_ends']
        # An independent check of the law against eyetrace's own dispersion at 400 and 700 nm.
        for (w, n), expected in zip((spectrum[0], spectrum[-1]), ends):
            if abs(n - expected) > 2e-5:
                raise SystemExit('%s at %d nm: %.6f here, %.6f in eyetrace' % (medium, w, n, expected))
        params.append('"spectrum ior%d" [%s]' % (slot, ' '.join('%d %.6f' % p for p in spectrum)))
    index_of_slot = {slot: media[m]['index_reference'] for slot, m in enumerate(SLOTS, 1)}
    power = paraxial_power(lines, index_of_slot)
    if abs(power - report['power_diopters']) > 1e-4:
        raise SystemExit('lens file power %.6f D, eyetrace %.6f D' % (power, report['power_diopters']))
    with open(os.path.join(outdir, 'camera.txt'), 'w') as f:
        f.write('\n'.join(params) + '\n')


if __name__ == '__main__':
    main()
