#!/usr/bin/python3
"""The Python module's cost: its overhead over the same calls in C++, and
threads against one thread (issue 43; docs/PERFORMANCE.md).

    PYTHONPATH=build/python bench/python_plan.py build [QUERIES] [ROUNDS] [SEED]

200 random ellipses (bench_planning's sizes and density: semi-major 5-40 m,
ratio 0.2-1, in a square of 150 sqrt(200) m) written as a CSV in UTM 32N;
QUERIES random free pairs across it. Overhead: each query's median over
ROUNDS through deepguide.plan against bench_plan_request (the same
load_obstacles, parse_position and plan_route_request in C++), the ratio of
the medians. Threads: the queries planned by 1 thread and by 8
(ThreadPoolExecutor), wall clock, and the results compared.
"""

import concurrent.futures
import math
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time

import deepguide

build = sys.argv[1] if len(sys.argv) > 1 else "build"
queries_n = int(sys.argv[2]) if len(sys.argv) > 2 else 100
rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 5
seed = int(sys.argv[4]) if len(sys.argv) > 4 else 1
rng = random.Random(seed)
side = 150.0 * math.sqrt(200)
x0, y0 = 500000.0, 6000000.0
ellipses = []
for i in range(200):
    a = rng.uniform(5.0, 40.0)
    ellipses.append((x0 + rng.uniform(0, side), y0 + rng.uniform(0, side), a, a * rng.uniform(0.2, 1.0),
                     rng.uniform(0, 180)))


def free(p):
    for (cx, cy, a, b, th) in ellipses:
        if math.hypot(p[0] - cx, p[1] - cy) < a + 5.5:
            return False
    return True


tmp = tempfile.mkdtemp()
csv = os.path.join(tmp, "o.csv")
with open(csv, "w") as f:
    f.write("id,x,y,semi_major_m,semi_minor_m,orientation_deg\n")
    for i, e in enumerate(ellipses):
        f.write(f"e{i},{e[0]!r},{e[1]!r},{e[2]!r},{e[3]!r},{e[4]!r}\n")
queries = []
while len(queries) < queries_n:
    a = (x0 + rng.uniform(0, side), y0 + rng.uniform(0, side))
    b = (x0 + rng.uniform(0, side), y0 + rng.uniform(0, side))
    if free(a) and free(b) and math.dist(a, b) > side / 2:
        queries.append((a, b))
qfile = os.path.join(tmp, "q.txt")
with open(qfile, "w") as f:
    for a, b in queries:
        f.write(f"{a[0]!r},{a[1]!r} {b[0]!r},{b[1]!r}\n")

crs = "EPSG:32632"


def plan(q):
    try:
        return deepguide.plan(q[0], q[1], obstacles=[csv], crs=crs, src_crs=crs).length_m
    except deepguide.NoRouteError:
        return -1.0


# Overhead: per query, the median over the rounds, Python and C++ alternating by round.
cxx = subprocess.run([os.path.join(build, "bench", "bench_plan_request"), csv, qfile, crs, str(rounds)],
                     capture_output=True, text=True, check=True).stdout.split("\n")
cxx_ms = [float(line.split()[0]) for line in cxx if line]
cxx_len = [float(line.split()[1]) for line in cxx if line]
py_ms, py_len = [], []
for q in queries:
    times = []
    for _ in range(rounds):
        t0 = time.perf_counter()
        length = plan(q)
        times.append((time.perf_counter() - t0) * 1000)
    py_ms.append(statistics.median(times))
    py_len.append(length)
same = sum(1 for a, b in zip(py_len, cxx_len) if a == b or (a < 0 and b < 0))
print(f"overhead: {queries_n} queries, median of {rounds} each: Python {statistics.median(py_ms):.3f} ms, "
      f"C++ {statistics.median(cxx_ms):.3f} ms, ratio {statistics.median(py_ms) / statistics.median(cxx_ms):.3f}; "
      f"{same}/{queries_n} lengths equal")

# Threads: the queries `rounds` times over, one thread and eight, alternating.
work = queries * rounds
ones, eights, same = [], [], True
for _ in range(3):
    t0 = time.perf_counter()
    alone = [plan(q) for q in work]
    ones.append(time.perf_counter() - t0)
    with concurrent.futures.ThreadPoolExecutor(8) as pool:
        t0 = time.perf_counter()
        together = list(pool.map(plan, work))
        eights.append(time.perf_counter() - t0)
    same = same and alone == together
one, eight = statistics.median(ones), statistics.median(eights)
print(f"threads: {len(work)} queries, median of 3: 1 thread {one:.2f} s, 8 threads {eight:.2f} s, "
      f"throughput x{one / eight:.2f} on {os.cpu_count()} cores; results {'identical' if same else 'DIFFER'}")
