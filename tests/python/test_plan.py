"""deepguide.plan against `deepguide plan --json`: the same inputs give the
same route (length to 1e-9 m, waypoints to 1e-9 degrees), the same report
keys and values; NumPy ellipses plan as the same obstacles read from a file;
bad input raises the library's one line as the right exception."""

import concurrent.futures
import json
import math
import random

import numpy as np
import pytest

import deepguide
from conftest import cli_json, real_file

FROM, TO = (10.240, 54.440), (10.265, 54.462)


def lonlat_text(p):
    return f"{p[0]!r},{p[1]!r}"


def test_version_is_the_commands(cli):
    assert cli("--version").stdout.split()[-1] == deepguide.__version__


@pytest.mark.parametrize("graph", ["visibility", "visibility-full", "tangent", "navmesh", "quadtree"])
def test_each_graph_plans_what_the_command_plans(cli, sample, tmp_path, graph):
    route = deepguide.plan(FROM, TO, obstacles=[str(sample)], graph=graph)
    out = tmp_path / "r.geojson"
    done = cli("plan", "--obstacles", sample, "--from", lonlat_text(FROM), "--to", lonlat_text(TO),
               "--graph", graph, "--json", "-o", out)
    want = cli_json(done)
    got = route.to_dict()
    assert route.graph == graph
    assert abs(route.length_m - want["length_m"]) <= 1e-9
    assert got.keys() == want.keys()
    for key in ("waypoints", "graph", "crs", "graph_vertices", "graph_edges", "min_clearance_m"):
        assert got[key] == want[key], key
    line = json.loads(out.read_text())["features"][0]["geometry"]["coordinates"]
    assert route.lonlat.shape == (len(line), 2)
    assert route.xy.dtype == np.float64
    assert np.max(np.abs(route.lonlat - np.array(line)[:, :2])) < 1e-9
    assert route.crs == want["crs"]
    assert repr(route).startswith("Route(length_m=")


def test_twenty_random_queries_equal_the_commands(cli, sample):
    rng = random.Random(20261207)
    compared = 0
    while compared < 20:
        a = (rng.uniform(10.238, 10.268), rng.uniform(54.438, 54.462))
        b = (rng.uniform(10.238, 10.268), rng.uniform(54.438, 54.462))
        done = cli("plan", "--obstacles", sample, "--from", lonlat_text(a), "--to", lonlat_text(b), "--json",
                   check=False)
        if done.returncode != 0:
            with pytest.raises((deepguide.NoRouteError, deepguide.InputError)) as raised:
                deepguide.plan(a, b, obstacles=[str(sample)])
            assert str(raised.value) in done.stderr
            continue
        assert deepguide.plan(a, b, obstacles=[str(sample)]).length_m == pytest.approx(
            cli_json(done)["length_m"], abs=1e-9)
        compared += 1


def test_enc_pairs_equal_the_commands(cli):
    cell = real_file("noaa-enc-US4MD81M/US4MD81M.000")
    # Pairs in the cell's water at 5 m (found by random draws), 13 to 34 km
    # apart, and one whose goal is charted too shallow.
    pairs = [((-76.41, 38.87), (-76.35, 38.60)), ((-76.465, 38.554), (-76.472, 38.761)),
             ((-76.385, 38.971), (-76.476, 38.672)), ((-76.411, 38.956), (-76.394, 38.682)),
             ((-76.439, 38.634), (-76.442, 38.519)), ((-76.342, 38.427), (-76.42, 38.678)),
             ((-76.40, 38.95), (-76.37, 38.70))]
    planned = 0
    for a, b in pairs:
        done = cli("plan", "--chart", cell, "--depth", 5, "--from", lonlat_text(a), "--to", lonlat_text(b),
                   "--json", check=False)
        if done.returncode != 0:
            with pytest.raises((deepguide.NoRouteError, deepguide.InputError)):
                deepguide.plan(a, b, charts=[str(cell)], depth=5)
            continue
        route = deepguide.plan(a, b, charts=[str(cell)], depth=5)
        assert route.graph == cli_json(done)["graph"] == "navmesh"
        assert route.length_m == pytest.approx(cli_json(done)["length_m"], abs=1e-9)
        planned += 1
    assert planned == 6


