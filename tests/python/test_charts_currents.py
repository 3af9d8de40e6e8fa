"""Charts and current fields read once (read_chart, read_current,
constant_current) against the command that reads them each time: the same
routes to 1e-9 m, the same chart facts, and a chart or field that cannot give
what a plan asks of it says so instead of planning on something else."""

import math

import numpy as np
import pytest

import deepguide
from conftest import SOURCE, cli_json, real_file

CELL = "noaa-enc-US4MD81M/US4MD81M.000"
PAIRS = [((-76.41, 38.87), (-76.35, 38.60)), ((-76.465, 38.554), (-76.472, 38.761)),
         ((-76.342, 38.427), (-76.42, 38.678))]


def text(p):
    return f"{p[0]!r},{p[1]!r}"


def test_a_chart_read_once_plans_what_the_command_plans(cli):
    cell = real_file(CELL)
    chart = deepguide.read_chart(cell, depth=5)
    assert chart.crs == "EPSG:32618" and chart.depth == 5 and chart.vertical_clearance == 2
    assert [f["kind"] for f in chart.files] == ["S-57 cell"]
    assert len(chart) == chart.files[0]["obstacles"] > 0
    for a, b in PAIRS:
        want = cli_json(cli("plan", "--chart", cell, "--depth", "5", "--from", text(a), "--to", text(b), "--json"))
        route = deepguide.plan(a, b, charts=chart)
        assert abs(route.length_m - want["length_m"]) <= 1e-9
        assert route.to_dict()["waypoints"] == want["waypoints"]
        # And as the files, read for this plan alone.
        again = deepguide.plan(a, b, charts=[cell], depth=5)
        assert again.length_m == route.length_m
    # What the chart holds is what `chart info` says of it.
    info = chart.info()
    want = cli_json(cli("chart", "info", cell, "--depth", "5", "--json"))
    want = want[0] if isinstance(want, list) else want
    for key in ("kind", "hazards", "land_features", "min_depth_m", "max_depth_m", "extent", "no_go", "local_crs"):
        assert info[0][key] == want[key], key
    # Its no-go outlines: one per obstacle, rings in lon/lat inside the cell.
    outlines = chart.outlines()
    assert len(outlines) == len(chart)
    e = want["extent"]
    for rings in outlines:
        for ring in rings:
            assert ring.ndim == 2 and ring.shape[0] >= 3 and ring.shape[1] == 2
            # (the no-go reaches a little past the cell: water it does not cover is no-go)
            assert e["west"] - 0.1 <= ring[:, 0].min() and ring[:, 0].max() <= e["east"] + 0.1
            assert e["south"] - 0.1 <= ring[:, 1].min() and ring[:, 1].max() <= e["north"] + 0.1


def test_chart_options_are_the_commands(cli):
    cell = real_file(CELL)
    a, b = PAIRS[1]
    exact = deepguide.read_chart(cell, depth=5, zoc="none")
    want = cli_json(cli("plan", "--chart", cell, "--depth", "5", "--zoc", "none", "--from", text(a), "--to", text(b),
                        "--json"))
    assert abs(deepguide.plan(a, b, charts=exact).length_m - want["length_m"]) <= 1e-9
    # Path charts take the same options.
    assert abs(deepguide.plan(a, b, charts=cell, depth=5, zoc="none").length_m - want["length_m"]) <= 1e-9
    # A restricted area across this pair's only water: no route, in the command's words.
    done = cli("plan", "--chart", cell, "--depth", "5", "--restricted", "--from", text(a), "--to", text(b),
               check=False)
    assert done.returncode == 3 and "MIPARE" in done.stderr
    with pytest.raises(deepguide.NoRouteError) as raised:
        deepguide.plan(a, b, charts=deepguide.read_chart(cell, depth=5, restricted_areas=True))
    assert str(raised.value) in done.stderr


