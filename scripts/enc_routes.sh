#!/usr/bin/env bash
# The issue-22 acceptance run on real ENCs: 50 seeded start/goal pairs per
# chart and depth (US4MD81M at D = 3, 7, 10 m, US5FL4DQ at 5 m: 200 pairs),
# every route checked by the test's own OGR reading and GEOS geometry, none
# refused while the test's own raster of free water connects the ends.
# CI runs the same test with 15 pairs each (tests/charts/test_enc_routes.cpp).
#   scripts/enc_routes.sh [PAIRS_PER_CASE [SEED_SHIFT]]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
build="$DEEPGUIDE_ROOT/build"
deepguide_setup "$build"
DEEPGUIDE_ENC_PAIRS="${1:-50}" DEEPGUIDE_ENC_SEED="${2:-0}" "$build/tests/test_charts" --gtest_filter='EncRoutes.*'
