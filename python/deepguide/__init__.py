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
    generate_suite,
    graphs,
    mission_check,
    mission_export,
    mission_plan,
    mission_simulate,
    plan,
    read_obstacles,
)

__all__ = [
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
    "evaluate",
    "generate_suite",
    "graphs",
    "identify",
    "mission_check",
    "mission_export",
    "mission_plan",
    "mission_simulate",
    "plan",
    "read_obstacles",
    "simulate",
]


def _png_of(thing):
    """`thing.render` to a temporary PNG, as bytes: what a notebook shows."""
    with _tempfile.TemporaryDirectory() as folder:
        path = _os.path.join(folder, "figure.png")
        thing.render(path)
        with open(path, "rb") as f:
            return f.read()


Route._repr_png_ = _png_of


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
    clearance_m, sector, status, course_unreachable.
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

    def render(self, path):
        """Draws the run over its scenario to `path` (.png or .svg)."""
        self._run.render(_os.fspath(path))

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
             allow_skips=False):
    """Runs every scenario of `suite` (a folder, its suite.yaml or one
    scenario file) through `methods` ("geometric,dipole" or a list; planners
    as GRAPH[:SEARCH][:COST]) into the folder `output`, as `deepguide
    evaluate`; resumes a run there unless `fresh`. `progress(done, total)` is
    called after each row. The GIL is released while it runs.

    A run that skipped broken scenarios raises PartialError (its `evaluation`
    attribute holds the run, written all the same) unless `allow_skips`, as
    the command exits 4 unless --allow-skips."""
    if not isinstance(methods, str):
        methods = ",".join(methods)
    run = Evaluation(_deepguide._evaluate(_os.fspath(suite), methods, _os.fspath(output), threads, fresh, timing,
                                          report, progress))
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
