#!/usr/bin/env bash
# Every graph is reached through its registry (planning/graph_registry.hpp):
# no code outside the registry and the graphs' own folders asks which graph
# it has by comparing GraphKind constants (it asks the entry's capabilities,
# or the graph's type with RouteGraph::as). A change that special-cases a
# graph again fails, naming the file and line. Tests are left out: a test may
# compare the kind it is parametrised with.
# Run by ctest (`registries`, and `registries_catches` on a fixture that breaks it).
#   scripts/check_registries.sh [ROOT]   (default: the repository; scans ROOT/lib and ROOT/apps)
set -euo pipefail
root="${1:-$(dirname "${BASH_SOURCE[0]}")/..}"
dirs=()
for d in lib apps; do [ -d "$root/$d" ] && dirs+=("$root/$d"); done
[ ${#dirs[@]} -gt 0 ] || { echo "$root: neither lib/ nor apps/ to scan"; exit 1; }
kind='(deepguide::)?GraphKind::[a-z_]+'
found="$(grep -rnE --include='*.cpp' --include='*.hpp' \
  "(==|!=)[[:space:]]*$kind|$kind[[:space:]]*(==|!=)|case[[:space:]]+$kind" "${dirs[@]}" |
  grep -vE '/deepguide/planning/(graph_registry\.(hpp|cpp)|graphs/)' || true)"
if [ -n "$found" ]; then
  while IFS= read -r line; do
    echo "${line%%:*}:$(cut -d: -f2 <<<"$line"): compares a graph kind outside the registry (ask graph_entry(kind).can or RouteGraph::as)"
  done <<<"$found"
  exit 1
fi
