#!/usr/bin/python3
"""Independent real-ray reference trace of the schematic eyes, surface by surface.

Written from the prescriptions in the shared eye-model reference (eye-models.json) alone: it
reads none of eyetrace's code or data files (data/eyes/*.json). It traces a fixed set of rays
through every surface of each eye and writes, for each ray, the start ray and the hit point and
direction after every surface. tests/optics/reference_trace_test.cpp traces the same start rays
with eyetrace and compares the hit points.

  /usr/bin/python3 tools/reference_trace.py --output tests/data/optics/reference_traces.json
  (--input defaults to /work/shared/optics/eye-models.json; --output - writes to stdout)

Needs Python 3 and numpy (Debian python3-numpy) only.

Conventions (those of eye-models.json): millimetres; z along the optical axis, z = 0 at the
anterior corneal vertex, +z towards the retina; a radius is > 0 when the centre of curvature lies
on the retina side; conic Q (= Zemax k), surface x^2 + y^2 + (1+Q) z^2 - 2 R z = 0 about its
vertex, sag z = c r^2 / (1 + sqrt(1 - (1+Q) c^2 r^2)), c = 1/R.

The eye as traced: the tabulated surfaces in order, the pupil (aperture stop: a flat plane at
pupil.position_from_cornea_mm, radius 2 mm for a 4 mm pupil, no refraction) inserted before the
first surface whose vertex is at or behind it, and the retina (image surface: a sphere of
retina.radius_mm, or a plane where eye-models.json gives no radius) at
retina.distance_from_cornea_mm, last.

Intersection: closed form. With p the ray origin relative to the vertex, d the unit direction and
k = 1 + Q, the surface is F(q) = c (qx^2 + qy^2) + c k qz^2 - 2 qz = 0 and F(p + t d) = 0 is
a t^2 + 2 b t + g = 0 with a = c (dx^2 + dy^2 + k dz^2), b = c (px dx + py dy + k pz dz) - dz,
g = F(p), after the ray has been carried (straight) to the vertex plane, pz = 0, so that g
stays small for distant origins (from z = -250 mm the cancellation in F(p) would cost 1e-12 mm).
The root taken is t = g / (-b + sqrt(b^2 - a g)): the one that tends to the plane
intersection -pz/dz as c -> 0, i.e. the sheet through the vertex (it also stays accurate when a
is 0 or tiny; the other root is the far sheet of a sphere or ellipsoid). Checked: 1 - c k qz >= 0
(the vertex sheet of the sag formula), the sag residual is < 1e-12 mm, and a Newton iteration on
F(p + t d) started from the plane z = vertex agrees to < 1e-12 mm.

Edges: a ray is lost (recorded with the surface and the reason, and its hits up to there) when it
misses a surface or meets it beyond its edge: the semi_diameter_mm eye-models.json gives
(ISETBio's, for the four-surface eyes), the 2 mm pupil radius, or the height where two adjacent
refracting surfaces meet (Gullstrand's lens nucleus ends there: 2.30 mm in the accommodated eye).

Refraction: vector Snell's law with the unit normal n = (c qx, c qy, c k qz - 1) / |...| turned
to point along the ray (n . d > 0), eta = n_before / n_after, cos_i = n . d,
d' = eta d + (sqrt(1 - eta^2 (1 - cos_i^2)) - eta cos_i) n.

Rays (no aiming is needed to reproduce them: each is given by its start point and direction):
for every eye state, at its reference wavelength,
  - object at infinity, field angles 0, 10, 20, 30 degrees in the y-z plane (object above the
    axis: direction (0, -sin w, cos w)), start point on the plane z = -3 mm;
  - finite objects at z = -250 mm: the axial point (0, 0) and the point (0, 100) mm;
and for each object point the five pupil points on the stop: the centre and +-0.9 of the stop
radius in x and in y (i.e. (0, 0), (+-1.8, 0), (0, +-1.8) mm). Each ray is aimed at its pupil
point here, by a 2-D Newton iteration (finite-difference Jacobian) on the start point's x, y
(object at infinity) or on the point where the ray crosses z = 0 (finite object), until it meets
the stop within 1e-12 mm (asserted < 1e-10 mm); the resulting start ray is recorded exactly
(shortest round-trip decimal of each double), the traced hit points and directions to 1e-12.
"""
import json
import math

import numpy as np

