#!/usr/bin/python3
"""Independent chromatic reference for the schematic eyes: refraction at many wavelengths and the
transverse chromatic aberration (TCA) of chief rays.

Written, like tools/reference_trace.py (whose real-ray tracer it reuses: conic intersection in
closed form, vector Snell's law, the eye as traced), from the shared eye-model reference
(eye-models.json) alone: none of eyetrace's code or data files (data/eyes/*.json) is read. The
dispersion laws and their data come from eye-models.json too (navarro_dispersion,
le_grand_dispersion_cornu, models.arizona.dispersion and abbe_vd).

  /usr/bin/python3 tools/chromatic_reference.py --output tests/data/optics/chromatic_reference.json
  (--input defaults to /work/shared/optics/eye-models.json; --output - writes to stdout)

Needs Python 3 and numpy (Debian python3-numpy) only.

Indices at a wavelength lam: n(lam) = n_tab + law(lam) - law(lam_ref), n_tab the tabulated index
of the eye state at its reference wavelength lam_ref (589.3 nm; 543 nm for Escudero-Sanz), so the
reference-wavelength eye is the tabulated one and the law gives only the change. The law of each
medium, per model:
  navarro, navarro_wu2011_table1, escudero_sanz_1999: Navarro 1985 Herzberger form, A1..A4 with
    L = 1/(lam^2 - 0.1673^2), lam in micrometres, through Le Grand's indices at 365, 486.1, 656.3
    and 1014 nm of cornea, aqueous, lens, vitreous (navarro_dispersion);
  le_grand: Cornu n_inf + K/(lam - 130 nm) (le_grand_dispersion_cornu);
  arizona: the Abbe line n_d + (lam - 589.3)(n_d - 1)/(V_d (486.1 - 656.3)), n_d the state's index
    (A-dependent for the lens), V_d from abbe_vd;
  kooijman (no published dispersion; the choice made for eyetrace): Le Grand's Cornu laws, its media
    being Le Grand's;
  gullstrand_exact_relaxed (no published dispersion; the choice made for eyetrace): Navarro's laws,
    cornea, aqueous and vitreous by their own, lens cortex and nucleus both by the lens law.
Navarro's accommodated lens (navarro_accommodation at D = 4) adds 9e-5 (10 D + D^2) at every
wavelength, which the anchoring does by itself (the state's n_tab carries the shift).

Refraction: paraxial, with 2x2 (y, n u) matrices through the tabulated surfaces (refraction
(n' - n)/R, transfer t/n) from the first vertex to the retina vertex; the object vergence V (D) at
the first vertex imaged on the retina solves A + B (-V/1000) = 0, i.e. V = 1000 A / B (mm). This is
the definition of eye-models.json's refraction_D; the reference-wavelength values are checked
against its paraxial_computed.refraction_D (to its 4-decimal rounding).

TCA: for an object point (at infinity in the direction of the field angle w: rays (0, -sin w,
cos w), the object above the axis; or at a distance from the paraxial entrance-pupil centre of the
reference-wavelength eye, in that direction), the chief ray at each of 450 and 650 nm is aimed
(reference_trace.aim: 2-D Newton to 1e-13 mm) through the centre of the stop and traced to the
retina with the real edges. Its retina point is given by the signed coordinate s: the arc length
from the retina vertex along the meridian (height for a flat retina), > 0 towards -y, where a
positive field images. Each point is then seen at the visual field angle whose chief ray from an
object at infinity, at the reference wavelength, lands at the same s (secant iteration to
1e-11 mm): TCA = 60 (angle(450) - angle(650)) arcmin, signed > 0 when the 450 nm image is seen
farther from the axis (along the field); retina_um = 1000 (s(450) - s(650)), the same sign.
"""
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reference_io  # noqa: E402
import reference_trace as rt  # noqa: E402

WAVELENGTHS_NM = [400.0 + 10.0 * i for i in range(31)]
TCA_SHORT_NM, TCA_LONG_NM = 450.0, 650.0
TCA_FIELDS_DEG = [0.0, 10.0, 20.0, 30.0, 40.0]
FINITE_TCA = [("navarro_relaxed", 0.5, [10.0, 20.0])]  # (state, object distance m, fields)
MEDIA_4 = ["cornea", "aqueous", "lens", "vitreous"]


# --- dispersion laws from eye-models.json ------------------------------------------------------

def herzberger(src, medium):
    nd = src["navarro_dispersion"]
    coef = [nd["coefficients_a_b_c_d"][k] for k in ("A1", "A2", "A3", "A4")]
    ref = nd["reference_indices_at_365_486.1_656.3_1014_nm"][medium]
    assert "0.1673^2" in nd["formula"] and "micrometres" in nd["formula"]

    def law(lam_nm):
        lam2 = (lam_nm * 1e-3) ** 2
        L = 1.0 / (lam2 - 0.1673 ** 2)
        return sum((a + b * lam2 + c * L + d * L * L) * n for (a, b, c, d), n in zip(coef, ref))
    return law, f"navarro-herzberger ({medium})"


