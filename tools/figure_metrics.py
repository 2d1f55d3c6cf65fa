"""Image I/O, sharpness measurement, montages, plots and the paper's claims for tools/figures.

Sharpness is the gradient energy (mean squared luminance difference between neighbouring
pixels) of a region, divided by the same region's gradient energy in a reference rendered with
the same camera and a pinhole-sized pupil (0.1 mm; a pinhole for the thin lens). The reference
has the same pixel mapping and the same texture detail, so the ratio isolates the blur the
optics add: 1 is as sharp as a pinhole, smaller is blurrier.

Sampling noise adds gradient energy of its own, so the ratio cannot fall below a noise floor.
Every panel is rendered as two halves with independent seeds; their difference is pure noise,
which measures the floor (the ratio a signal-free image with this noise would have) and the
scatter of the ratio itself, so a claim can be judged against the noise instead of strictly.
"""
import csv
import os
from typing import NamedTuple

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import image_files

FOV = 50.0
ECCENTRICITY_EDGES = [0, 5, 10, 15, 20, 25, 30, 35]
ECCENTRICITY_CENTRES = [0.5 * (a + b) for a, b in zip(ECCENTRICITY_EDGES[:-1], ECCENTRICITY_EDGES[1:])]
WALL_BAND_DEG = (1.0, 9.0)  # vertical angles above the horizon where only the far wall is seen
CENTRE_DEG = (0.0, 10.0)  # horizontal eccentricities of the far-wall centre (Figure 4)
# Letter charts of scenes/peripheral.pbrt: (name, horizontal deg, vertical deg, distance m).
CHARTS = [("chart 0.25 m", -26, -10, 0.25), ("chart 1 m", 0, -11, 1.0), ("chart 4 m", 26, -10, 4.0)]
REFERENCE_PUPIL_MM = 0.1


def read_rgb(path):
    return image_files.read_rgb(path, "figures")


write_exr = image_files.write_exr
write_png = image_files.write_png


def luminance(rgb):
    return 0.2126 * rgb[:, :, 0] + 0.7152 * rgb[:, :, 1] + 0.0722 * rgb[:, :, 2]


def gradient_energy(y):
    """Per-pixel squared gradient (forward differences), same shape as y (last row/col 0)."""
    e = np.zeros_like(y)
    e[:, :-1] += (y[:, 1:] - y[:, :-1]) ** 2
    e[:-1, :] += (y[1:, :] - y[:-1, :]) ** 2
    return e


def pixel_angles(shape, model, fov=FOV):
    """Horizontal and vertical visual angle (degrees) of every pixel centre, fov (degrees) across
    the shorter (vertical) axis. Eye cameras map pixels linearly in angle; the thin lens and
    pinhole map them linearly in tan(angle)."""
    h, w = shape
    s = 2.0 / h  # the shorter (vertical) axis spans the field of view
    x = (np.arange(w) + 0.5 - w / 2) * s
    y = (h / 2 - np.arange(h) - 0.5) * s
    if model in ("thinlens", "pinhole"):
        t = np.tan(np.radians(fov / 2))
        ax, ay = np.degrees(np.arctan(x * t)), np.degrees(np.arctan(y * t))
    else:
        ax, ay = x * fov / 2, y * fov / 2
    return np.meshgrid(ax, ay)


class Sharpness(NamedTuple):
    """One region's sharpness ratio (value); the ratio sampling noise alone would give it (floor);
    the ratio in half a minus that in half b (gap: one sample of the noise's scatter); and the
    standard deviation of value - floor from sampling noise (sigma, set by pool_sigma)."""
    value: float
    floor: float
    gap: float
    sigma: float = float("nan")


NO_SHARPNESS = Sharpness(float("nan"), float("nan"), float("nan"))


def sharpness(y, y_ref, mask=None):
    """Gradient energy of luminance y over that of y_ref, within mask (default: everywhere)."""
    m = np.ones(y.shape, bool) if mask is None else mask
    e, er = gradient_energy(y)[m].mean(), gradient_energy(y_ref)[m].mean()
    return float(e / er) if er > 0 else float("nan")


def half_paths(out_dir, name):
    """The two half-sample renders (independent seeds) whose mean is panel `name`."""
    return [os.path.join(out_dir, "halves", f"{name}-{h}.exr") for h in "ab"]


