#!/usr/bin/python3
"""peer_equal_error.py: eyetrace against ISET3d's realisticEye camera (pbrt-v3-spectral) at equal
error, through the same Navarro eye (issue 19, item 4; docs/performance.md, "Against ISET3d's
realisticEye").

    /usr/bin/python3 bench/peer_equal_error.py --pbrt /work/oracles/pbrt-v3-spectral/build/pbrt \
        [--scenes peer,peripheral] [--modes mono,spec] [--work out/peer] [--csv out/peer/peer_equal_error.csv]
    /usr/bin/python3 bench/peer_equal_error.py --analyse --csv docs/data/peer-equal-error-2026-11-26.csv

For each scene (scenes/peer.pbrt, scenes/peripheral.pbrt) and each mode (monochromatic at 550 nm,
spectral) it renders with both programs at a ladder of samples per pixel and once at a reference
count, and scores every ladder image against that program's own reference:

    relMSE = mean over the scored pixels of (image - reference)^2 / (mean of the reference)^2

on the luminance Y of the linear RGB EXR (Rec. 709 weights). Dividing by the reference's mean is the
issue's brightness normalisation (realisticEye has no radiometric ray weight, so its images are
several times darker). The scored pixels are those inside realisticEye's round field (its retina
disc inscribed in the square image), shrunk by one pixel so that no pixel straddles its edge.

The time to relMSE 1e-3 and 7.5e-3 is interpolated on each side, log-log between the two ladder
rungs around it (extrapolated along the last two when outside), for CPU time (user + sys of the
child, from wait4) and for wall time. CPU time is the fairer measure on a shared machine.

The scenes for pbrt-v3 are translated from ours (Film, Sampler, Integrator and Camera written here;
shapes, materials, textures and lights translated one for one). realisticEye's eye comes from
tools/oracles/realisticeye_navarro.py, fed with `eyetrace optics --json` of the same camera.
Its modes: monochromatic = its "path" (or "directlighting") integrator, whose camera rays carry
550 nm through the eye and the full 31-sample spectrum through the scene; spectral = its
"spectralpath" integrator with numCABands 4: each camera sample traces one path per band, each
band's ray refracted at the band's centre wavelength. eyetrace's: `"float wavelength" 550`, and its
default dispersive eye (four hero wavelengths per path, spectral MIS).

The references share their first samples with the ladder images on both sides (deterministic Halton
on both; pbrt-v3 has no seed option), so what is measured is v(n) - v(N) rather than v(n); `corrected`
adds v(N) back from a power-law fit to the ladder. For eyetrace, which draws independent images
(--seed), every rung also records the two-seed estimate mean((a - b)^2) / 2 / mean^2 as a check.

Both use Halton, as the issue's own comparison did; --eyetrace-sampler and --pbrt-sampler choose
others (eyetrace's default zsobol, pbrt-v3's sobol...) for a comparison of each program at its best.

Rows are appended to --csv as they are measured (one invocation per scene and mode keeps each run
short); --analyse prints the corrected ladders and the table of times and ratios from that file.
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import time

import numpy as np
import OpenImageIO as oiio

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TARGETS = (7.5e-3, 1e-3)

EYE = {'accommodation': 1, 'pupil_mm': 4, 'fov_deg': 30}
SCENES = {
    # name: (our scene file, pbrt-v3 integrator lines for (monochromatic, spectral))
    'peer': ('scenes/peer.pbrt',
             'Integrator "path" "integer maxdepth" 5',
             'Integrator "spectralpath" "integer maxdepth" 5 "integer numCABands" 4'),
    # The figure scene is direct lighting only: realisticEye's spectral integrator is a path
    # tracer, stopped after the first bounce by maxdepth 1 (it still traces the bounce ray).
    'peripheral': ('scenes/peripheral.pbrt',
                   'Integrator "directlighting" "integer maxdepth" 1',
                   'Integrator "spectralpath" "integer maxdepth" 1 "integer numCABands" 4'),
}


def eyetrace_camera(monochromatic):
    cam = ('Camera "navarro" "float accommodation" %g "float pupildiameter" %g "float fov" %g'
           % (EYE['accommodation'], EYE['pupil_mm'], EYE['fov_deg']))
    return cam + (' "float wavelength" 550' if monochromatic else '')


def run_timed(cmd, log):
    """Runs cmd; returns (cpu seconds of the child: user + sys, wall seconds)."""
    start = time.monotonic()
    with open(log, 'w') as out:
        proc = subprocess.Popen(cmd, stdout=out, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit('failed (%s): %s' % (log, ' '.join(cmd)))
    return usage.ru_utime + usage.ru_stime, wall


def scene_body(path):
    """The world part of one of our scenes, with texture paths made absolute."""
    text = open(os.path.join(ROOT, path)).read()
    body = text[text.index('WorldBegin') + len('WorldBegin'):]
    base = os.path.dirname(os.path.join(ROOT, path))
    return re.sub(r'"string filename" "([^"/][^"]*)"',
                  lambda m: '"string filename" "%s"' % os.path.join(base, m.group(1)), body)


def to_pbrt_v3(body):
    """pbrt-v4 syntax (as our scenes use it) to pbrt-v3's, for the statements these scenes use."""
    body = re.sub(r'#[^\n]*', '', body)
    body = body.replace('"point3 ', '"point ').replace('"point2 uv"', '"float uv"')
    body = body.replace('Material "diffuse" "texture reflectance"', 'Material "matte" "texture Kd"')
    body = body.replace('Material "diffuse" "rgb reflectance"', 'Material "matte" "rgb Kd"')
    # A bilinear patch p00 p10 p01 p11 is the two triangles (0 1 2) (2 1 3).
    body = body.replace('Shape "bilinearmesh"', 'Shape "trianglemesh" "integer indices" [0 1 2 2 1 3]')
    for v4_only in ('bilinearmesh', 'diffuse', 'point3', 'point2'):
        if v4_only in body:
            sys.exit('to_pbrt_v3: untranslated "%s" left in the scene' % v4_only)
    return body + '\nWorldEnd\n'


