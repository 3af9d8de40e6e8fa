#!/usr/bin/env bash
# No silent regressions: the planning benchmark and `evaluate` of two commits,
# run interleaved on this machine, as HEAD/BASE ratios.
#
#   scripts/bench_compare.sh BASE [HEAD]
#
# Builds BASE and HEAD (default: the checkout's HEAD commit) in temporary git
# worktrees, Release, only the CLI and bench_planning; the builds are kept by
# commit in $DEEPGUIDE_BENCH_CACHE (default ~/.cache/deepguide/bench-builds),
# so a second comparison against the same commit builds nothing. Then, ROUNDS
# times, BASE's run and HEAD's run one after the other (so drift in the
# machine's speed hits both alike):
#  - `bench_planning --no-peer --scenarios SCENARIOS` (the same seeded
#    scenarios in both: the benchmark draws them from fixed seeds);
#  - `deepguide evaluate` of one suite (`suite generate --scenarios 200 --seed
#    SUITE_SEED`, made once by HEAD's CLI) with each method of METHODS alone,
#    `--threads 2 --no-report --no-timing`, wall clock.
# Prints, for every table both commits' benchmarks print, each row they share
# (keyed by its leading columns: N, graph, ...) and each column in ms: the
# median of BASE's rounds, of HEAD's, and HEAD/BASE; then evaluate's seconds
# per method the same way. Ratios above 1.1 are marked "slower".
#
# Environment: ROUNDS (3), SCENARIOS (5), METHODS (visibility,tangent,geometric),
# SUITE_SEED (99), JOBS (2: parallel compile jobs), EVALUATE_BASE (default
# BASE: the commit whose `evaluate` is timed against HEAD's; issue 44 asks
# the planning tables against 58e4a16 and evaluate against 4257f9b, which
# `EVALUATE_BASE=4257f9b scripts/bench_compare.sh 58e4a16` gives in one run).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
[ $# -ge 1 ] || { sed -n '2,24p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 2; }
rounds="${ROUNDS:-3}"
scenarios="${SCENARIOS:-5}"
methods="${METHODS:-visibility,tangent,geometric}"
suite_seed="${SUITE_SEED:-99}"
jobs="${JOBS:-2}"
cache="${DEEPGUIDE_BENCH_CACHE:-$HOME/.cache/deepguide/bench-builds}"

base=$(git -C "$root" rev-parse --verify "$1^{commit}")
head=$(git -C "$root" rev-parse --verify "${2:-HEAD}^{commit}")
eval_base=$(git -C "$root" rev-parse --verify "${EVALUATE_BASE:-$1}^{commit}")
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"; git -C "$root" worktree prune' EXIT

# build SHA: the CLI and bench_planning of SHA in $cache/SHA (once).
build() {
  local sha="$1" out="$cache/$1"
  if [ -x "$out/bench/bench_planning" ] && [ -x "$out/apps/deepguide" ]; then return 0; fi
  echo "bench_compare: building ${sha:0:10} (once; kept in $out)" >&2
  local src="$tmp/src-$sha"
  git -C "$root" worktree add --detach -q "$src" "$sha"
  mkdir -p "$out"
  cmake -S "$src" -B "$out" -G Ninja -DCMAKE_BUILD_TYPE=Release -DDEEPGUIDE_BUILD_TESTS=OFF \
    -DDEEPGUIDE_BUILD_BENCH=ON >"$tmp/cmake-$sha.log" 2>&1 ||
    { tail -20 "$tmp/cmake-$sha.log" >&2; exit 1; }
  nice ninja -C "$out" -j "$jobs" bench_planning deepguide_cli >"$tmp/ninja-$sha.log" 2>&1 ||
    { tail -20 "$tmp/ninja-$sha.log" >&2; exit 1; }
  git -C "$root" worktree remove --force "$src"
}
build "$base"
build "$head"
build "$eval_base"

# evaluate is timed only where both CLIs have it with these options (older commits do not).
evaluate=1
for sha in "$eval_base" "$head"; do
  "$cache/$sha/apps/deepguide" evaluate --help 2>/dev/null | grep -q -- "--no-report" || evaluate=0
done
if [ "$evaluate" = 1 ]; then
  "$cache/$head/apps/deepguide" suite generate "$tmp/suite" --scenarios 200 --seed "$suite_seed" >/dev/null
else
  echo "bench_compare: one of the commits has no 'evaluate --no-report': evaluate is not timed" >&2
fi
: >"$tmp/evaluate.txt"

seconds() {  # runs "$@" quietly; prints its wall-clock seconds
  local t0 t1
  t0=$(date +%s.%N)
  "$@" >/dev/null 2>&1 || { echo "bench_compare: failed: $*" >&2; exit 1; }
  t1=$(date +%s.%N)
  echo "$t1 - $t0" | bc
}

IFS=',' read -r -a method_list <<<"$methods"
for r in $(seq "$rounds"); do
  for which in base head; do
    sha=$([ "$which" = base ] && echo "$base" || echo "$head")
    echo "bench_compare: round $r/$rounds, ${which} (${sha:0:10})" >&2
    "$cache/$sha/bench/bench_planning" --no-peer --scenarios "$scenarios" >"$tmp/$which-$r.md"
    [ "$evaluate" = 1 ] || continue
    if [ "$which" = base ]; then sha="$eval_base"; fi
    for m in "${method_list[@]}"; do
      rm -rf "$tmp/eval"
      s=$(seconds "$cache/$sha/apps/deepguide" evaluate "$tmp/suite" --methods "$m" --threads 2 --no-report \
        --no-timing -o "$tmp/eval")
      echo "$which $r $m $s" >>"$tmp/evaluate.txt"
    done
  done
done

echo "# bench_compare: HEAD ${head:0:10} / BASE ${base:0:10}"
echo
echo "$(uname -n), $(nproc) cores, $(date -u +%Y-%m-%d); $rounds interleaved rounds; bench_planning --no-peer" \
  "--scenarios $scenarios; medians over the rounds."
python3 - "$tmp" "$rounds" "${eval_base:0:10}" <<'PY'
import re, statistics, sys
tmp, rounds, eval_base = sys.argv[1], int(sys.argv[2]), sys.argv[3]

def tables(path):
    """{title: (header, {key: {column: value}})} for every markdown table of a run."""
    out, title, header = {}, None, None
    for line in open(path, encoding="utf-8"):
        line = line.rstrip("\n")
        if line.startswith("#"):
            title, header = line.lstrip("# ").strip(), None
            continue
        if not line.startswith("|"):
            header = None
            continue
        cells = [c.strip() for c in line.strip("|").split("|")]
        if header is None:
            header = cells
            out.setdefault(title, (header, {}))
            continue
        if set(line) <= set("|-: "):
            continue
        # The key: the columns before the first measurement ("n" or one in ms).
        k = next((i for i, h in enumerate(header) if h == "n" or " ms" in h or h.endswith("ms")), len(header))
        key = " | ".join(cells[:max(k, 1)])
        row = {}
        for h, c in zip(header, cells):
            if "ms" in h.split() or h.endswith(" ms") or "ms (" in h:
                m = re.match(r"\s*(-?[0-9.]+)", c)
                if m:
                    row[h] = float(m.group(1))
        out[title][1][key] = row
    return out

runs = {w: [tables(f"{tmp}/{w}-{r}.md") for r in range(1, rounds + 1)] for w in ("base", "head")}
def median_of(which, title, key, col):
    vals = [t[title][1][key][col] for t in runs[which]
            if title in t and key in t[title][1] and col in t[title][1][key]]
    return statistics.median(vals) if len(vals) == rounds else None

for title, (header, rows) in runs["head"][0].items():
    if title not in runs["base"][0]:
        continue
    lines = []
    for key, row in rows.items():
        for col in row:
            b, h = median_of("base", title, key, col), median_of("head", title, key, col)
            if b is None or h is None or b <= 0:
                continue
            ratio = h / b
            lines.append(f"| {key} | {col} | {b:.3f} | {h:.3f} | {ratio:.2f}{' slower' if ratio > 1.1 else ''} |")
    if lines:
        print(f"\n## {title}\n\n| row | column | BASE | HEAD | HEAD/BASE |\n|---|---|---:|---:|---:|")
        print("\n".join(lines))

ev = {}
lines = open(f"{tmp}/evaluate.txt").read().split("\n")
if not any(lines):
    print("\nevaluate: not timed (a commit without `evaluate --no-report`)")
    sys.exit(0)
for line in filter(None, lines):
    which, _, method, s = line.split()
    ev.setdefault(method, {}).setdefault(which, []).append(float(s))
print(f"\n## evaluate, 200 scenarios, one method at a time (s; BASE here is {eval_base})\n")
print("| method | BASE | HEAD | HEAD/BASE |\n|---|---:|---:|---:|")
for method, w in ev.items():
    b, h = statistics.median(w["base"]), statistics.median(w["head"])
    print(f"| {method} | {b:.2f} | {h:.2f} | {h / b:.2f}{' slower' if h / b > 1.1 else ''} |")
PY
