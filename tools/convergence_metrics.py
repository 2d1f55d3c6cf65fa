"""Error metrics, fovea/periphery masks, log-log interpolation, plots and the summary table of
tools/convergence.

Errors are taken over every colour channel of every pixel the reference sees (a pixel whose
reference is exactly black in all channels, e.g. outside an eye's traced field, is left out:
there is nothing to converge there):
  relMSE  mean of (x - ref)^2 / (ref^2 + 1e-2)   (1e-2 keeps dark pixels from dominating)
  RMSE    sqrt(mean of (x - ref)^2)
The fovea is the disc of eccentricity <= FOVEA_DEG around the image centre (the eccentricity of
a pixel is the angle between its chief ray and the optical axis: pinhole and thin lens map
tan(angle) linearly to pixels, the eye cameras map the angle itself); the periphery is the rest.
"""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import image_files

FOV = 50.0        # degrees across the shorter (vertical) image axis, for every camera
FOVEA_DEG = 10.0  # eccentricity radius of the "fovea" region (see docs/convergence.md)
REL_EPS = 1e-2
CLOCK_LABELS = {"model_seconds": "spp x measured seconds per spp (s)",
                "net_seconds": "render time less fixed overhead (s)", "render_seconds": "render time (s)",
                "cpu_seconds": "process CPU time (s)"}
REGIONS = ("image", "fovea", "periphery")
TARGETS = (1e-3, 1e-4)
REFERENCE_MARGIN = 3.0  # a target needs the reference's own relMSE this many times below it


def read_rgb(path):
    return image_files.read_rgb(path, "convergence")


write_exr = image_files.write_exr


def write_png(rgb, path):
    """sRGB preview, exposure scaled so the 99th percentile of luminance maps to white."""
    y = 0.2126 * rgb[:, :, 0] + 0.7152 * rgb[:, :, 1] + 0.0722 * rgb[:, :, 2]
    top = float(np.percentile(y, 99)) if y.size else 1.0
    image_files.write_png(rgb, path, 1.0 / (top if top > 0 else 1.0))


def eccentricity(shape, camera):
    """Eccentricity (degrees) of every pixel centre for camera 'pinhole', 'thinlens' or an eye."""
    h, w = shape
    s = 2.0 / min(h, w)  # the shorter image axis spans [-1, 1] on pbrt's screen
    x = (np.arange(w) + 0.5 - w / 2) * s
    y = (np.arange(h) + 0.5 - h / 2) * s
    r = np.hypot(*np.meshgrid(x, y))
    if camera.split("-")[0] in ("pinhole", "thinlens"):  # "thinlens-4mm" is a thin lens too
        return np.degrees(np.arctan(r * math.tan(math.radians(FOV / 2))))
    return r * FOV / 2


def region_masks(ref, camera, fovea_deg=FOVEA_DEG):
    """Boolean (h, w) masks of the pixels each region measures."""
    seen = np.any(ref != 0.0, axis=2)
    fovea = eccentricity(ref.shape[:2], camera) <= fovea_deg
    return {"image": seen, "fovea": seen & fovea, "periphery": seen & ~fovea}


def errors(img, ref, masks):
    """{region: (relMSE, RMSE)} of img against ref."""
    d2 = (img - ref) ** 2
    rel = d2 / (ref ** 2 + REL_EPS)
    out = {}
    for name, m in masks.items():
        out[name] = (float(rel[m].mean()), float(math.sqrt(d2[m].mean()))) if m.any() else (math.nan, math.nan)
    return out


def reference_self_error(half_a, half_b, masks):
    """relMSE of the mean of two independent half references against the truth, estimated from
    their difference: E[(a - b)^2] = 2 var(half) and var(mean) = var(half) / 2, so
    var(mean) = E[(a - b)^2] / 4. It is the floor under every measured error."""
    ref = 0.5 * (half_a + half_b)
    rel = (half_a - half_b) ** 2 / 4.0 / (ref ** 2 + REL_EPS)
    return {name: float(rel[m].mean()) if m.any() else math.nan for name, m in masks.items()}


