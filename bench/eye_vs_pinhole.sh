#!/bin/bash
# Scripted render: the figure scene through the Navarro eye and through a pinhole at equal
# samples per pixel, alternated so machine load hits both alike; prints each render time
# (from --stats, setup excluded) and the eye / pinhole ratio of the medians. Target: <= 1.3.
#
#   bench/eye_vs_pinhole.sh [EYETRACE] [RESOLUTION] [SPP] [REPEATS] [THREADS]
#   bench/eye_vs_pinhole.sh build/bin/eyetrace 480x320 32 5 2
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BIN="${1:-$ROOT/build/bin/eyetrace}"
RES="${2:-480x320}"
SPP="${3:-32}"
REPEATS="${4:-5}"
THREADS="${5:-2}"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

declare -A CAMERA=(
  [navarro]='Camera "navarro" "float pupildiameter" 5 "float fov" 50'
  [pinhole]='Camera "pinhole" "float fov" 50'
)
for name in navarro pinhole; do : > "$TMP/$name.times"; done
for ((i = 0; i < REPEATS; ++i)); do
  for name in navarro pinhole; do
    "$BIN" render "$ROOT/scenes/peripheral.pbrt" --camera "${CAMERA[$name]}" --resolution "$RES" --spp "$SPP" \
      --threads "$THREADS" --quiet -o "$TMP/$name.exr" --stats "$TMP/$name.json"
    /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['render_seconds'])" "$TMP/$name.json" \
      >> "$TMP/$name.times"
  done
done
/usr/bin/python3 - "$TMP" "$RES" "$SPP" "$THREADS" <<'EOF'
import statistics, sys
tmp, res, spp, threads = sys.argv[1:]
t = {n: [float(x) for x in open(f"{tmp}/{n}.times")] for n in ("navarro", "pinhole")}
m = {n: statistics.median(v) for n, v in t.items()}
for n in t:
    print(f"{n:8s} {res} {spp} spp {threads} threads: median {m[n]:.3f} s  (runs: {', '.join(f'{x:.3f}' for x in t[n])})")
print(f"eye / pinhole wall-time ratio: {m['navarro'] / m['pinhole']:.3f}  (target <= 1.3)")
EOF
