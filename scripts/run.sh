#!/usr/bin/env bash
# Sets up, builds (Release) and runs deepguide's main job on the bundled sample.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
deepguide_setup "$DEEPGUIDE_ROOT/build"
cd "$DEEPGUIDE_ROOT"
./build/apps/deepguide obstacles info data/sample_obstacles.geojson
