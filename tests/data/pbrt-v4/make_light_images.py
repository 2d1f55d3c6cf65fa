# Light images for the goniometric and projection reference scenes (tests/data/pbrt-v4/PROVENANCE).
import numpy as np, OpenImageIO as oiio
# goniometric.exr: 32 x 32 equal-area, float RGB; pixel (x, y): a ramp across x, a checker of
# 8-pixel squares, and unequal channels (the light takes their average).
n = 32
g = np.zeros((n, n, 3), np.float32)
for y in range(n):
    for x in range(n):
        base = 0.2 + 1.6 * x / (n - 1) + 0.8 * (((x // 8) + (y // 8)) % 2)
        g[y, x] = (base * 1.2, base * 0.9, base * 0.6 + 0.3 * y / (n - 1))
out = oiio.ImageOutput.create("goniometric.exr")
spec = oiio.ImageSpec(n, n, 3, oiio.FLOAT)
spec.attribute("compression", "zip")
out.open("goniometric.exr", spec); out.write_image(g); out.close()
# projection.png: 48 x 32 (wider than tall), 8-bit sRGB; red ramps across, green down, blue a
# checker of 8-pixel squares.
w, h = 48, 32
p = np.zeros((h, w, 3), np.uint8)
for y in range(h):
    for x in range(w):
        p[y, x] = (int(40 + 215 * x / (w - 1)), int(255 - 200 * y / (h - 1)), 230 if ((x // 8) + (y // 8)) % 2 else 30)
out = oiio.ImageOutput.create("projection.png")
out.open("projection.png", oiio.ImageSpec(w, h, 3, oiio.UINT8)); out.write_image(p); out.close()
