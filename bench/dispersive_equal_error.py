#!/usr/bin/python3
# Time to equal error of the dispersive Navarro eye against the monochromatic one (docs/spectral.md,
# "The dispersive eye"): relMSE in linear sRGB against each camera's own 2048-spp render, fitted
# over 16-128 spp, extrapolated to relMSE 1e-3; time is the renders' CPU time (user + system of
# the eyetrace processes), so other load on the machine does not skew the ratio.
# Usage: bench/dispersive_equal_error.py [box|gaussian]  (the figure scene's pixel filter is a
# box; "gaussian" renders it with pbrt-v4's default filter instead). Run from anywhere after
# building build/bin/eyetrace (or with EYETRACE=path/to/eyetrace); writes its renders into the current directory.
# The cameras take turns at every rung, REPEATS=3 times (environment; seeds 1..REPEATS), median CPU and
# mean relMSE per rung: about 12 minutes.
import json, math, os, resource, subprocess, sys
import numpy as np, OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
B = os.environ.get("EYETRACE", os.path.join(ROOT, "build/bin/eyetrace"))  # another build: EYETRACE=path
FILTER = sys.argv[1] if len(sys.argv) > 1 else "box"
REPEATS = int(os.environ.get("REPEATS", "3"))  # renders (seeds) per camera and rung
# "disp" is the eye's default (dispersionsampling "auto": spectral MIS in a uniform render, with
# normalised splats for a box filter; paths only for a box under adaptive sampling, which this
# is not, so "disp" renders the images "mis" does and their times differ by the machine's noise);
# "mis" and "paths" force each strategy.
CAMS = {"mono": 'Camera "navarro" "float fov" 60 "float pupildiameter" 3 "float wavelength" 555',
        "disp": 'Camera "navarro" "float fov" 60 "float pupildiameter" 3',
        "mis": 'Camera "navarro" "float fov" 60 "float pupildiameter" 3 "string dispersionsampling" "mis"',
        "paths": 'Camera "navarro" "float fov" 60 "float pupildiameter" 3 "string dispersionsampling" "paths"'}


def scene():
    text = open(os.path.join(ROOT, "scenes/peripheral.pbrt")).read()
    if FILTER != "box":
        text = text.replace('PixelFilter "box"', f'PixelFilter "{FILTER}"')
    path = os.path.abspath(f"peripheral_{FILTER}.pbrt")
    # Relative includes and textures resolve against the scene's folder: keep them there.
    text = text.replace('"textures/', f'"{ROOT}/scenes/textures/')
    open(path, "w").write(text)
    return path


def cpu_seconds():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def render(path, cam, spp, out, seed=1):
    before = cpu_seconds()
    subprocess.run([B, "render", path, "-o", out, "--spp", str(spp), "--resolution", "150x100", "--quiet",
                    "--threads", "2", "--seed", str(seed), "--camera", CAMS[cam]], check=True)
    return cpu_seconds() - before


def read(p):
    return oiio.ImageBuf(p).get_pixels(oiio.FLOAT)[:, :, :3]


def main():
    path = scene()
    res = {}
    refs = {}
    for cam in CAMS:
        render(path, cam, 2048, f"{cam}_{FILTER}_ref.exr", seed=99)
        refs[cam] = read(f"{cam}_{FILTER}_ref.exr")
    # The machine's speed drifts by tens of per cent within minutes (shared hosts): the two
    # cameras take turns at every rung, REPEATS times, and each rung keeps its median CPU time.
    # Each turn renders another seed and the rung's relMSE is their mean: one render's relMSE
    # varies by seed enough to move the fitted spp by 20 % (docs/performance.md, ZSobol).
    for spp in [16, 32, 64, 128]:
        secs = {cam: [] for cam in CAMS}
        for seed in range(1, REPEATS + 1):
            for cam in CAMS:
                secs[cam].append(render(path, cam, spp, f"{cam}_{FILTER}_{spp}_{seed}.exr", seed))
        for cam in CAMS:
            ref = refs[cam]
            m = ref.mean()
            sec = float(np.median(secs[cam]))
            rels = [float(((read(f"{cam}_{FILTER}_{spp}_{seed}.exr") - ref) ** 2).mean() / (m * m))
                    for seed in range(1, REPEATS + 1)]
            rel = float(np.mean(rels))
            res.setdefault(cam, []).append((spp, sec, rel, rels))
            print(cam, spp, f"{sec:.2f} s", f"relMSE {rel:.3e}", flush=True)
    def spp_at_target(spps, rels):
        k, c = np.polyfit(np.log(spps), np.log(rels), 1)
        return k, math.exp((math.log(1e-3) - c) / k)

    out, fitted = {}, {}
    for cam, v in res.items():
        k, spp_t = spp_at_target([x[0] for x in v], [x[2] for x in v])
        # Each seed's ladder fitted alone: how far one seed's answer strays (the spread of the
        # mean's is about this over sqrt(REPEATS)).
        per_seed = [spp_at_target([x[0] for x in v], [x[3][i] for x in v])[1] for i in range(REPEATS)]
        print(f"{cam}: spp at 1e-3 by seed alone: " + ", ".join(f"{n:.0f}" for n in per_seed))
        sec_per_spp = sum(x[1] for x in v) / sum(x[0] for x in v)
        out[cam] = spp_t * sec_per_spp
        # Also one render of spp_t samples: CPU = fixed + spp * marginal, fitted over the ladder
        # (the ladder's mean above charges four startups to its 240 spp).
        marginal, fixed = np.polyfit([x[0] for x in v], [x[1] for x in v], 1)
        fitted[cam] = fixed + marginal * spp_t
        print(f"{cam}: slope {k:.3f}, spp at 1e-3 {spp_t:.0f}, CPU s per spp {sec_per_spp:.4f}, s {out[cam]:.1f}; "
              f"fixed {fixed:.2f} s + {marginal:.4f} s/spp: one render {fitted[cam]:.2f} s")
    spp_t = {cam: spp_at_target([x[0] for x in v], [x[2] for x in v])[1] for cam, v in res.items()}
    for cam in ("disp", "mis", "paths"):
        # With a box filter a dispersive sample does all that a monochromatic one does (the same
        # film point draw, eye trace and four-wavelength scene path) and more, so its samples
        # ratio bounds its time ratio from below however cheap its own extra work were made.
        # (With a smooth filter the dispersive eye draws uniform points where the monochromatic
        # one samples the filter: not a bound there.)
        print(f"filter {FILTER}: {cam}/monochromatic time at relMSE 1e-3: {out[cam] / out['mono']:.2f} "
              f"(one render each: {fitted[cam] / fitted['mono']:.2f}; samples alone, the bound at any "
              f"cost per sample: {spp_t[cam] / spp_t['mono']:.2f})")


main()