def time_to_reach(times, errs, target):
    """(time, how) at which the error first falls to target; times and errs in order of
    increasing spp. how is "=" (interpolated linearly in log-log between the two sweep points
    around the crossing), "<" (the first point is already below: an upper bound), "~"
    (extrapolated along the log-log slope of the last three points, at most a decade of error
    beyond the last one) or None (not reached)."""
    pts = [(math.log(t), math.log(e)) for t, e in zip(times, errs) if t > 0 and e > 0 and math.isfinite(e)]
    lt = math.log(target)
    for i, (t, e) in enumerate(pts):
        if e <= lt:
            if i == 0:
                return math.exp(t), "<"
            t0, e0 = pts[i - 1]
            return math.exp(t0 + (lt - e0) / (e - e0) * (t - t0)), "="
    if len(pts) >= 3 and pts[-1][1] - lt <= math.log(10.0):
        (ta, ea), (tb, eb) = pts[-3], pts[-1]
        k = (eb - ea) / (tb - ta) if tb > ta else 0.0
        if k < -0.2:  # error still falling: follow the line
            return math.exp(tb + (lt - eb) / k), "~"
    return None, None


def format_reach(r):
    t, how = r
    if t is None:
        return "not reached"
    return {"=": "", "<": "<", "~": "~"}[how] + f"{t:.3g} s"


def time_at_error(times, errs, target):
    """Interpolated time (log-log) at which the error curve passes target, or None."""
    t, how = time_to_reach(times, errs, target)
    return t if how == "=" else None


def slope(xs, ys):
    """Least-squares slope of log(y) against log(x)."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(pts) < 2:
        return math.nan
    lx, ly = np.array(pts).T
    return float(np.polyfit(lx, ly, 1)[0])


def cost_model(spps, times):
    """(a, c): fixed seconds per render and seconds per sample per pixel of one configuration.
    a is what the cheapest render costs beyond c spp (lazy texture loading, thread start);
    c = sum(t - a) / sum(spp) over the sweep, so the long renders set it. Each configuration is
    timed at every spp level right after the others (spp-major order), so a change of machine
    load changes every configuration's c alike: c compares configurations fairly, where a single
    render's time carries whatever load the machine had at that moment."""
    pts = sorted(zip(spps, times))
    if len(pts) < 2:
        return 0.0, pts[0][1] / pts[0][0] if pts else math.nan
    n0, t0 = pts[0]
    c = sum(t - t0 for _, t in pts) / sum(n - n0 for n, _ in pts)
    if not c > 0:
        return 0.0, sum(t for _, t in pts) / sum(n for n, _ in pts)
    return max(t0 - c * n0, 0.0), c


def add_model_times(rows):
    """Adds overhead_seconds (a), seconds_per_spp (c), model_seconds (c spp: the time axis of the
    plots and summary by default) and net_seconds (render_seconds - a, at least 0.1 c spp)."""
    groups = {}
    for r in rows:
        groups.setdefault((r["scene"], r["camera"], r["sampler"]), []).append(r)
    for sel in groups.values():
        a, c = cost_model([r["spp"] for r in sel], [r["render_seconds"] for r in sel])
        for r in sel:
            r["overhead_seconds"], r["seconds_per_spp"] = a, c
            r["model_seconds"] = c * r["spp"]
            r["net_seconds"] = max(r["render_seconds"] - a, 0.1 * c * r["spp"])


COLOURS = {"independent": "tab:gray", "stratified": "tab:blue", "halton": "tab:green", "sobol": "tab:orange",
           "zsobol": "tab:red", "zsobol-padded": "tab:purple", "sobol-none": "tab:brown",
           "sobol-permutedigits": "tab:pink", "sobol-owen": "tab:olive", "pmj02bn": "tab:cyan",
           "paddedsobol": "gold"}
STYLES = {"pinhole": "-", "thinlens": "--", "navarro": ":"}
STYLES.update({f"{c}-{mm}mm": STYLES[c] for c in ("thinlens", "navarro") for mm in (2, 4, 6)})
STYLES.update({f"navarro-{mm}mm-polar": "-." for mm in (2, 4, 6)})


