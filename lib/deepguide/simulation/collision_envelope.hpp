#pragma once
// Whether a collision could have been avoided at all: the vehicle's turning
// envelope when the obstacle it hit first came into the sonar's view.
//
// A collision is unavoidable when, from the state in which the obstacle first
// entered the sonar's sector, neither hard-over turn keeps clear of the
// obstacle's true footprint: full rudder to port or to starboard (the rudder
// moving at its rate from where it was, the turning rate building from the
// present one), at the speed the vehicle had, in the current it was in, for
// one full circle. If either turn misses the obstacle, guidance that turned
// away at once would have missed it: the collision is avoidable, and it is
// the method's. Only the obstacle hit is considered: a neighbour that closes
// the escape does not make a collision unavoidable (the method should have
// kept out of such a pocket). Slowing down is not credited: DeepC's surge
// lags by 20 s, so within one circle it changes little.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/vehicle/vehicle_model.hpp"

namespace DEEPGUIDE_API deepguide {

struct CollisionCause {
  std::size_t obstacle = 0;  ///< index into the scenario's obstacles
  double time_s = 0.0;       ///< when the vehicle entered its footprint
  bool seen = false;         ///< it had been in the sonar's sector before
  double seen_time_s = 0.0;
  double seen_distance_m = 0.0;     ///< from the vehicle to the footprint then
  double escape_clearance_m = 0.0;  ///< the better hard-over turn's least clearance to it then (< 0: both hit it)
  bool unavoidable = false;
  std::string reason;  ///< one line, naming the obstacle
};

/// The least clearance to `footprint` of a hard-over turn to `side` (+1 port,
/// -1 starboard) from `state`, sailed for one full circle in a uniform
/// `current` (negative: the turn meets it).
double hard_over_clearance(const VehicleParams& vehicle, VehicleState state, const Ellipse& footprint,
                           const Vec2& current, int side);

/// Watches a run step by step: when each obstacle first enters the sonar's
/// sector, and the first collision.
class CollisionWatch {
 public:
  explicit CollisionWatch(const Scenario& scenario) : scenario_(scenario), first_seen_(scenario.obstacles.size()) {}
  /// The vehicle's state at one step (in time order).
  void observe(const VehicleState& state);
  /// The first collision and its cause; nullopt if there was none.
  const std::optional<CollisionCause>& cause() const { return cause_; }

 private:
  const Scenario& scenario_;
  std::vector<std::optional<VehicleState>> first_seen_;
  std::optional<CollisionCause> cause_;
};

}  // namespace deepguide
