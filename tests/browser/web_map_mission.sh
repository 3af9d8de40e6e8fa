#!/usr/bin/env bash
# `mission plan --html` and `mission simulate --html` in a real browser
# (headless Chromium): the sample mission, its page opened with the network
# shut off. Checked (tests/browser/check_web_map.py): every layer drawn with
# every feature; the waypoints and the table equal what `mission export`
# writes to GeoJSON (positions to 1e-7 degrees); the conflicts are mission
# plan --json's; a click inside the first obstacle names it; the simulated
# page has the track; `mission check --html` draws the plan as written (its
# waypoints mission export --as-written's) with mission check's obstacles
# and conflicts; the mission's raster chart is drawn as its depth shading.
# Exit 77 (ctest: skipped) without Chromium.
#   tests/browser/web_map_mission.sh DEEPGUIDE_CLI SOURCE_DIR [OUTPUT_DIR]
set -euo pipefail
cli="$1"
source_dir="$2"
source "$(dirname "${BASH_SOURCE[0]}")/browser.sh"
out="${3:-$(mktemp -d)}"
[ -n "${3:-}" ] || trap 'rm -rf "$out"' EXIT
mkdir -p "$out"
mission="$source_dir/data/missions/sample_mission.yaml"
"$cli" mission plan "$mission" --html "$out/page.html" --json > "$out/plan.json"
"$cli" mission export "$mission" -o "$out/export.geojson" > /dev/null
"$cli" mission check "$mission" --html "$out/check.html" --json > "$out/check.json"
"$cli" mission export "$mission" --as-written -o "$out/export_written.geojson" > /dev/null 2>&1
"$cli" mission simulate "$mission" --unknown "$source_dir/data/missions/sample_unknown.geojson" \
  --html "$out/simulated.html" --json > "$out/run.json"
read -r record click < <(python3 "$source_dir/tests/browser/check_web_map.py" pick-obstacle "$out/page.html")
browse --dump-dom "file://$out/page.html#test&click=$click" > "$out/dom.html"
browse --dump-dom "file://$out/simulated.html#test" > "$out/simulated_dom.html"
browse --dump-dom "file://$out/check.html#test" > "$out/check_dom.html"
browse --screenshot="$out/zoom_far.png" "file://$out/page.html"
browse --screenshot="$out/zoom_near.png" "file://$out/page.html#zoom=17&center=$click"
python3 "$source_dir/tests/browser/check_web_map.py" check-mission "$out" "$record"
