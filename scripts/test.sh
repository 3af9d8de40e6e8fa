#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite.
#   scripts/test.sh              Release build in build/
#   scripts/test.sh --sanitize   AddressSanitizer + UndefinedBehaviorSanitizer build in build-sanitize/:
#                                the suites that take outside input, and the fuzz seeds (CI runs this)
#   scripts/test.sh --sanitize --all   every suite under the sanitizers (about an hour and a half on 2 cores)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
if [ "${1:-}" = "--sanitize" ]; then
  build="$DEEPGUIDE_ROOT/build-sanitize"
  # -O0 -g1: the sanitizer build is the largest part of CI's time. At -O1 the
  # template-heavy sources took 45 % longer to compile (enc_no_go.cpp: 96 s
  # against 52 s of CPU); the input suites it runs by default are not bound
  # by computation (the compute suites are, and time out at -O0: run them with
  # --all, which takes far longer). docs/PERFORMANCE.md, "CI". -g1 keeps the
  # line tables the sanitizers' stack traces need.
  all=OFF
  if [ "${2:-}" = "--all" ]; then all=ON; fi
  deepguide_setup "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O0 -g1" \
    -DDEEPGUIDE_SANITIZE=ON -DDEEPGUIDE_SANITIZE_ALL="$all"
  # A 16 MB quarantine (256 MB by default) still catches a use after free of
  # anything freed within the last few thousand allocations, and lets ASan
  # reuse freed memory instead of faulting in new pages.
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:quarantine_size_mb=16"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
else
  build="$DEEPGUIDE_ROOT/build"
  deepguide_setup "$build"
fi
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
