#!/usr/bin/env bash
# Regenerates the seed's figures (docs/images/seed, `deepguide figures`; the
# README shows them), the sample mission's figure (docs/images/sample_mission.png), the quadtree, replanning and octree figures and the Gulf Stream time
# route (docs/PLANNING.md; the latter when ../shared has the HYCOM sample),
# and the reactive level's and the identification's figures
# (docs/SIMULATION.md, docs/IDENTIFICATION.md) from every scenario in
# data/scenarios/*.yaml into docs/figures/. A scenario with an identify
# section gets
#   NAME_identification.png  the areas, the current and the track (Figs. 14-16)
# every other one
#   NAME_field_METHOD.png  gradient lines of each method (the seed's Figs. 8, 10)
#   NAME_simulation.png    the methods' simulated trajectories (Fig. 11)
#   NAME_turn_rates.png    r_ref and r over time per method (Fig. 12)
# Builds first (scripts/setup.sh, Release, incremental). To use a deepguide
# binary that is already built instead: DEEPGUIDE_CLI=path/to/deepguide scripts/figures.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
if [ -z "${DEEPGUIDE_CLI:-}" ]; then
  deepguide_setup_cli "$DEEPGUIDE_ROOT/build"
  DEEPGUIDE_CLI="$DEEPGUIDE_ROOT/build/apps/deepguide"
fi
cd "$DEEPGUIDE_ROOT"
mkdir -p docs/figures
# The seed paper's Figs. 4, 6, 7, 8, 10, 11 and 12 (README, "The seed's figures").
"$DEEPGUIDE_CLI" figures -o docs/images/seed > /dev/null
# The README's figure: the sample mission, planned (docs/MISSIONS.md).
"$DEEPGUIDE_CLI" render mission data/missions/sample_mission.yaml -o docs/images/sample_mission.png
# The seed's Fig. 4: an object nobody knew, found by the sonar on the survey, evaded while the route is repaired.
"$DEEPGUIDE_CLI" mission simulate data/missions/sample_mission.yaml --unknown data/missions/sample_unknown.geojson \
  --planning-delay 30 --render docs/images/sample_mission_simulated.png --zoom 120 > /dev/null