def plot_camera(rows, scene, camera, floors, path, clock):
    """Error against time for one scene and camera: one line per sampler, one panel per region."""
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2), sharey=True)
    for ax, region in zip(axes, REGIONS):
        for sampler in COLOURS:
            pts = sorted((r["spp"], r[clock], r[f"relmse_{region}"]) for r in rows
                         if r["scene"] == scene and r["camera"] == camera and r["sampler"] == sampler)
            if pts:
                ax.loglog(*list(zip(*pts))[1:], "o-", ms=3, color=COLOURS[sampler], label=sampler)
        floor = floors.get((scene, camera), {}).get(region)
        if floor and floor > 0:
            ax.axhline(floor, color="k", lw=0.8, ls=":", label="reference noise")
        for t in TARGETS:
            ax.axhline(t, color="0.7", lw=0.6)
        ax.set_title(f"{region}" + (f" (ecc. <= {FOVEA_DEG:g} deg)" if region == "fovea" else ""))
        ax.set_xlabel(CLOCK_LABELS[clock])
        ax.grid(True, which="both", alpha=0.25)
    axes[0].set_ylabel("relative MSE")
    axes[0].legend(fontsize=8)
    fig.suptitle(f"{scene}, {camera}: error against time")
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def plot_spp_grid(rows, scene, path):
    """Image relMSE against spp, log-log: one small panel per camera, one line per sampler, with
    each line's fitted slope in the legend (the convergence rate, independent of the machine)."""
    cameras = [c for c in STYLES if any(r["scene"] == scene and r["camera"] == c for r in rows)]
    cols = min(4, len(cameras))
    nrows = (len(cameras) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(3.2 * cols, 2.7 * nrows), sharex=True, sharey=True, squeeze=False)
    for ax, camera in zip(axes.flat, cameras):
        for sampler in COLOURS:
            pts = sorted((r["spp"], r["relmse_image"]) for r in rows
                         if r["scene"] == scene and r["camera"] == camera and r["sampler"] == sampler)
            if len(pts) > 1:
                xs, ys = zip(*pts)
                ax.loglog(xs, ys, "o-", ms=2.5, lw=1, color=COLOURS[sampler], label=f"{sampler} {slope(xs, ys):.2f}")
        ax.set_title(camera, fontsize=9)
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=6)
        ax.tick_params(labelsize=7)
    for ax in axes.flat[len(cameras):]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("spp", fontsize=8)
    for ax in axes[:, 0]:
        ax.set_ylabel("relMSE (image)", fontsize=8)
    fig.suptitle(f"{scene}: error against samples per pixel (legend: log-log slope)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=70)
    plt.close(fig)


def plot_scene(rows, scene, path, clock):
    """Image relMSE against time for every sampler x camera of one scene."""
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for camera in STYLES:
        for sampler in COLOURS:
            pts = sorted((r["spp"], r[clock], r["relmse_image"]) for r in rows
                         if r["scene"] == scene and r["camera"] == camera and r["sampler"] == sampler)
            if pts:
                ax.loglog(*list(zip(*pts))[1:], STYLES[camera], marker="o", ms=2.5, color=COLOURS[sampler],
                          label=f"{sampler}, {camera}")
    for t in TARGETS:
        ax.axhline(t, color="0.7", lw=0.6)
    ax.set_xlabel(CLOCK_LABELS[clock])
    ax.set_ylabel("relative MSE (image)")
    ax.set_title(f"{scene}: every sampler x camera")
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=7, ncol=3)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def summarize(rows, floors, clock="model_seconds"):
    """Summary text: time to each target per configuration, best sampler per camera, camera /
    pinhole time ratio at equal error, convergence slopes."""
    lines = [f"t(...): '<' reached at the first point, '~' extrapolated (slope of the last 3 points), "
             f"'ref. noisy' the reference's own relMSE is above 1/{REFERENCE_MARGIN:g} of the target"]
    cameras = [c for c in STYLES if any(r["camera"] == c for r in rows)]
    samplers = [s for s in COLOURS if any(r["sampler"] == s for r in rows)]
    for scene in sorted({r["scene"] for r in rows}):
        curves, reach = {}, {}
        lines.append(f"\n== {scene} (time = {clock}; relMSE over the image)")
        lines.append(f"{'camera':9} {'sampler':12} {'t(1e-3)':>12} {'t(1e-4)':>12} {'spp(1e-3)':>9} "
                     f"{'spp(1e-4)':>9} {'slope/spp':>9} "
                     f"{'relMSE@max':>10} {'fovea':>9} {'periph.':>9} {'ms/spp':>7} {'fixed s':>7}")
        for camera in cameras:
            floor = floors.get((scene, camera), {}).get("image", 0.0)
            for sampler in samplers:
                sel = sorted((r for r in rows if r["scene"] == scene and r["camera"] == camera
                              and r["sampler"] == sampler), key=lambda r: r["spp"])
                if not sel:
                    continue
                ts, es = [r[clock] for r in sel], [r["relmse_image"] for r in sel]
                curves[(camera, sampler)] = (ts, es, floor)
                # Below ~3x the reference's own noise the measured error is mostly that noise.
                reach[(camera, sampler)] = [time_to_reach(ts, es, t) if t >= REFERENCE_MARGIN * floor
                                            else (None, "noisy") for t in TARGETS]
                last = sel[-1]
                spps = [r["spp"] for r in sel]
                n_reach = [time_to_reach(spps, es, t) if r[1] != "noisy" else (None, None)
                           for t, r in zip(TARGETS, reach[(camera, sampler)])]
                lines.append(f"{camera:9} {sampler:12} " + " ".join(
                    f"{'ref. noisy' if r[1] == 'noisy' else format_reach(r):>12}" for r in reach[(camera, sampler)])
                    + " " + " ".join(f"{(n[1] if n[1] != '=' else '') + f'{n[0]:.0f}' if n[0] else '-':>9}"
                                     for n in n_reach)
                    + f" {slope([r['spp'] for r in sel], es):9.2f} {last['relmse_image']:10.2e}"
                    f" {last['relmse_fovea']:9.2e} {last['relmse_periphery']:9.2e}"
                    f" {1e3 * last['seconds_per_spp']:7.2f} {last['overhead_seconds']:7.3f}")
            lines.append(f"{camera:9} (reference's own relMSE ~ {floor:.1e})")
        best = best_samplers(reach, cameras, lines, scene)
        ratios(curves, reach, best, cameras, samplers, lines, scene)
    return "\n".join(lines)


