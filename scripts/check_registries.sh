#!/usr/bin/env bash
# Every graph and every reactive method is reached through its registry
# (planning/graph_registry.hpp, reactive/reactive_registry.hpp): no code
# outside a registry and the graphs' own folders or the methods' own files
# asks which one it has by comparing GraphKind or ReactiveMethod constants
# (it asks the entry: graph_entry(kind).can, RouteGraph::as,
# reactive_method_entry(method)). A change that special-cases a graph or a
# method again fails, naming the file and line. Tests are left out: a test
# may compare the kind it is parametrised with.
# Run by ctest (`registries`, and `registries_catches` on a fixture that breaks both).
#   scripts/check_registries.sh [ROOT]   (default: the repository; scans ROOT/lib and ROOT/apps)
set -euo pipefail
root="${1:-$(dirname "${BASH_SOURCE[0]}")/..}"
dirs=()
for d in lib apps; do [ -d "$root/$d" ] && dirs+=("$root/$d"); done
[ ${#dirs[@]} -gt 0 ] || { echo "$root: neither lib/ nor apps/ to scan"; exit 1; }
status=0
# check TYPE ALLOWED WHAT: comparisons (==, !=, case) of TYPE's constants outside ALLOWED (an ERE on paths).
check() {
  local constant="(deepguide::)?$1::[a-z_]+" allowed="$2" what="$3" found
  found="$(grep -rnE --include='*.cpp' --include='*.hpp' \
    "(==|!=)[[:space:]]*$constant|$constant[[:space:]]*(==|!=)|case[[:space:]]+$constant" "${dirs[@]}" |
    grep -vE "$allowed" || true)"
  [ -z "$found" ] && return 0
  while IFS= read -r line; do
    echo "${line%%:*}:$(cut -d: -f2 <<<"$line"): compares $what"
  done <<<"$found"
  status=1
}
check GraphKind '/deepguide/planning/(graph_registry\.(hpp|cpp)|graphs/)' \
  'a graph kind outside the registry (ask graph_entry(kind).can or RouteGraph::as)'
check ReactiveMethod '/deepguide/reactive/(reactive_registry|dipole_field|geometric_construction|potential_field)\.(hpp|cpp)' \
  'a reactive method outside the registry (ask reactive_method_entry(method))'
exit $status
