"""Missions from Python against `deepguide mission check|plan|export|simulate
--json`: the same reports, the same failures, the same files."""

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
