#!/bin/bash
# Scripted render: what a big render costs beyond the rendering (issue 17: "the film reduction
# and output of a 4096 x 4096 render take under 1 s"). Renders the Cornell box through a pinhole
# at 1 spp, one process with 2 threads and, when the binary has MPI, 2 ranks x 1 thread, and
# prints --stats' output_seconds (rank 0's wall time from the last sample to the written image:
# gathering the other ranks' tiles, computing the image, writing the EXR) with the median of the
# runs. The image goes to a temporary folder (tmpfs or disk: say which when you quote it).
#
#   bench/film_output.sh [EYETRACE] [RESOLUTION] [REPEATS]
#   bench/film_output.sh build/bin/eyetrace 4096x4096 5
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
BIN="${1:-$ROOT/build/bin/eyetrace}"
RES="${2:-4096x4096}"
REPEATS="${3:-5}"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT

render() {  # label, threads, then the command that launches the render (env, or mpirun ...)
  local label="$1" threads="$2"
  shift 2
  : > "$TMP/$label.times"
  for ((i = 0; i < REPEATS; ++i)); do
    "$@" "$BIN" render "$ROOT/scenes/cornell-box.pbrt" --resolution "$RES" --spp 1 --threads "$threads" --quiet \
      -o "$TMP/out.exr" --stats "$TMP/stats.json"
    /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d['output_seconds'], d['render_seconds'], d['ranks']['count'])" \
      "$TMP/stats.json" >> "$TMP/$label.times"
  done
}
labels=("1 rank x 2 threads")
render "${labels[0]}" 2 env
if command -v mpirun > /dev/null; then  # a binary without MPI renders as 2 separate processes: ranks 1
  labels+=("2 ranks x 1 thread")
  render "${labels[1]}" 1 mpirun --oversubscribe --allow-run-as-root -n 2
fi
/usr/bin/python3 - "$TMP" "$RES" "${labels[@]}" <<'EOF'
import statistics, sys
tmp, res, labels = sys.argv[1], sys.argv[2], sys.argv[3:]
for label in labels:
    rows = [tuple(map(float, l.split())) for l in open(f"{tmp}/{label}.times")]
    out = [r[0] for r in rows]
    if label.startswith("2 ranks") and any(r[2] != 2 for r in rows):
        print(f"{res} {label}: skipped, the binary was built without MPI")
        continue
    print(f"{res} {label}: output {statistics.median(out):.3f} s median (runs: {', '.join(f'{x:.3f}' for x in out)}), "
          f"render {statistics.median(r[1] for r in rows):.2f} s")
EOF
