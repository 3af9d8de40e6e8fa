#pragma once
// (c) Attractive/repulsive potentials (Khatib, "Real-time obstacle avoidance
// for manipulators and mobile robots", IJRR 5(1), 1986): the baseline whose
// weaknesses (local minima, oscillation in narrow passages; Koren & Borenstein,
// ICRA 1991) motivate the other two methods.
//
//   F(p) = unit(g - p) + sum_i m(rho_i) n_i
// Attraction: a cone potential |g - p|, i.e. a unit pull at any distance
// (the commanded speed is fixed, so only the direction matters, and a
// quadratic well would make the repulsion's reach depend on the range to the
// target). Repulsion of zone i (its security ellipse): rho_i the distance to
// it, n_i the unit outward direction from its nearest point,
//   U_rep = eta/2 (1/rho - 1/rho0)^2  for rho < rho0 = influence_m, else 0,
//   m(rho) = eta (1/rho - 1/rho0) / rho^2,   eta = potential_gain rho0^3 / 4,
// which puts the balance with the unit attraction, for gain 1, at
// rho = rho0 / 2 in front of a single zone.
//
// Status stalled where |F| < potential_stall_fraction: a local minimum (in
// front of a wide wall, in a U) or the point of balance on the axis of one
// zone (the saddle). A vehicle that follows the direction of F at constant
// speed oscillates about such a point rather than resting there; the
// threshold catches it within a step. A target closer to a zone than the
// balance distance is never reached (the "goal non-reachable with obstacles
// nearby" problem of potential fields): the vehicle stalls short of it.
// Inside a zone: straight out along the outward normal (pure repulsion, no
// blend: the baseline keeps its chatter), status leaving_zone.
// No memory: the method has no side to latch.

#include <span>

#include "deepguide/core/api.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/reactive/reactive_registry.hpp"

namespace DEEPGUIDE_API deepguide {

/// The method's own parameters, read from ReactiveParams::tuning (defaults
/// and ranges in its registry entry).
struct PotentialParams {
  double gain;            ///< repulsive gain relative to the unit attraction ("potential_gain", 1, > 0)
  double stall_fraction;  ///< stalled below this fraction of the unit attraction ("potential_stall_fraction", 0.05, in
                          ///< (0, 1))
};
PotentialParams potential_params(const ReactiveParams& params);

/// One step; the method keeps no memory (it empties the one it is given).
ReactiveCommand potential_command(const ReactiveParams& params, ReactiveMemory& memory, const ReactiveInput& input);

Vec2 potential_gradient(const ReactiveParams& params, const Vec2& point, const Vec2& target,
                        std::span<const Ellipse> objects);

/// The method's registry entry (reactive_registry.hpp).
ReactiveMethodEntry potential_method_entry();

}  // namespace deepguide