def realisticeye_camera(eyetrace, work):
    """The realisticEye Camera statement for our eye (lens file and index spectra in work/eye)."""
    report = os.path.join(work, 'optics.json')
    with open(report, 'w') as f:
        subprocess.run([eyetrace, 'optics', '--camera', eyetrace_camera(False), '--json'],
                       stdout=f, check=True)
    eye_dir = os.path.join(work, 'eye')
    subprocess.run([sys.executable, os.path.join(ROOT, 'tools/oracles/realisticeye_navarro.py'),
                    report, eye_dir], check=True)
    optics = json.load(open(report))
    # Its field: the square image circumscribes the retina disc of retinaSemiDiam, whose edge it maps
    # to that lateral height on the retina sphere. Ours is 30 degrees across: the height of the chief
    # ray at 15 degrees on the sphere, through the nodal points (paraxially, as an approximation).
    n2 = optics['nodal_points_mm'][1]
    axial = optics['axial_length_mm']
    radius = abs(optics['retina_radius_mm'])
    centre = axial - radius  # the retina sphere's centre, from the cornea
    half = math.radians(EYE['fov_deg'] / 2)
    b = centre - n2
    t = b * math.cos(half) + math.sqrt(radius ** 2 - (b * math.sin(half)) ** 2)
    semi = t * math.sin(half)
    params = open(os.path.join(eye_dir, 'camera.txt')).read().split('\n')
    return ('Camera "realisticEye" "string specfile" "%s" "bool mmUnits" "false"\n'
            '  "float pupilDiameter" %g "float retinaSemiDiam" %.4f\n  %s\n'
            % (os.path.join(eye_dir, 'navarro.dat'), EYE['pupil_mm'], semi, '\n  '.join(p for p in params if p)))


