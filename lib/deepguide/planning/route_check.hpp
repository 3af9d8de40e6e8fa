#pragma once
// The independent route checker: every planner's output is verified with it.
//
// It deliberately shares no geometry with the planners (they plan on enclosing
// polygons and tangent graphs); it measures each leg of the route against the
// obstacles' exact footprints through ObstacleField:
//   min_clearance = min over segments s, obstacles i of min_{x in s} sd_i(x)
//   safe          <=> min_clearance >= margin - tolerance
// The tolerance only absorbs rounding of a route planned to touch a safety
// zone; it is not a second margin.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "deepguide/world/water_volume.hpp"

namespace DEEPGUIDE_API deepguide {

struct RouteCheck {
  bool safe = true;               ///< every segment keeps >= margin - tolerance from every obstacle
  double min_clearance_m = 0.0;   ///< smallest segment clearance over the route (+inf if no obstacles)
  std::size_t worst_segment = 0;  ///< index of the segment (0 = first) where it occurs
  std::string worst_obstacle;     ///< obstacle_name of the nearest obstacle there ("" if none)
  Vec2 worst_point{0.0, 0.0};     ///< point of that segment closest to it
  double margin_m = 0.0;          ///< the field's safety margin, for the report
  std::size_t segments = 0;       ///< segments checked; 0 for a single-point route
  bool of_legs = false;           ///< check_route_legs: worst_segment counts lines and arcs ("leg N")

  /// One line without a verdict word, e.g. "segment 3 passes 1.27 m from
  /// obstacle 'c5' at (120.00, 45.50) (margin 5 m)", "segment 0 enters obstacle
  /// 'c1' (2.00 m deep) at (...) (margin 5 m)", "no obstacles (margin 5 m)".
  std::string describe() const;
};

/// Checks the polyline against the field. A single point is checked as the
/// degenerate segment 0. Throws InputError for an empty polyline or a waypoint
/// with NaN/inf coordinates (naming its index), std::invalid_argument for a
/// tolerance that is not finite and >= 0.
RouteCheck check_route(const std::vector<Vec2>& polyline, const ObstacleField& field, double tolerance = 1e-6);

/// Checks a route given as exact lines and arcs (RouteLeg): lines exactly,
/// arcs from their own curve (RouteLeg::core, offset_m, phi_from, phi_to),
/// sampled where needed: clearance is 1-Lipschitz, so between two samples s
/// apart it is at least their mean less s / 2, and a stretch is split until
/// that bound decides it to within `tolerance`. Also checks that consecutive
/// legs join (1 um). Throws InputError for no legs, non-finite points, or legs
/// that do not join.
RouteCheck check_route_legs(const std::vector<RouteLeg>& legs, const ObstacleField& field, double tolerance = 1e-6);

/// The checker for routes in depth (the octree graph's): every leg against
/// the water volume (the band, the sea floor exactly, each obstacle's zone and
/// top: world/water_volume.hpp) and against the dive angle. It shares the
/// volume's geometry with the planner, not the planner's cells.
struct DepthRouteCheck {
  bool safe = true;
  std::size_t segments = 0;
  std::size_t first_bad_segment = 0;  ///< the first leg that fails (when !safe)
  std::string problem;                ///< why, one line ("" when safe)
  double steepest_deg = 0.0;          ///< the steepest leg's angle from horizontal
  /// Smallest floor depth minus the route's depth over the route (+inf without a floor).
  double min_floor_gap_m = std::numeric_limits<double>::infinity();
  std::string describe() const;  ///< "leg 3 comes within 0.42 m of the sea floor ...", or a summary
};

/// Checks a route whose waypoints carry depth_m. Throws InputError for a
/// route without depths (or a different count), non-finite points, an
/// empty route, or a dive angle outside (0, 90) degrees.
DepthRouteCheck check_route_in_depth(const Route& route, const WaterVolume& volume, double max_dive_deg);

}  // namespace deepguide
