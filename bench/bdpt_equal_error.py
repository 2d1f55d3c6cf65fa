#!/usr/bin/python3
# bdpt (with its t = 1 strategies, and without: "bdpt-t2", Integrator "bdpt" "bool lighttracing"
# false) against path at equal error (docs/performance.md, "bdpt"). Scenes without specular
# surfaces, where all converge to the same image: the Cornell box of scenes/ with its glass
# sphere made diffuse (lit by its area light, plus a point light), and the test scene
# tests/data/pbrt-v4/bdpt.pbrt (a closed box lit by a small area light under the ceiling, so
# that most light arrives after two or more bounces); and the caustic
# tests/data/pbrt-v4/bdpt-caustic.pbrt (a point light's caustic through a glass sphere on a
# diffuse floor, seen directly), which only bdpt with t = 1 renders: there path and bdpt-t2
# converge to a darker image, so their relMSE keeps their bias. Each integrator renders N spp;
# all are scored against one converged render of another seed (path; bdpt for the caustic):
#   relMSE = mean over pixels and channels of (x - ref)^2 / (ref^2 + 1e-2)
# The cost at equal error is CPU time x relMSE (relMSE falls as 1 / time for an unbiased
# estimator), so the ratio bdpt / path of that product is how much longer bdpt takes for the
# same error. CPU time is the eyetrace processes' user + system time.
# Usage: bench/bdpt_equal_error.py [SPP] [REF_SPP]  (defaults 64, 4096). Writes into the current
# directory. About 8 minutes on 2 cores.
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
    lt = ""
    if integrator == "bdpt-t2":
        integrator, lt = "bdpt", ' "bool lighttracing" false'
    if name == "caustic":
        s = open(os.path.join(ROOT, "tests/data/pbrt-v4/bdpt-caustic.pbrt")).read()
        return s.replace('Integrator "bdpt" "integer maxdepth" 5', 'Integrator "%s" "integer maxdepth" 5%s' % (integrator, lt))
    if name == "cornell":
        s = open(os.path.join(ROOT, "scenes/cornell-box.pbrt")).read()
        s = s.replace('Integrator "path" "integer maxdepth" 8', 'Integrator "%s" "integer maxdepth" 5%s' % (integrator, lt))
        s = s.replace('PixelFilter "gaussian"', 'PixelFilter "box"')
        s = s.replace('Material "dielectric" "float eta" 1.5', 'Material "diffuse" "rgb reflectance" [0.5 0.6 0.7]')
        return s.replace("WorldBegin\n", 'WorldBegin\nLightSource "point" "point3 from" [0.3 0.8 0.4] "rgb I" [0.5 0.5 0.5]\n')
    s = open(os.path.join(ROOT, "tests/data/pbrt-v4/bdpt.pbrt")).read()
    return s.replace('Integrator "bdpt"', 'Integrator "%s"%s' % (integrator, lt))


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


for name in ["cornell", "box", "caustic"]:
    ref = read(render(name, "bdpt" if name == "caustic" else "path", REF_SPP, 99)[0])
    row = {}
    for integrator in ["path", "bdpt-t2", "bdpt"]:
        out, t = render(name, integrator, SPP, 1)
        x = read(out)
        rel_mse = float(np.mean((x - ref) ** 2 / (ref ** 2 + 1e-2)))
        bias = float(x.mean() / ref.mean() - 1)
        row[integrator] = (t, rel_mse)
        print("%-8s %-7s %4d spp: cpu %.2f s, relMSE %.3e, mean/ref - 1 %+.4f" % (name, integrator, SPP, t, rel_mse, bias))
    for other in ["path", "bdpt-t2"]:
        (tp, ep), (tb, eb) = row[other], row["bdpt"]
        print("%-8s time ratio bdpt/%s %.2f, relMSE ratio %.3f, equal-error cost ratio %.2f" % (
            name, other, tb / tp, eb / ep, tb * eb / (tp * ep)))
