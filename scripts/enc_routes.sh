#!/usr/bin/env bash
# The issue-22 acceptance run on real ENCs: 50 seeded start/goal pairs per
# chart and depth (US4MD81M at D = 3, 7, 10 m, US5FL4DQ at 5 m: 200 pairs),
# every route checked by the test's own OGR reading and GEOS geometry, none
# refused while the test's own raster of free water connects the ends.
# CI runs the same test with 15 pairs each (tests/charts/test_enc_routes.cpp).
# The Kachemak exchange set (11 cells, bands 3 to 5; issue 42): KACHEMAK_PAIRS
# transits 20 to 150 km at each of D = 5, 7, 12 m (default 70: 210 in all;
# CI runs 2 each).
#   scripts/enc_routes.sh [PAIRS_PER_CASE [SEED_SHIFT [KACHEMAK_PAIRS]]]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
build="$DEEPGUIDE_ROOT/build"
deepguide_setup "$build"
DEEPGUIDE_ENC_PAIRS="${1:-50}" DEEPGUIDE_ENC_SEED="${2:-0}" DEEPGUIDE_KACHEMAK_PAIRS="${3:-70}" \
  "$build/tests/test_charts" --gtest_filter='EncRoutes.*'