class PanelEnergy:
    """Gradient energies of a panel rendered as two independent halves y_a, y_b (luminance).

    The panel is their mean. Its noise (n_a + n_b) / 2 has the same statistics as
    (n_a - n_b) / 2, and the difference y_a - y_b holds no signal at all, so a quarter of the
    difference's gradient energy is the noise's share of the panel's gradient energy."""

    def __init__(self, y_a, y_b):
        self.mean = gradient_energy(0.5 * (y_a + y_b))
        self.noise = gradient_energy(y_a - y_b) / 4.0
        self.half_gap = gradient_energy(y_a) - gradient_energy(y_b)


def region_sharpness(panel, e_ref, mask):
    """Sharpness of one region with its noise floor and the gap between the halves."""
    if not mask.any() or e_ref[mask].mean() <= 0:
        return NO_SHARPNESS
    r = e_ref[mask].mean()
    return Sharpness(float(panel.mean[mask].mean() / r), float(panel.noise[mask].mean() / r),
                     float(panel.half_gap[mask].mean() / r))


def pool_sigma(stats):
    """The Sharpness list (one region in several panels) with sigma set from the halves' gaps.

    One gap per panel is too few to estimate a scatter, and pixel blocks will not do either:
    the low-discrepancy samplers scramble with one seed for the whole image, so the noise of
    distant pixels is correlated and a region's noise energy scatters more from seed to seed
    than independent pixels would. So the scatter is pooled as a fraction c of the noise floor
    (noise energy scales with it), c = rms(gap / (2 floor)): a panel's value scatters at most
    half as much as the gap (a half has twice the noise, and the gap differences two halves).
    The floor's estimate scatters about as much as the value where noise dominates, so
    value - floor has sigma = sqrt(2) c floor."""
    ok = [s for s in stats if np.isfinite(s.gap) and s.floor > 0]
    if not ok:
        return list(stats)
    c = float(np.sqrt(np.mean([(s.gap / (2 * s.floor)) ** 2 for s in ok])))
    return [s._replace(sigma=float(np.sqrt(2.0) * c * s.floor)) for s in stats]


def wall_mask(ax, ay, lo_deg, hi_deg):
    """Far-wall band pixels with horizontal eccentricity in [lo_deg, hi_deg)."""
    band = (ay >= WALL_BAND_DEG[0]) & (ay <= WALL_BAND_DEG[1])
    return band & (np.abs(ax) >= lo_deg) & (np.abs(ax) < hi_deg)


def chart_mask(ax, ay, h_deg, v_deg, half_deg=3.5):
    return (np.abs(ax - h_deg) < half_deg) & (np.abs(ay - v_deg) < half_deg)


def model_of(panel):
    return panel.split("-")[1]


def falls_to_floor(values, floors, sigmas, z=3.0):
    """Whether the signal (value - floor) falls strictly until it is within z sigma of zero (the
    value has reached its noise floor), then stays there (sigma: of value - floor). The signal,
    not the raw value, is compared between panels because the floor itself grows with blur (a
    blurred pixel averages a wider patch of texture, so its samples vary more): the raw value
    can rise while the image gets blurrier. Returns (holds, index of the first value at the
    floor or None)."""
    signal = [v - f for v, f in zip(values, floors)]
    at_floor = [x <= z * s for x, s in zip(signal, sigmas)]
    reached = next((i for i, a in enumerate(at_floor) if a), None)
    end = len(values) - 1 if reached is None else reached
    falling = all(signal[i + 1] < signal[i] for i in range(end))
    if reached is None:
        return falling, None
    return bool(falling and all(at_floor[reached:])), reached


