"""deepguide from Python: plan safe routes for an AUV among obstacles and on
sea charts, with the same library, the same checks and the same numbers as
the `deepguide` command (docs/PYTHON.md).

    >>> import deepguide
    >>> route = deepguide.plan((10.2405, 54.4470), (10.2640, 54.4560),
    ...                        obstacles=["data/sample_obstacles.geojson"])  # doctest: +SKIP
    >>> route.length_m, route.lonlat.shape                                  # doctest: +SKIP

Errors are exceptions with the library's one-line message: InputError (a
ValueError: bad input), NoRouteError (no safe route), ManoeuvreError,
PartialError. `plan` releases the GIL while it works, so threads plan in
parallel.
"""

import csv as _csv
import io as _io
import os as _os
import tempfile as _tempfile

import numpy as _np

from . import _deepguide
from ._deepguide import (
    Chart,
    CurrentField,
    Identification,
    InputError,
    ManoeuvreError,
    MissionCheck,
    MissionPlan,
    MissionRun,
    NoRouteError,
    Obstacles,
    PartialError,
    Route,
    RouteCheck,
    __version__,
    check_route,
    constant_current,
    generate_suite,
    graphs,
    mission_check,
    mission_export,
    mission_plan,
    mission_simulate,
    plan,
    read_chart,
    read_current,
    read_obstacles,
)

__all__ = [
    "Chart",
    "CurrentField",
    "Evaluation",
    "Identification",
    "InputError",
    "ManoeuvreError",
    "MissionCheck",
    "MissionPlan",
    "MissionRun",
    "NoRouteError",
    "Obstacles",
    "PartialError",
    "Route",
    "RouteCheck",
    "Simulation",
    "__version__",
    "check_route",
    "constant_current",
    "evaluate",
    "generate_suite",
    "graphs",
    "identify",
    "mission_check",
    "mission_export",
    "mission_plan",
    "mission_simulate",
    "plan",
    "read_chart",
    "read_current",
    "read_obstacles",
    "render_field",
    "render_identification",
    "render_mission",
    "render_simulation",
    "render_turn_rates",
    "seed_figure",
    "seed_figures",
    "simulate",
]


def _drawing(draw, path, format):
    """Calls `draw(file)`: into `path` (its extension says PNG or SVG), then
    None; or, when `path` is None, into a temporary file of `format` (png or
    svg), then the drawing's bytes."""
    if path is not None:
        draw(_os.fspath(path))
        return None
    if format not in ("png", "svg"):
        raise InputError(f"`format`: expected png or svg, got {format!r}")
    with _tempfile.TemporaryDirectory() as folder:
        file = _os.path.join(folder, "figure." + format)
        draw(file)
        with open(file, "rb") as f:
            return f.read()


def _route_render(self, path=None, *, draw_graph=False, format="png"):
    """Draws the route over its obstacles or chart, as `plan --render`: into
    `path` (.png or .svg), or, without one, as bytes of `format`."""
    return _drawing(lambda file: self._render(file, draw_graph), path, format)


Route.render = _route_render


def _png_of(thing):
    """`thing.render()` as PNG bytes: what a notebook shows."""
    return thing.render()


Route._repr_png_ = _png_of


def _chart_render(self, path=None, *, width=1200, title="", obstacles=(), format="png"):
    """Draws the chart as `deepguide render chart` does (depth shading, land,
    hazards, the no-go at its depth, scale bar, north arrow; `obstacles`
    files drawn over it): into `path` (.png or .svg), or as bytes of `format`."""
    files = [_os.fspath(o) for o in obstacles]
    return _drawing(lambda file: self._render(file, width, title, files), path, format)


Chart.render = _chart_render
Chart._repr_png_ = _png_of


def _mission_render(self, path=None, *, zoom=0.0, width=1200, title="", format="png"):
    """Draws the run as `mission simulate --render` does: the plan as it
    ended, the track (coloured where the reactive level steered), the objects
    found; `zoom` metres around the first of them when > 0. Into `path` (.png
    or .svg), or as bytes of `format`."""
    return _drawing(lambda file: self._render(file, zoom, width, title), path, format)


MissionRun.render = _mission_render
MissionRun._repr_png_ = _png_of


_ALL_METHODS = ("dipole", "geometric", "potential")


def _method_list(methods):
    return [methods] if isinstance(methods, str) else list(methods)


