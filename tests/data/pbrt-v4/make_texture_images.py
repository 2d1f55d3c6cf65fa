# The texture of the imagemap reference scene (tests/data/pbrt-v4/PROVENANCE).
import numpy as np, OpenImageIO as oiio
# imagemap.png: 24 x 12 (neither side a power of two, so pbrt-v4 resizes it up to 32 x 16 before
# building its MIP map), 8-bit sRGB RGB; blocks of 6 x 4 texels in saturated colours with hard
# edges between them (where decoding before or after interpolating differs), and a grey ramp
# along the bottom row.
w, h = 24, 12
colours = [(230, 20, 20), (20, 200, 40), (30, 40, 240), (250, 250, 250), (10, 10, 10), (240, 200, 30)]
p = np.zeros((h, w, 3), np.uint8)
for y in range(h):
    for x in range(w):
        p[y, x] = colours[((x // 6) + 2 * (y // 4)) % len(colours)]
for x in range(w):
    p[h - 1, x] = int(255 * x / (w - 1))
out = oiio.ImageOutput.create("imagemap.png")
out.open("imagemap.png", oiio.ImageSpec(w, h, 3, oiio.UINT8)); out.write_image(p); out.close()
