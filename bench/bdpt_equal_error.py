#!/usr/bin/python3
# bdpt against path at equal error (docs/performance.md, "bdpt"). Scenes without specular
# surfaces, where the two converge to the same image: the Cornell box of scenes/ with its glass
# sphere made diffuse (lit by its area light, plus a point light), and the test scene
# tests/data/pbrt-v4/bdpt.pbrt (a closed box lit by a small area light under the ceiling, so
# that most light arrives after two or more bounces). Each integrator renders N spp; both are
# scored against one converged path render of another seed:
#   relMSE = mean over pixels and channels of (x - ref)^2 / (ref^2 + 1e-2)
# The cost at equal error is CPU time x relMSE (relMSE falls as 1 / time for an unbiased
# estimator), so the ratio bdpt / path of that product is how much longer bdpt takes for the
# same error. CPU time is the eyetrace processes' user + system time.
# Usage: bench/bdpt_equal_error.py [SPP] [REF_SPP]  (defaults 64, 4096). Writes into the current
# directory. About 5 minutes on 2 cores.
import os, resource, subprocess, sys
import numpy as np, OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
B = os.path.join(ROOT, "build/bin/eyetrace")
SPP = int(sys.argv[1]) if len(sys.argv) > 1 else 64
REF_SPP = int(sys.argv[2]) if len(sys.argv) > 2 else 4096


def cpu_seconds():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def scene_text(name, integrator):
    if name == "cornell":
        s = open(os.path.join(ROOT, "scenes/cornell-box.pbrt")).read()
        s = s.replace('Integrator "path" "integer maxdepth" 8', 'Integrator "%s" "integer maxdepth" 5' % integrator)
        s = s.replace('PixelFilter "gaussian"', 'PixelFilter "box"')
        s = s.replace('Material "dielectric" "float eta" 1.5', 'Material "diffuse" "rgb reflectance" [0.5 0.6 0.7]')
        return s.replace("WorldBegin\n", 'WorldBegin\nLightSource "point" "point3 from" [0.3 0.8 0.4] "rgb I" [0.5 0.5 0.5]\n')
    s = open(os.path.join(ROOT, "tests/data/pbrt-v4/bdpt.pbrt")).read()
    return s.replace('Integrator "bdpt"', 'Integrator "%s"' % integrator)


def render(name, integrator, spp, seed):
    scene = "%s-%s.pbrt" % (name, integrator)
    open(scene, "w").write(scene_text(name, integrator))
    out = "%s-%s-%d-%d.exr" % (name, integrator, spp, seed)
    before = cpu_seconds()
    subprocess.run([B, "render", scene, "-o", out, "--resolution", "64x64", "--spp", str(spp), "--seed", str(seed),
                    "--threads", "2", "--quiet"], check=True)
    return out, cpu_seconds() - before


def read(p):
    return oiio.ImageBuf(p).get_pixels(oiio.FLOAT)[:, :, :3].astype(np.float64)


for name in ["cornell", "box"]:
    ref = read(render(name, "path", REF_SPP, 99)[0])
    row = {}
    for integrator in ["path", "bdpt"]:
        out, t = render(name, integrator, SPP, 1)
        x = read(out)
        rel_mse = float(np.mean((x - ref) ** 2 / (ref ** 2 + 1e-2)))
        bias = float(x.mean() / ref.mean() - 1)
        row[integrator] = (t, rel_mse)
        print("%-8s %-5s %4d spp: cpu %.2f s, relMSE %.3e, mean/ref - 1 %+.4f" % (name, integrator, SPP, t, rel_mse, bias))
    (tp, ep), (tb, eb) = row["path"], row["bdpt"]
    print("%-8s time ratio bdpt/path %.2f, relMSE ratio %.3f, equal-error cost ratio %.2f" % (name, tb / tp, eb / ep,
                                                                                              tb * eb / (tp * ep)))
