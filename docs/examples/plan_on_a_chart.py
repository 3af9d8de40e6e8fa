"""Plan across NOAA's US4MD81M (Chesapeake Bay) at 5 m and draw the route
over the chart's no-go areas with matplotlib.
    python3 plan_on_a_chart.py [CELL] [OUT.png]"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.patches import PathPatch
from matplotlib.path import Path

import deepguide

cell = sys.argv[1] if len(sys.argv) > 1 else "../shared/data/real/noaa-enc-US4MD81M/US4MD81M.000"
out = sys.argv[2] if len(sys.argv) > 2 else "route_on_chart.png"
route = deepguide.plan((-76.41, 38.87), (-76.35, 38.60), charts=[cell], depth=5)
fig, ax = plt.subplots(figsize=(6, 8))
for rings in route.outlines():  # the no-go at 5 m (land, shoals, hazards' discs), holes kept
    ax.add_patch(PathPatch(Path.make_compound_path(*map(Path, rings)), facecolor="0.7", linewidth=0))
ax.plot(route.lonlat[:, 0], route.lonlat[:, 1], color="tab:orange", linewidth=2,
        label=f"{route.graph}: {route.length_m / 1000:.1f} km, {len(route.lonlat)} waypoints")
(x0, y0), (x1, y1) = route.lonlat.min(axis=0), route.lonlat.max(axis=0)
ax.set_xlim(x0 - 0.05, x1 + 0.05)
ax.set_ylim(y0 - 0.03, y1 + 0.03)
ax.set_aspect(1 / 0.78)  # degrees of longitude are 0.78 of latitude's at 38.7 N
ax.set_xlabel("longitude")
ax.set_ylabel("latitude")
ax.legend(loc="lower left")
fig.savefig(out, dpi=110, bbox_inches="tight")
