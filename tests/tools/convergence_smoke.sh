#!/bin/sh
# Smoke test of tools/convergence: runs the --quick sweep into a scratch directory, then checks
# that results.csv exists, every number in it is finite, and every configuration's error falls
# with the sample count (16 spp at least 3x below 1 spp in relative MSE: even the independent
# sampler gives ~16x less variance, so 3x leaves room for the 256-spp reference's own noise).
#   tests/tools/convergence_smoke.sh EYETRACE_BINARY [SCRATCH_DIR]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
eyetrace=${1:?usage: convergence_smoke.sh EYETRACE_BINARY [SCRATCH_DIR]}
out=${2:-$(mktemp -d)}
rm -rf "$out/convergence"
mkdir -p "$out/convergence"

/usr/bin/python3 "$root/tools/convergence" --quick --eyetrace "$eyetrace" --out "$out/convergence" \
  --cameras pinhole,navarro --samplers independent,zsobol --threads 2

/usr/bin/python3 - "$out/convergence/results.csv" <<'EOF'
import csv, math, sys
from collections import defaultdict
rows = list(csv.DictReader(open(sys.argv[1])))
assert rows, "results.csv is empty"
numeric = [k for k in rows[0] if k not in ("scene", "camera", "sampler")]
for r in rows:
    for k in numeric:
        assert math.isfinite(float(r[k])), f"{k} = {r[k]} in {r}"
    assert float(r["render_seconds"]) > 0 and float(r["samples"]) > 0, r
    assert int(r["nonfinite_samples"]) == 0, r
configs = defaultdict(dict)
for r in rows:
    configs[(r["scene"], r["camera"], r["sampler"])][int(r["spp"])] = float(r["relmse_image"])
assert len(configs) == 2 * 2 * 2, sorted(configs)
for key, by_spp in configs.items():
    lo, hi = by_spp[min(by_spp)], by_spp[max(by_spp)]
    assert hi * 3 < lo, f"{key}: relMSE {lo:.3g} at {min(by_spp)} spp, {hi:.3g} at {max(by_spp)} spp"
    print(f"{key}: relMSE {lo:.3g} -> {hi:.3g} ({lo / hi:.1f}x)")
print(f"convergence smoke: {len(rows)} rows, all finite, error falls with spp in all {len(configs)} configurations")
EOF
for f in peripheral-pinhole.png small-light-navarro.png peripheral.png; do
  test -s "$out/convergence/$f" || { echo "missing plot $f"; exit 1; }
done
