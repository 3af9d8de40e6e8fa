#!/usr/bin/env bash
# Sails a mission's .bhv export with the real MOOS-IvP helm (pHelmIvP,
# uSimMarineV22, pMarinePIDV22; prebuilt in ../shared/tools/moos-ivp),
# headless, and compares the .alog with the plan: every phase in order to
# DG_DONE, no IVPHELM_ALLSTOP before it, the distance from the route along the
# legs and each phase's depth at its end (docs/MISSIONS.md, "MOOS-IvP").
# CI sails the short data/missions/moos_check.yaml in the same test.
#   scripts/moos_sail.sh [MISSION.yaml [KEEP_DIR]]
# KEEP_DIR (default out/moos_sail) receives the .bhv, the .moos, the .alog and
# sailed.png (the track over the plan; docs/images/moos_sailed.png is the
# sample mission's).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
build="$DEEPGUIDE_ROOT/build"
deepguide_setup "$build"
mission="$(realpath "${1:-$DEEPGUIDE_ROOT/data/missions/sample_mission.yaml}")"
keep="${2:-$DEEPGUIDE_ROOT/out/moos_sail}"
mkdir -p "$keep"
DEEPGUIDE_MOOS_MISSION="$mission" DEEPGUIDE_MOOS_KEEP="$(realpath "$keep")" \
  "$build/tests/test_mission" --gtest_filter='MoosHelm.TheRealHelmSailsTheExportToItsEnd'
echo "kept in $keep"
