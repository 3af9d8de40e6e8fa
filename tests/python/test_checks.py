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
