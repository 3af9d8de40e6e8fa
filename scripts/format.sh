#!/usr/bin/env bash
# Formats the C++ sources with the repository's .clang-format (Debian's
# clang-format 14). --check: list the files that differ and exit 1.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
command -v clang-format >/dev/null || { echo "format.sh: install clang-format (apt-get install clang-format)" >&2; exit 1; }
mapfile -t files < <(git ls-files 'lib/*.cpp' 'lib/*.hpp' 'apps/*.cpp' 'apps/*.hpp' 'tests/*.cpp' 'tests/*.hpp' \
  'bench/*.cpp' 'bench/*.hpp' 'fuzz/*.cpp' 'fuzz/*.hpp' 'python/*.cpp' 'python/*.hpp')
if [ "${1:-}" = "--check" ]; then
  differ=0
  for f in "${files[@]}"; do
    if ! clang-format "$f" | cmp -s "$f" -; then echo "$f"; differ=1; fi
  done
  exit $differ
fi
clang-format -i "${files[@]}"