def measure(out_dir, rows, optics_spots, reference_exr):
    """Measures every panel against its model's reference (reference_exr(model) -> EXR path).
    optics_spots(model, accommodation) -> {field_deg: RMS spot radius um}, object at 10 m."""
    refs = {}
    result = []
    for r in rows:
        model = model_of(r["panel"])
        if model not in refs:
            refs[model] = gradient_energy(luminance(read_rgb(reference_exr(model))))
        ref = refs[model]
        panel = PanelEnergy(*[luminance(read_rgb(p)) for p in half_paths(out_dir, r["panel"])])
        ax, ay = pixel_angles(ref.shape, model)
        d = float(r["label"].split()[0]) if r["figure"] == "figure4" else 0.0
        spots = optics_spots(model, d) if model != "thinlens" else {}
        edges = zip(ECCENTRICITY_EDGES[:-1], ECCENTRICITY_EDGES[1:])
        result.append(dict(
            figure=r["figure"], panel=r["panel"], model=model, accommodation=d,
            wall=[region_sharpness(panel, ref, wall_mask(ax, ay, lo, hi)) for lo, hi in edges],
            centre=region_sharpness(panel, ref, wall_mask(ax, ay, *CENTRE_DEG)),
            spots=[spots.get(round(c, 3), float("nan")) for c in ECCENTRICITY_CENTRES],
            axial_spot=spots.get(0.0, float("nan")),
            charts={name: region_sharpness(panel, ref, chart_mask(ax, ay, h, v)) for name, h, v, _ in CHARTS}))
    for fig in ("figure3", "figure4"):
        with_sigma(m for m in result if m["figure"] == fig)
    return result


def with_sigma(ms):
    """Sets every region's sigma, pooling each region's gaps over the panels ms (a region's
    relative scatter depends on its size, so regions are not pooled with each other)."""
    ms = list(ms)
    for i in range(len(ECCENTRICITY_CENTRES)):
        for m, s in zip(ms, pool_sigma([m["wall"][i] for m in ms])):
            m["wall"][i] = s
    for m, s in zip(ms, pool_sigma([m["centre"] for m in ms])):
        m["centre"] = s
    for name, _, _, _ in CHARTS:
        for m, s in zip(ms, pool_sigma([m["charts"][name] for m in ms])):
            m["charts"][name] = s


