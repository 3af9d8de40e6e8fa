#!/usr/bin/env bash
# Sets up, builds the benchmarks (Release) and runs them; figures belong in docs/PERFORMANCE.md.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
deepguide_setup "$DEEPGUIDE_ROOT/build" -DDEEPGUIDE_BUILD_BENCH=ON
for b in "$DEEPGUIDE_ROOT"/build/bench/bench_*; do
  [ -x "$b" ] && "$b" --benchmark_min_time=0.2 "$@"
done