import reference_io
PUPIL_DIAMETER_MM = 4.0
PUPIL_FRACTION = 0.9
FIELDS_DEG = [0.0, 10.0, 20.0, 30.0]
INFINITY_START_Z = -3.0
FINITE_OBJECTS = [(0.0, 0.0, -250.0), (0.0, 100.0, -250.0)]
FINITE_AIM_Z = 0.0
ACCOMMODATION_NAVARRO_D = 4.0
ACCOMMODATION_ARIZONA_A = 4.0
DECIMALS = 12


# --- eye states built from eye-models.json ------------------------------------------------

def formula(expr, **variables):
    """Evaluates one of eye-models.json's accommodation formulas (a string such as
    '12.0 - 0.4*A' or '1.42 + 9e-5*(10*D + D^2)') for the given variables."""
    expr = expr.replace("(constant)", "").replace("^", "**").strip()
    return float(eval(expr, {"__builtins__": {}}, dict(variables, ln=math.log)))


def tabulated(model):
    """(surfaces, pupil z, retina) of a model entry as tabulated."""
    surfaces = [dict(name=s["name"], radius=s["radius_mm"], conic=s["conic"], thickness=s["thickness_mm"],
                     n_after=s["index_after"], semi_diameter=s.get("semi_diameter_mm")) for s in model["surfaces"]]
    retina = model["retina"]
    return surfaces, model["pupil"]["position_from_cornea_mm"], dict(
        z=retina["distance_from_cornea_mm"], radius=retina["radius_mm"], conic=retina["conic"] or 0.0)


def navarro_accommodated(src, key, D, lens_index_formula):
    """Navarro's accommodation formulas (eye-models.json 'navarro_accommodation') applied to the
    model `key` at parameter D, axial length held fixed (the JSON's 'retina' note); the pupil
    stays at the anterior lens vertex."""
    model = src["models"][key]
    acc = src["navarro_accommodation"]
    surfaces, _, retina = tabulated(model)
    cornea_front, cornea_back, lens_front, lens_back = surfaces
    cornea_back["thickness"] = formula(acc["aqueous_depth_mm"], D=D)
    lens_front["radius"] = formula(acc["R_anterior_lens_mm"], D=D)
    lens_front["conic"] = formula(acc["Q_anterior_lens"], D=D)
    lens_front["thickness"] = formula(acc["lens_thickness_mm"], D=D)
    lens_front["n_after"] = formula(acc[lens_index_formula], D=D)
    lens_back["radius"] = formula(acc["R_posterior_lens_mm"], D=D)
    lens_back["conic"] = formula(acc["Q_posterior_lens"], D=D)
    lens_back["thickness"] = retina["z"] - (cornea_front["thickness"] + cornea_back["thickness"] +
                                            lens_front["thickness"])
    pupil_z = cornea_front["thickness"] + cornea_back["thickness"]
    return surfaces, pupil_z, retina


def arizona_accommodated(src, A):
    """The Arizona eye's published accommodation formulas (eye-models.json
    models.arizona.accommodation); the stop stays at the anterior lens vertex, as at A = 0."""
    model = src["models"]["arizona"]
    acc = model["accommodation"]
    surfaces, _, retina = tabulated(model)
    cornea_front, cornea_back, lens_front, lens_back = surfaces
    cornea_back["thickness"] = formula(acc["aqueous_depth_mm"], A=A)
    lens_front["radius"] = formula(acc["R_anterior_lens_mm"], A=A)
    lens_front["conic"] = formula(acc["Q_anterior_lens"], A=A)
    lens_front["thickness"] = formula(acc["lens_thickness_mm"], A=A)
    lens_front["n_after"] = formula(acc["n_lens_d"], A=A)
    lens_back["radius"] = formula(acc["R_posterior_lens_mm"], A=A)
    lens_back["conic"] = formula(acc["Q_posterior_lens"], A=A)
    lens_back["thickness"] = formula(acc["vitreous_mm"], A=A)
    z_retina = sum(s["thickness"] for s in surfaces)
    retina = dict(retina, z=z_retina)
    pupil_z = cornea_front["thickness"] + cornea_back["thickness"]
    return surfaces, pupil_z, retina


