#pragma once
// What a straight leg costs in a sea current (docs/PLANNING.md, "Costs in a current"):
// its time and its propulsion energy, at a given speed through the water or
// at the speed that spends least energy on it. The building block of routes
// weighed by time or energy (plan --cost time|energy, issue 6).
//
// Crossing. Along the unit direction d, at speed v through the water, in the
// current c, the vehicle crabs so that its ground velocity lies along d; its
// ground speed is s = d.c + sqrt(v^2 - (d x c)^2) (vehicle/autopilot.hpp,
// ground_speed_along). No heading holds the line when v < |d x c|, and the
// current wins when s <= 0: the leg is then infeasible.
// Integration. The leg is cut into n = ceil(L / step_m) equal pieces and the
// current taken at each piece's middle (the midpoint rule: exact for a
// uniform current, error O(step^2) for a smooth one), so a current that
// changes along the leg counts where the vehicle meets it, not once at the
// leg's middle:
//   t = sum dl / s_k,   E = P(v) t,   P(v) = P_hotel + k v^3.
// Any infeasible piece makes the leg infeasible.
// Optimal speed. E(v) = P(v) sum dl / s_k(v) over v in [v_min, v_max] (v_min
// raised to what every piece needs to hold the line): Brent's minimisation
// (boost::math::tools::brent_find_minima, 52 bits). Brent finds a local
// minimum; in a uniform current E(v) has one, and the tests check the answer
// against a fine scan of v in currents that change along the leg.
//
// Admissible lower bounds for A*, c_max the fastest current
// anywhere: the ground speed never exceeds v + c_max, so for a route of
// length >= D (the straight distance)
//   time   >= D / (v + c_max)                              (v the speed used)
//   energy >= D * min over v in [v_min, v_max] of P(v) / (v + c_max)
// Both are a constant times the distance: consistent as well.

#include <functional>
#include <optional>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/vehicle/energy_model.hpp"

namespace DEEPGUIDE_API deepguide {

/// The current (m/s, local frame) at a point, steady.
using CurrentAt = std::function<Vec2(const Vec2&)>;

struct LegOptions {
  double step_m = 10.0;  ///< integration piece, > 0 (about half the current grid's spacing)
  EnergyModel energy;
};

struct LegCost {
  bool feasible = false;
  double length_m = 0.0;
  double time_s = 0.0;     ///< +inf when infeasible
  double energy_j = 0.0;   ///< +inf when infeasible
  double speed_mps = 0.0;  ///< through the water
};

/// The leg a -> b at `speed_mps` through the water. Throws InputError for a
/// speed <= 0, a step <= 0 or non-finite input.
LegCost leg_cost(const Vec2& a, const Vec2& b, double speed_mps, const CurrentAt& current,
                 const LegOptions& options = {});

/// The leg a -> b at the speed in [min_speed_mps, max_speed_mps] that spends
/// least energy on it (header); infeasible when no speed in the range holds the
/// line and makes way. Throws InputError for a bad range.
LegCost leg_cost_economical(const Vec2& a, const Vec2& b, double min_speed_mps, double max_speed_mps,
                            const CurrentAt& current, const LegOptions& options = {});

/// A current that changes in time: the velocity (m/s, local frame) at a point
/// and a time (seconds since the Unix epoch); std::nullopt where the field has
/// no value (the caller's adapter decides what that means, see cost_model.hpp).
using CurrentAtTime = std::function<std::optional<Vec2>(const Vec2&, double)>;

/// The leg a -> b at `speed_mps` leaving at `depart_s` in a current that
/// changes in time. The time is marched piece by piece (docs/PLANNING.md, "Time-dependent fields"):
/// t_{k+1} = t_k + dl / s(x_k, t_k + dl / (2 s(x_k, t_k))), the current taken
/// at the piece's middle in space and (by one predictor step) in time. A leg
/// is infeasible where the current has no value at a piece or at its arrival.
LegCost leg_cost_in_time(const Vec2& a, const Vec2& b, double speed_mps, double depart_s, const CurrentAtTime& current,
                         const LegOptions& options = {});

/// Lower bound of the time over `distance_m` at `speed_mps` with currents up to `max_current_mps`.
double time_lower_bound(double distance_m, double speed_mps, double max_current_mps);

/// Lower bound of the energy per metre with speeds in [min, max] and currents up to `max_current_mps`.
double energy_per_metre_lower_bound(const EnergyModel& energy, double min_speed_mps, double max_speed_mps,
                                    double max_current_mps);

}  // namespace deepguide
