"""deepguide.check_route and deepguide.identify against `deepguide check
route --json` and `deepguide identify --json`."""

import json

import pytest

import deepguide
from conftest import SOURCE, cli_json

FROM, TO = (10.240, 54.440), (10.265, 54.462)


def test_a_planned_route_checks_safe_and_a_straight_one_not(cli, sample, tmp_path):
    route = tmp_path / "r.geojson"
    cli("plan", "--obstacles", sample, "--from", f"{FROM[0]},{FROM[1]}", "--to", f"{TO[0]},{TO[1]}", "-o", route)
    ok = deepguide.check_route(route, obstacles=[sample])
    assert ok.safe and ok.waypoints >= 3
    assert ok.to_dict() == cli_json(cli("check", "route", route, "--obstacles", sample, "--json"))
    straight = tmp_path / "s.geojson"
    straight.write_text(json.dumps({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
                        "geometry": {"type": "LineString", "coordinates": [list(FROM), list(TO)]}}]}))
    bad = deepguide.check_route(straight, obstacles=[sample])
    assert not bad.safe and "'c" in bad.why
    assert bad.to_dict() == cli_json(cli("check", "route", straight, "--obstacles", sample, "--json", check=False))
    with pytest.raises(deepguide.InputError, match="operating depth"):
        deepguide.check_route(route, charts=[sample])


@pytest.mark.parametrize("mode,file", [("align", "align_in_current.yaml"), ("around", "around_object.yaml")])
def test_identify_is_the_commands(cli, mode, file):
    scenario = SOURCE / "data" / "scenarios" / file
    run = deepguide.identify(scenario, mode=mode)
    want = cli_json(cli("identify", scenario, "--mode", mode, "--json", check=False))
    assert run.to_dict() == want
    assert run.end == want["end"]
    with pytest.raises(deepguide.InputError, match="`mode`"):
        deepguide.identify(scenario, mode="hover")


def test_a_failed_manoeuvre_raises_the_commands_line(cli, tmp_path):
    text = (SOURCE / "data" / "scenarios" / "align_in_current.yaml").read_text()
    # Beside a copy of the vehicle file it names (../vehicles/deepc.yaml).
    (tmp_path / "vehicles").mkdir()
    (tmp_path / "vehicles" / "deepc.yaml").write_text((SOURCE / "data" / "vehicles" / "deepc.yaml").read_text())
    (tmp_path / "scenarios").mkdir()
    strong = tmp_path / "scenarios" / "strong.yaml"
    strong.write_text(text.replace('current: "1.0,100"', 'current: "3.5,100"'))
    done = cli("identify", strong, check=False)
    assert done.returncode == 3
    with pytest.raises(deepguide.ManoeuvreError) as raised:
        deepguide.identify(strong)
    assert str(raised.value) in done.stderr
    assert raised.value.identification.failure == str(raised.value)
    assert deepguide.identify(strong, check=False).failure == str(raised.value)


def test_a_run_that_skipped_a_broken_scenario_raises_partial_error(cli, tmp_path):
    deepguide.generate_suite(tmp_path / "s", scenarios=3, seed=4)
    (tmp_path / "s" / "scenario-0001.yaml").write_text("name: [broken\n")
    done = cli("evaluate", tmp_path / "s", "--methods", "geometric", "-o", tmp_path / "cli", "-q", "--no-report",
               check=False)
    assert done.returncode == 4
    with pytest.raises(deepguide.PartialError) as raised:
        deepguide.evaluate(tmp_path / "s", "geometric", tmp_path / "py")
    assert str(raised.value) in done.stderr
    assert len(raised.value.evaluation.rows) == 2
    assert len(deepguide.evaluate(tmp_path / "s", "geometric", tmp_path / "py", allow_skips=True).rows) == 2
