#!/usr/bin/python3
"""The worked example of docs/python.md: the Navarro eye from Python.

  PYTHONPATH=build/python /usr/bin/python3 docs/python_example.py [--out FILE.png] [--spp N]
      [--resolution WxH] [--dpi N]

1. Sweeps the Navarro eye's accommodation from 0 to 6 D and plots its refraction (the optics
   report's `refraction_diopters`) and its on-axis RMS spot radius (real rays, 4 mm pupil).
2. Renders the letter-chart scene (scenes/peripheral.pbrt) through the eye accommodated to 0 D
   (focused far, on the wall 10 m away) and to 2 D (focused at 0.5 m, on the near chart) and
   shows the two side by side.
Everything goes into one figure (default out/python_example.png). tests/python runs this script
at a small size, so the example cannot rot.
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np

import eyetrace

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "scenes", "peripheral.pbrt")


def sweep(accommodations):
    """Refraction (D) and on-axis RMS spot radius (um) of the Navarro eye at each accommodation."""
    refraction, spot = [], []
    for a in accommodations:
        eye = eyetrace.Eye("navarro", pupildiameter=4, accommodation=a)
        refraction.append(eye.report(fields=[0])["refraction_diopters"])
        spot.append(eye.spot(field=0)["rms_radius_um"])
    return np.array(refraction), np.array(spot)


def to_display(image):
    """Linear RGB to sRGB in [0, 1] for imshow."""
    x = np.clip(image[..., :3], 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default="out/python_example.png")
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--resolution", default="600x400")
    ap.add_argument("--dpi", type=int, default=80, help="the figure is 12 x 8 inches")
    a = ap.parse_args()

    accommodations = np.linspace(0.0, 6.0, 13)
    refraction, spot = sweep(accommodations)

    renders = {}
    for acc in (0.0, 2.0):
        camera = f'Camera "navarro" "float pupildiameter" 4 "float accommodation" {acc} "float fov" 50'
        renders[acc] = eyetrace.render(SCENE, camera=camera, spp=a.spp, resolution=a.resolution, seed=1)

    fig = plt.figure(figsize=(12, 8), constrained_layout=True)
    grid = fig.add_gridspec(2, 2)
    ax = fig.add_subplot(grid[0, 0])
    ax.plot(accommodations, refraction, "o-")
    ax.set_xlabel("accommodation (D)")
    ax.set_ylabel("refraction (D)")
    ax.set_title("Navarro eye: refraction")
    ax = fig.add_subplot(grid[0, 1])
    ax.plot(accommodations, spot, "o-", color="C1")
    ax.set_xlabel("accommodation (D)")
    ax.set_ylabel("RMS spot radius on axis (µm)")
    ax.set_title("Navarro eye, 4 mm pupil: spot size")
    for i, (acc, image) in enumerate(renders.items()):
        ax = fig.add_subplot(grid[1, i])
        ax.imshow(to_display(image))
        ax.set_title(f"accommodation {acc:g} D")
        ax.axis("off")
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    fig.savefig(a.out, dpi=a.dpi)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
