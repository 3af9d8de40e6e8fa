#pragma once
// Where a vehicle that cannot turn tighter than a radius R may turn round a
// safety zone.
//
// The tangent graph's routes wrap the zones along their boundaries, so a route
// turns as tightly as a zone's boundary is curved: round a polygon corner the
// zone is an arc of radius d (the margin), round an ellipse's tip one of
// b^2/a + d. Where that is below R, the route turns on a circle of radius R
// instead, one that holds the corner's zone, so the turn keeps at least d
// from the obstacle:
//   polygon corner v (convex as seen from the water), w its outward bisector:
//     centre v - (R - d) w, so |c - v| = R - d and the circle holds disc(v, d).
//   ellipse tip (b^2/a + d < R): centre on the major axis, R inside the
//     zone's tip, the circle tangent there. From the tip the zone's boundary
//     turns faster than the circle for as long as its radius is below R, so
//     that stretch stays inside the circle (a local form of Blaschke's rolling
//     theorem); the rest of the boundary has radius >= R.
// Each circle is pushed a micrometre outward so it holds the corner strictly.
// The circles are places to turn, not obstacles: a straight leg may cross
// them as long as it keeps the margin, so a straight channel stays open.
// What this gives up: a route turns round a corner only on its one circle, so
// one that bends a little there passes up to (R - d)(1 - cos a) wider than it
// must (a: half the corner's exterior angle), and no route turns with its
// circle centred anywhere else.

#include <cstddef>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct TurningCircle {
  Vec2 centre;
  std::size_t obstacle = 0;  ///< the obstacle whose corner it rounds (ellipses first, then polygons)
};

/// The circles of radius R (m) for margin d (m): none where the zone already
/// turns at R or wider (none at all when R <= d). Throws InputError when R is
/// not finite and > 0, or d not finite and >= 0.
std::vector<TurningCircle> turning_circles(const ObstacleSet& obstacles, double margin, double turn_radius);

/// Sides of the polygon round each turning circle in rounded_zone_polygons.
inline constexpr int kTurningPolygonSides = 32;

/// The polygon graphs' zones for a vehicle that turns no tighter than R:
/// `zones` (the enclosing zone polygons, vertices at most `tolerance` outside
/// the zones) joined with the regular 32-gon round each turning circle
/// widened to R + tolerance, which then holds those vertices about its corner
/// too. A route wrapping these polygons turns at a 32-gon's vertex by at most
/// 2 pi / 32, so its fillet of radius R there (corner_fillets.hpp) takes at
/// most R tan(pi / 32) of each side, less than half the side, and stays
/// outside the circle; elsewhere the zone turns no tighter than R. Unlike the
/// tangent graph's circles, these are obstacles: a leg may not cross one, so a
/// channel narrower than the circles leave open is closed to these graphs.
BgMultiPolygon rounded_zone_polygons(const BgMultiPolygon& zones, const ObstacleSet& obstacles, double margin,
                                     double turn_radius, double tolerance);

}  // namespace deepguide
