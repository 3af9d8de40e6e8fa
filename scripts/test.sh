#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite.
#   scripts/test.sh              Release build in build/
#   scripts/test.sh --sanitize   AddressSanitizer + UndefinedBehaviorSanitizer build in build-sanitize/
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
if [ "${1:-}" = "--sanitize" ]; then
  build="$DEEPGUIDE_ROOT/build-sanitize"
  # -O1 -g1: the sanitizer build is about half of CI's time; -O1 compiles the
  # template-heavy sources faster than -O2, and -g1 keeps the line tables the
  # sanitizers' stack traces need.
  deepguide_setup "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
    -DDEEPGUIDE_SANITIZE=ON
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
else
  build="$DEEPGUIDE_ROOT/build"
  deepguide_setup "$build"
fi
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
