#!/usr/bin/env bash
# One `deepguide plan` over 5000 obstacles, as the user runs it (issue 25's
# scale case): random ellipses (semi-major 5..40 m, b/a 0.2..1, any heading;
# overlaps allowed) written to a CSV in UTM 32N, then visibility and tangent
# single queries, each a fresh process, best of RUNS wall-clock seconds.
# Layouts:
#   uniform   one obstacle per 150 m x 150 m square (10.6 km side), west -> east
#   diagonal  the same field, corner to corner
#   dense     one per 100 m x 100 m (7.1 km side), corner to corner
#   corridor  a band 10 km long and 6 km wide, along it
#   tight     a band 10 km long and 3 km wide, along it (54 000 usable zone
#             corners in the last focus; the tangent graph refuses it)
# Needs python3 (the generator); prints markdown rows for docs/PERFORMANCE.md.
#   bench/many_obstacles.sh [BUILD_DIR] [RUNS] [N]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
runs="${2:-3}"
n="${3:-5000}"
cli="$build/apps/deepguide"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# generate LAYOUT SEED > CSV; prints "FROM TO" (x,y in EPSG:32632) on fd 3
generate() {
  python3 - "$1" "$2" "$n" <<'PY'
import math, os, random, sys
layout, seed, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
rng = random.Random(seed)
cx, cy = 500000.0, 6000000.0
if layout in ("uniform", "diagonal", "dense"):
    side = (100.0 if layout == "dense" else 150.0) * math.sqrt(n)
    w, h = side, side
else:
    w, h = 10000.0, 6000.0 if layout == "corridor" else 3000.0
print("id,x,y,semi_major_m,semi_minor_m,orientation_deg")
for i in range(n):
    a = rng.uniform(5, 40)
    b = a * rng.uniform(0.2, 1)
    x = cx + rng.uniform(-w / 2, w / 2)
    y = cy + rng.uniform(-h / 2, h / 2)
    print(f"o{i},{x:.2f},{y:.2f},{a:.2f},{b:.2f},{rng.uniform(0, 180):.1f}")
off = 80.0  # outside every safety zone (40 m + 5 m margin) beyond the field's edge
if layout in ("diagonal", "dense"):
    ends = (cx - w / 2 - off, cy - h / 2 - off, cx + w / 2 + off, cy + h / 2 + off)
else:
    ends = (cx - w / 2 - off, cy, cx + w / 2 + off, cy)
with os.fdopen(3, "w") as f:
    f.write("%.1f,%.1f %.1f,%.1f\n" % ends)
PY
}

echo "| layout | graph | best s of $runs | obstacles used | vertices | edges | rounds | route m | note |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---|"
for layout in uniform diagonal dense corridor tight; do
  generate "$layout" 1 >"$tmp/o.csv" 3>"$tmp/ends"
  read -r from to <"$tmp/ends"
  for graph in visibility tangent; do
    best="" out=""
    for _ in $(seq "$runs"); do
      start=$(date +%s.%N)
      if out=$("$cli" plan --obstacles "$tmp/o.csv" --src-crs EPSG:32632 --crs EPSG:32632 \
                 --from "$from" --to "$to" --graph "$graph" --json 2>&1); then ok=1; else ok=0; fi
      s=$(echo "$(date +%s.%N) - $start" | bc)
      if [ -z "$best" ] || [ "$(echo "$s < $best" | bc)" = 1 ]; then best=$s; fi
    done
    if [ "$ok" = 1 ]; then
      row=$(echo "$out" | python3 -c '
import json, sys
j = json.load(sys.stdin)
print("%s | %s | %s | %s | %.1f | min clearance %.2f m |" % (j["obstacles_in_graph"], j["graph_vertices"],
      j["graph_edges"], j["rounds"], j["length_m"], j["min_clearance_m"]))')
      printf "| %s | %s | %.2f | %s\n" "$layout" "$graph" "$best" "$row"
    else
      printf "| %s | %s | %.2f | | | | | | %s |\n" "$layout" "$graph" "$best" "$(echo "$out" | tail -1 | cut -c1-160)"
    fi
  done
done
