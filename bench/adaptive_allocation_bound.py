#!/usr/bin/python3
# How much any per-pixel allocation of samples can gain on the figure scene through the figures'
# Navarro eye, and how much allocations built from estimates a renderer can have do gain
# (docs/adaptive-sampling.md, "What any allocation can gain").
#
# Every number comes from uniform renders of independent seeds, none from the adaptive code:
#   - four renders at N spp: two (a, b) give the estimates, the other two (c, d) score them, so an
#     allocation is never judged on the noise it was built from; the reference for the error's
#     normalisation is their mean;
#   - two renders at N/2 spp (a pass's halves, as a two-buffer estimate would see them) and
#     sixteen at 1 spp (the per-sample spread an adaptive renderer estimates from its own samples).
# The error is tools/convergence's per-pixel relMSE, (x - ref)^2 / (ref^2 + 1e-2), summed over the
# channels; a pixel's error variance at N is half the squared difference of c and d. An allocation
# n_p (mean N, at least 16 as --min-spp) is scored by the image's error if each pixel's error
# scales as 1/n_p from what it is at N, against N everywhere; the printed number is that ratio,
# the speed-up at equal error if every sample costs the same.
#   bound           (2/pi) mean(d^2) / mean(|d|)^2 of c - d (d Gaussian: E|d| = sqrt(2/pi) sigma), so
#                   mean(sigma^2) / mean(sigma)^2, the gain of n proportional to the exact sigma
#                   (the Lagrange optimum); per channel, as if each channel had its own count, so
#                   a little above what one count per pixel can reach
#   own pair        n_p from the pixel's own squared difference of a and b
#   pooled pair     the same, averaged over 3x3 pixels
#   pooled halves   from the two N/2 renders, 3x3-averaged (a two-half-buffers estimate)
#   per-sample s    from the 1-spp renders' spread, max(own, 3x3 mean): what --adaptive uses
# Usage: bench/adaptive_allocation_bound.py [WxH] [N]   (default 240x160 128; writes EXRs into the
# current folder and reuses them). 240x160: about a minute; 1024x683 (the figures' paper size):
# about 8 CPU minutes.
import math, os, subprocess, sys
import numpy as np, OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
B = os.environ.get("EYETRACE", os.path.join(ROOT, "build/bin/eyetrace"))
RES = sys.argv[1] if len(sys.argv) > 1 else "240x160"
N = int(sys.argv[2]) if len(sys.argv) > 2 else 128
MIN_SPP = 16
# The paper figures' camera (tools/figures: Figure 3's Navarro panel), as bench/adaptive_equal_error.py.
CAMERA = 'Camera "navarro" "float fov" 50 "float pupildiameter" 5 "float accommodation" 0 "float wavelength" 589.3'


def render(seed, spp):
    out = f"bound_{RES}_{spp}spp_seed{seed}.exr"
    if not os.path.exists(out):
        subprocess.run([B, "render", os.path.join(ROOT, "scenes/peripheral.pbrt"), "-o", out, "--resolution", RES,
                        "--quiet", "--threads", "2", "--seed", str(seed), "--spp", str(spp), "--camera", CAMERA],
                       check=True)
    return oiio.ImageBuf(out).get_pixels(oiio.FLOAT)[:, :, :3].astype(np.float64)


def pool(x):
    """Mean over each pixel's 3x3 neighbourhood (edges repeated)."""
    p = np.pad(x, 1, mode="edge")
    h, w = x.shape
    return sum(p[dy:dy + h, dx:dx + w] for dy in range(3) for dx in range(3)) / 9.0


def main():
    a, b, c, d = (render(s, N) for s in (1, 2, 3, 4))
    h1, h2 = (render(s, N // 2) for s in (5, 6))
    ones = np.array([render(100 + s, 1) for s in range(16)])
    ref = (a + b + c + d) / 4
    weight = 1.0 / (ref * ref + 1e-2)
    scored = ((c - d) ** 2 / 2 * weight).sum(axis=2)  # error variance at N, per pixel

    def error(n):
        return float((scored * N / n).mean())

    uniform = error(np.full(scored.shape, float(N)))

    def gain(sigma):
        n = np.maximum(sigma / sigma.mean() * N, MIN_SPP)
        return uniform / error(n * (N / n.mean()))

    diff = (c - d) ** 2 * weight
    bound = (2 / math.pi) * diff.mean() / np.sqrt(diff).mean() ** 2
    pair = ((a - b) ** 2 / 2 * weight).sum(axis=2)
    halves = ((h1 - h2) ** 2 / 2 * weight).sum(axis=2)
    s = np.sqrt((ones.var(axis=0, ddof=1) * weight).sum(axis=2))
    print(f"figure scene, Navarro 5 mm, {RES}, {N} spp: gain at equal per-pixel relMSE")
    print(f"  bound (exact sigma)        {bound:.2f}")
    print(f"  own pair                   {gain(np.sqrt(pair)):.2f}")
    print(f"  pooled pair                {gain(np.sqrt(pool(pair))):.2f}")
    print(f"  pooled halves (N/2)        {gain(np.sqrt(pool(halves))):.2f}")
    print(f"  per-sample s, max(own, 3x3) {gain(np.maximum(s, pool(s))):.2f}")


main()
