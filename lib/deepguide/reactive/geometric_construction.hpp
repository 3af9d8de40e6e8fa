#pragma once
// (b) The seed's geometric construction of gradient lines (Eichhorn, UT'04 /
// IFAC 2005; the seed names only the sectors, so the rules below are a reconstruction).
//
// Zones: each object's security ellipse (reactive_method.hpp), not its
// enclosing circle: for an elongated object the circle a + d would double the
// detour, and tangents to an ellipse are as closed-form as to a circle (map to
// the unit circle, take the circle's tangents, map back; geometry/
// ellipse_tangents.hpp). For a disc both coincide.
//
// Sectors, for vehicle p and target g:
//   3  p inside a zone (the deepest one if several): leave it. The course the
//      construction gives just outside the nearest boundary point (sector 1's
//      tangent on the latched side, or sector 2's line to the target once that
//      is free), turned outward by beta (reactive_support.hpp): continuous with
//      the outside at the boundary, and a vehicle riding just inside still
//      leaves towards the target. Status leaving_zone.
//   2  the segment p -> g meets no zone's interior: course straight at g; the
//      side latch is released.
//   1  blocked: follow the tangent from p to the engaged zone on the latched
//      side sigma: the tangent point T (left tangent for sigma = +1, seen from p
//      looking at the centre), course along the zone's tangent line at T,
//      oriented by sigma (exact even when p is on the boundary and T = p).
//      On one disc this is the shortest path: tangent, arc at rate U/R, tangent.
// Side: the symmetry-axis rule with the course tie-break (reactive_support.hpp),
// latched when the object is first engaged and kept while it blocks the line
// of sight; released in sector 2. Inside a zone a latched side is kept even if
// the zone is a neighbour's (overlapping zones), so the rotation sense cannot
// flip between them.
//
// Several objects (the seed treats one; options (a) first zone on the line of sight,
// (b) merge, (c) virtual-target cascade):
//   - engaged zone = the latched one while it still blocks the line of sight,
//     else the first zone the line of sight enters (option a); hysteresis on
//     the object, so two zones at similar range cannot take turns;
//   - the tangent course itself is checked: if the segment p -> T enters
//     another zone, that zone's tangent on the same side is taken instead, and
//     so on (the virtual-target cascade, option c). Each step turns the course
//     further to the same side (the blocking zone's cone contains the previous
//     course), so the cascade ends within the number of zones; if it does not
//     find a free tangent, the vehicle is enclosed on that side: stalled.
//   - overlapping zones need no separate merge (option b): the cascade over
//     a chain of overlapping zones yields the tangent to their convex hull.
// A newly engaged object gets its own side from the axis rule (after passing
// one object the next may be passed on the other side, the shorter way).
//
// Sailing (ReactiveParams::turn_rate_limit known, as in every simulation):
// the construction of lines assumes a vehicle that takes each course at
// once; one that turns at most r sweeps U/r (19.6 m for DeepC at cruise)
// while it turns. Three rules, from traces of the Monte Carlo collisions:
//   - hysteresis: the engaged zone stays engaged until the line of sight
//     clears it by a band (a fifth of the margin, at least 1 m), and a
//     tangent must clear the other zones by the band (else the cascade goes
//     on); the sonar's noise flipped grazing lines between blocked and free,
//     the turn began late or the course flipped between two ways round;
//   - the turn checked: a course more than 20 deg off the present one is
//     sailed ahead as the vehicle turns (its turning rate going from the
//     present one, ReactiveInput::turn_rate, to the full rate with the closed
//     loop's lag, turn_lag_s; then straight for 2 U/r). If that cuts into a
//     zone by more than a fifth of the margin, the other side's construction
//     is taken when its turn keeps clear or cuts a fifth of the margin less
//     (at most 3 times per engaged object, or it could dither); if neither
//     side will do, for that step the course of a 24-way fan round the
//     vehicle nearest the construction's whose turn keeps clear (else the
//     one that cuts least). Checking the turn as an instant full-rate turn
//     missed the 4-7 s DeepC takes to build up a turn (10-15 m of straight
//     travel) and the turn it was already in;
//   - the release checked: when the way to the target comes free, a turn to
//     it of more than 20 deg that would cut a zone so keeps the engaged zone
//     engaged (its tangent held) until the turn to the target keeps clear;
//   - without a turning rate (0: the figures' gradient lines, a kinematic
//     vehicle) none of this applies: the seed's construction, exactly.

#include <span>

#include "deepguide/core/api.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/reactive/side_latch.hpp"

namespace DEEPGUIDE_API deepguide {

/// The method's own parameter, read from ReactiveParams::tuning (default and
/// range in its registry entry).
struct GeometricParams {
  /// Zones closer than this to each other (overlapping ones included) are
  /// passed as one: round the group, never through the gap
  /// ("geometric_passage_m", 20 m, >= 0). 20 m is about the DeepC-like
  /// vehicle's hard-over turning radius at cruise (19.6 m): a narrower gap
  /// between two zones is a pocket it cannot turn in. In 500 Monte Carlo
  /// scenarios: 17 collisions with 0 m, 1 with 10 m, none with 20 m
  /// (docs/SIMULATION.md).
  double passage_m;
};
GeometricParams geometric_params(const ReactiveParams& params);

/// What the method remembers: its side latch, and how often it changed the
/// side for the engaged object because the turn to the present one would
/// have cut into a zone (a few times at most, or it could dither).
struct GeometricMemory : SideLatch {
  int turn_switches = 0;
};

/// One step; the memory is a GeometricMemory.
ReactiveCommand geometric_command(const ReactiveParams& params, ReactiveMemory& memory, const ReactiveInput& input);

Vec2 geometric_gradient(const ReactiveParams& params, const Vec2& point, const Vec2& target,
                        std::span<const Ellipse> objects);

/// The method's registry entry (reactive_registry.hpp).
ReactiveMethodEntry geometric_method_entry();

}  // namespace deepguide
