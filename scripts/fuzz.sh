#!/usr/bin/env bash
# The fuzzing soak (issue 25; docs/RELIABILITY.md). Builds every harness in
# fuzz/ with clang's libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer
# in build-fuzz/, then runs each for RUNS executions (default 10^6), each input
# limited to 10 s and 4 GiB, starting from a corpus seeded with the harness's
# seeds (fuzz/CMakeLists.txt). Prints a markdown row per harness: executions,
# seconds, corpus size, and findings (crash, leak, timeout or out-of-memory
# inputs, kept in build-fuzz/findings/).
#   scripts/fuzz.sh [RUNS] [HARNESS...]        e.g. scripts/fuzz.sh 1000000
#   scripts/fuzz.sh 20000 s57_cell mission_yaml
#   FUZZ_SECONDS=120 scripts/fuzz.sh 1000000   (each harness stops after 120 s if not done)
# CI does not run this (it takes hours); it replays the seeds and 1000 seeded
# mutations per harness through ctest instead (fuzz.* tests).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
runs="${1:-1000000}"
shift || true
DEEPGUIDE_PACKAGES+=(clang libclang-rt-14-dev)
deepguide_install_packages
build="$DEEPGUIDE_ROOT/build-fuzz"
cmake -S "$DEEPGUIDE_ROOT" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DDEEPGUIDE_LIBFUZZER=ON -DDEEPGUIDE_BUILD_TESTS=OFF >/dev/null
harnesses=("$@")
if [ ${#harnesses[@]} -eq 0 ]; then
  mapfile -t harnesses < <(ls "$DEEPGUIDE_ROOT"/fuzz/fuzz_*.cpp | sed 's|.*/fuzz_||; s|\.cpp$||')
fi
cmake --build "$build" -j "$(nproc)" --target $(printf 'fuzz_%s ' "${harnesses[@]}") >&2

# Each input goes to a scratch file: keep those in memory where there is a tmpfs.
if [ -z "${TMPDIR:-}" ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
echo "| harness | executions | seconds | exec/s | corpus files | findings |"
echo "|---|---:|---:|---:|---:|---|"
for h in "${harnesses[@]}"; do
  seeds="$build/seeds/$h" corpus="$build/corpus/$h" findings="$build/findings"
  mkdir -p "$seeds" "$corpus" "$findings"
  IFS=';' read -r -a listed <"$build/fuzz/seeds_$h.txt" || true
  for s in "${listed[@]}"; do
    if [ -d "$s" ]; then cp -f "$s"/* "$seeds"/; elif [ -f "$s" ]; then cp -f "$s" "$seeds"/; fi
  done
  log="$build/fuzz_$h.log"
  start=$(date +%s)
  status=0
  (cd "$build" && "./fuzz/fuzz_$h" "$corpus" "$seeds" -runs="$runs" -timeout=10 -rss_limit_mb=4096 \
     ${FUZZ_SECONDS:+-max_total_time=$FUZZ_SECONDS} -artifact_prefix="$findings/$h-" -print_final_stats=1) \
     >"$log" 2>&1 || status=$?
  seconds=$(( $(date +%s) - start ))
  done_runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  found=$(ls "$findings" 2>/dev/null | grep -c "^$h-" || true)
  rate=$(( seconds > 0 ? done_runs / seconds : done_runs ))
  note=$([ "$status" = 0 ] && echo "none" || echo "$found input(s) in build-fuzz/findings, exit $status (log: build-fuzz/fuzz_$h.log)")
  echo "| $h | $done_runs | $seconds | $rate | $(ls "$corpus" | wc -l) | $note |"
done
