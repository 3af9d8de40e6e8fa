#include "deepguide/planning/waypoint_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "deepguide/core/error.hpp"

namespace deepguide {

std::size_t WaypointGrid::columns() const {
  return active() ? static_cast<std::size_t>(std::floor((max.x() - min.x()) / spacing_m)) + 1 : 0;
}

std::size_t WaypointGrid::rows() const {
  return active() ? static_cast<std::size_t>(std::floor((max.y() - min.y()) / spacing_m)) + 1 : 0;
}

Vec2 WaypointGrid::point(std::size_t i, std::size_t j) const {
  return min + spacing_m * Vec2(static_cast<double>(i), static_cast<double>(j));
}

void validate(const WaypointGrid& grid) {
  if (grid.spacing_m == 0.0) return;
  char buf[160];
  if (!(grid.spacing_m > 0.0) || !std::isfinite(grid.spacing_m)) {
    std::snprintf(buf, sizeof buf, "`spacing_m`: expected a spacing > 0 m, got %g", grid.spacing_m);
    throw InputError(buf);
  }
  if (!grid.min.allFinite() || !grid.max.allFinite() || grid.max.x() < grid.min.x() || grid.max.y() < grid.min.y()) {
    throw InputError("`spacing_m`: expected a finite box with min <= max");
  }
  // In doubles first: a tiny spacing over a large box overflows size_t.
  const double points = (std::floor((grid.max.x() - grid.min.x()) / grid.spacing_m) + 1.0) *
                        (std::floor((grid.max.y() - grid.min.y()) / grid.spacing_m) + 1.0);
  if (points > static_cast<double>(WaypointGrid::kMaxPoints)) {
    std::snprintf(buf, sizeof buf,
                  "`spacing_m`: a %g m spacing puts %.0f points over the %.0f m x %.0f m search box; expected at "
                  "most %zu: give a spacing of at least %.0f m",
                  grid.spacing_m, points, grid.max.x() - grid.min.x(), grid.max.y() - grid.min.y(),
                  WaypointGrid::kMaxPoints,
                  std::ceil(std::sqrt((grid.max.x() - grid.min.x()) * (grid.max.y() - grid.min.y()) /
                                      static_cast<double>(WaypointGrid::kMaxPoints))) +
                      1.0);
    throw InputError(buf);
  }
}

WaypointGrid waypoint_grid_for(const Vec2& start, const Vec2& goal, double spacing_m) {
  WaypointGrid grid;
  grid.spacing_m = spacing_m;
  if (!std::isfinite(spacing_m) || spacing_m <= 0.0) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "`spacing_m`: expected a spacing > 0 m, got %g", spacing_m);
    throw InputError(buf);
  }
  const double pad = std::max((goal - start).norm() / 3.0, 2.0 * spacing_m);
  grid.min = start.cwiseMin(goal) - Vec2(pad, pad);
  grid.max = start.cwiseMax(goal) + Vec2(pad, pad);
  validate(grid);
  return grid;
}

}  // namespace deepguide