def cornu(src, medium):
    lg = src["le_grand_dispersion_cornu"]
    assert "lam0 = 130 nm" in lg["formula"]
    n_inf, k = lg["n_inf"][medium], lg["K_nm"][medium]
    return (lambda lam_nm: n_inf + k / (lam_nm - 130.0)), f"cornu ({medium})"


def abbe(n_d, v_d):
    return (lambda lam_nm: n_d + (lam_nm - 589.3) * (n_d - 1.0) / (v_d * (486.1 - 656.3))), f"abbe-linear (V_d {v_d})"


def laws_for(src, key, surfaces):
    """One (law, name) per tabulated surface, for the medium after it."""
    if key in ("navarro", "navarro_wu2011_table1", "escudero_sanz_1999"):
        return [herzberger(src, m) for m in MEDIA_4]
    if key in ("le_grand", "kooijman"):
        return [cornu(src, m) for m in MEDIA_4]
    if key == "arizona":
        assert src["models"]["arizona"]["dispersion"].startswith("published as nd and Vd only")
        return [abbe(s["n_after"], v) for s, v in zip(surfaces, src["models"]["arizona"]["abbe_vd"])]
    if key == "gullstrand_exact_relaxed":
        media = ["cornea", "aqueous", "lens", "lens", "lens", "vitreous"]  # cortex, nucleus, cortex by the lens law
        return [herzberger(src, m) for m in media]
    raise KeyError(key)


def at_wavelength(surfaces, laws, lam_ref, lam):
    out = []
    for s, (law, _) in zip(surfaces, laws):
        out.append(dict(s, n_after=s["n_after"] + law(lam) - law(lam_ref)))
    return out


# --- paraxial refraction -------------------------------------------------------------------------

def refraction_D(surfaces, retina_z):
    M = np.eye(2)
    n = 1.0
    z = 0.0
    for s in surfaces:
        power = 0.0 if s["radius"] is None else (s["n_after"] - n) / s["radius"]
        M = np.array([[1.0, 0.0], [-power, 1.0]]) @ M
        n = s["n_after"]
        M = np.array([[1.0, s["thickness"] / n], [0.0, 1.0]]) @ M
        z += s["thickness"]
    assert abs(z - retina_z) < 1e-9
    return 1000.0 * M[0, 0] / M[0, 1]


def entrance_pupil_z(surfaces, pupil_z):
    """Object-space position of the paraxial image of the stop centre (first vertex = 0)."""
    M = np.eye(2)
    n = 1.0
    z = 0.0
    for s in surfaces:
        if z >= pupil_z - 1e-9:
            break
        power = 0.0 if s["radius"] is None else (s["n_after"] - n) / s["radius"]
        M = np.array([[1.0, 0.0], [-power, 1.0]]) @ M
        n = s["n_after"]
        step = min(s["thickness"], pupil_z - z)
        M = np.array([[1.0, step / n], [0.0, 1.0]]) @ M
        z += step
    return M[0, 1] / M[0, 0]  # the axial object point e with A (-e u) + B u = 0


# --- chief rays ----------------------------------------------------------------------------------

def coordinate(retina, point):
    if retina["radius"] is None:
        return -point[1]
    R = retina["radius"]
    zc = retina["z"] + R
    axial = (point[2] - zc) * (1.0 if R < 0 else -1.0)
    return abs(R) * math.atan2(-point[1], axial)


def chief_coordinate(seq, retina, field_deg, source=None, z_pupil=None):
    """Signed retina coordinate of the chief ray of the object point (infinity when source is
    None), traced with the real edges; raises rt.Lost."""
    stop = next(i for i, s in enumerate(seq) if s["role"] == "stop")
    target = np.zeros(2)
    if source is None:
        w = math.radians(field_deg)
        d0 = np.array([0.0, -math.sin(w), math.cos(w)])

        def make(u):
            return np.array([u[0], u[1], rt.INFINITY_START_Z]), d0
        guess = -d0[:2] / d0[2] * (seq[stop]["z"] - rt.INFINITY_START_Z)
    else:
        def make(u):
            v = np.array([u[0], u[1], z_pupil]) - source
            return source.copy(), v / np.linalg.norm(v)
        guess = np.zeros(2)
    o, d, miss = rt.aim(seq, stop, target, make, guess)
    assert miss < 1e-10, f"chief ray misses the stop centre by {miss} mm"
    hits = rt.trace(seq, o, d)
    return coordinate(retina, hits[-1][0])


def visual_angle(seq, retina, s_target):
    """Field angle (deg) whose reference-wavelength chief ray from infinity lands at s_target."""
    if s_target == 0.0:
        return 0.0
    a0, a1 = 0.0, math.degrees(math.atan(s_target / 16.5))
    f0, f1 = -s_target, chief_coordinate(seq, retina, a1) - s_target
    for _ in range(100):
        if abs(f1) < 1e-11:
            return a1
        a0, a1, f0 = a1, a1 - f1 * (a1 - a0) / (f1 - f0), f1
        f1 = chief_coordinate(seq, retina, a1) - s_target
    raise RuntimeError("visual angle: no convergence")


