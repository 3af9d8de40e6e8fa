#!/usr/bin/env bash
# `render chart --html` in a real browser (headless Chromium): NOAA's
# 11-cell Kachemak exchange set at 7 m, its page opened with the network shut
# off. Checked (tests/browser/check_web_map.py): every layer drawn with every
# feature; the no-go by class and the land equal chart info's counts; the
# cells' table and outlines name every cell chart info lists; a click inside
# the largest no-go DEPARE opens a popup with its record id and its DRVAL1
# as GDAL's ogrinfo reads it from its cell; screenshots at two zoom levels
# differ. Exit 77 (ctest: skipped) without Chromium or the shared charts.
#   tests/browser/web_map_chart.sh DEEPGUIDE_CLI SOURCE_DIR [OUTPUT_DIR]
set -euo pipefail
cli="$1"
source_dir="$2"
source "$(dirname "${BASH_SOURCE[0]}")/browser.sh"
set_dir="$source_dir/../shared/data/real/noaa-enc-kachemak"
if [ ! -d "$set_dir" ]; then
  echo "SKIP: $set_dir is absent (the shared real data)"
  exit 77
fi
out="${3:-$(mktemp -d)}"
[ -n "${3:-}" ] || trap 'rm -rf "$out"' EXIT
mkdir -p "$out"
"$cli" render chart "$set_dir" --depth 7 --html "$out/page.html" > /dev/null
"$cli" chart info "$set_dir" --depth 7 --json > "$out/info.json"
read -r record click < <(python3 "$source_dir/tests/browser/check_web_map.py" pick "$out/page.html" DEPARE)
cell="${record%%:*}"
rcid="${record##*/}"
cell_file="$(find "$set_dir" -name "$cell.000" | head -n 1)"
OGR_S57_OPTIONS="RETURN_PRIMITIVES=OFF,RETURN_LINKAGES=OFF,LNAM_REFS=ON" \
  ogrinfo -ro -q "$cell_file" DEPARE -where "RCID=$rcid" > "$out/ogrinfo.txt"
browse --dump-dom "file://$out/page.html#test&click=$click" > "$out/dom.html"
browse --screenshot="$out/zoom_far.png" "file://$out/page.html"
browse --screenshot="$out/zoom_near.png" "file://$out/page.html#zoom=13&center=$click"
python3 "$source_dir/tests/browser/check_web_map.py" check-chart "$out" "$record"