def render_pbrt(args, work, scene, mono, spp, camera):
    path, mono_integrator, spectral_integrator = SCENES[scene]
    tag = '%s-%s-pbrt-%d' % (scene, 'mono' if mono else 'spec', spp)
    exr = os.path.join(work, tag + '.exr')
    src = os.path.join(work, tag + '.pbrt')
    res = args.resolution
    with open(src, 'w') as f:
        f.write('Film "image" "integer xresolution" %d "integer yresolution" %d "string filename" "%s"\n'
                '  "bool spectralFlag" "false"\n' % (res, res, exr))
        f.write('Sampler "%s" "integer pixelsamples" %d\nPixelFilter "box"\n' % (args.pbrt_sampler, spp))
        f.write((mono_integrator if mono else spectral_integrator) + '\n')
        f.write(camera)
        f.write('WorldBegin\n' + to_pbrt_v3(scene_body(path)))
    cmd = ['nice', '-n', '5', args.pbrt, '--nthreads', str(args.threads), '--quiet', src]
    cpu, wall = run_timed(cmd, os.path.join(work, tag + '.log'))
    return exr, cpu, wall


def render_eyetrace(args, work, scene, mono, spp, seed=0):
    path = SCENES[scene][0]
    tag = '%s-%s-eyetrace-%d-s%d' % (scene, 'mono' if mono else 'spec', spp, seed)
    exr = os.path.join(work, tag + '.exr')
    src = os.path.join(work, tag + '.pbrt')
    with open(src, 'w') as f:  # the scene as it is, with its --eyetrace-sampler and absolute paths
        f.write('Film "rgb" "string filename" "x.exr"\nSampler "%s"\nPixelFilter "box"\n' % args.eyetrace_sampler)
        f.write('Integrator "path" "integer maxdepth" 5\n' if scene == 'peer' else 'Integrator "direct"\n')
        f.write('WorldBegin\n' + scene_body(path))
    cmd = ['nice', '-n', '5', args.eyetrace, 'render', src, '--camera', eyetrace_camera(mono),
           '--spp', str(spp), '--resolution', '%dx%d' % (args.resolution, args.resolution),
           '--threads', str(args.threads), '--seed', str(seed), '--quiet', '-o', exr]
    cpu, wall = run_timed(cmd, os.path.join(work, tag + '.log'))
    return exr, cpu, wall


def luminance(exr):
    image = oiio.ImageBuf(exr)
    pixels = image.get_pixels(oiio.FLOAT)
    if not np.all(np.isfinite(pixels)):
        sys.exit('%s: non-finite pixels' % exr)
    return pixels[:, :, 0] * 0.2126 + pixels[:, :, 1] * 0.7152 + pixels[:, :, 2] * 0.0722


def round_field(res):
    """Pixels whose whole square lies inside realisticEye's retina disc (radius res/2 pixels)."""
    y, x = np.mgrid[0:res, 0:res] + 0.5
    return np.hypot(x - res / 2, y - res / 2) <= res / 2 - math.sqrt(0.5)


def rel_mse(image, reference, mask):
    return float(np.mean((image[mask] - reference[mask]) ** 2) / np.mean(reference[mask]) ** 2)


def corrected(rows, reference_spp):
    """relMSE against the truth from relMSE against a reference that shares the first samples.

    With the first n of the reference's N samples in the image, image - reference and
    reference - truth are uncorrelated (exactly so for independent samples), so the measured value
    is v(n) - v(N): the fit of a n^-p (n^-p - N^-p) to the ladder gives v(N) = a N^-p, added back."""
    n = np.array([r['spp'] for r in rows], float)
    m = np.array([r['relmse'] for r in rows], float)
    best = None
    for p in np.arange(0.5, 2.5, 0.001):
        basis = n ** -p - reference_spp ** -p
        a = np.sum(basis * m / m ** 2) / np.sum(basis ** 2 / m ** 2)  # least squares in relative error
        err = np.sum(((a * basis - m) / m) ** 2)
        if best is None or err < best[0]:
            best = (err, a, p)
    _, a, p = best
    return [m_i + a * reference_spp ** -p for m_i in m], p