# --- states --------------------------------------------------------------------------------------

def chromatic_states(src):
    """(id, eye-models key, eyetrace preset, builder) of the states computed here."""
    by_id = {s[0]: s for s in rt.states(src)}
    keep = ["gullstrand_relaxed", "legrand_relaxed", "kooijman", "navarro_relaxed", "navarro_D4",
            "navarro_wu2011_relaxed", "escudero_sanz", "arizona_relaxed", "arizona_A4"]
    return [by_id[k] for k in keep]


def main():
    args = reference_io.parse_args(__doc__)
    raw, src = reference_io.read_input(args.input)

    out_states = []
    for state_id, key, description, preset, builder in chromatic_states(src):
        model = src["models"][key]
        lam_ref, _ = rt.wavelength_of(model)
        surfaces, pupil_z, retina = builder()
        laws = laws_for(src, key, surfaces)
        assert len(laws) == len(surfaces)
        ref_refraction = refraction_D(surfaces, retina["z"])
        if state_id.endswith(("relaxed",)) or state_id in ("kooijman", "escudero_sanz"):
            published = model["paraxial_computed"]["refraction_D"]
            assert abs(ref_refraction - published) < 6e-5, f"{state_id}: {ref_refraction} vs {published}"
        lams = sorted(set(WAVELENGTHS_NM + [lam_ref]))
        refraction = [dict(wavelength_nm=lam, refraction_D=round(refraction_D(at_wavelength(surfaces, laws, lam_ref, lam),
                                                                              retina["z"]), 10) + 0.0)
                      for lam in lams]
        entry = dict(id=state_id, source_model_key=key, state=description, eyetrace_preset=preset,
                     reference_wavelength_nm=lam_ref, dispersion=[name for _, name in laws], refraction=refraction)

        tca = []
        if not state_id.endswith(("D4", "A4")):
            seq_ref = rt.build(surfaces, pupil_z, retina)
            seq_s = rt.build(at_wavelength(surfaces, laws, lam_ref, TCA_SHORT_NM), pupil_z, retina)
            seq_l = rt.build(at_wavelength(surfaces, laws, lam_ref, TCA_LONG_NM), pupil_z, retina)
            cases = [(f, None) for f in TCA_FIELDS_DEG]
            cases += [(f, dist) for sid, dist, fields in FINITE_TCA if sid == state_id for f in fields]
            for field, dist in cases:
                source = z_pupil = None
                if dist is not None:
                    z_pupil = entrance_pupil_z(surfaces, pupil_z)
                    w = math.radians(field)
                    source = np.array([0.0, 0.0, z_pupil]) - dist * 1000.0 * np.array([0.0, -math.sin(w), math.cos(w)])
                s_short = chief_coordinate(seq_s, retina, field, source, z_pupil)
                s_long = chief_coordinate(seq_l, retina, field, source, z_pupil)
                a_short, a_long = visual_angle(seq_ref, retina, s_short), visual_angle(seq_ref, retina, s_long)
                sign = -1.0 if field < 0 else 1.0
                tca.append(dict(field_deg=field, object_distance_m=dist, short_nm=TCA_SHORT_NM, long_nm=TCA_LONG_NM,
                                short_coordinate_mm=round(s_short, 12) + 0.0, long_coordinate_mm=round(s_long, 12) + 0.0,
                                short_angle_deg=round(a_short, 12) + 0.0, long_angle_deg=round(a_long, 12) + 0.0,
                                tca_arcmin=round(sign * 60.0 * (a_short - a_long), 10) + 0.0,
                                retina_um=round(sign * 1000.0 * (s_short - s_long), 9) + 0.0))
        entry["tca"] = tca
        out_states.append(entry)

    doc = {
        "provenance": {
            "what": "independent chromatic reference of the schematic eyes of eye-models.json: paraxial refraction "
                    "at 400-700 nm (every 10 nm and the reference wavelength) and chief-ray transverse chromatic "
                    "aberration between 450 and 650 nm",
            "script": "tools/chromatic_reference.py (reuses tools/reference_trace.py's tracer)",
            **reference_io.run_provenance("tools/chromatic_reference.py", args.input, raw, np.__version__),
            "independence": "written from the prescriptions, dispersion data and formulas of the input file only; "
                            "eyetrace's code and data/eyes files were not used",
            "method": __doc__[__doc__.index("Indices at a wavelength"):].strip(),
            "precision": "refraction rounded to 1e-10 D, angles and coordinates to 1e-12, TCA to 1e-10 arcmin",
        },
        "states": out_states,
    }
    reference_io.write_output(json.dumps(doc, indent=1) + "\n", args.output)


if __name__ == "__main__":
    main()
