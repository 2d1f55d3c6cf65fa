#!/usr/bin/env python3
"""roulette_equal_error.py: Russian roulette from the second scattering vertex (pbrt-v4) against the
fifth (eyetrace's default, Mitsuba 3's rr_depth) and none, in time to equal error.

    /usr/bin/python3 bench/roulette_equal_error.py [--work out/roulette] [--seeds 1,2]

For each scene it renders one reference without roulette (an unbiased estimate of the same image,
with its own seed), then each variant at the scene's ladder spp with each seed, and prints the CPU
seconds (user + sys of the child), relMSE = mean((image - reference)^2) / mean(reference)^2 on
luminance, and their product: the work to reach a given error is proportional to it, so the ratio
of two products is the speed-up at equal error. The reference's own variance adds the same small
amount to every variant (its spp is 16-32 times the ladder's), which makes the ratios slightly
conservative.
"""
import argparse
import os
import re
import resource
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NAVARRO = ('Camera "navarro" "float accommodation" 1 "float pupildiameter" 4 "float fov" 30 '
           '"float wavelength" 550')
# name: (scene, extra render options, spp, reference spp)
SCENES = {
    'peer': ('scenes/peer.pbrt', ['--camera', NAVARRO, '--resolution', '128x128'], 128, 2048),
    'cornell-box': ('scenes/cornell-box.pbrt', ['--resolution', '128x128'], 64, 2048),
    'small-light': ('scenes/small-light.pbrt', ['--resolution', '150x100'], 64, 1024),
}
VARIANTS = (('rrdepth 2 (pbrt-v4)', '"integer rrdepth" 2'), ('rrdepth 5 (default)', '"integer rrdepth" 5'),
            ('no roulette', '"float rrthreshold" 0'))


def with_integrator_params(scene, params, work, tag):
    """The scene with params appended to its Integrator statement (texture paths made absolute)."""
    text = open(os.path.join(ROOT, scene)).read()
    text, n = re.subn(r'(Integrator "(?:vol)?path"[^\n]*)', lambda m: m.group(1) + ' ' + params, text, count=1)
    if n != 1:
        sys.exit('%s: no path Integrator statement' % scene)
    base = os.path.dirname(os.path.join(ROOT, scene))
    text = re.sub(r'"string filename" "([^"/][^"]*\.(?:png|exr|ply))"',
                  lambda m: '"string filename" "%s"' % os.path.join(base, m.group(1)), text)
    path = os.path.join(work, tag + '.pbrt')
    open(path, 'w').write(text)
    return path


def render(args, scene_file, extra, spp, seed, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([args.eyetrace, 'render', scene_file, '--spp', str(spp), '--seed', str(seed), '--threads', '2',
                    '--quiet', '-o', out] + extra, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime


def luminance(exr):
    pixels = oiio.ImageBuf(exr).get_pixels(oiio.FLOAT)
    if not np.all(np.isfinite(pixels)):
        sys.exit('%s: non-finite pixels' % exr)
    return pixels[:, :, :3] @ np.array([0.2126, 0.7152, 0.0722])


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--eyetrace', default=os.path.join(ROOT, 'build/bin/eyetrace'))
    p.add_argument('--work', default=os.path.join(ROOT, 'out/roulette'))
    p.add_argument('--scenes', default=','.join(SCENES))
    p.add_argument('--seeds', default='1,2')
    args = p.parse_args()
    os.makedirs(args.work, exist_ok=True)
    seeds = [int(s) for s in args.seeds.split(',')]
    print('| scene | roulette | spp | CPU s | relMSE | CPU x relMSE | speed-up against rrdepth 2 |')
    print('|---|---|---:|---:|---:|---:|---:|')
    for name in args.scenes.split(','):
        scene, extra, spp, ref_spp = SCENES[name]
        ref = os.path.join(args.work, name + '-reference.exr')
        render(args, with_integrator_params(scene, VARIANTS[-1][1], args.work, name + '-ref'), extra, ref_spp, 99, ref)
        reference = luminance(ref)
        mean = reference.mean()
        first = None
        for label, params in VARIANTS:
            src = with_integrator_params(scene, params, args.work, name + '-' + label.split()[0])
            cpu, err = [], []
            for seed in seeds:
                out = os.path.join(args.work, '%s-%d.exr' % (name, seed))
                cpu.append(render(args, src, extra, spp, seed, out))
                err.append(float(np.mean((luminance(out) - reference) ** 2) / mean ** 2))
            work = np.mean(cpu) * np.mean(err)
            first = first or work
            print('| %s | %s | %d | %.2f | %.4g | %.4g | %.2fx |' % (name, label, spp, np.mean(cpu), np.mean(err), work,
                                                                   first / work), flush=True)


if __name__ == '__main__':
    main()