shopt -s nullglob
scenarios=(data/scenarios/*.yaml)
if [ ${#scenarios[@]} -eq 0 ]; then
  echo "deepguide: no scenarios in data/scenarios/" >&2
  exit 1
fi
for scenario in "${scenarios[@]}"; do
  name="$(basename "$scenario" .yaml)"
  if grep -q '^identify:' "$scenario"; then
    "$DEEPGUIDE_CLI" render identification "$scenario" -o "docs/figures/${name}_identification.png"
    continue
  fi
  for method in dipole geometric potential; do
    "$DEEPGUIDE_CLI" render field "$scenario" --method "$method" -o "docs/figures/${name}_field_${method}.png"
  done
  "$DEEPGUIDE_CLI" render simulation "$scenario" -o "docs/figures/${name}_simulation.png"
  "$DEEPGUIDE_CLI" render turn-rates "$scenario" -o "docs/figures/${name}_turn_rates.png"
done

# The seed's Fig. 7 (the quadtree over the sample obstacles) and a D* Lite
# replay of two sonar reports (docs/PLANNING.md).
mkdir -p docs/images
"$DEEPGUIDE_CLI" plan --obstacles data/sample_obstacles.geojson --from 10.2405,54.4470 --to 10.2640,54.4560 \
  --graph quadtree --min-cell 4 --render docs/images/quadtree_cells.png --render-graph >/dev/null
"$DEEPGUIDE_CLI" plan --obstacles data/sample_obstacles.geojson --from 10.2405,54.4470 --to 10.2640,54.4560 \
  --graph quadtree --replan-events data/replan_events.csv --render docs/images/replanning_replay.png >/dev/null
# The same on the navigation mesh: a rock reported on the exact route.
"$DEEPGUIDE_CLI" plan --obstacles data/sample_obstacles.geojson --from 10.2405,54.4470 --to 10.2640,54.4560 \
  --graph navmesh --replan-events data/replan_events_navmesh.csv --render docs/images/replanning_navmesh.png >/dev/null

# A route in depth over the sample chart: its depth profile with the sea
# floor, the hazards' tops and the octree's cells (docs/PLANNING.md).
"$DEEPGUIDE_CLI" plan --chart charts/sample_chart.tif charts/sample_chart_hazards.gpkg --graph octree --depth 10 \
  --from 10.2446,54.4413 --to 10.2626,54.4606 --min-cell 1 --smooth \
  --render-profile docs/images/octree_depth_profile.png >/dev/null

# The time route through the real HYCOM Gulf Stream sample (docs/PLANNING.md),
# when ../shared holds it (it is never copied into the project).
hycom="$DEEPGUIDE_ROOT/../shared/data/real/currents-hycom/hycom_glby_930_2019030712_t003_uv3z.nc"
if [ -f "$hycom" ]; then
  mkdir -p docs/images
  "$DEEPGUIDE_CLI" plan --obstacles data/gulf_stream_banks.geojson --from -74.80,35.10 --to -75.40,34.60 \
    --current "$hycom" --cost time --waypoint-grid 1000 --render docs/images/gulf_stream_time_route.png >/dev/null
else
  echo "deepguide: $hycom is absent: skipping the Gulf Stream route figure" >&2
fi

# Real S-57 cells drawn as an ECDIS draws them, with their no-go (docs/CHARTS.md),
# and a route down Chesapeake Bay planned on one, when ../shared holds them.
enc="$DEEPGUIDE_ROOT/../shared/data/real"
if [ -f "$enc/noaa-enc-US4MD81M/US4MD81M.000" ] && [ -f "$enc/noaa-enc-US5FL4DQ/US5FL4DQ.000" ]; then
  "$DEEPGUIDE_CLI" render chart "$enc/noaa-enc-US5FL4DQ/US5FL4DQ.000" --depth 1 -o docs/images/enc_key_west.png >/dev/null
  "$DEEPGUIDE_CLI" plan --chart "$enc/noaa-enc-US4MD81M/US4MD81M.000" --depth 5 --from -76.41,38.87 --to -76.35,38.60 \
    --render docs/images/enc_chesapeake_route.png >/dev/null
  # A 116 km transit across the 11-cell Kachemak exchange set (bands 3 to 5), when ../shared holds it.
  if [ -d "$enc/noaa-enc-kachemak" ]; then
    "$DEEPGUIDE_CLI" plan --chart "$enc/noaa-enc-kachemak" --depth 5 --from -152.775099,59.423333 \
      --to -150.795995,59.162818 --render docs/images/enc_kachemak_transit.png >/dev/null
  fi
else
  echo "deepguide: the NOAA cells in $enc are absent: skipping the ENC figures" >&2
fi
# docs/PYTHON.md's worked examples (the Python module in build/python; the chart one needs ../shared's US4MD81M).
if [ -d "$DEEPGUIDE_ROOT/build/python/deepguide" ]; then
  PYTHONPATH="$DEEPGUIDE_ROOT/build/python" /usr/bin/python3 docs/examples/turning_rates.py docs/images/python_turning_rates.png
  cell="$DEEPGUIDE_ROOT/../shared/data/real/noaa-enc-US4MD81M/US4MD81M.000"
  if [ -f "$cell" ]; then
    PYTHONPATH="$DEEPGUIDE_ROOT/build/python" /usr/bin/python3 docs/examples/plan_on_a_chart.py "$cell" \
      docs/images/python_route_on_chart.png
  fi
fi
# The web map of the Chesapeake route (docs/WEB_MAP.md), as headless Chromium shows it, when both are here.
cell="$DEEPGUIDE_ROOT/../shared/data/real/noaa-enc-US4MD81M/US4MD81M.000"
chromium="$(command -v chromium || true)"
if [ -f "$cell" ] && [ -n "$chromium" ]; then
  page="$(mktemp -d)"
  "$DEEPGUIDE_CLI" plan --chart "$cell" --depth 5 --from -76.41,38.87 --to -76.35,38.60 --html "$page/map.html" >/dev/null
  # Zoomed to the route's turn round the shoals off Cove Point, a DEPARE's reason open.
  "$chromium" --headless=new --no-sandbox --disable-gpu --disable-dev-shm-usage --hide-scrollbars --window-size=1400,800 \
    --host-resolver-rules="MAP * ~NOTFOUND" --virtual-time-budget=15000 \
    --screenshot="$DEEPGUIDE_ROOT/docs/images/web_map_chesapeake.png" \
    "file://$page/map.html#zoom=12.5&center=-76.392,38.556&click=-76.380,38.545" 2>/dev/null
  rm -rf "$page"
else
  echo "deepguide: Chromium or US4MD81M is absent: skipping the web map's screenshot" >&2
fi