def render_field(scenario, method, path=None, *, width=1200, title="", format="png"):
    """A reactive method's gradient lines around a scenario's obstacles, as
    `deepguide render field` (the seed's Figs. 8 and 10): into `path` (.png
    or .svg), or as bytes of `format`."""
    return _drawing(lambda file: _deepguide._render_field(_os.fspath(scenario), method, file, width, title), path,
                    format)


def render_simulation(scenario, methods=_ALL_METHODS, path=None, *, width=1200, title="", format="png"):
    """The reactive methods simulated through a scenario and their tracks, as
    `deepguide render simulation` (the seed's Fig. 11)."""
    names = _method_list(methods)
    return _drawing(lambda file: _deepguide._render_simulation(_os.fspath(scenario), names, file, width, title),
                    path, format)


def render_turn_rates(scenario, methods=_ALL_METHODS, path=None, *, width=1200, title="", format="png"):
    """r_ref and r over time for each method, as `deepguide render
    turn-rates` (the seed's Fig. 12)."""
    names = _method_list(methods)
    return _drawing(lambda file: _deepguide._render_turn_rates(_os.fspath(scenario), names, file, width, title),
                    path, format)


def render_identification(scenario, path=None, *, mode="", width=1200, title="", format="png"):
    """An identification manoeuvre (`mode` align or around; empty: the
    scenario's) and its track, as `deepguide render identification`. A
    manoeuvre that fails is drawn all the same: its legend says so."""
    return _drawing(lambda file: _deepguide._render_identification(_os.fspath(scenario), mode, file, width, title),
                    path, format)


def render_mission(mission, path=None, *, as_written=False, width=1200, title="", format="png"):
    """A mission over its chart, as `deepguide render mission`: the plan with
    its evasions and identification laps and where conflicts began (or the
    plan `as_written`)."""
    return _drawing(lambda file: _deepguide._render_mission(_os.fspath(mission), file, width, title, as_written),
                    path, format)


def seed_figures(output, *, only=None, format="png", width=1200, data=None):
    """Draws the seed paper's Figs. 4, 6, 7, 8, 10, 11 and 12 (or those in
    `only`) into the folder `output`, as `deepguide figures`, from the bundled
    data (`data`: the folder holding data/; default: $DEEPGUIDE_DATA, the
    current folder, the source tree, the installed share/deepguide). Returns
    what `figures --json` prints: per figure its file, summary and facts."""
    return _deepguide._seed_figures(_os.fspath(output), list(only or []), format, width,
                                    "" if data is None else _os.fspath(data))


def seed_figure(number, *, format="png", width=1200, data=None):
    """One of the seed paper's figures (4, 6, 7, 8, 10, 11 or 12) as bytes of
    `format`."""
    with _tempfile.TemporaryDirectory() as folder:
        drawn = seed_figures(folder, only=[number], format=format, width=width, data=data)
        with open(drawn["figures"][0]["file"], "rb") as f:
            return f.read()


def _mission_track(self):
    """The track sailed (`mission_simulate`), a sample a second: a NumPy
    structured array of time_s, x_m, y_m (the mission's frame), lon, lat,
    depth_m, heading_deg (clockwise from north), along_m (the vehicle's place
    on the plan of the time) and reactive (the reactive level had control)."""
    columns = self._track_columns()
    return _np.rec.fromarrays([_np.asarray(columns[n]) for n in columns], names=list(columns))


MissionRun.track = property(_mission_track)


class Simulation:
    """One reactive run, as `deepguide simulate` makes it.

    trajectory: a NumPy structured array, one record per sample, with the
    trajectory CSV's fields and units (docs/SIMULATION.md) at full precision:
    time_s, x_m, y_m, heading_deg, course_cmd_deg, rate_cmd_deg_s,
    rate_ref_deg_s, rate_deg_s (turning rates clockwise positive), speed_mps,
    clearance_m, sector, status, course_unreachable, and contacts (the sonar
    contacts the method was given at that step; not in the CSV).
    to_dict(): the statistics as `simulate --json` prints them.
    """

    def __init__(self, compiled):
        self._run = compiled
        columns = compiled._columns()
        names = list(columns)
        arrays = [_np.asarray(columns[n]) if n != "status" else _np.array(columns[n], dtype="U24") for n in names]
        self.trajectory = _np.rec.fromarrays(arrays, names=names)

    end = property(lambda self: self._run.end, doc="Why the run ended (reached, collided, time_out, ...).")
    reached = property(lambda self: self._run.reached)
    collided = property(lambda self: self._run.collided)
    method = property(lambda self: self._run.method)

    def to_dict(self):
        return self._run.to_dict()

    def text(self):
        return self._run.text()

    def render(self, path=None, *, format="png"):
        """Draws the run over its scenario: into `path` (.png or .svg), or as
        bytes of `format`."""
        return _drawing(self._run._render, path, format)

    _repr_png_ = _png_of

    def __repr__(self):
        return f"Simulation(method={self.method!r}, end={self.end!r}, samples={len(self.trajectory)})"


