#!/usr/bin/env bash
# The library's layering (docs/ARCHITECTURE.md, "Layers"): each module may
# include only the modules below it in the document's drawing (its arrows,
# followed to the end). A change that makes a module reach up (core including planning, the
# reactive methods including the planners) fails, naming the file and line.
# Run by ctest (`layering`, and `layering_catches` on a fixture that breaks it).
#   scripts/check_layering.sh [LIB_DIR]   (default: lib; LIB_DIR/deepguide/<module>/...)
set -euo pipefail
lib="${1:-$(dirname "${BASH_SOURCE[0]}")/../lib}"
declare -A uses=(
  [core]=""
  [geometry]="core"
  [world]="core geometry"
  [currents]="core geometry world"
  [obstacle_files]="core geometry world"
  [charts]="core geometry obstacle_files world"
  [vehicle]="core currents geometry world"
  [planning]="charts core currents geometry obstacle_files vehicle world"
  [reactive]="core geometry"
  [identification]="core geometry reactive"
  [mission]="charts core currents geometry identification obstacle_files planning reactive vehicle world"
  [simulation]="charts core currents geometry identification mission obstacle_files planning reactive vehicle world"
  [render]="charts core currents geometry identification mission obstacle_files planning reactive simulation vehicle world"
  [evaluation]="charts core currents geometry identification mission obstacle_files planning reactive render simulation vehicle world"
)
bad=0
for dir in "$lib"/deepguide/*/; do
  module="$(basename "$dir")"
  if [ -z "${uses[$module]+known}" ]; then
    echo "$dir: a module docs/ARCHITECTURE.md does not place (add it to its table and to this script)"
    bad=1
    continue
  fi
  # file:line:module for every include of another deepguide module.
  while IFS=: read -r file line used; do
    [ "$used" = "$module" ] && continue
    if [[ " ${uses[$module]} " != *" $used "* ]]; then
      echo "$file:$line: $module includes $used (allowed: ${uses[$module]:-nothing})"
      bad=1
    fi
  done < <(grep -rnE '^#include "deepguide/[a-z_]+/' "$dir" |
    sed -E 's|^([^:]+):([0-9]+):#include "deepguide/([a-z_]+)/.*|\1:\2:\3|' || true)
done
exit "$bad"
