#!/usr/bin/env bash
# Sets up, builds (Release) and runs deepguide's main job on the bundled sample:
# a route through the sample obstacles, checked, written and drawn to out/.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
deepguide_setup "$DEEPGUIDE_ROOT/build"
cd "$DEEPGUIDE_ROOT"
mkdir -p out
./build/apps/deepguide obstacles info data/sample_obstacles.geojson
echo
./build/apps/deepguide plan --obstacles data/sample_obstacles.geojson \
  --from 10.2405,54.4470 --to 10.2640,54.4560 --graph tangent \
  -o out/sample_route.geojson --render out/sample_route.png --render-graph
./build/apps/deepguide check route out/sample_route.geojson --obstacles data/sample_obstacles.geojson
