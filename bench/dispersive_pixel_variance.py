#!/usr/bin/python3
# Per-pixel relative variance of the dispersive and monochromatic Navarro eyes on the figure
# scene (docs/spectral.md, "Cost at equal error", the table of ideas): two seeds' renders at the
# same spp, mean over pixels and channels of (a - b)^2 / 2 divided by the image mean squared;
# also for luminance alone, and the CPU seconds per spp (user + system, startup included).
# Usage: bench/dispersive_pixel_variance.py [box|gaussian] [spp] [mono|disp ...]   (default
# gaussian 32, both cameras); EYETRACE=path runs another build. About 20 s. Writes its renders
# into the current directory.
import os, resource, subprocess, sys
import numpy as np, OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
B = os.environ.get("EYETRACE", os.path.join(ROOT, "build/bin/eyetrace"))
FILTER = sys.argv[1] if len(sys.argv) > 1 else "gaussian"
SPP = int(sys.argv[2]) if len(sys.argv) > 2 else 32
CAMS = {"mono": 'Camera "navarro" "float fov" 60 "float pupildiameter" 3 "float wavelength" 555',
        "disp": 'Camera "navarro" "float fov" 60 "float pupildiameter" 3'}


def scene():
    text = open(os.path.join(ROOT, "scenes/peripheral.pbrt")).read()
    if FILTER != "box":
        text = text.replace('PixelFilter "box"', f'PixelFilter "{FILTER}"')
    text = text.replace('"textures/', f'"{ROOT}/scenes/textures/')
    path = os.path.abspath(f"peripheral_{FILTER}.pbrt")
    open(path, "w").write(text)
    return path


def cpu_seconds():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def main():
    path = scene()
    lum = np.array([0.2126, 0.7152, 0.0722])
    for cam in sys.argv[3:] or list(CAMS):
        images, seconds = [], 0.0
        for seed in (1, 2):
            out = f"variance_{cam}_{FILTER}_{seed}.exr"
            before = cpu_seconds()
            subprocess.run([B, "render", path, "-o", out, "--spp", str(SPP), "--resolution", "150x100", "--quiet",
                            "--threads", "2", "--seed", str(seed), "--camera", CAMS[cam]], check=True)
            seconds += cpu_seconds() - before
            images.append(oiio.ImageBuf(out).get_pixels(oiio.FLOAT)[:, :, :3].astype(np.float64))
        a, b = images
        rel = ((a - b) ** 2).mean() / 2 / ((a + b) / 2).mean() ** 2
        la, lb = a @ lum, b @ lum
        rel_y = ((la - lb) ** 2).mean() / 2 / ((la + lb) / 2).mean() ** 2
        print(f"{FILTER} {cam} {SPP} spp: relative variance {rel:.5f}, luminance {rel_y:.5f}, "
              f"CPU s per spp {seconds / 2 / SPP:.4f}")


main()
