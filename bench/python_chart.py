#!/usr/bin/python3
"""A chart read once against a chart read for each query, from Python
(issue 43; docs/PERFORMANCE.md).

    PYTHONPATH=build/python bench/python_chart.py CHART DEPTH [QUERIES] [SEED]

Draws QUERIES random pairs in the chart's extent that plan (the draws that
have no route are skipped and counted), then plans each twice: with
plan(charts=[CHART], depth=DEPTH), which reads the files for the query as
`deepguide plan --chart` does, and with plan(charts=chart) on the Chart
read_chart made once. Prints the read's time, each way's median and worst
query, their ratio, and checks the lengths are equal bit for bit.
"""

import random
import statistics
import sys
import time

import deepguide

chart_path, depth = sys.argv[1], float(sys.argv[2])
queries_n = int(sys.argv[3]) if len(sys.argv) > 3 else 20
rng = random.Random(int(sys.argv[4]) if len(sys.argv) > 4 else 1)

t0 = time.perf_counter()
chart = deepguide.read_chart(chart_path, depth=depth)
read_s = time.perf_counter() - t0
e = chart.info()[0]["extent"]
pairs, skipped = [], 0
while len(pairs) < queries_n:
    a = (rng.uniform(e["west"], e["east"]), rng.uniform(e["south"], e["north"]))
    b = (rng.uniform(e["west"], e["east"]), rng.uniform(e["south"], e["north"]))
    try:
        deepguide.plan(a, b, charts=chart)
        pairs.append((a, b))
    except (deepguide.NoRouteError, deepguide.InputError):
        skipped += 1

once, each = [], []
for a, b in pairs:
    t0 = time.perf_counter()
    kept = deepguide.plan(a, b, charts=chart)
    once.append(time.perf_counter() - t0)
    t0 = time.perf_counter()
    fresh = deepguide.plan(a, b, charts=[chart_path], depth=depth)
    each.append(time.perf_counter() - t0)
    assert kept.length_m == fresh.length_m, (a, b, kept.length_m, fresh.length_m)

print(f"{chart_path} at {depth:g} m: {len(chart)} no-go polygons, read once in {read_s:.2f} s; "
      f"{len(pairs)} queries ({skipped} draws without a route skipped), lengths equal")
print(f"  read for each query: median {statistics.median(each) * 1000:.1f} ms, worst {max(each) * 1000:.1f} ms")
print(f"  on the chart read once: median {statistics.median(once) * 1000:.1f} ms, worst {max(once) * 1000:.1f} ms")
print(f"  ratio of the medians: x{statistics.median(each) / statistics.median(once):.1f}")
