"""Image I/O, sharpness measurement, montages, plots and the paper's claims for tools/figures.

Sharpness is the gradient energy (mean squared luminance difference between neighbouring
pixels) of a region, divided by the same region's gradient energy in a reference rendered with
the same camera and a pinhole-sized pupil (0.1 mm; a pinhole for the thin lens). The reference
has the same pixel mapping and the same texture detail, so the ratio isolates the blur the
optics add: 1 is as sharp as a pinhole, smaller is blurrier.
"""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import OpenImageIO as oiio

FOV = 50.0
ECCENTRICITY_EDGES = [0, 5, 10, 15, 20, 25, 30, 35]
ECCENTRICITY_CENTRES = [0.5 * (a + b) for a, b in zip(ECCENTRICITY_EDGES[:-1], ECCENTRICITY_EDGES[1:])]
WALL_BAND_DEG = (1.0, 9.0)  # vertical angles above the horizon where only the far wall is seen
# Letter charts of scenes/peripheral.pbrt: (name, horizontal deg, vertical deg, distance m).
CHARTS = [("chart 0.25 m", -26, -10, 0.25), ("chart 1 m", 0, -11, 1.0), ("chart 4 m", 26, -10, 4.0)]
REFERENCE_PUPIL_MM = 0.1


def read_rgb(path):
    inp = oiio.ImageInput.open(path)
    if inp is None:
        raise SystemExit(f"figures: cannot read {path}: {oiio.geterror()}")
    px = inp.read_image(oiio.FLOAT)
    inp.close()
    return np.asarray(px, dtype=np.float64)[:, :, :3]


def write_png(rgb, path):
    v = np.clip(rgb, 0.0, None)
    srgb = np.where(v <= 0.0031308, 12.92 * v, 1.055 * np.power(v, 1 / 2.4) - 0.055)
    data = (np.clip(srgb, 0, 1) * 255 + 0.5).astype(np.uint8)
    tmp = path + ".tmp.png"
    out = oiio.ImageOutput.create(tmp)
    out.open(tmp, oiio.ImageSpec(data.shape[1], data.shape[0], 3, oiio.UINT8))
    out.write_image(data)
    out.close()
    os.replace(tmp, path)


def luminance(rgb):
    return 0.2126 * rgb[:, :, 0] + 0.7152 * rgb[:, :, 1] + 0.0722 * rgb[:, :, 2]


def gradient_energy(y):
    """Per-pixel squared gradient (forward differences), same shape as y (last row/col 0)."""
    e = np.zeros_like(y)
    e[:, :-1] += (y[:, 1:] - y[:, :-1]) ** 2
    e[:-1, :] += (y[1:, :] - y[:-1, :]) ** 2
    return e


def pixel_angles(shape, model):
    """Horizontal and vertical visual angle (degrees) of every pixel centre. Eye cameras map
    pixels linearly in angle; the thin lens and pinhole map them linearly in tan(angle)."""
    h, w = shape
    s = 2.0 / h  # the shorter (vertical) axis spans the field of view
    x = (np.arange(w) + 0.5 - w / 2) * s
    y = (h / 2 - np.arange(h) - 0.5) * s
    if model in ("thinlens", "pinhole"):
        t = np.tan(np.radians(FOV / 2))
        ax, ay = np.degrees(np.arctan(x * t)), np.degrees(np.arctan(y * t))
    else:
        ax, ay = x * FOV / 2, y * FOV / 2
    return np.meshgrid(ax, ay)


def sharpness_by_eccentricity(img, ref, model):
    """Sharpness ratio in each eccentricity bin of the far-wall band."""
    e, er = gradient_energy(luminance(img)), gradient_energy(luminance(ref))
    ax, ay = pixel_angles(e.shape, model)
    band = (ay >= WALL_BAND_DEG[0]) & (ay <= WALL_BAND_DEG[1])
    out = []
    for lo, hi in zip(ECCENTRICITY_EDGES[:-1], ECCENTRICITY_EDGES[1:]):
        m = band & (np.abs(ax) >= lo) & (np.abs(ax) < hi)
        out.append(float(e[m].mean() / er[m].mean()) if m.any() and er[m].mean() > 0 else float("nan"))
    return out


def sharpness_of_chart(img, ref, model, h_deg, v_deg, half_deg=3.5):
    e, er = gradient_energy(luminance(img)), gradient_energy(luminance(ref))
    ax, ay = pixel_angles(e.shape, model)
    m = (np.abs(ax - h_deg) < half_deg) & (np.abs(ay - v_deg) < half_deg)
    return float(e[m].mean() / er[m].mean()) if m.any() and er[m].mean() > 0 else float("nan")


def model_of(panel):
    return panel.split("-")[1]


def measure(out_dir, rows, optics_spots, render_reference):
    """Measures every panel against its model's reference (render_reference(model) -> EXR path)."""
    refs = {}
    result = []
    for r in rows:
        model = model_of(r["panel"])
        if model not in refs:
            refs[model] = read_rgb(render_reference(model))
        img = read_rgb(os.path.join(out_dir, r["panel"] + ".exr"))
        d = float(r["label"].split()[0]) if r["figure"] == "figure4" else 0.0
        spots = optics_spots(model, d) if model != "thinlens" else {}
        m = dict(figure=r["figure"], panel=r["panel"], model=model, accommodation=d,
                 wall=sharpness_by_eccentricity(img, refs[model], model),
                 spots=[spots.get(round(c, 3), float("nan")) for c in ECCENTRICITY_CENTRES],
                 charts={name: sharpness_of_chart(img, refs[model], model, h, v) for name, h, v, _ in CHARTS})
        result.append(m)
    return result


