#!/usr/bin/env bash
# The navigation mesh against the visibility graph on real charts, with more
# pairs than CI runs (tests/charts/test_enc_navmesh.cpp): PAIRS per chart
# (default 200) on US4MD81M, US5FL4DQ and the Kachemak set; SEED shifts the
# seeds (a claim holds only when a fresh seed confirms it). Needs a Release
# build in build/ (scripts/test.sh makes one) and ../shared/data/real.
#   scripts/navmesh_charts.sh [PAIRS] [SEED]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DEEPGUIDE_NAVMESH_PAIRS="${1:-200}" DEEPGUIDE_ENC_SEED="${2:-0}" \
  "$root/build/tests/test_charts" --gtest_filter='EncNavMesh.*'