def states(src):
    """The traced eye states: (id, eye-models.json key, description, eyetrace preset, builder)."""
    m = src["models"]

    def plain(key):
        return lambda: tabulated(m[key])

    return [
        ("gullstrand_relaxed", "gullstrand_exact_relaxed", "as tabulated",
         dict(model="gullstrand", variant="", accommodation_D=0.0, end_state=False), plain("gullstrand_exact_relaxed")),
        ("gullstrand_accommodated", "gullstrand_exact_accommodated", "as tabulated (Gullstrand's accommodated eye)",
         dict(model="gullstrand", variant="", accommodation_D=10.87013, end_state=True),
         plain("gullstrand_exact_accommodated")),
        ("legrand_relaxed", "le_grand", "as tabulated",
         dict(model="legrand", variant="", accommodation_D=0.0, end_state=False), plain("le_grand")),
        ("legrand_accommodated", "le_grand_accommodated", "as tabulated (Le Grand's accommodated eye)",
         dict(model="legrand", variant="", accommodation_D=7.0525, end_state=True), plain("le_grand_accommodated")),
        ("kooijman", "kooijman", "as tabulated",
         dict(model="kooijman", variant="", accommodation_D=0.0, end_state=False), plain("kooijman")),
        ("navarro_relaxed", "navarro", "as tabulated",
         dict(model="navarro", variant="", accommodation_D=0.0, end_state=False), plain("navarro")),
        ("navarro_D4", "navarro",
         "navarro_accommodation formulas at D = 4 (lens index n_lens), axial length fixed",
         dict(model="navarro", variant="", accommodation_D=ACCOMMODATION_NAVARRO_D, end_state=False),
         lambda: navarro_accommodated(src, "navarro", ACCOMMODATION_NAVARRO_D, "n_lens")),
        ("navarro_wu2011_relaxed", "navarro_wu2011_table1", "as tabulated",
         dict(model="navarro", variant="wu2011", accommodation_D=0.0, end_state=False),
         plain("navarro_wu2011_table1")),
        ("navarro_wu2011_D4", "navarro_wu2011_table1",
         "navarro_accommodation formulas at D = 4 with the lens index as misprinted in Wu 2011 "
         "(n_lens_as_misprinted_in_wu2011), axial length fixed",
         dict(model="navarro", variant="wu2011", accommodation_D=ACCOMMODATION_NAVARRO_D, end_state=False),
         lambda: navarro_accommodated(src, "navarro_wu2011_table1", ACCOMMODATION_NAVARRO_D,
                                      "n_lens_as_misprinted_in_wu2011")),
        ("escudero_sanz", "escudero_sanz_1999", "as tabulated (543 nm indices)",
         dict(model="escudero-sanz", variant="", accommodation_D=0.0, end_state=False), plain("escudero_sanz_1999")),
        ("arizona_relaxed", "arizona", "as tabulated (A = 0)",
         dict(model="arizona", variant="", accommodation_D=0.0, end_state=False), plain("arizona")),
        ("arizona_A4", "arizona", "models.arizona.accommodation formulas at A = 4",
         dict(model="arizona", variant="", accommodation_D=ACCOMMODATION_ARIZONA_A, end_state=False),
         lambda: arizona_accommodated(src, ACCOMMODATION_ARIZONA_A)),
    ]


def wavelength_of(model):
    """(reference wavelength in nm, note) of a model entry."""
    if model.get("wavelength_nm") is not None:
        return float(model["wavelength_nm"]), "wavelength_nm of eye-models.json"
    return 589.3, model.get("wavelength_note", "not stated") + " (589.3 nm assumed; the tabulated indices are used)"


def check_indices(src):
    """Where eye-models.json tabulates indices at a model's reference wavelength elsewhere than in
    its surfaces, they must be the surfaces' (so the tabulated surfaces are that wavelength's)."""
    m = src["models"]
    es = m["escudero_sanz_1999"]
    surface_n = [s["index_after"] for s in es["surfaces"]]
    assert es["indices_by_wavelength_nm"]["543"] == surface_n, "ES99 543 nm indices differ from its surfaces"
    navarro_n = [s["index_after"] for s in m["navarro"]["surfaces"]]
    assert es["indices_by_wavelength_nm"]["589.3"] == navarro_n, "ES99 589.3 nm indices differ from Navarro's"
    return ("escudero_sanz_1999: indices_by_wavelength_nm['543'] equal its surface indices; "
            "navarro: ES99's indices_by_wavelength_nm['589.3'] equal its surface indices (cornea 1.376); "
            "arizona: the surface indices are its published n_d (589.3 nm)")