def time_to(target, points):
    """Log-log interpolation of time against relMSE at target (extrapolated from the nearest pair)."""
    pts = sorted((math.log(e), math.log(t)) for e, t in points)
    lo = [q for q in pts if q[0] <= math.log(target)]
    hi = [q for q in pts if q[0] > math.log(target)]
    if lo and hi:
        a, b = hi[0], lo[-1]
    elif hi:  # every rung above the target: extrapolate along the two lowest-error rungs
        a, b = pts[1], pts[0]
    else:
        a, b = pts[-1], pts[-2]
    s = (b[1] - a[1]) / (b[0] - a[0])
    return math.exp(a[1] + s * (math.log(target) - a[0]))


FIELDS = ['scene', 'mode', 'renderer', 'spp', 'cpu_s', 'wall_s', 'relmse', 'relmse_two_seeds',
          'reference_spp', 'reference_cpu_s', 'reference_mean']


def measure(args):
    os.makedirs(args.work, exist_ok=True)
    camera = realisticeye_camera(args.eyetrace, args.work)
    mask = round_field(args.resolution)
    ladders = {'pbrt': [int(s) for s in args.ladder.split(',')],
               'eyetrace': [int(s) for s in (args.eyetrace_ladder or args.ladder).split(',')]}
    refs = {'pbrt': args.reference_spp, 'eyetrace': args.eyetrace_reference_spp or args.reference_spp}
    new = not os.path.exists(args.csv)
    with open(args.csv, 'a', newline='') as f:
        if new:
            f.write('# bench/peer_equal_error.py %s; eyetrace %s; pbrt-v3-spectral c4d605a; %dx%d, %d threads\n'
                    % (' '.join(sys.argv[1:]), git_head(), args.resolution, args.resolution, args.threads))
        out = csv.DictWriter(f, fieldnames=FIELDS)
        if new:
            out.writeheader()
        for scene in args.scenes.split(','):
            for mode in args.modes.split(','):
                mono = mode == 'mono'
                for who in args.renderers.split(','):
                    def render(spp, seed=0):
                        if who == 'pbrt':
                            return render_pbrt(args, args.work, scene, mono, spp, camera)
                        return render_eyetrace(args, args.work, scene, mono, spp, seed)
                    ref_exr, ref_cpu, ref_wall = render(refs[who])
                    reference = luminance(ref_exr)
                    ref_mean = float(np.mean(reference[mask]))
                    for spp in ladders[who]:
                        exr, cpu, wall = render(spp)
                        image = luminance(exr)
                        two = ''
                        if who == 'eyetrace':  # eyetrace draws independent images: the variance directly
                            other = luminance(render(spp, seed=1)[0])
                            two = '%.6g' % (np.mean((image[mask] - other[mask]) ** 2) / 2 / np.mean(image[mask]) ** 2)
                        row = dict(scene=scene, mode=mode, renderer=who, spp=spp, cpu_s='%.4g' % cpu,
                                   wall_s='%.4g' % wall, relmse='%.6g' % rel_mse(image, reference, mask),
                                   relmse_two_seeds=two, reference_spp=refs[who],
                                   reference_cpu_s='%.4g' % ref_cpu, reference_mean='%.6g' % ref_mean)
                        out.writerow(row)
                        f.flush()
                        print(' '.join('%s=%s' % kv for kv in row.items()), flush=True)


