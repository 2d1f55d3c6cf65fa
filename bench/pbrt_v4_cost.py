#!/usr/bin/python3
# What each pbrt-v4 feature costs in eyetrace against pbrt-v4 itself (issue 18, "Speed": each new
# material, texture and shape at equal spp at most 1.2x pbrt-v4's CPU build on its test scene;
# docs/performance.md, "What issue 18's pbrt-v4 features cost").
#
# Renders every feature scene of tests/data/pbrt-v4/ (the scenes of the reference test, unmodified)
# with both programs at the same samples per pixel and thread count, alternating the two programs
# for N rounds, and reports per scene the median whole-process CPU time (user + system, GNU time)
# of each and their ratio eyetrace / pbrt-v4. Whole processes: each program's start-up counts.
# Scenes that need a generated file (nanovdb.pbrt's grid, written by the reference test) are
# skipped and listed. motion.pbrt runs pbrt-v4 with --render-coord-sys world, as its reference.
#
# Usage: bench/pbrt_v4_cost.py --pbrt PBRT-V4 [--eyetrace build/bin/eyetrace] [--spp 256]
#                              [--threads 1] [--rounds 3] [--scenes a,b] [--work DIR]
import argparse
import glob
import os
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "tests", "data", "pbrt-v4")
NEEDS_GENERATED_FILE = {"nanovdb"}
PBRT_EXTRA = {"motion": ["--render-coord-sys", "world"]}


def cpu_seconds(cmd, work):
    """CPU seconds (user + system) of one child, measured by GNU time; None if it failed."""
    out = os.path.join(work, "time.txt")
    proc = subprocess.run(["/usr/bin/time", "-f", "%U %S", "-o", out] + cmd, cwd=DATA,
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if proc.returncode != 0:
        sys.stderr.write("failed (%d): %s\n%s\n" % (proc.returncode, " ".join(cmd),
                                                    proc.stderr.decode(errors="replace")[-2000:]))
        return None
    user, system = open(out).read().split()[-2:]
    return float(user) + float(system)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--pbrt", required=True, help="pbrt-v4 binary")
    ap.add_argument("--eyetrace", default=os.path.join(ROOT, "build", "bin", "eyetrace"))
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--scenes", default="", help="comma-separated names (default: all)")
    ap.add_argument("--work", default="/tmp/pbrt-v4-cost")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    names = sorted(os.path.splitext(os.path.basename(p))[0] for p in glob.glob(os.path.join(DATA, "*.pbrt")))
    if a.scenes:
        names = [n for n in names if n in a.scenes.split(",")]
    eyetrace, pbrt = os.path.abspath(a.eyetrace), os.path.abspath(a.pbrt)
    print("spp %d, %d thread(s), %d rounds, medians of CPU seconds (user + system)" % (a.spp, a.threads, a.rounds))
    print("| scene | eyetrace CPU s | pbrt-v4 CPU s | eyetrace / pbrt-v4 |")
    print("|---|---:|---:|---:|")
    ratios, skipped = [], []
    for name in names:
        if name in NEEDS_GENERATED_FILE:
            skipped.append(name)
            continue
        scene = name + ".pbrt"
        cmds = {
            "eyetrace": [eyetrace, "render", scene, "-q", "--threads", str(a.threads), "--spp", str(a.spp), "-o",
                         os.path.join(a.work, name + "-e.exr")],
            "pbrt-v4": [pbrt, "--quiet", "--nthreads", str(a.threads), "--spp", str(a.spp), "--outfile",
                        os.path.join(a.work, name + "-p.exr")] + PBRT_EXTRA.get(name, []) + [scene],
        }
        times = {k: [] for k in cmds}
        for _ in range(a.rounds):
            for k, cmd in cmds.items():
                times[k].append(cpu_seconds(cmd, a.work))
        if any(t is None for v in times.values() for t in v):
            print("| %s | failed | | |" % name)
            continue
        e, p = statistics.median(times["eyetrace"]), statistics.median(times["pbrt-v4"])
        ratios.append(e / p)
        print("| `%s` | %.2f | %.2f | %.2f |" % (name, e, p, e / p))
        sys.stdout.flush()
    if ratios:
        print("\n%d scenes: ratio median %.2f, max %.2f; above 1.2: %d" %
              (len(ratios), statistics.median(ratios), max(ratios), sum(r > 1.2 for r in ratios)))
    if skipped:
        print("skipped (need a generated file): " + ", ".join(skipped))


if __name__ == "__main__":
    main()
