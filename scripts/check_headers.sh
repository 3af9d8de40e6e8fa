#!/usr/bin/env bash
# Installs the Release build (build/, made by scripts/test.sh or setup.sh)
# into a scratch prefix and compiles every installed header on its own with
# nothing precompiled: the strict form of ctest's package_consumer test,
# which precompiles the third-party headers and leaves out the headers the
# library's own sources already compile first, to stay quick (this script
# takes about 5.5 minutes on 2 cores; tests/consumer/CMakeLists.txt).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build}"
cmake -DBUILD_DIR="$build" -DCONSUMER_DIR="$root/tests/consumer" -DWORK_DIR="$build/tests/consumer_strict" \
  -DSTRICT_HEADERS=ON -P "$root/tests/consumer/run_consumer.cmake"
echo "every installed header compiles on its own"