def test_a_chart_says_what_it_cannot_give(tmp_path):
    cell = real_file(CELL)
    a, b = PAIRS[0]
    chart = deepguide.read_chart(cell, depth=5)
    for keywords, words in [({"depth": 7}, "`depth`: 7 m, but the chart was read with 5 m"),
                            ({"vertical_clearance": 1}, "`vertical_clearance`: 1 m"),
                            ({"zoc": "strict"}, "zones of confidence clipped, expected strict"),
                            ({"crs": "EPSG:32617"}, "`crs`: EPSG:32617, but the chart was read in EPSG:32618")]:
        with pytest.raises(deepguide.InputError, match=words):
            deepguide.plan(a, b, charts=chart, **keywords)
    # The same values as the chart's are no conflict.
    assert deepguide.plan(a, b, charts=chart, depth=5, vertical_clearance=2, zoc="clipped").length_m > 0
    # Read without a depth: drawn and described, not planned on.
    undepthed = deepguide.read_chart(cell)
    assert undepthed.depth is None
    with pytest.raises(deepguide.InputError, match="`depth`: expected the operating depth"):
        deepguide.plan(a, b, charts=undepthed)
    with pytest.raises(deepguide.InputError, match="`depth`"):
        undepthed.outlines()
    assert undepthed.render(format="svg").lstrip().startswith(b"<?xml")
    # Bad input: one line naming the file or the keyword.
    with pytest.raises(deepguide.InputError, match="nowhere.000"):
        deepguide.read_chart(tmp_path / "nowhere.000", depth=5)
    with pytest.raises(deepguide.InputError, match="`zoc`: expected clipped, strict or none, got 'maybe'"):
        deepguide.read_chart(cell, depth=5, zoc="maybe")
    with pytest.raises(deepguide.InputError, match="`depth`: expected an operating depth >= 0 m"):
        deepguide.read_chart(cell, depth=-1)
    with pytest.raises(deepguide.InputError, match="`depth`: expected an operating depth >= 0 m"):
        deepguide.read_chart(cell, depth=math.nan)
    with pytest.raises(deepguide.InputError):
        deepguide.read_chart(cell, depth=5, unassessed_zoc=(2, 1.5, 500))
    with pytest.raises(deepguide.InputError, match="`charts`: expected at least one"):
        deepguide.read_chart([], depth=5)


def test_a_chart_draws_as_the_command_draws_it(cli, tmp_path):
    cell = real_file(CELL)
    chart = deepguide.read_chart(cell, depth=5)
    cli("render", "chart", cell, "--depth", "5", "-o", tmp_path / "cli.png")
    assert chart.render() == (tmp_path / "cli.png").read_bytes()
    assert chart._repr_png_() == chart.render()
    assert chart.render(tmp_path / "py.svg") is None
    assert (tmp_path / "py.svg").read_bytes().lstrip().startswith(b"<?xml")
    with pytest.raises(deepguide.InputError, match="`format`: expected png or svg"):
        chart.render(format="gif")
    with pytest.raises(deepguide.InputError, match="figure.bmp"):
        chart.render(tmp_path / "figure.bmp")
    assert not (tmp_path / "figure.bmp").exists()


def test_a_current_field_read_once_plans_what_the_command_plans(cli, tmp_path):
    hycom = real_file("currents-hycom/hycom_glby_930_2019030712_t003_uv3z.nc")
    banks = tmp_path / "banks.geojson"
    banks.write_text("""{"type": "FeatureCollection", "features": [
      {"type": "Feature", "properties": {"id": "bank-a"}, "geometry": {"type": "Polygon", "coordinates":
        [[[-75.05, 34.90], [-74.95, 34.90], [-74.95, 35.00], [-75.05, 35.00], [-75.05, 34.90]]]}}]}""")
    a, b = (-74.80, 35.10), (-75.40, 34.60)
    field = deepguide.read_current(hycom)
    want = cli_json(cli("plan", "--obstacles", banks, "--from", text(a), "--to", text(b), "--current", hycom,
                        "--cost", "time", "--json"))
    route = deepguide.plan(a, b, obstacles=[banks], current=field, cost="time")
    assert abs(route.length_m - want["length_m"]) <= 1e-9
    assert abs(route.to_dict()["time_s"] - want["time_s"]) <= 1e-9
    assert deepguide.plan(a, b, obstacles=[banks], current=str(hycom), cost="time").length_m == route.length_m
    # The field's nodes come back exactly; between them it is bilinear; off them, NaN.
    grid = field.grid()
    assert grid["u"].shape == (max(1, len(grid["times_s"])), len(grid["y"]), len(grid["x"]))
    j, i = len(grid["y"]) // 2, len(grid["x"]) // 2
    assert field.geographic and field.crs == "EPSG:4326"
    at = field.at(np.array([[grid["x"][i], grid["y"][j]]]))
    assert at[0, 0] == grid["u"][0, j, i] and at[0, 1] == grid["v"][0, j, i]
    mid = field.at(np.array([[(grid["x"][i] + grid["x"][i + 1]) / 2, grid["y"][j]]]))[0, 0]
    assert mid == pytest.approx((grid["u"][0, j, i] + grid["u"][0, j, i + 1]) / 2, rel=1e-12)
    assert np.isnan(field.at(np.array([[0.0, 0.0]]))).all()
    summary = field.summary()
    assert summary["width"] == len(grid["x"]) and summary["height"] == len(grid["y"])
    assert summary["max_speed_mps"] == pytest.approx(want["max_current_mps"], rel=0.5)
    with pytest.raises(deepguide.InputError, match="`points`"):
        field.at(np.zeros((3, 3)))
    with pytest.raises(deepguide.InputError, match="nowhere.nc"):
        deepguide.read_current(tmp_path / "nowhere.nc")
    with pytest.raises(deepguide.InputError, match="`current`: expected a field .* or `current_const`, not both"):
        deepguide.plan(a, b, obstacles=[banks], current=field, current_const="0.5,45")


