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

from ._deepguide import (
    InputError,
    ManoeuvreError,
    NoRouteError,
    PartialError,
    Route,
    __version__,
    graphs,
    plan,
)

__all__ = [
    "InputError",
    "ManoeuvreError",
    "NoRouteError",
    "PartialError",
    "Route",
    "__version__",
    "graphs",
    "plan",
]
