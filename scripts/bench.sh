#!/usr/bin/env bash
# Sets up, builds the benchmarks (Release) and runs them; figures belong in docs/PERFORMANCE.md.
# Usage: scripts/bench.sh [Google Benchmark flags...]
#   the Google Benchmark programs (bench_geometry) get --benchmark_min_time=0.2 and the flags given;
#   bench_planning prints markdown tables (build/bench/bench_planning --help; also
#   BENCH_PLANNING_ARGS="--quick"). Its OMPL peer needs Debian's libompl-dev, which
#   only this script installs, and only when it can (root or sudo); without it the
#   peer is left out and the run says so. bench_no_go takes no flags here
#   (build/bench/bench_no_go --help).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"

deepguide_install_ompl() {
  dpkg-query -W -f='${Status}' libompl-dev 2>/dev/null | grep -q "install ok installed" && return 0
  echo "deepguide: installing libompl-dev for the OMPL peer benchmark" >&2
  if [ "$(id -u)" -eq 0 ]; then
    { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends libompl-dev >/dev/null; } ||
      echo "deepguide: could not install libompl-dev; the OMPL peer is left out" >&2
  elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    { sudo apt-get update -qq && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends libompl-dev >/dev/null; } ||
      echo "deepguide: could not install libompl-dev; the OMPL peer is left out" >&2
  else
    echo "deepguide: libompl-dev is missing and this is not root; the OMPL peer is left out" >&2
  fi
}

deepguide_install_packages
deepguide_install_ompl
deepguide_setup "$DEEPGUIDE_ROOT/build" -DDEEPGUIDE_BUILD_BENCH=ON
read -r -a planning_args <<<"${BENCH_PLANNING_ARGS:-}"
for b in "$DEEPGUIDE_ROOT"/build/bench/bench_*; do
  [ -x "$b" ] || continue
  case "$(basename "$b")" in
    bench_planning) "$b" "${planning_args[@]}" ;;
    bench_reactive) "$b" ;;  # Monte Carlo over 500 scenarios x 3 methods, then the 1-hour throughput run
    bench_identification) (cd "$DEEPGUIDE_ROOT" && "$b") ;;  # the sample identify scenarios in 0..1 m/s currents
    bench_cost_planning) (cd "$DEEPGUIDE_ROOT" && "$b") ;;  # 100 random current fields, then HYCOM from ../shared
    bench_replanning) "$b" ;;  # D* Lite repair against A* from scratch, 2 km quadtree at 2 m
    bench_octree)  # one configuration per process: its peak RSS is the row's
      "$b" --header
      for args in "--min-cell 1 --dive 45" "--min-cell 1 --dive 30" "--min-cell 1 --dive 14" "--min-cell 2 --dive 45"; do
        read -r -a octree_args <<<"$args"
        "$b" "${octree_args[@]}"
      done ;;
    bench_no_go) "$b" ;;  # writes a 20000 x 20000 GeoTIFF in the temp folder (~1 GiB), then deletes it
    *) "$b" --benchmark_min_time=0.2 "$@" ;;
  esac
done
