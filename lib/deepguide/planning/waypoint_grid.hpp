#pragma once
// Open-water waypoints for routes in a current (plan --waypoint-grid M).
//
// Why: a visibility graph bends routes only at obstacle corners. That is
// exact for length, and for time and energy in a uniform current (both are
// then a norm of the displacement, so straight legs between corners are
// optimal), but where the current changes from place to place the cheapest
// route bends in open water: around the core of a jet, across a stream where
// it is narrow. A square lattice of extra vertices, `spacing_m` apart over a
// box, gives the search those bends; each joins the lattice points and
// corners it sees within link_radius() (2.3 spacings: the 16 directions
// (1,0), (1,1), (2,1), (1,2) and their mirrors), so every lattice edge is
// short and cheap to price, and start and goal join the lattice points
// within the same radius.
// The lattice is part of the graph's definition for a query (its box does
// not depend on the search), so the single-query bounds stay exact: the
// route is optimal over corners + lattice. A lattice of 16 directions does
// not approach the continuous optimum as it gets finer (1.0-1.7 % slower on
// a jet-plus-vortex field from 2000 m down to 500 m): it chooses the way, and
// route_refinement.hpp finds the line.

#include <cstddef>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

struct WaypointGrid {
  double spacing_m = 0.0;  ///< 0 = no lattice
  Vec2 min{0.0, 0.0};      ///< the box the lattice covers (local frame)
  Vec2 max{0.0, 0.0};

  /// Refused above this many lattice points (InputError naming `spacing_m`).
  static constexpr std::size_t kMaxPoints = 40000;

  bool active() const { return spacing_m > 0.0; }
  double link_radius() const { return 2.3 * spacing_m; }
  std::size_t columns() const;
  std::size_t rows() const;
  /// Point (i, j) of the lattice: min + spacing (i, j).
  Vec2 point(std::size_t i, std::size_t j) const;
};

/// The lattice over the box of start and goal widened on every side by a
/// third of their distance (at least two spacings): room for a route to bend
/// around a jet between them. Throws InputError for a spacing <= 0 or not
/// finite, or more than kMaxPoints points.
WaypointGrid waypoint_grid_for(const Vec2& start, const Vec2& goal, double spacing_m);

/// Checks a grid given directly (the same rules).
void validate(const WaypointGrid& grid);

}  // namespace deepguide