def write_blur_csv(ms, path):
    """One row per panel and region: sharpness, its noise floor and sigma, and the optics RMS
    spot radius (object at 10 m) at the region's field angle where it has one."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["figure", "panel", "model", "accommodation_D", "region", "eccentricity_deg",
                    "sharpness_ratio", "noise_floor", "signal_sigma", "rms_spot_um"])
        for m in ms:
            def row(region, ecc, s, spot=""):
                w.writerow([m["figure"], m["panel"], m["model"], m["accommodation"], region, ecc,
                            f"{s.value:.4f}", f"{s.floor:.4f}", f"{s.sigma:.4f}",
                            spot if spot == "" else f"{spot:.2f}"])
            row("far wall 10 m, centre 0-10 deg", 0.0, m["centre"], m["axial_spot"])
            for c, s, spot in zip(ECCENTRICITY_CENTRES, m["wall"], m["spots"]):
                row("far wall 10 m", c, s, spot)
            for name, h, v, _ in CHARTS:
                row(name, f"{np.hypot(h, v):.1f}", m["charts"][name])


def montage(pngs, labels, path, title, cols=None, tile_inches=(4.2, 3.1)):
    """The PNGs in a grid (cols columns; default up to 4), each labelled below, with a title;
    tile_inches: the size of one image and its label."""
    n = len(pngs)
    cols = cols or min(n, 4 if n > 5 else n)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(tile_inches[0] * cols, tile_inches[1] * rows + 0.5), squeeze=False)
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


def export_for_docs(paths, dest, width=1200, max_bytes=300_000):
    """Copies of the montages and plots small enough to commit: at most width pixels wide, and
    reduced to 256 colours where that is what it takes to stay under max_bytes."""
    from PIL import Image
    os.makedirs(dest, exist_ok=True)
    for src in paths:
        if not os.path.exists(src):
            continue
        im = Image.open(src).convert("RGB")
        if im.width > width:
            im = im.resize((width, round(im.height * width / im.width)), Image.LANCZOS)
        out = os.path.join(dest, os.path.basename(src))
        im.save(out, optimize=True)
        if os.path.getsize(out) > max_bytes:
            im.quantize(256, method=Image.Quantize.MEDIANCUT).save(out, optimize=True)
        print(f"  {out}: {im.width}x{im.height}, {os.path.getsize(out) // 1000} kB")


def plot(ms, out):
    f3 = [m for m in ms if m["figure"] == "figure3"]
    if f3:
        fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
        for m in f3:
            line, = a.plot(ECCENTRICITY_CENTRES, [s.value for s in m["wall"]], "o-", label=m["model"])
            a.plot(ECCENTRICITY_CENTRES, [s.floor for s in m["wall"]], ":", color=line.get_color())
            if m["model"] != "thinlens":
                b.plot(ECCENTRICITY_CENTRES, m["spots"], "o-", label=m["model"])
        a.set(xlabel="eccentricity (deg)", ylabel="sharpness (1 = pinhole)",
              title="Far wall (10 m): sharpness (dotted: noise floor)")
        b.set(xlabel="field angle (deg)", ylabel="RMS spot radius (um)",
              title="eyetrace optics: RMS spot, 5 mm pupil, object 10 m")
        for ax in (a, b):
            ax.grid(alpha=0.3)
            ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(out, "blur-vs-eccentricity.png"), dpi=100)
        plt.close(fig)
    f4 = sorted([m for m in ms if m["figure"] == "figure4"], key=lambda m: m["accommodation"])
    if f4:
        fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
        d = [m["accommodation"] for m in f4]
        a.errorbar(d, [m["centre"].value for m in f4], yerr=[3 * m["centre"].sigma for m in f4],
                   fmt="o-", capsize=3, label="far wall 10 m, centre 0-10 deg (bars: 3 sigma)")
        a.plot(d, [m["centre"].floor for m in f4], "k:", label="its noise floor")
        for name, _, _, _ in CHARTS:
            a.plot(d, [m["charts"][name].value for m in f4], "s--", label=name)
        a.set(xlabel="accommodation parameter D (dioptres)", ylabel="sharpness (1 = pinhole)",
              title="Navarro eye: sharpness against accommodation")
        a.legend(fontsize=8)
        b.plot(d, [m["axial_spot"] for m in f4], "o-")
        b.set(xlabel="accommodation parameter D (dioptres)", ylabel="RMS spot radius (um)",
              title="eyetrace optics: on-axis RMS spot, object 10 m")
        for ax in (a, b):
            ax.grid(alpha=0.3)
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
        w = np.array([s.value for s in tl["wall"]])
        near = tl["charts"]["chart 0.25 m"].value
        say("thin lens blurs only with depth, not eccentricity",
            bool(np.nanmin(w) > 0.85 * np.nanmax(w) and near < 0.7 * np.nanmean(w)),
            f"far-wall sharpness {np.nanmin(w):.2f}..{np.nanmax(w):.2f} across 0-35 deg; chart at 0.25 m {near:.2f}")
    periph = lambda m: float(np.nanmean([s.value for s in m["wall"][4:]]))  # 20-35 deg
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
        check_accommodation(f4, say)
    return verdicts


def check_accommodation(f4, say):
    """The Figure 4 claim, from the image (noise-aware) and from the optics (noise-free)."""
    c = [m["centre"] for m in f4]
    values, floors, sigmas = [s.value for s in c], [s.floor for s in c], [s.sigma for s in c]
    holds, reached = falls_to_floor(values, floors, sigmas)
    if reached is None:
        where = "the end: it never reaches its noise floor"
    else:
        stays = all(v - f <= 3 * s for v, f, s in zip(values[reached:], floors[reached:], sigmas[reached:]))
        where = (f"it reaches its noise floor at {f4[reached]['accommodation']:g} D and "
                 + ("stays within 3 sigma of it" if stays else "rises above it again by more than 3 sigma"))
    end = len(values) - 1 if reached is None else reached
    falling = all(values[i + 1] - floors[i + 1] < values[i] - floors[i] for i in range(end))
    say("Navarro's image of the distant scene gets blurrier as accommodation grows",
        holds, "far-wall centre sharpness (noise floor, sigma of value - floor) "
        + ", ".join(f"{m['accommodation']:g} D {s.value:.4f} ({s.floor:.4f}, {s.sigma:.4f})" for m, s in zip(f4, c))
        + f"; value - floor falls strictly until {where}"
        + ("" if falling else "; it does not fall strictly before the floor"))
    spots = [m["axial_spot"] for m in f4]
    say("cross-check, noise-free: Navarro's on-axis RMS spot for an object at 10 m grows with accommodation",
        all(b > a for a, b in zip(spots, spots[1:])),
        ", ".join(f"{m['accommodation']:g} D {v:.0f} um" for m, v in zip(f4, spots)))