def write_blur_csv(ms, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["figure", "panel", "model", "accommodation_D", "region", "eccentricity_deg",
                    "sharpness_ratio", "rms_spot_um"])
        for m in ms:
            for c, s, spot in zip(ECCENTRICITY_CENTRES, m["wall"], m["spots"]):
                w.writerow([m["figure"], m["panel"], m["model"], m["accommodation"], "far wall 10 m",
                            c, f"{s:.4f}", f"{spot:.2f}"])
            for name, h, v, _ in CHARTS:
                w.writerow([m["figure"], m["panel"], m["model"], m["accommodation"], name,
                            f"{np.hypot(h, v):.1f}", f"{m['charts'][name]:.4f}", ""])


def montage(pngs, labels, path, title):
    n = len(pngs)
    cols = min(n, 4 if n > 5 else n)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.1 * rows + 0.5), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ax, png, label in zip(axes.flat, pngs, labels):
        img = plt.imread(png)
        ax.imshow(img)
        ax.set_title(label, fontsize=13, y=-0.13)
    fig.suptitle(title, fontsize=14)
    fig.tight_layout()
    fig.savefig(path + ".tmp.png", dpi=110)
    plt.close(fig)
    os.replace(path + ".tmp.png", path)


def plot(ms, out):
    f3 = [m for m in ms if m["figure"] == "figure3"]
    if f3:
        fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
        for m in f3:
            a.plot(ECCENTRICITY_CENTRES, m["wall"], "o-", label=m["model"])
            if m["model"] != "thinlens":
                b.plot(ECCENTRICITY_CENTRES, m["spots"], "o-", label=m["model"])
        a.set(xlabel="eccentricity (deg)", ylabel="sharpness (1 = pinhole)", title="Far wall (10 m): image sharpness")
        b.set(xlabel="field angle (deg)", ylabel="RMS spot radius (um)", title="eyetrace optics: RMS spot, 5 mm pupil")
        for ax in (a, b):
            ax.grid(alpha=0.3)
            ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(out, "blur-vs-eccentricity.png"), dpi=100)
        plt.close(fig)
    f4 = sorted([m for m in ms if m["figure"] == "figure4"], key=lambda m: m["accommodation"])
    if f4:
        fig, ax = plt.subplots(figsize=(6, 4))
        d = [m["accommodation"] for m in f4]
        ax.plot(d, [np.nanmean(m["wall"][:2]) for m in f4], "o-", label="far wall 10 m, centre (0-10 deg)")
        for name, _, _, _ in CHARTS:
            ax.plot(d, [m["charts"][name] for m in f4], "s--", label=name)
        ax.set(xlabel="accommodation parameter D (dioptres)", ylabel="sharpness (1 = pinhole)",
               title="Navarro eye: sharpness against accommodation")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "blur-vs-accommodation.png"), dpi=100)
        plt.close(fig)


def check_claims(ms):
    """Prints each of the paper's claims with what eyetrace measured. Returns the verdicts."""
    by = {m["panel"]: m for m in ms}
    verdicts = {}

    def say(claim, holds, detail):
        verdicts[claim] = holds
        print(f"  [{'HOLDS' if holds else 'DOES NOT HOLD'}] {claim}: {detail}")

    print("The paper's claims, measured:")
    tl = by.get("figure3-thinlens")
    if tl:
        w = np.array(tl["wall"])
        near = tl["charts"]["chart 0.25 m"]
        say("thin lens blurs only with depth, not eccentricity",
            bool(np.nanmin(w) > 0.85 * np.nanmax(w) and near < 0.7 * np.nanmean(w)),
            f"far-wall sharpness {np.nanmin(w):.2f}..{np.nanmax(w):.2f} across 0-35 deg; chart at 0.25 m {near:.2f}")
    periph = lambda m: float(np.nanmean(m["wall"][4:]))  # 20-35 deg
    eyes = {k: by.get(f"figure3-{k}") for k in ("gullstrand", "legrand", "kooijman", "navarro")}
    if all(eyes.values()):
        s = {k: periph(m) for k, m in eyes.items()}
        spot = {k: float(np.nanmean(m["spots"][4:])) for k, m in eyes.items()}
        say("Gullstrand and Le Grand are blurrier than Kooijman and Navarro in the periphery",
            max(s["gullstrand"], s["legrand"]) < min(s["kooijman"], s["navarro"]),
            "sharpness 20-35 deg " + ", ".join(f"{k} {v:.2f}" for k, v in s.items())
            + "; RMS spot 20-35 deg " + ", ".join(f"{k} {v:.0f} um" for k, v in spot.items()))
        rel = abs(s["kooijman"] - s["navarro"]) / max(s["kooijman"], s["navarro"])
        say("Kooijman and Navarro are nearly the same", rel < 0.15,
            f"peripheral sharpness differs by {100 * rel:.0f}% (threshold 15%)")
    f4 = sorted([m for m in ms if m["figure"] == "figure4"], key=lambda m: m["accommodation"])
    if len(f4) >= 3:
        c = [float(np.nanmean(m["wall"][:2])) for m in f4]
        say("Navarro's image of the distant scene gets blurrier as accommodation grows",
            all(b < a for a, b in zip(c, c[1:])),
            "far-wall centre sharpness " + ", ".join(f"{m['accommodation']:g} D {v:.2f}" for m, v in zip(f4, c)))
    return verdicts