def test_a_constant_current_is_current_const(sample):
    a, b = (10.240, 54.440), (10.265, 54.462)
    field = deepguide.constant_current(0.5, 45)
    assert field.steady and field.summary()["max_speed_mps"] == 0.5
    east, north = field.at(np.array([[10.25, 54.45]]))[0]
    assert east == pytest.approx(0.5 * math.sin(math.radians(45)), abs=1e-15)
    assert north == pytest.approx(0.5 * math.cos(math.radians(45)), abs=1e-15)
    by_object = deepguide.plan(a, b, obstacles=[sample], cost="time", current=field)
    by_text = deepguide.plan(a, b, obstacles=[sample], cost="time", current_const="0.5,45")
    assert by_object.length_m == by_text.length_m
    assert by_object.to_dict()["time_s"] == by_text.to_dict()["time_s"]
    with pytest.raises(deepguide.InputError):
        deepguide.constant_current(-1, 0)
    assert SOURCE.exists()


def test_a_prepared_chart_read_once_plans_what_the_command_plans(cli, tmp_path):
    cell = real_file(CELL)
    prepared = tmp_path / "md5.gpkg"
    cli("chart", "prepare", cell, "--depth", "5", "-o", prepared)
    chart = deepguide.read_chart(prepared, depth=5)
    assert chart.crs == "EPSG:32618" and len(chart) > 0
    for a, b in PAIRS[:2]:
        want = cli_json(cli("plan", "--chart", prepared, "--depth", "5", "--from", text(a), "--to", text(b), "--json"))
        assert abs(deepguide.plan(a, b, charts=chart).length_m - want["length_m"]) <= 1e-9
    assert chart.render()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(deepguide.InputError, match="prepared for depth 5 m"):
        deepguide.read_chart(prepared, depth=7)


def test_a_route_and_a_chart_as_web_maps(cli, tmp_path):
    """to_html is the page the command writes: the same data (the page's
    JSON), hence the same layers, features and table."""
    cell = real_file(CELL)
    import re

    def data(page):
        return re.search(r'<script id="dg-data" type="application/json">(.*?)</script>', page, re.S).group(1)

    chart = deepguide.read_chart(cell, depth=5)
    a, b = PAIRS[0]
    route = deepguide.plan(a, b, charts=chart)
    page = route.to_html()
    cli("plan", "--chart", cell, "--depth", "5", "--from", text(a), "--to", text(b), "--html", tmp_path / "cli.html")
    assert data(page) == data((tmp_path / "cli.html").read_text())
    cli("render", "chart", cell, "--depth", "5", "--html", tmp_path / "chart.html")
    assert data(chart.to_html()) == data((tmp_path / "chart.html").read_text())
    with pytest.raises(deepguide.InputError, match="`depth`"):
        deepguide.read_chart(cell).to_html()