def test_an_array_of_ellipses_plans_as_the_same_obstacles_from_a_file(tmp_path):
    crs = "EPSG:32632"
    rows = np.array([[500000.0, 6000000.0, 40.0, 15.0, 30.0],
                     [500120.0, 6000040.0, 25.0, 25.0, 0.0],
                     [500260.0, 5999980.0, 60.0, 8.0, 115.0]])
    csv = tmp_path / "o.csv"
    csv.write_text("id,x,y,semi_major_m,semi_minor_m,orientation_deg\n" +
                   "".join(f"e{i},{r[0]!r},{r[1]!r},{r[2]!r},{r[3]!r},{r[4]!r}\n" for i, r in enumerate(rows)))
    start, goal = (499900.0, 6000000.0), (500400.0, 6000010.0)
    from_array = deepguide.plan(start, goal, ellipses=rows, crs=crs)
    from_file = deepguide.plan(start, goal, obstacles=[str(csv)], crs=crs, src_crs=crs)
    assert from_array.length_m > math.dist(start, goal) + 1.0
    assert from_array.length_m == pytest.approx(from_file.length_m, abs=1e-6)
    assert np.max(np.abs(from_array.xy - from_file.xy)) < 1e-6


def test_bad_input_raises_the_librarys_line(sample):
    with pytest.raises(deepguide.NoRouteError, match="'c1'"):
        deepguide.plan((10.240, 54.440), (10.2500, 54.4501), obstacles=[str(sample)])
    with pytest.raises(deepguide.InputError, match="`margin`") as raised:
        deepguide.plan(FROM, TO, obstacles=[str(sample)], margin=-3)
    assert isinstance(raised.value, ValueError)
    with pytest.raises(deepguide.InputError):
        deepguide.plan(FROM, FROM, obstacles=[str(sample)])
    with pytest.raises(deepguide.InputError, match="nowhere.geojson"):
        deepguide.plan(FROM, TO, obstacles=["nowhere.geojson"])
    with pytest.raises(deepguide.InputError, match="graph"):
        deepguide.plan(FROM, TO, obstacles=[str(sample)], graph="magic")
    with pytest.raises(deepguide.InputError, match=r"\(n, 5\)"):
        deepguide.plan((0.0, 0.0), (10.0, 0.0), ellipses=np.zeros((2, 4)), crs="EPSG:32632")
    with pytest.raises(deepguide.InputError, match="`crs`"):
        deepguide.plan((0.0, 0.0), (10.0, 0.0), ellipses=np.zeros((1, 5)))
    with pytest.raises(deepguide.InputError, match="`depth`"):
        deepguide.plan(FROM, TO, obstacles=[str(sample)], depth=-1)
    assert issubclass(deepguide.NoRouteError, RuntimeError)


def test_threads_plan_in_parallel_with_the_same_results(sample):
    rng = random.Random(7)
    queries = [((rng.uniform(10.238, 10.242), rng.uniform(54.438, 54.442)),
                (rng.uniform(10.262, 10.266), rng.uniform(54.458, 54.462))) for _ in range(8)]
    alone = [deepguide.plan(a, b, obstacles=[str(sample)]).length_m for a, b in queries]
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        together = list(pool.map(lambda q: deepguide.plan(*q, obstacles=[str(sample)]).length_m, queries))
    assert together == alone


def test_graphs_lists_the_registry():
    names = deepguide.graphs()
    for name in ("visibility", "visibility-full", "tangent", "quadtree", "navmesh"):
        assert name in names


