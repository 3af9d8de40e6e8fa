"""Missions from Python against `deepguide mission check|plan|export|simulate
--json`: the same reports, the same failures, the same files."""

import numpy as np
import pytest

import deepguide
from conftest import SOURCE, cli_json

SAMPLE = SOURCE / "data" / "missions" / "sample_mission.yaml"
UNKNOWN = SOURCE / "data" / "missions" / "sample_unknown.geojson"


def test_check_and_plan_report_what_the_command_does(cli):
    check = deepguide.mission_check(SAMPLE)
    assert check.to_dict() == cli_json(cli("mission", "check", SAMPLE, "--json", check=False))
    planned = deepguide.mission_plan(SAMPLE)
    done = cli("mission", "plan", SAMPLE, "--json")
    assert planned.to_dict() == cli_json(done)
    assert planned.failure is None
    assert planned.text() == cli("mission", "plan", SAMPLE).stdout
    assert "MissionPlan(file=" in repr(planned)


def test_export_writes_the_commands_file(cli, tmp_path):
    # The same file name in two folders: RTZ names the route after its file.
    (tmp_path / "py").mkdir()
    (tmp_path / "cli").mkdir()
    line = deepguide.mission_export(SAMPLE, tmp_path / "py" / "survey.rtz")
    cli("mission", "export", SAMPLE, "-o", tmp_path / "cli" / "survey.rtz")
    assert line.startswith("wrote ")
    assert (tmp_path / "py" / "survey.rtz").read_bytes() == (tmp_path / "cli" / "survey.rtz").read_bytes()


def test_a_simulated_mission_is_the_commands(cli):
    run = deepguide.mission_simulate(SAMPLE, unknown=[UNKNOWN], seed=3)
    want = cli_json(cli("mission", "simulate", SAMPLE, "--unknown", UNKNOWN, "--seed", 3, "--json", check=False))
    assert run.to_dict() == want


def test_a_missing_mission_is_bad_input(tmp_path):
    with pytest.raises(deepguide.InputError, match="nowhere.yaml"):
        deepguide.mission_plan(tmp_path / "nowhere.yaml")


def test_a_simulated_missions_track_is_an_array_that_adds_up():
    run = deepguide.mission_simulate(SAMPLE, unknown=[UNKNOWN], seed=3)
    t = run.track
    summary = run.to_dict()
    assert len(t) > 100
    assert t.dtype.names == ("time_s", "x_m", "y_m", "lon", "lat", "depth_m", "heading_deg", "along_m", "reactive")
    steps = np.diff(t["time_s"])
    assert np.all(steps > 0) and np.median(steps) == pytest.approx(1.0, abs=1e-6)
    assert t["time_s"][-1] <= summary["time_s"] + 1e-6
    # The samples, a second apart, cut the track's corners: no longer than it, and nearly as long.
    sampled = float(np.sum(np.hypot(np.diff(t["x_m"]), np.diff(t["y_m"]))))
    assert 0.98 * summary["length_m"] <= sampled <= summary["length_m"] + 1e-6
    assert t["reactive"].any() == any("reactive level" in e["what"] for e in summary["events"])
    assert np.all((t["heading_deg"] >= 0) & (t["heading_deg"] < 360))


def test_chart_options_reach_the_missions_and_the_route_check(cli, tmp_path):
    planned = deepguide.mission_plan(SAMPLE, zoc="none", restricted_areas=True)
    assert planned.to_dict() == cli_json(cli("mission", "plan", SAMPLE, "--zoc", "none", "--restricted", "--json"))
    for call in (lambda: deepguide.mission_check(SAMPLE, zoc="maybe"),
                 lambda: deepguide.mission_plan(SAMPLE, zoc="maybe"),
                 lambda: deepguide.mission_simulate(SAMPLE, zoc="maybe"),
                 lambda: deepguide.mission_export(SAMPLE, tmp_path / "m.rtz", zoc="maybe"),
                 lambda: deepguide.check_route(tmp_path / "r.gpx", zoc="maybe")):
        with pytest.raises(deepguide.InputError, match="`zoc`: expected clipped, strict or none, got 'maybe'"):
            call()
    with pytest.raises(deepguide.InputError, match="unassessed"):
        deepguide.mission_plan(SAMPLE, unassessed_zoc=(2, 0.05, -1))
    assert list(tmp_path.iterdir()) == []
