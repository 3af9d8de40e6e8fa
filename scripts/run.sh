#!/usr/bin/env bash
# Sets up, builds (Release; only the `deepguide` command, not the tests) and runs deepguide's main job on the bundled sample
# chart (charts/, made by `deepguide chart synth`): the sample mission
# (data/missions/sample_mission.yaml) checked, planned with every conflict
# resolved, and drawn; then the chart's summary and a route out of the harbour
# through the dredged channel at 10 m operating depth; then a route through
# the sample obstacles, checked. Results go to out/.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
deepguide_setup_cli "$DEEPGUIDE_ROOT/build"
cd "$DEEPGUIDE_ROOT"
mkdir -p out
MISSION=data/missions/sample_mission.yaml
./build/apps/deepguide mission plan "$MISSION"
./build/apps/deepguide render mission "$MISSION" -o out/sample_mission.png
./build/apps/deepguide mission export "$MISSION" -o out/sample_mission.plan --overwrite
./build/apps/deepguide mission simulate "$MISSION" --unknown data/missions/sample_unknown.geojson \
  --planning-delay 30 --render out/sample_mission_simulated.png --zoom 120
echo
CHART="charts/sample_chart.tif charts/sample_chart_hazards.gpkg"
# shellcheck disable=SC2086  # two file names
./build/apps/deepguide chart info $CHART --depth 10
echo
# shellcheck disable=SC2086
./build/apps/deepguide plan --chart $CHART --depth 10 \
  --from 10.2446,54.4413 --to 10.2626,54.4606 \
  -o out/chart_route.geojson --render out/chart_route.png
echo
./build/apps/deepguide obstacles info data/sample_obstacles.geojson
echo
./build/apps/deepguide plan --obstacles data/sample_obstacles.geojson \
  --from 10.2405,54.4470 --to 10.2640,54.4560 --graph tangent \
  -o out/sample_route.geojson --render out/sample_route.png --render-graph
./build/apps/deepguide check route out/sample_route.geojson --obstacles data/sample_obstacles.geojson