def test_a_route_draws_as_the_command_draws_it(cli, sample, tmp_path):
    route = deepguide.plan(FROM, TO, obstacles=[str(sample)])
    route.render(tmp_path / "py.png")
    cli("plan", "--obstacles", sample, "--from", lonlat_text(FROM), "--to", lonlat_text(TO),
        "--render", tmp_path / "cli.png")
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()
    png = route._repr_png_()
    assert png == (tmp_path / "py.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(deepguide.InputError, match="figure.bmp"):
        route.render(tmp_path / "figure.bmp")


def test_headings_and_a_current_plan_as_the_command_plans(cli, sample):
    base = ["plan", "--obstacles", sample, "--from", lonlat_text(FROM), "--to", lonlat_text(TO), "--json"]
    dubins = deepguide.plan(FROM, TO, obstacles=[str(sample)], turn_radius=30, start_heading=90, goal_heading=0)
    want = cli_json(cli(*base, "--turn-radius", 30, "--from-heading", 90, "--to-heading", 0))
    assert dubins.graph == want["graph"] == "tangent"
    assert dubins.length_m == pytest.approx(want["length_m"], abs=1e-9)
    timed = deepguide.plan(FROM, TO, obstacles=[str(sample)], cost="time", current_const="0.5,45",
                           depart="2026-12-07T06:00:00Z")
    want = cli_json(cli(*base, "--cost", "time", "--current-const", "0.5,45", "--depart", "2026-12-07T06:00:00Z"))
    got = timed.to_dict()
    assert got["time_s"] == pytest.approx(want["time_s"], abs=1e-9)
    assert got["length_m"] == pytest.approx(want["length_m"], abs=1e-9)
    assert got["depart"] == want["depart"]
    with pytest.raises(deepguide.InputError, match="`current_const`"):
        deepguide.plan(FROM, TO, obstacles=[str(sample)], cost="time", current_const="fast")


def test_obstacles_read_into_arrays_plan_as_their_file(sample, tmp_path):
    obstacles = deepguide.read_obstacles([sample])
    assert len(obstacles) == len(obstacles.ellipse_ids) + len(obstacles.polygon_ids) > 0
    assert obstacles.ellipses.shape == (len(obstacles.ellipse_ids), 5)
    assert all(r.shape[1] == 2 for rings in obstacles.polygons for r in rings)
    # The ellipses alone, from their file and from the arrays read back.
    doc = json.loads(sample.read_text())
    doc["features"] = [f for f in doc["features"] if f["geometry"]["type"] == "Point"]
    points = tmp_path / "points.geojson"
    points.write_text(json.dumps(doc))
    read = deepguide.read_obstacles([points])
    from_file = deepguide.plan(FROM, TO, obstacles=[points])
    # With `crs`, start and goal are in it: the file route's own ends.
    start, goal = tuple(from_file.xy[0]), tuple(from_file.xy[-1])
    from_arrays = deepguide.plan(start, goal, ellipses=read.ellipses, crs=read.crs)
    assert from_arrays.length_m == pytest.approx(from_file.length_m, abs=1e-6)
    # The array's fields are the file's: orientation and axes as written.
    by_id = {f["properties"]["id"]: f["properties"] for f in doc["features"]}
    for name, row in zip(read.ellipse_ids, read.ellipses):
        assert row[2] == pytest.approx(by_id[name]["semi_major_m"], rel=1e-12)
        assert row[4] == pytest.approx(by_id[name]["orientation_deg"] % 180, abs=1e-9)
    assert "ellipses" in repr(read)


def test_arrays_of_polygons_plan_as_their_file(sample, tmp_path):
    obstacles = deepguide.read_obstacles([sample])
    assert obstacles.polygons, "the sample has a hazard area"
    from_file = deepguide.plan(FROM, TO, obstacles=[sample])
    start, goal = tuple(from_file.xy[0]), tuple(from_file.xy[-1])
    from_arrays = deepguide.plan(start, goal, ellipses=obstacles.ellipses, polygons=obstacles.polygons,
                                 crs=obstacles.crs)
    assert from_arrays.length_m == pytest.approx(from_file.length_m, abs=1e-6)
    # One ring alone is an outline; a ring that crosses itself is refused as a file's is.
    square = np.array([[0.0, 0.0], [0.0, 10.0], [10.0, 10.0], [10.0, 0.0]]) + [500000.0, 6000000.0]
    alone = deepguide.plan((499980.0, 6000005.0), (500030.0, 6000005.0), polygons=[square], crs="EPSG:32632")
    assert alone.length_m > 50.0
    bowtie = np.array([[0.0, 0.0], [10.0, 10.0], [10.0, 0.0], [0.0, 10.0]]) + [500000.0, 6000000.0]
    with pytest.raises(deepguide.InputError, match="polygon 0"):
        deepguide.plan((499980.0, 6000005.0), (500030.0, 6000005.0), polygons=[bowtie], crs="EPSG:32632")