def simulate(scenario, method, *, seed=None):
    """Runs a scenario file with one reactive method (dipole, geometric or
    potential), as `deepguide simulate SCENARIO --method METHOD [--seed N]`.
    The GIL is released while it runs. Raises InputError for a bad scenario."""
    return Simulation(_deepguide._simulate(_os.fspath(scenario), method, seed))


def _csv_column(values):
    """A CSV column as integers if every value is one, else as floats (an
    empty cell is NaN) if every value is one and some are there, else as text."""
    try:
        return _np.array([int(v) for v in values], dtype=_np.int64)
    except ValueError:
        pass
    if any(v != "" for v in values):
        try:
            return _np.array([float(v) if v != "" else _np.nan for v in values], dtype=_np.float64)
        except ValueError:
            pass
    return _np.array(values, dtype=str)


def _csv_table(text):
    """The library's CSV text (quoted fields included) as a structured array."""
    header, *body = list(_csv.reader(_io.StringIO(text)))
    columns = [_csv_column([row[k] for row in body]) for k in range(len(header))]
    return _np.rec.fromarrays(columns, names=header)


class Evaluation:
    """An evaluation run, as `deepguide evaluate` writes it to its folder.

    rows: a NumPy structured array, one record per scenario and method, with
    rows.csv's fields and values (a structured array rather than a list of
    dicts: columns are what one compares and plots, and pandas takes it as
    it is: pandas.DataFrame(evaluation.rows)).
    to_dict(): what results.json holds (summary per method, the seed's
    claims, every row); summary_markdown(): what `evaluate` prints.
    """

    def __init__(self, compiled):
        self._run = compiled
        self.rows = _csv_table(compiled._rows_csv())

    complete = property(lambda self: self._run.complete)

    def to_dict(self):
        return self._run.to_dict()

    def summary_markdown(self):
        return self._run.summary_markdown()

    def __repr__(self):
        return f"Evaluation(rows={len(self.rows)})"


def evaluate(suite, methods, output, *, threads=0, fresh=False, timing=True, report=False, progress=None,
             allow_skips=False, html=False):
    """Runs every scenario of `suite` (a folder, its suite.yaml or one
    scenario file) through `methods` ("geometric,dipole" or a list; planners
    as GRAPH[:SEARCH][:COST]) into the folder `output`, as `deepguide
    evaluate`; resumes a run there unless `fresh`. `progress(done, total)` is
    called after each row. The GIL is released while it runs.

    A run that skipped broken scenarios raises PartialError (its `evaluation`
    attribute holds the run, written all the same) unless `allow_skips`, as
    the command exits 4 unless --allow-skips. `html`: also the web maps of the
    scenarios where each method came closest to an obstacle or collided, in
    output/maps (as `evaluate --html`)."""
    if not isinstance(methods, str):
        methods = ",".join(methods)
    run = Evaluation(_deepguide._evaluate(_os.fspath(suite), methods, _os.fspath(output), threads, fresh, timing,
                                          report, progress, html))
    skipped = run._run._skipped_line()
    if skipped and not allow_skips:
        error = PartialError(skipped)
        error.evaluation = run
        raise error
    return run


def identify(scenario, *, mode="", check=True):
    """Runs a scenario's identify section (aligning in a current, or going
    around the object; `mode` align or around, empty: the scenario's), as
    `deepguide identify`. A manoeuvre that fails (overpowered by the current,
    a collision, out of time) raises ManoeuvreError with the command's line
    (its `identification` attribute holds the run) unless `check` is False;
    then the run's `failure` says it."""
    run = _deepguide.identify(_os.fspath(scenario), mode=mode)
    if check and run.failure:
        error = ManoeuvreError(run.failure)
        error.identification = run
        raise error
    return run