def build(surfaces, pupil_z, retina):
    """The traced sequence: [dict(name, role, z, c, k, n_after, semi_diameter, radius, conic)]."""
    seq = []
    z = 0.0
    stop_inserted = False
    for s in surfaces:
        if not stop_inserted and z >= pupil_z - 1e-9:
            seq.append(dict(name="pupil", role="stop", z=pupil_z, radius=None, conic=0.0,
                            n_after=seq[-1]["n_after"], semi_diameter=PUPIL_DIAMETER_MM / 2))
            stop_inserted = True
        seq.append(dict(name=s["name"], role="refract", z=z, radius=s["radius"], conic=s["conic"],
                        n_after=s["n_after"], semi_diameter=s["semi_diameter"]))
        z += s["thickness"]
    assert stop_inserted, "pupil behind the last surface"
    assert abs(z - retina["z"]) < 1e-9, f"thicknesses add to {z}, retina at {retina['z']}"
    seq.append(dict(name="retina", role="image", z=retina["z"], radius=retina["radius"], conic=retina["conic"],
                    n_after=seq[-1]["n_after"], semi_diameter=None))
    for s in seq:
        s["c"] = 0.0 if s["radius"] is None else 1.0 / s["radius"]
        s["k"] = 1.0 + s["conic"]
        s["edge"], s["edge_why"] = math.inf, ""
        if s["semi_diameter"] is not None:
            s["edge"], s["edge_why"] = s["semi_diameter"], "semi-diameter"
    # Two adjacent refracting surfaces bound a medium only up to the height where they meet (a
    # lens nucleus ends there): a sequential ray cannot meet either face beyond it.
    for a, b in zip(seq, seq[1:]):
        if a["role"] == b["role"] == "refract":
            h = meeting_height(a, b)
            for s in (a, b):
                if h < s["edge"]:
                    s["edge"], s["edge_why"] = h, f"where {a['name']} and {b['name']} meet"
    return seq


def reach(s):
    """Largest height the surface's sag formula covers."""
    kc2 = s["k"] * s["c"] ** 2
    return math.sqrt(1.0 / kc2) if kc2 > 0.0 else math.inf


def meeting_height(a, b):
    """Smallest height at which surfaces a and b (a in front) meet, +inf when they do not below
    10 mm (scan in 1e-3 mm steps, then bisection to 1e-15 mm)."""
    top = min(reach(a), reach(b), 10.0)

    def gap(r):
        return (b["z"] + sag(b, r * r)) - (a["z"] + sag(a, r * r))

    steps = 10000
    lo = 0.0
    for i in range(1, steps + 1):
        hi = top * i / steps
        if gap(hi) <= 0.0:
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if gap(mid) > 0.0:
                    lo = mid
                else:
                    hi = mid
                if hi - lo < 1e-15:
                    break
            return hi
        lo = hi
    return math.inf


# --- the trace ----------------------------------------------------------------------------

def sag(s, r2):
    c, k = s["c"], s["k"]
    return c * r2 / (1.0 + math.sqrt(1.0 - k * c * c * r2))


def intersect(s, o, d):
    """Hit point of the ray o + t d with surface s (closed form, vertex sheet)."""
    c, k = s["c"], s["k"]
    p = o - np.array([0.0, 0.0, s["z"]])
    p = p + (-p[2] / d[2]) * d  # carried to the vertex plane first: keeps g small (see above)
    p[2] = 0.0
    a = c * (d[0] ** 2 + d[1] ** 2 + k * d[2] ** 2)
    b = c * (p[0] * d[0] + p[1] * d[1] + k * p[2] * d[2]) - d[2]
    g = c * (p[0] ** 2 + p[1] ** 2 + k * p[2] ** 2) - 2.0 * p[2]
    disc = b * b - a * g
    if disc < 0.0:
        raise ValueError(f"{s['name']}: ray misses the surface")
    if -b <= 0.0:
        raise ValueError(f"{s['name']}: ray does not travel towards +z at the surface")
    t = g / (-b + math.sqrt(disc))
    q = p + t * d
    # Checks: vertex sheet, on the surface by the sag formula, Newton from the plane agrees.
    assert 1.0 - c * k * q[2] >= 0.0, f"{s['name']}: hit on the far sheet"
    r2 = q[0] ** 2 + q[1] ** 2
    assert abs(q[2] - sag(s, r2)) < 1e-12, f"{s['name']}: sag residual {q[2] - sag(s, r2)}"
    tn = -p[2] / d[2]
    for _ in range(50):
        qn = p + tn * d
        f = c * (qn[0] ** 2 + qn[1] ** 2 + k * qn[2] ** 2) - 2.0 * qn[2]
        df = 2.0 * (c * (qn[0] * d[0] + qn[1] * d[1] + k * qn[2] * d[2]) - d[2])
        step = f / df
        tn -= step
        if abs(step) < 1e-15:
            break
    assert abs(tn - t) < 1e-12, f"{s['name']}: Newton {tn} vs closed form {t}"
    return q + np.array([0.0, 0.0, s["z"]]), q


