#!/usr/bin/env bash
# `plan --html` in a real browser (headless Chromium): a route across NOAA's
# US4MD81M at 5 m, its page opened with the network shut off. Checked
# (tests/browser/check_web_map.py): every layer is drawn with the library's
# own counts (chart info's no-go by class, plan --json's obstacles and
# waypoints); a click inside a chosen DEPARE opens a popup with its record id
# and its DRVAL1 as GDAL's ogrinfo reads it from the cell; the waypoint table
# equals the GeoJSON route to 1e-7 degrees; screenshots at two zoom levels
# differ. Exit 77 (ctest: skipped) without Chromium or the shared chart.
#   tests/browser/web_map_plan.sh DEEPGUIDE_CLI SOURCE_DIR [OUTPUT_DIR]
set -euo pipefail
cli="$1"
source_dir="$2"
source "$(dirname "${BASH_SOURCE[0]}")/browser.sh"
cell="$source_dir/../shared/data/real/noaa-enc-US4MD81M/US4MD81M.000"
if [ ! -f "$cell" ]; then
  echo "SKIP: $cell is absent (the shared real data)"
  exit 77
fi
out="${3:-$(mktemp -d)}"
[ -n "${3:-}" ] || trap 'rm -rf "$out"' EXIT
mkdir -p "$out"
"$cli" plan --chart "$cell" --depth 5 --from -76.41,38.87 --to -76.35,38.60 -o "$out/route.geojson" \
  --html "$out/page.html" --json > "$out/plan.json"
"$cli" chart info "$cell" --depth 5 --json > "$out/info.json"
record="DEPARE/3844"
OGR_S57_OPTIONS="RETURN_PRIMITIVES=OFF,RETURN_LINKAGES=OFF,LNAM_REFS=ON" \
  ogrinfo -ro -q "$cell" DEPARE -where "RCID=${record#*/}" > "$out/ogrinfo.txt"
click="$(python3 "$source_dir/tests/browser/check_web_map.py" click "$out/page.html" "$record")"
browse --dump-dom "file://$out/page.html#test&click=$click" > "$out/dom.html"
browse --screenshot="$out/zoom_far.png" "file://$out/page.html#zoom=9"
browse --screenshot="$out/zoom_near.png" "file://$out/page.html#zoom=14&center=$click"
python3 "$source_dir/tests/browser/check_web_map.py" check "$out" "$record"
