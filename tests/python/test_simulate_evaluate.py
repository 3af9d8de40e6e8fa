"""deepguide.simulate, generate_suite and evaluate against the commands:
a trajectory equals `simulate -o`'s file (to its rounding) and its
statistics `simulate --json`; a suite equals `suite generate`'s; evaluate's
rows equal `evaluate`'s rows.csv row for row on 50 scenarios; bad input
raises the library's line."""

import csv
import json

import numpy as np
import pytest

import deepguide
from conftest import cli_json

# The trajectory CSV's decimals (simulation/trajectory_io.hpp): half a unit in the last place.
ROUNDING = {"time_s": 5e-4, "x_m": 5e-4, "y_m": 5e-4, "heading_deg": 5e-4, "course_cmd_deg": 5e-4,
            "rate_cmd_deg_s": 5e-5, "rate_ref_deg_s": 5e-5, "rate_deg_s": 5e-5, "speed_mps": 5e-5,
            "clearance_m": 5e-4}


@pytest.fixture(scope="module")
def suite(tmp_path_factory, cli):
    folder = tmp_path_factory.mktemp("suites")
    name = deepguide.generate_suite(folder / "py", scenarios=50, seed=77)
    cli("suite", "generate", folder / "cli", "--scenarios", 50, "--seed", 77, "--name", name)
    return folder


def test_a_suite_is_the_commands(suite):
    py, cl = suite / "py", suite / "cli"
    names = sorted(p.name for p in py.iterdir())
    assert names == sorted(p.name for p in cl.iterdir())
    assert len(names) == 51
    for n in names:
        assert (py / n).read_bytes() == (cl / n).read_bytes(), n


@pytest.mark.parametrize("method", ["geometric", "dipole", "potential"])
def test_a_trajectory_is_the_commands_file(suite, cli, tmp_path, method):
    scenario = suite / "py" / "scenario-0003.yaml"
    run = deepguide.simulate(scenario, method, seed=11)
    out = tmp_path / "t.csv"
    want = cli_json(cli("simulate", scenario, "--method", method, "--seed", 11, "-o", out, "--json"))
    assert run.to_dict() == want
    assert run.method == method and run.end == want["end"]
    with out.open() as f:
        rows = list(csv.DictReader(f))
    t = run.trajectory
    assert len(t) == len(rows) > 100
    for name, half in ROUNDING.items():
        file = np.array([float(r[name]) for r in rows])
        assert np.max(np.abs(t[name] - file)) <= half * (1 + 1e-9), name
    assert list(t["status"]) == [r["status"] for r in rows]
    assert list(t["sector"]) == [int(r["sector"]) for r in rows]
    assert list(t["course_unreachable"]) == [r["course_unreachable"] == "1" for r in rows]
    # The contacts the method was given: remembered for the whole run, so
    # they never drop, and they end at the run's count.
    assert np.all(np.diff(t["contacts"]) >= 0)
    assert t["contacts"][-1] == want["contacts"] > 0


def test_evaluate_rows_are_the_commands_rows(suite, cli, tmp_path):
    methods = "geometric,visibility"
    cli("evaluate", suite / "py", "--methods", methods, "-o", tmp_path / "cli", "--threads", 2, "--no-timing",
        "--no-report", "-q")
    seen = []
    run = deepguide.evaluate(suite / "py", methods.split(","), tmp_path / "py", threads=2, timing=False,
                             progress=lambda done, total: seen.append((done, total)))
    assert (tmp_path / "py" / "rows.csv").read_bytes() == (tmp_path / "cli" / "rows.csv").read_bytes()
    with (tmp_path / "cli" / "rows.csv").open() as f:
        rows = list(csv.DictReader(f))
    assert len(run.rows) == len(rows) == 100
    for got, want in zip(run.rows, rows):
        for name, value in want.items():
            if run.rows.dtype[name].kind in "iuf":
                assert got[name] == pytest.approx(float(value), abs=0, rel=0, nan_ok=True), name
            else:
                assert got[name] == value, name
    assert seen[-1] == (100, 100)
    results = json.loads((tmp_path / "cli" / "results.json").read_text())
    assert run.to_dict()["summary"] == results["summary"]
    assert "| geometric |" in run.summary_markdown()


def test_bad_input_raises_the_librarys_line(suite, tmp_path):
    with pytest.raises(deepguide.InputError, match="`method`"):
        deepguide.simulate(suite / "py" / "scenario-0000.yaml", "magnetic")
    with pytest.raises(deepguide.InputError, match="nowhere.yaml"):
        deepguide.simulate(tmp_path / "nowhere.yaml", "geometric")
    with pytest.raises(deepguide.InputError):
        deepguide.evaluate(suite / "py", "warp-drive", tmp_path / "x")
    with pytest.raises(deepguide.InputError):
        deepguide.generate_suite(tmp_path / "bad", scenarios=10, min_size=-1)


def test_a_run_draws_itself(suite, tmp_path):
    run = deepguide.simulate(suite / "py" / "scenario-0003.yaml", "geometric", seed=11)
    png = run._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 20000
    run.render(tmp_path / "run.svg")
    assert (tmp_path / "run.svg").read_text().lstrip().startswith("<?xml")
