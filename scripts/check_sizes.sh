#!/usr/bin/env bash
# Lists the library's files over 600 lines and functions over 150 lines
# (issue 41: each file one concept, each function readable in one sitting).
# Functions and their extents come from universal-ctags (Debian's
# universal-ctags, which scripts/setup.sh installs). Exit 1 when anything is
# listed, 2 without ctags. Run by ctest (`sizes`).
#   scripts/check_sizes.sh [MAX_FILE_LINES [MAX_FUNCTION_LINES]]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
max_file="${1:-600}"
max_function="${2:-150}"
if ! command -v ctags >/dev/null || ! ctags --version 2>/dev/null | grep -q "Universal Ctags"; then
  echo "check_sizes: needs universal-ctags (apt-get install universal-ctags)" >&2
  exit 2
fi
found=0
while read -r lines file; do
  [ "$file" = total ] && continue
  if [ "$lines" -gt "$max_file" ]; then
    echo "file     $lines lines  $file"
    found=1
  fi
done < <(find lib -name '*.cpp' -o -name '*.hpp' | sort | xargs wc -l)
# ctags' tab-separated lines: name, file, pattern, kind, then line:N ... end:M.
while IFS= read -r row; do
  echo "$row"
  found=1
done < <(find lib -name '*.cpp' | sort | xargs ctags --c++-kinds=f --fields=+ne -f - 2>/dev/null |
  awk -F'\t' -v max="$max_function" '{
    start = 0; end = 0
    for (i = 4; i <= NF; ++i) {
      if ($i ~ /^line:/) start = substr($i, 6)
      if ($i ~ /^end:/) end = substr($i, 5)
    }
    if (start > 0 && end - start + 1 > max) printf "function %d lines  %s:%d %s\n", end - start + 1, $2, start, $1
  }' | sort -k2 -rn)
exit "$found"
