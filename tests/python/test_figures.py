"""Every drawing of `deepguide render` and `deepguide figures` from Python:
the bytes equal the command's file (the same library call draws both), in a
process that has drawn other figures and formats before (a figure's bytes do
not depend on what was drawn earlier), and bad input is one line with
nothing written."""

import pytest

import deepguide
from conftest import SOURCE

PNG = b"\x89PNG\r\n\x1a\n"
SCENARIOS = SOURCE / "data" / "scenarios"
MISSIONS = SOURCE / "data" / "missions"


def test_reactive_figures_are_the_commands(cli, tmp_path):
    one, field = SCENARIOS / "one_obstacle.yaml", SCENARIOS / "obstacle_field.yaml"
    # An SVG first: the PNGs after it must not change for it.
    assert deepguide.render_field(one, "geometric", format="svg").lstrip().startswith(b"<?xml")
    cli("render", "field", one, "--method", "dipole", "-o", tmp_path / "field.png")
    assert deepguide.render_field(one, "dipole") == (tmp_path / "field.png").read_bytes()
    cli("render", "simulation", field, "--methods", "dipole,geometric", "-o", tmp_path / "sim.png")
    assert deepguide.render_simulation(field, ["dipole", "geometric"]) == (tmp_path / "sim.png").read_bytes()
    cli("render", "turn-rates", field, "--title", "Fig. 12", "-o", tmp_path / "rates.png")
    assert deepguide.render_turn_rates(field, title="Fig. 12") == (tmp_path / "rates.png").read_bytes()
    # Written to a path: nothing returned, the same bytes there.
    assert deepguide.render_field(one, "dipole", tmp_path / "py.png") is None
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "field.png").read_bytes()
    # One run's drawing, and what a notebook shows of it.
    run = deepguide.simulate(one, "potential")
    assert run.render()[:8] == PNG and run._repr_png_() == run.render()
    assert run.render(format="svg").lstrip().startswith(b"<?xml")


def test_identification_and_mission_figures_are_the_commands(cli, tmp_path):
    align = SCENARIOS / "align_in_current.yaml"
    cli("render", "identification", align, "--width", "800", "-o", tmp_path / "id.png")
    assert deepguide.render_identification(align, width=800) == (tmp_path / "id.png").read_bytes()
    mission = MISSIONS / "sample_mission.yaml"
    cli("render", "mission", mission, "-o", tmp_path / "m.png")
    assert deepguide.render_mission(mission) == (tmp_path / "m.png").read_bytes()
    cli("render", "mission", mission, "--as-written", "-o", tmp_path / "w.png")
    assert deepguide.render_mission(mission, as_written=True) == (tmp_path / "w.png").read_bytes()
    assert (tmp_path / "w.png").read_bytes() != (tmp_path / "m.png").read_bytes()
    # A simulated run drawn from the run in hand, as `mission simulate --render`.
    unknown = MISSIONS / "sample_unknown.geojson"
    cli("mission", "simulate", mission, "--unknown", unknown, "--planning-delay", "30", "--render",
        tmp_path / "run.png", "--zoom", "120")
    run = deepguide.mission_simulate(mission, unknown=[unknown], planning_delay=30)
    assert run.render(zoom=120) == (tmp_path / "run.png").read_bytes()


def test_seed_figures_are_the_commands(cli, tmp_path):
    cli("figures", "-o", tmp_path / "cli", "--only", "8")
    want = (tmp_path / "cli" / "fig08_dipole_gradient_lines.png").read_bytes()
    assert deepguide.seed_figure(8, data=SOURCE) == want
    drawn = deepguide.seed_figures(tmp_path / "py", only=[6, 8], data=SOURCE)
    assert [f["figure"] for f in drawn["figures"]] == [6, 8]
    assert (tmp_path / "py" / "fig08_dipole_gradient_lines.png").read_bytes() == want
    assert drawn["figures"][0]["facts"]["route_m"] > 0
    with pytest.raises(deepguide.InputError, match="5"):
        deepguide.seed_figure(5, data=SOURCE)
    with pytest.raises(deepguide.InputError, match="nowhere"):
        deepguide.seed_figure(8, data=tmp_path / "nowhere")


def test_bad_figure_input_is_one_line_and_writes_nothing(tmp_path):
    one = SCENARIOS / "one_obstacle.yaml"
    with pytest.raises(deepguide.InputError, match="`method`: expected dipole, geometric or potential, got 'magnet'"):
        deepguide.render_field(one, "magnet")
    with pytest.raises(deepguide.InputError, match="`methods`: expected at least one method"):
        deepguide.render_simulation(one, [])
    with pytest.raises(deepguide.InputError, match="`methods`: expected each method once, got 'dipole' twice"):
        deepguide.render_turn_rates(one, ["dipole", "dipole"])
    with pytest.raises(deepguide.InputError, match="`width`: expected 300 to 8000 pixels, got 10"):
        deepguide.render_field(one, "dipole", width=10)
    with pytest.raises(deepguide.InputError, match="`format`: expected png or svg, got 'jpg'"):
        deepguide.render_mission(MISSIONS / "sample_mission.yaml", format="jpg")
    with pytest.raises(deepguide.InputError, match="nowhere.yaml"):
        deepguide.render_identification(tmp_path / "nowhere.yaml")
    missing = tmp_path / "no" / "folder" / "f.png"
    with pytest.raises(deepguide.InputError, match="f.png"):
        deepguide.render_field(one, "dipole", missing)
    assert not (tmp_path / "no").exists()
    with pytest.raises(deepguide.InputError, match="f.gif"):
        deepguide.render_turn_rates(one, path=tmp_path / "f.gif")
    assert list(tmp_path.iterdir()) == []
