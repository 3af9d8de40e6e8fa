#!/usr/bin/env bash
# Whole-cell ENC planning, as the user runs it (issue 22): the no-go of
# US4MD81M at one depth (time, peak RSS), one cold query across the whole cell
# from the cell file and from a prepared GeoPackage (median of N runs, peak
# RSS), each a fresh process. Needs ../shared/data/real; prints markdown rows
# for docs/PERFORMANCE.md.
#   bench/enc_bench.sh [BUILD_DIR] [RUNS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
runs="${2:-7}"
cli="$build/apps/deepguide"
cell="$root/../shared/data/real/noaa-enc-US4MD81M/US4MD81M.000"
[ -f "$cell" ] || { echo "enc_bench: $cell is absent" >&2; exit 1; }
# From the north end of the cell to its south end (56 km apart), in water deep enough at every depth below.
from=-76.39,38.95
to=-76.36,38.45
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# median of the numbers on stdin
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
# runs "$@" once under GNU time; prints "seconds peak_kib"
timed() { /usr/bin/time -f "%e %M" -o "$tmp/t" "$@" >/dev/null 2>&1 || true; cat "$tmp/t"; }

echo "| depth (D) | no-go s | no-go peak MiB | query from cell: median s (min..max) | peak MiB | from GeoPackage: median s (min..max) | peak MiB | route m |"
echo "|---|---|---|---|---|---|---|---|"
for depth in 1 5 8; do
  nogo=$(timed "$cli" chart nogo "$cell" --depth "$depth" --tolerance 1 -o "$tmp/n$depth.gpkg")
  "$cli" chart prepare "$cell" --depth "$depth" -o "$tmp/a$depth.gpkg" >/dev/null
  : >"$tmp/cell"; : >"$tmp/gpkg"
  for _ in $(seq "$runs"); do
    timed "$cli" plan --chart "$cell" --depth "$depth" --from "$from" --to "$to" -o "$tmp/r.geojson" >>"$tmp/cell"
    timed "$cli" plan --chart "$tmp/a$depth.gpkg" --depth "$depth" --from "$from" --to "$to" -o "$tmp/r2.geojson" >>"$tmp/gpkg"
  done
  length=$("$cli" plan --chart "$tmp/a$depth.gpkg" --depth "$depth" --from "$from" --to "$to" --json |
    python3 -c 'import json, sys; print("%.1f" % json.load(sys.stdin)["length_m"])')
  row() {  # file -> "median (min..max) | peak MiB"
    local m lo hi rss
    m=$(cut -d' ' -f1 "$1" | median); lo=$(cut -d' ' -f1 "$1" | sort -g | head -1); hi=$(cut -d' ' -f1 "$1" | sort -g | tail -1)
    rss=$(cut -d' ' -f2 "$1" | sort -g | tail -1)
    printf "%s (%s..%s) | %.0f" "$m" "$lo" "$hi" "$(awk -v k="$rss" "BEGIN {print k / 1024}")"
  }
  printf "| %s m (%s m) | %s | %.0f | %s | %s | %.1f |\n" "$depth" "$((depth + 2))" "$(echo "$nogo" | cut -d' ' -f1)" \
    "$(awk -v k="$(echo "$nogo" | cut -d' ' -f2)" "BEGIN {print k / 1024}")" "$(row "$tmp/cell")" "$(row "$tmp/gpkg")" "$length"
done
