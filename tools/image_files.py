"""Reading and writing the images of tools/figures and tools/convergence with OpenImageIO.

Writes go to a temporary file in the same folder and are renamed into place, so an
interrupted tool never leaves a half-written image under the final name.
"""
import os

import numpy as np
import OpenImageIO as oiio


def read_rgb(path, tool):
    """The first three channels of an image as float64 (H, W, 3); exits naming `tool` if unreadable."""
    inp = oiio.ImageInput.open(path)
    if inp is None:
        raise SystemExit(f"{tool}: cannot read {path}: {oiio.geterror()}")
    px = inp.read_image(oiio.FLOAT)
    inp.close()
    return np.asarray(px, dtype=np.float64)[:, :, :3]


def read_channels(path, tool):
    """Every channel of an image by name, as float64 (H, W) arrays; exits naming `tool` if unreadable."""
    inp = oiio.ImageInput.open(path)
    if inp is None:
        raise SystemExit(f"{tool}: cannot read {path}: {oiio.geterror()}")
    names = list(inp.spec().channelnames)
    px = np.asarray(inp.read_image(oiio.FLOAT), dtype=np.float64)
    inp.close()
    return {n: px[:, :, i] for i, n in enumerate(names)}


def _write(data, path, pixel_type, suffix):
    tmp = path + ".tmp" + suffix
    out = oiio.ImageOutput.create(tmp)
    out.open(tmp, oiio.ImageSpec(data.shape[1], data.shape[0], 3, pixel_type))
    out.write_image(data)
    out.close()
    os.replace(tmp, path)


def write_exr(rgb, path):
    """Linear float RGB."""
    _write(np.ascontiguousarray(rgb, dtype=np.float32), path, oiio.FLOAT, ".exr")


def write_png(rgb, path, scale=1.0):
    """8-bit sRGB of linear `rgb` times `scale`."""
    v = np.clip(rgb * scale, 0.0, None)
    srgb = np.where(v <= 0.0031308, 12.92 * v, 1.055 * np.power(v, 1 / 2.4) - 0.055)
    _write((np.clip(srgb, 0, 1) * 255 + 0.5).astype(np.uint8), path, oiio.UINT8, ".png")
