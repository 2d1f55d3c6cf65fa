#!/usr/bin/python3
# Independent evaluation of pbrt-v4's CloudMedium::Density (src/pbrt/media.h) with its Perlin
# Noise and DNoise (src/pbrt/util/noise.cpp), written from those formulas in double precision
# (pbrt-v4 and eyetrace use float: agreement to ~1e-4 is expected). Prints the density at fixed
# points of the medium's space for (density, wispiness, frequency) settings; the numbers are
# pasted into tests/media/cloud_medium_test.cpp.
import math

PERM = [151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69, 142,
        8, 99, 37, 240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219, 203, 117,
        35, 11, 32, 57, 177, 33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175, 74, 165, 71,
        134, 139, 48, 27, 166, 77, 146, 158, 231, 83, 111, 229, 122, 60, 211, 133, 230, 220, 105, 92, 41,
        55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1, 216, 80, 73, 209, 76, 132, 187, 208, 89, 18,
        169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198, 173, 186, 3, 64, 52, 217, 226, 250,
        124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206, 59, 227, 47, 16, 58, 17, 182, 189,
        28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163, 70, 221, 153, 101, 155, 167, 43, 172, 9,
        129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232, 178, 185, 112, 104, 218, 246, 97, 228, 251,
        34, 242, 193, 238, 210, 144, 12, 191, 179, 162, 241, 81, 51, 145, 235, 249, 14, 239, 107, 49, 192,
        214, 31, 181, 199, 106, 157, 184, 84, 204, 176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205,
        93, 222, 114, 67, 29, 24, 72, 243, 141, 128, 195, 78, 66, 215, 61, 156, 180]
assert sorted(PERM) == list(range(256))
P = PERM + PERM  # pbrt-v4's doubled table of 512


def grad(x, y, z, dx, dy, dz):
    h = P[P[P[x] + y] + z] & 15
    u = dx if (h < 8 or h == 12 or h == 13) else dy
    v = dy if (h < 4 or h == 12 or h == 13) else dz
    return (-u if h & 1 else u) + (-v if h & 2 else v)


def weight(t):
    return 6 * t**5 - 15 * t**4 + 10 * t**3


def lerp(t, a, b):
    return (1 - t) * a + t * b


def noise(x, y, z):
    ix, iy, iz = math.floor(x), math.floor(y), math.floor(z)
    dx, dy, dz = x - ix, y - iy, z - iz
    ix, iy, iz = ix & 255, iy & 255, iz & 255
    w = {}
    for a in (0, 1):
        for b in (0, 1):
            for c in (0, 1):
                w[a, b, c] = grad(ix + a, iy + b, iz + c, dx - a, dy - b, dz - c)
    wx, wy, wz = weight(dx), weight(dy), weight(dz)
    x00, x10 = lerp(wx, w[0, 0, 0], w[1, 0, 0]), lerp(wx, w[0, 1, 0], w[1, 1, 0])
    x01, x11 = lerp(wx, w[0, 0, 1], w[1, 0, 1]), lerp(wx, w[0, 1, 1], w[1, 1, 1])
    return lerp(wz, lerp(wy, x00, x10), lerp(wy, x01, x11))


def dnoise(p):
    d = 0.01
    n = noise(*p)
    return [(noise(p[0] + d, p[1], p[2]) - n) / d, (noise(p[0], p[1] + d, p[2]) - n) / d,
            (noise(p[0], p[1], p[2] + d) - n) / d]


def density(p, dens, wisp, freq):
    pp = [freq * c for c in p]
    if wisp > 0:
        vo, vl = 0.05 * wisp, 10.0
        for _ in range(2):
            g = dnoise([vl * c for c in pp])
            pp = [a + vo * b for a, b in zip(pp, g)]
            vo *= 0.5
            vl *= 1.99
    d, o, l = 0.0, 0.5, 1.0
    for _ in range(5):
        d += o * noise(*[l * c for c in pp])
        o *= 0.5
        l *= 1.99
    d = min(max((1 - p[1]) * 4.5 * dens * d, 0.0), 1.0)
    d += 2 * max(0.0, 0.5 - p[1])
    return min(max(d, 0.0), 1.0)


POINTS = [(0.13, 0.62, 0.41), (0.77, 0.55, 0.29), (0.5, 0.9, 0.5), (0.31, 0.71, 0.88), (0.92, 0.58, 0.07),
          (0.45, 0.66, 0.6), (0.2, 0.8, 0.3), (0.66, 0.53, 0.74)]
SETTINGS = [(1.0, 1.0, 5.0), (2.0, 0.0, 3.0), (1.5, 2.0, 7.0)]
for s in SETTINGS:
    print("{%g, %g, %g}:" % s, ", ".join("%.6f" % density(p, *s) for p in POINTS))
