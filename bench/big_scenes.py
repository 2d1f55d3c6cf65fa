#!/usr/bin/python3
# Loading big scenes, eyetrace against pbrt-v4 (issue 18, item 5; docs/performance.md, "Big
# scenes"). Generates, in the work directory:
#   mesh10m  one binary PLY height field of 9,999,392 triangles (190 MB)
#   inst     10,000 instances (random translation, rotation, scale 1/2) of a 100,352-triangle PLY
#   text4    four Imported text files, each a trianglemesh of 999,698 triangles (35 MB each)
#   empty    the same header with no shape: each process's fixed cost (dynamic loading, set-up)
# and renders each at 16x16 pixels, 1 sample per pixel, 2 threads, so that the time is the
# loading (parse, mesh build, BVH). Runs alternate between the two programs, N rounds; reported
# per program: median wall seconds, median CPU seconds (user + system of the child) and the
# median peak resident set (GNU time's %M), and the ratio
# eyetrace / pbrt-v4 of each.
# Usage: bench/big_scenes.py --pbrt PBRT-V4 [--rounds N] [--work DIR] [--scenes a,b]
import argparse, os, statistics, subprocess, sys
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HEADER = """LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" 40
Film "rgb" "integer xresolution" 16 "integer yresolution" 16 "string filename" "out.exr"
Sampler "independent" "integer pixelsamples" 1
Integrator "path" "integer maxdepth" 1
WorldBegin
LightSource "distant" "point3 from" [0 0 5] "point3 to" [0 0 0] "rgb L" [1 1 1]
Material "diffuse"
"""


def grid(n):
    """An n x n vertex height field over [-1, 1]^2: vertices (float32) and triangles (int32)."""
    x, y = np.meshgrid(np.linspace(-1, 1, n, dtype=np.float32), np.linspace(-1, 1, n, dtype=np.float32))
    z = (0.05 * np.sin(20 * x) * np.cos(17 * y)).astype(np.float32)
    v = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    i = np.arange(n * n, dtype=np.int32).reshape(n, n)
    a, b, c, d = i[:-1, :-1].ravel(), i[:-1, 1:].ravel(), i[1:, 1:].ravel(), i[1:, :-1].ravel()
    return v, np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])


def write_ply(path, n):
    v, tris = grid(n)
    faces = np.empty(len(tris), dtype=[("n", "u1"), ("i", "<i4", 3)])
    faces["n"], faces["i"] = 3, tris
    with open(path, "wb") as out:
        out.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                   "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                   % (len(v), len(tris))).encode())
        out.write(v.astype("<f4").tobytes())
        out.write(faces.tobytes())


def write_text_mesh(path, n, dx):
    v, tris = grid(n)
    with open(path, "w") as f:
        f.write('AttributeBegin\nTranslate %g 0 -3\nShape "trianglemesh" "point3 P" [' % dx)
        f.write(" ".join("%.6f" % c for c in v.ravel()))
        f.write(']\n "integer indices" [' + " ".join(map(str, tris.ravel())) + "]\nAttributeEnd\n")


def make_scenes(work, names):
    os.makedirs(work, exist_ok=True)
    p = lambda f: os.path.join(work, f)
    if "mesh10m" in names and not os.path.exists(p("mesh10m.pbrt")):
        write_ply(p("mesh10m.ply"), 2237)
        open(p("mesh10m.pbrt"), "w").write(HEADER + 'Shape "plymesh" "string filename" "mesh10m.ply"\n')
    if "inst" in names and not os.path.exists(p("inst.pbrt")):
        write_ply(p("mesh100k.ply"), 225)
        rng = np.random.default_rng(1)
        with open(p("inst.pbrt"), "w") as f:
            f.write(HEADER + 'ObjectBegin "m"\nShape "plymesh" "string filename" "mesh100k.ply"\nObjectEnd\n')
            for _ in range(10000):
                x, y, z = rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-60, -5)
                f.write('AttributeBegin\nTranslate %.4f %.4f %.4f\nRotate %.2f 0 0 1\nScale 0.5 0.5 0.5\n'
                        'ObjectInstance "m"\nAttributeEnd\n' % (x, y, z, rng.uniform(0, 360)))
    if "text4" in names and not os.path.exists(p("text4.pbrt")):
        for k in range(4):
            write_text_mesh(p("part%d.pbrt" % k), 708, 2 * k - 3)
        open(p("text4.pbrt"), "w").write(HEADER + "".join('Import "part%d.pbrt"\n' % k for k in range(4)))
    if "empty" in names:
        open(p("empty.pbrt"), "w").write(HEADER)


def run(cmd, cwd):
    """Wall seconds, CPU seconds and peak RSS (MB) of one child process, measured by GNU time
    (a child forked from this Python process would report this process's resident set, which
    exec carries into the child's high-water mark)."""
    out = os.path.join(cwd, "time.txt")
    proc = subprocess.run(["/usr/bin/time", "-f", "%e %U %S %M", "-o", out] + cmd, cwd=cwd,
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if proc.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (proc.returncode, " ".join(cmd), proc.stderr.decode(errors="replace")))
    wall, user, system, rss_kb = open(out).read().split()[-4:]
    return float(wall), float(user) + float(system), float(rss_kb) / 1024.0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pbrt", required=True, help="pbrt-v4 binary")
    ap.add_argument("--eyetrace", default=os.path.join(ROOT, "build/bin/eyetrace"))
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--work", default="out/big-scenes")
    ap.add_argument("--scenes", default="empty,inst,text4,mesh10m")
    a = ap.parse_args()
    names = a.scenes.split(",")
    make_scenes(a.work, names)
    programs = {
        "eyetrace": lambda s: [os.path.abspath(a.eyetrace), "render", s + ".pbrt", "-q", "--threads", "2", "-o", s + "-e.exr"],
        "pbrt-v4": lambda s: [os.path.abspath(a.pbrt), "--nthreads", "2", "--quiet", "--outfile", s + "-p.exr", s + ".pbrt"],
    }
    print("| scene | program | wall s | CPU s | peak RSS MB |")
    print("|---|---|---:|---:|---:|")
    for s in names:
        res = {k: [] for k in programs}
        for _ in range(a.rounds):
            for k, cmd in programs.items():
                res[k].append(run(cmd(s), a.work))
        med = {k: [statistics.median(r[i] for r in v) for i in range(3)] for k, v in res.items()}
        for k in programs:
            print("| %s | %s | %.2f | %.2f | %.0f |" % (s, k, *med[k]))
        e, p = med["eyetrace"], med["pbrt-v4"]
        ratio = lambda x, y: "%.2f" % (x / y) if y > 0 else "-"
        print("| %s | **eyetrace / pbrt-v4** | %s | %s | %s |" % (s, ratio(e[0], p[0]), ratio(e[1], p[1]), ratio(e[2], p[2])))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
