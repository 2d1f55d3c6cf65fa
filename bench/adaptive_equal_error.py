#!/usr/bin/python3
# Adaptive against uniform sampling at equal error on the figure scene (scenes/peripheral.pbrt)
# through the Navarro eye (docs/adaptive-sampling.md). Both are scored against one uniform
# 4096-spp render of another seed, with two errors:
#   global  mean (x - ref)^2 / mean(ref)^2           (the brightness-normalised relMSE)
#   pixel   mean (x - ref)^2 / (ref^2 + 1e-2)         (tools/convergence's per-pixel relMSE)
# Uniform renders at 16-512 spp give error against CPU time (user + system of the eyetrace
# processes, so other load on the machine does not skew it); a straight line in log-log through
# them gives the uniform time at each adaptive render's error, and the ratio is the speed-up.
# Also the bias: the adaptive image's mean against the reference's, beside its noise.
# Usage: bench/adaptive_equal_error.py [WxH]  (default 240x160). Run after building
# build/bin/eyetrace; writes its renders into the current directory. About 10 minutes.
import math, os, resource, subprocess, sys
import numpy as np, OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
B = os.path.join(ROOT, "build/bin/eyetrace")
RES = sys.argv[1] if len(sys.argv) > 1 else "240x160"
# The paper figures' camera (tools/figures: Figure 3's Navarro panel).
CAMERA = 'Camera "navarro" "float fov" 50 "float pupildiameter" 5 "float accommodation" 0 "float wavelength" 589.3'
UNIFORM = [16, 32, 64, 128, 256, 512]
TARGETS = [0.08, 0.06, 0.04, 0.025]


def cpu_seconds():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def render(out, extra, seed=1):
    before = cpu_seconds()
    subprocess.run([B, "render", os.path.join(ROOT, "scenes/peripheral.pbrt"), "-o", out, "--resolution", RES,
                    "--quiet", "--threads", "2", "--seed", str(seed), "--camera", CAMERA] + extra, check=True)
    return cpu_seconds() - before


def read(p):
    return oiio.ImageBuf(p).get_pixels(oiio.FLOAT)[:, :, :3].astype(np.float64)


def errors(img, ref):
    d2 = (img - ref) ** 2
    return float(d2.mean() / ref.mean() ** 2), float((d2 / (ref * ref + 1e-2)).mean())


def uniform_time(points, err):
    """CPU seconds a uniform render needs for `err`, from the log-log line through `points`."""
    k, c = np.polyfit(np.log([p[1] for p in points]), np.log([p[0] for p in points]), 1)
    return math.exp(c + k * math.log(err))


def main():
    render("adaptive_ref.exr", ["--spp", "4096"], seed=99)
    ref = read("adaptive_ref.exr")
    uni = []
    for spp in UNIFORM:
        sec = render(f"uniform_{spp}.exr", ["--spp", str(spp)])
        g, p = errors(read(f"uniform_{spp}.exr"), ref)
        uni.append((sec, g, p))
        print(f"uniform {spp:5d} spp: {sec:7.2f} s  global {g:.3e}  pixel {p:.3e}", flush=True)
    print(f"{'target':>8} {'mean spp':>8} {'s':>7} {'global':>10} {'uniform s':>9} {'ratio':>6} "
          f"{'pixel':>10} {'uniform s':>9} {'ratio':>6} {'bias':>9} {'noise':>8}")
    for e in TARGETS:
        out = f"adaptive_{e}.exr"
        sec = render(out, ["--adaptive", "--target-error", str(e), "--max-spp", "1024", "--stats", out + ".json"])
        img = read(out)
        g, p = errors(img, ref)
        tg = uniform_time([(s, x) for s, x, _ in uni], g)
        tp = uniform_time([(s, y) for s, _, y in uni], p)
        mean_spp = float(__import__("json").load(open(out + ".json"))["samples_per_pixel_distribution"]["mean"])
        # Bias of the image mean, relative, beside the standard error of that mean (pixels as
        # independent: an underestimate where neighbours correlate, so read it as a lower bound).
        diff = (img - ref).mean(axis=2).ravel()
        bias = diff.mean() / ref.mean()
        noise = diff.std() / math.sqrt(diff.size) / ref.mean()
        print(f"{e:8.3f} {mean_spp:8.1f} {sec:7.2f} {g:10.3e} {tg:9.2f} {tg / sec:6.2f} {p:10.3e} {tp:9.2f} "
              f"{tp / sec:6.2f} {bias:9.2e} {noise:8.1e}", flush=True)


main()