def refract(s, q, d, n_before):
    """Direction after surface s at local hit point q (vector Snell's law)."""
    c, k = s["c"], s["k"]
    n = np.array([c * q[0], c * q[1], c * k * q[2] - 1.0])
    n /= np.linalg.norm(n)
    if np.dot(n, d) < 0.0:
        n = -n
    eta = n_before / s["n_after"]
    cos_i = float(np.dot(n, d))
    root = 1.0 - eta * eta * (1.0 - cos_i * cos_i)
    if root < 0.0:
        raise ValueError(f"{s['name']}: total internal reflection")
    out = eta * d + (math.sqrt(root) - eta * cos_i) * n
    return out / np.linalg.norm(out)


class Lost(Exception):
    def __init__(self, surface, reason, hits):
        super().__init__(f"lost at surface {surface}: {reason}")
        self.surface, self.reason, self.hits = surface, reason, hits


def trace(seq, o, d, last=None, edges=True):
    """[(point, direction after)] at every surface up to index `last` (inclusive). Raises Lost
    when the ray misses a surface or (edges=True) meets it beyond its edge (see build)."""
    hits = []
    n_before = 1.0  # object space is air
    for i, s in enumerate(seq):
        try:
            point, q = intersect(s, o, d)
        except ValueError as e:
            raise Lost(i, str(e), hits)
        h = math.hypot(q[0], q[1])
        if edges and h > s["edge"]:
            raise Lost(i, f"{s['name']}: hit at height {h:.6f} mm beyond the edge {s['edge']:.6f} mm ({s['edge_why']})",
                       hits)
        if s["role"] == "refract":
            d = refract(s, q, d, n_before)
        hits.append((point, d))
        n_before = s["n_after"]
        o = point
        if last is not None and i == last:
            break
    return hits


def aim(seq, stop, target, make_ray, guess):
    """Newton iteration on the 2 parameters of make_ray(u) -> (origin, direction) so that the ray
    meets the stop at target (x, y). Returns (origin, direction, miss distance)."""
    u = np.array(guess, dtype=float)

    def miss(u):
        o, d = make_ray(u)
        p = trace(seq, o, d, last=stop, edges=False)[-1][0]  # edges do not matter while aiming
        return p[:2] - target

    r = miss(u)
    for _ in range(60):
        if np.linalg.norm(r) < 1e-13:
            break
        h = 1e-6
        J = np.empty((2, 2))
        for j in range(2):
            e = np.zeros(2)
            e[j] = h
            J[:, j] = (miss(u + e) - miss(u - e)) / (2 * h)
        u = u - np.linalg.solve(J, r)
        r = miss(u)
    o, d = make_ray(u)
    return o, d, float(np.linalg.norm(r))


