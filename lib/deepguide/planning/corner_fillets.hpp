#pragma once
// A polyline's corners rounded on circles of radius R: the lines and arcs a
// vehicle that turns no tighter than R can sail.
//
// At corner P, with u the unit direction in, v the one out and theta the
// signed turn from u to v (left positive), the arc of radius R tangent to
// both legs touches them t = R tan(|theta| / 2) before and after P:
//   T1 = P - t u,  T2 = P + t v,  centre C = T1 + R n,
// n the unit normal of u towards the turn. The arc lies inside the corner,
// within R (1 / cos(theta / 2) - 1) of P. Two corners fit on one leg when
// their t's together are no longer than it; otherwise the polyline turns
// tighter than R there and no fillet of radius R follows it.
//
// The polygon graphs plan round zones whose corners are already rounded on
// circles of radius R (turn_rounding.hpp, rounded_zone_polygons), so their
// corners' fillets fit and stay out of the zones; route_check verifies it.

#include <cstddef>
#include <optional>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/route.hpp"

namespace DEEPGUIDE_API deepguide {

struct FilletedRoute {
  std::vector<RouteLeg> legs;  ///< lines and arcs, empty when a fillet did not fit
  /// The first corner (index into the polyline) whose fillet overlaps a
  /// neighbour's or runs past the route's end, when one does.
  std::optional<std::size_t> too_tight;
};

/// Where the fillets of two corners turning the same way overlap (a polygon
/// graph's route wrapping a zone polygon's short sides), the two become one
/// corner where the legs before and after them meet, turning by their sum,
/// until every fillet fits or no such pair is left (one next to an end, or
/// an S-bend). The joined corner lies outside the wrapped zone: a convex
/// chain's edges, extended, meet outside it; other zones must be checked.
/// The polyline as it was where nothing overlaps.
std::vector<Vec2> join_tight_corners(const std::vector<Vec2>& polyline, double radius);

/// The polyline with every corner rounded on radius R (> 0). Corners that
/// turn by less than 1e-9 rad are left as they are. Throws InputError for
/// fewer than two points, a non-finite point, or R not finite and > 0.
FilletedRoute fillet_corners(const std::vector<Vec2>& polyline, double radius);

}  // namespace deepguide