def analyse(path):
    rows = [r for r in csv.DictReader(line for line in open(path) if not line.startswith('#'))]
    for r in rows:
        for k in ('spp', 'cpu_s', 'wall_s', 'relmse', 'reference_spp'):
            r[k] = float(r[k])
    groups = {}
    for r in rows:
        groups.setdefault((r['scene'], r['mode'], r['renderer']), []).append(r)
    result = {}
    for (scene, mode, who), sel in sorted(groups.items()):
        sel.sort(key=lambda r: r['spp'])
        truth, p = corrected(sel, sel[0]['reference_spp'])
        k, fixed = np.polyfit([r['spp'] for r in sel], [r['cpu_s'] for r in sel], 1)
        print('%-10s %-4s %-8s fitted relMSE ~ spp^-%.2f; CPU = %.3f s + %.2f ms per spp'
              % (scene, mode, who, p, fixed, 1000 * k))
        for r, c in zip(sel, truth):
            print('    %5d spp  cpu %7.2f s  wall %7.2f s  relMSE %.2e (measured %.2e%s)'
                  % (r['spp'], r['cpu_s'], r['wall_s'], c, r['relmse'],
                     ', two seeds %.2e' % float(r['relmse_two_seeds']) if r['relmse_two_seeds'] else ''))
        for target in TARGETS:
            result[(scene, mode, who, target)] = (
                time_to(target, [(c, r['cpu_s']) for r, c in zip(sel, truth)]),
                time_to(target, [(c, r['wall_s']) for r, c in zip(sel, truth)]),
                time_to(target, [(c, r['spp']) for r, c in zip(sel, truth)]))
    # The ratio of CPU times is the ratio of samples needed times the ratio of CPU per sample.
    print('\n| scene | mode | relMSE | eyetrace spp | CPU s | wall s | realisticEye spp | CPU s | wall s '
          '| ratio CPU | ratio wall | spp ratio | CPU per spp ratio |')
    print('|---|---|---|---|---|---|---|---|---|---|---|---|---|')
    for (scene, mode, who, target), (cpu, wall, spp) in sorted(result.items()):
        if who != 'eyetrace' or (scene, mode, 'pbrt', target) not in result:
            continue
        pcpu, pwall, pspp = result[(scene, mode, 'pbrt', target)]
        print('| %s | %s | %.1e | %.0f | %.2f | %.2f | %.0f | %.2f | %.2f | **%.1fx** | %.1fx | %.1fx | %.2fx |'
              % (scene, mode, target, spp, cpu, wall, pspp, pcpu, pwall, pcpu / cpu, pwall / wall, pspp / spp,
                 (pcpu / pspp) / (cpu / spp)))


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('--pbrt', help='pbrt-v3-spectral binary (to render)')
    p.add_argument('--eyetrace', default=os.path.join(ROOT, 'build/bin/eyetrace'))
    p.add_argument('--work', default=os.path.join(ROOT, 'out/peer'))
    p.add_argument('--csv', default=os.path.join(ROOT, 'out/peer/peer_equal_error.csv'),
                   help='measured rows are appended here; --analyse reads it')
    p.add_argument('--analyse', action='store_true', help='only analyse the CSV')
    p.add_argument('--resolution', type=int, default=128)
    p.add_argument('--threads', type=int, default=2)
    p.add_argument('--scenes', default='peer,peripheral')
    p.add_argument('--modes', default='mono,spec')
    p.add_argument('--renderers', default='eyetrace,pbrt')
    p.add_argument('--eyetrace-sampler', default='halton', help='eyetrace\'s Sampler (the issue\'s comparison: halton)')
    p.add_argument('--pbrt-sampler', default='halton', help='pbrt-v3\'s Sampler (halton, sobol, zerotwosequence, ...)')
    p.add_argument('--ladder', default='16,32,64,128,256,512,1024', help='spp of the scored images')
    p.add_argument('--reference-spp', type=int, default=4096)
    p.add_argument('--eyetrace-ladder', default=None, help='spp ladder for eyetrace (default --ladder)')
    p.add_argument('--eyetrace-reference-spp', type=int, default=None)
    args = p.parse_args()
    args.work = os.path.abspath(args.work)  # pbrt-v3 resolves relative file names against the scene's folder
    if not args.analyse:
        if not args.pbrt and 'pbrt' in args.renderers:
            p.error('--pbrt is needed to render')
        measure(args)
    analyse(args.csv)


def git_head():
    return subprocess.run(['git', '-C', ROOT, 'rev-parse', '--short', 'HEAD'], capture_output=True,
                          text=True).stdout.strip() or 'unknown'


if __name__ == '__main__':
    main()
