#!/usr/bin/python3
"""Where a render's time goes, grouped as issue 19 asks, from a linux-perf recording.

    perf record -F 2000 -o nav.data build/bin/eyetrace render scenes/peripheral.pbrt \\
        --camera 'Camera "navarro" "float fov" 50 "float pupildiameter" 5 "float wavelength" 589.3' \\
        --resolution 480x320 --spp 32 --threads 1 -o /tmp/nav.exr -q
    bench/perf_breakdown.py nav.data [more.data ...]

Each sample is charged to the function it was taken in (self time; inlined code counts in the
function it was inlined into), and each function to the first group whose pattern matches its
library or name. --unmatched lists what fell into "other".
"""
import argparse
import re
import subprocess
import sys
from collections import defaultdict

# (group, pattern on "library symbol"), first match wins. The order matters where names overlap.
GROUPS = [
    ("intersection: Embree traversal", r"libembree"),
    ("intersection: hit to interaction", r"Scene::intersect|Scene::occluded|TriangleMesh::|Shape::|"
     r"spawn_ray|offset_ray_origin|to_world|Triangle"),
    ("camera", r"Camera|optics::|CompiledSystem|trace_block|Pupil|LensSystem|Eye"),
    ("sampler", r"Sampler|sobol|Sobol|halton|Halton|radical_inverse|mix_bits|Owen|Morton|morton"),
    ("textures", r"OpenImageIO|libOpenImageIO|Texture|texture|filtered_square_wave|Checkerboard|ImageCache|"
     r"srgb_to_linear|MipMap|Mipmap|mipmap|libImath|libOpenEXR|libpng|read_png"),
    ("light sampling", r"Light|light|sample_li"),
    ("shading (BSDF, material)", r"BSDF|BxDF|Material|material|apply_normal_map|Bump|bump|Frame"),
    ("spectra (RGB to spectrum, wavelengths)", r"Spectrum|spectrum|visible_wavelength|RGBToSpectrum|Sigmoid|"
     r"powf|expf|__pow|__exp"),
    ("film (filter, colour, accumulate)", r"Film|Filter|sampled_to_xyz|xyz_to_linear|cie_xyz|add_sample"),
    ("integrator and render loop", r"Integrator|RenderLoop|SampleBatch|render_tile|radiance|power_heuristic"),
    ("start-up (loader, parsing, image I/O)", r"ld-linux|do_lookup|_dl_|parse|Parser|Tokenizer|libz|inflate"),
]


def breakdown(data):
    out = subprocess.run(["perf", "report", "-i", data, "--no-children", "--sort", "dso,sym", "--stdio",
                          "-g", "none", "--percent-limit", "0"], capture_output=True, text=True, check=True).stdout
    totals, unmatched = defaultdict(float), defaultdict(float)
    row = re.compile(r"^\s*([\d.]+)%\s+(\S+)\s+\[[.k]\]\s+(.*)$")
    for line in out.splitlines():
        m = row.match(line)
        if not m:
            continue
        pct, dso, sym = float(m.group(1)), m.group(2), m.group(3).strip()
        key = f"{dso} {sym}"
        for name, pat in GROUPS:
            if re.search(pat, key):
                totals[name] += pct
                break
        else:
            totals["other"] += pct
            unmatched[key] += pct
    return totals, unmatched


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("data", nargs="+", help="perf.data files (one column each)")
    ap.add_argument("--unmatched", action="store_true", help="list the functions counted as other")
    a = ap.parse_args()
    results = [breakdown(d) for d in a.data]
    names = [g for g, _ in GROUPS] + ["other"]
    print("| group | " + " | ".join(a.data) + " |")
    print("|---|" + "---:|" * len(a.data))
    for n in names:
        print(f"| {n} | " + " | ".join(f"{t.get(n, 0.0):.1f}%" for t, _ in results) + " |")
    if a.unmatched:
        for d, (_, un) in zip(a.data, results):
            print(f"\nother in {d}:", file=sys.stderr)
            for k, v in sorted(un.items(), key=lambda kv: -kv[1])[:25]:
                print(f"  {v:5.2f}% {k}", file=sys.stderr)


if __name__ == "__main__":
    main()