def best_samplers(reach, cameras, lines, scene):
    """{(camera, target index): (time, how, sampler)}: the fastest sampler to each target."""
    lines.append(f"best sampler per camera ({scene}):")
    best = {}
    for camera in cameras:
        for ti, target in enumerate(TARGETS):
            cands = sorted((r[ti][0], r[ti][1], s) for (c, s), r in reach.items() if c == camera and r[ti][0])
            if cands:
                best[(camera, ti)] = cands[0]
                t, how, s = cands[0]
                lines.append(f"  {camera:9} relMSE {target:.0e}: {s} ({format_reach((t, how))})")
            else:
                lines.append(f"  {camera:9} relMSE {target:.0e}: none (not reached or reference too noisy)")
    return best


def ratios(curves, reach, best, cameras, samplers, lines, scene):
    """Camera / pinhole time at equal error: at each target (with the same sampler, and best
    against best), and at the lowest error both curves measure (always available)."""
    lines.append(f"time ratio camera / pinhole at equal error ({scene}):")
    for camera in cameras:
        if camera == "pinhole":
            continue
        for ti, target in enumerate(TARGETS):
            parts = []
            for sampler in samplers:
                a, b = reach.get((camera, sampler)), reach.get(("pinhole", sampler))
                ok = a and b and a[ti][0] and b[ti][0]
                mark = "~" if ok and "~" in (a[ti][1], b[ti][1]) else ""
                parts.append(f"{sampler} {mark}{a[ti][0] / b[ti][0]:.2f}" if ok else f"{sampler} -")
            x, y = best.get((camera, ti)), best.get(("pinhole", ti))
            mark = "~" if x and y and "~" in (x[1], y[1]) else ""
            lines.append(f"  {camera:9} at {target:.0e}: " + ", ".join(parts)
                         + (f"; best/best {mark}{x[0] / y[0]:.2f}" if x and y else "; best/best -"))
        parts = []
        for sampler in samplers:
            a, b = curves.get((camera, sampler)), curves.get(("pinhole", sampler))
            if not (a and b):
                continue
            # The lowest error both reach, kept above both references' noise.
            e = max(min(a[1]), min(b[1]), REFERENCE_MARGIN * a[2], REFERENCE_MARGIN * b[2])
            ta, tb = time_at_error(a[0], a[1], e * 1.0001), time_at_error(b[0], b[1], e * 1.0001)
            parts.append(f"{sampler} {ta / tb:.2f} @{e:.1e}" if ta and tb else f"{sampler} -")
        lines.append(f"  {camera:9} at the lowest common error: " + ", ".join(parts))
