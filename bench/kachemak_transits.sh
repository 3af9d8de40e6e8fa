#!/usr/bin/env bash
# Transits across an exchange set, as the user runs them (issue 42): seeded
# start/goal pairs 20 to 150 km apart in the Kachemak set
# (../shared/data/real/noaa-enc-kachemak, 11 cells in 3 bands), each planned
# from the cells and from a prepared GeoPackage with plan's default graph (the
# navmesh on charts, read from the GeoPackage's kept mesh), and from the
# GeoPackage with the reduced visibility graph for comparison; a fresh
# process each; per run the exit code, time and peak RSS. The ends are drawn by GDAL's Python
# bindings alone (points in depth areas of the band-3 cell at least 20 m
# deep), not by the library. Prints markdown for docs/PERFORMANCE.md.
#   bench/kachemak_transits.sh [BUILD_DIR] [PAIRS] [SEED] [DEPTH]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
pairs="${2:-20}"
seed="${3:-1}"
depth="${4:-7}"
cli="$build/apps/deepguide"
set_dir="$root/../shared/data/real/noaa-enc-kachemak"
[ -d "$set_dir" ] || { echo "kachemak_transits: $set_dir is absent" >&2; exit 1; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

/usr/bin/python3 - "$set_dir" "$pairs" "$seed" >"$tmp/pairs" <<'EOF'
import math, random, sys
from osgeo import ogr
set_dir, n, seed = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
ds = ogr.Open(set_dir + "/US3AK12M_ENC_ROOT/US3AK12M/US3AK12M.000")
deep = [f.GetGeometryRef().Clone() for f in ds.GetLayerByName("DEPARE")
        if f.GetField("DRVAL1") is not None and f.GetField("DRVAL1") >= 20.0]
weights = [g.GetArea() for g in deep]
rng = random.Random(seed)
def point():
    while True:
        g = rng.choices(deep, weights)[0]
        x0, x1, y0, y1 = g.GetEnvelope()
        p = ogr.Geometry(ogr.wkbPoint)
        p.AddPoint_2D(rng.uniform(x0, x1), rng.uniform(y0, y1))
        if g.Contains(p):
            return p.GetX(), p.GetY()
def km(a, b):
    k = math.cos(math.radians(0.5 * (a[1] + b[1])))
    return 111.32 * math.hypot((a[0] - b[0]) * k, a[1] - b[1])
done = 0
while done < n:
    a, b = point(), point()
    if 20.0 <= km(a, b) <= 150.0:
        print("%.6f,%.6f %.6f,%.6f %.1f" % (a[0], a[1], b[0], b[1], km(a, b)))
        done += 1
EOF

timed() {  # runs "$@"; prints "exit seconds peak_kib"
  local rc=0
  /usr/bin/time -f "%e %M" -o "$tmp/t" "$@" >"$tmp/out" 2>"$tmp/err" || rc=$?
  echo "$rc $(cat "$tmp/t" | tail -1)"
}

prep=$(timed "$cli" chart prepare "$set_dir" --depth "$depth" -o "$tmp/set.gpkg")
echo "chart prepare at $depth m: $(echo "$prep" | cut -d' ' -f2) s, peak $(( $(echo "$prep" | cut -d' ' -f3) / 1024 )) MiB"
echo
echo "| pair | km | from cells: exit | s | MiB | from GeoPackage: exit | s | MiB | route km | GeoPackage, visibility: exit | s | route km |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
: >"$tmp/cold"; : >"$tmp/warm"; : >"$tmp/vis"; internal=0; k=0
while read -r from to dist; do
  k=$((k + 1))
  cold=$(timed "$cli" plan --chart "$set_dir" --depth "$depth" --from "$from" --to "$to" -o "$tmp/r.geojson" --json)
  grep -q "internal error" "$tmp/err" && internal=$((internal + 1))
  length=-
  [ "$(echo "$cold" | cut -d' ' -f1)" = 0 ] && length=$(/usr/bin/python3 -c \
    'import json,sys; print("%.1f" % (json.load(open(sys.argv[1]))["length_m"] / 1000))' "$tmp/out")
  warm=$(timed "$cli" plan --chart "$tmp/set.gpkg" --depth "$depth" --from "$from" --to "$to" -o "$tmp/r2.geojson")
  grep -q "internal error" "$tmp/err" && internal=$((internal + 1))
  vis=$(timed "$cli" plan --chart "$tmp/set.gpkg" --depth "$depth" --from "$from" --to "$to" -o "$tmp/r3.geojson" \
    --graph visibility --json)
  grep -q "internal error" "$tmp/err" && internal=$((internal + 1))
  vis_length=-
  [ "$(echo "$vis" | cut -d' ' -f1)" = 0 ] && vis_length=$(/usr/bin/python3 -c \
    'import json,sys; print("%.1f" % (json.load(open(sys.argv[1]))["length_m"] / 1000))' "$tmp/out")
  echo "$cold" >>"$tmp/cold"; echo "$warm" >>"$tmp/warm"; echo "$vis" >>"$tmp/vis"
  printf "| %d | %s | %s | %s | %d | %s | %s | %d | %s | %s | %s | %s |\n" "$k" "$dist" "$(echo "$cold" | cut -d' ' -f1)" \
    "$(echo "$cold" | cut -d' ' -f2)" "$(( $(echo "$cold" | cut -d' ' -f3) / 1024 ))" "$(echo "$warm" | cut -d' ' -f1)" \
    "$(echo "$warm" | cut -d' ' -f2)" "$(( $(echo "$warm" | cut -d' ' -f3) / 1024 ))" "$length" \
    "$(echo "$vis" | cut -d' ' -f1)" "$(echo "$vis" | cut -d' ' -f2)" "$vis_length"
done <"$tmp/pairs"
stats() {  # file -> "median s, worst s, peak MiB, exits"
  local m w r
  m=$(cut -d' ' -f2 "$1" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}')
  w=$(cut -d' ' -f2 "$1" | sort -g | tail -1)
  r=$(cut -d' ' -f3 "$1" | sort -g | tail -1)
  echo "median $m s, worst $w s, peak $((r / 1024)) MiB, exit codes $(cut -d' ' -f1 "$1" | sort | uniq -c | awk '{printf "%s x%s ", $2, $1}')"
}
echo
echo "from the cells:      $(stats "$tmp/cold")"
echo "from the GeoPackage: $(stats "$tmp/warm")"
echo "GeoPackage, --graph visibility: $(stats "$tmp/vis")"
median() { cut -d' ' -f2 "$1" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
echo "default / visibility, medians from the GeoPackage: $(echo "scale=3; $(median "$tmp/warm") / $(median "$tmp/vis")" | bc)"
echo "internal errors:     $internal"