def rays_for(seq):
    stop = next(i for i, s in enumerate(seq) if s["role"] == "stop")
    z_stop = seq[stop]["z"]
    radius = PUPIL_DIAMETER_MM / 2
    pupil_points = [("centre", (0.0, 0.0)), ("+x", (PUPIL_FRACTION, 0.0)), ("-x", (-PUPIL_FRACTION, 0.0)),
                    ("+y", (0.0, PUPIL_FRACTION)), ("-y", (0.0, -PUPIL_FRACTION))]
    out = []
    for w in FIELDS_DEG:
        d0 = np.array([0.0, -math.sin(math.radians(w)), math.cos(math.radians(w))])
        for label, (fx, fy) in pupil_points:
            target = np.array([fx * radius, fy * radius])

            def make(u, d0=d0):
                return np.array([u[0], u[1], INFINITY_START_Z]), d0

            guess = target - d0[:2] / d0[2] * (z_stop - INFINITY_START_Z)
            o, d, miss = aim(seq, stop, target, make, guess)
            out.append(dict(object=dict(kind="infinity", field_deg=w), pupil=label,
                            stop_target_mm=[float(target[0]), float(target[1])], origin=o, direction=d, miss=miss))
    for obj in FINITE_OBJECTS:
        P = np.array(obj)
        for label, (fx, fy) in pupil_points:
            target = np.array([fx * radius, fy * radius])

            def make(u, P=P):
                v = np.array([u[0], u[1], FINITE_AIM_Z]) - P
                return P.copy(), v / np.linalg.norm(v)

            o, d, miss = aim(seq, stop, target, make, target.copy())
            out.append(dict(object=dict(kind="point", position_mm=list(obj)), pupil=label,
                            stop_target_mm=[float(target[0]), float(target[1])], origin=o, direction=d, miss=miss))
    return stop, out


def rounded(v):
    return [round(float(x), DECIMALS) + 0.0 for x in v]


def main():
    args = reference_io.parse_args(__doc__)
    raw, src = reference_io.read_input(args.input)
    index_check = check_indices(src)

    out_states = []
    worst_miss = 0.0
    for state_id, key, description, preset, builder in states(src):
        model = src["models"][key]
        seq = build(*builder())
        stop, rays = rays_for(seq)
        wavelength, wavelength_note = wavelength_of(model)
        out_rays = []
        for r in rays:
            lost = None
            try:
                hits = trace(seq, r["origin"], r["direction"])
            except Lost as e:
                hits, lost = e.hits, dict(surface=e.surface, reason=e.reason)
            miss = float(np.linalg.norm(hits[stop][0][:2] - np.array(r["stop_target_mm"])))
            assert miss < 1e-10, f"{state_id}: ray misses its pupil point by {miss} mm"
            worst_miss = max(worst_miss, miss)
            ray = dict(
                object=r["object"], pupil_point=r["pupil"], stop_target_mm=r["stop_target_mm"],
                stop_miss_mm=float(f"{miss:.3g}"),
                start=dict(origin=[float(x) for x in r["origin"]], direction=[float(x) for x in r["direction"]]),
                surfaces=[dict(point=rounded(p), direction=rounded(d)) for p, d in hits])
            if lost:
                ray["lost"] = lost
            out_rays.append(ray)
        out_states.append(dict(
            id=state_id, source_model_key=key, state=description, source=model["source"], status=model["status"],
            eyetrace_preset=preset, wavelength_nm=wavelength, wavelength_note=wavelength_note,
            pupil_diameter_mm=PUPIL_DIAMETER_MM, stop_index=stop,
            surfaces=[dict(name=s["name"], role=s["role"], vertex_z_mm=s["z"], radius_mm=s["radius"], conic=s["conic"],
                           index_after=s["n_after"], semi_diameter_mm=s["semi_diameter"],
                           edge_mm=None if math.isinf(s["edge"]) else round(s["edge"], DECIMALS),
                           edge_note=s["edge_why"] or None) for s in seq],
            rays=out_rays))

    doc = {
        "provenance": {
            "what": "independent real-ray trace of the schematic eyes of eye-models.json, surface by surface",
            "script": "tools/reference_trace.py",
            **reference_io.run_provenance("tools/reference_trace.py", args.input, raw, np.__version__),
            "independence": "written from the prescriptions and formulas of the input file only; eyetrace's code "
                            "and data/eyes files were not used",
            "method": __doc__[__doc__.index("Conventions (those"):].strip(),
            "index_check": index_check,
            "largest_stop_miss_mm": worst_miss,
            "precision": f"hit points and directions rounded to {DECIMALS} decimals; start rays exact (shortest "
                         "round-trip decimal of each double)",
        },
        "conventions": src["conventions"],
        "states": out_states,
    }
    text = json.dumps(doc, indent=1)
    reference_io.write_output(compact_vectors(text) + "\n", args.output)


def compact_vectors(text):
    """Puts each list of plain numbers on one line (json.dumps(indent=1) gives one per line)."""
    import re
    return re.sub(r"\[\s*(-?[0-9.eE+-]+(?:,\s*-?[0-9.eE+-]+)*)\s*\]",
                  lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]", text)


if __name__ == "__main__":
    main()
