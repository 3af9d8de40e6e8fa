#pragma once
// The plant every simulation drives (the reactive run, simulation.hpp, and
// the identification run, identification_run.hpp): the vehicle model, its
// autopilot and the water it moves in, stepped at the vehicle's fixed step h.
// A guidance unit asks for a course over ground, a speed and a depth; the
// plant turns that into rudder and thrust (autopilot_step, with the true
// current as its estimate) and integrates the vehicle (RK4) over one step.
//
// Time is counted, not summed: step k is at k h exactly (3000 x 0.1 is 300
// this way), so a stop rule fires on the step it names.
//
// The current is the scenario's: uniform, or its field sampled at the
// vehicle's position, depth and time. A field with no value where the vehicle
// is is an error (InputError naming the scenario), never a zero.
//
// Clearance: the signed distance (geometry/ellipse_distance.hpp, exact) from
// the position to the nearest TRUE footprint, negative inside. Per step the
// last nearest obstacle is measured first, and an obstacle is skipped when
// |p - c| - a (a lower bound of its signed distance, also inside) is not below
// the best so far: with 100 obstacles about one or two exact distances a step.

#include <cstddef>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/vehicle/autopilot.hpp"
#include "deepguide/vehicle/vehicle_model.hpp"

namespace DEEPGUIDE_API deepguide {

/// The exact clearance to the nearest of `obstacles`' footprints (header); +inf without obstacles.
class NearestClearance {
 public:
  explicit NearestClearance(const std::vector<EllipticCylinder>& obstacles) : obstacles_(obstacles) {}
  double at(const Vec2& p);
  /// The obstacle the last at() measured to (its index in `obstacles`).
  std::size_t nearest() const { return nearest_; }

 private:
  const std::vector<EllipticCylinder>& obstacles_;
  std::size_t nearest_ = 0;
};

class Plant {
 public:
  /// The vehicle at `start` on `heading` (math rad) at `speed_mps` through
  /// the water, at the scenario's depth, turning at 0, at time 0. `scenario`
  /// must outlive the plant.
  Plant(const Scenario& scenario, const Vec2& start, double heading, double speed_mps);

  /// Sets the time to step k (k h).
  void at_step(std::size_t k) { state_.time_s = static_cast<double>(k) * scenario_.vehicle.step_s; }
  const VehicleState& state() const { return state_; }
  double time_s() const { return state_.time_s; }

  /// The current at the vehicle now.
  Vec2 current() const { return current_at(state_.position, state_.time_s); }
  /// The autopilot's answer to `setpoint` (its memory advances).
  AutopilotOutput steer(const AutopilotSetpoint& setpoint);
  /// Integrates the vehicle over one step with the last steer()'s command.
  void advance();

 private:
  Vec2 current_at(const Vec2& p, double t) const;

  const Scenario& scenario_;
  CurrentFunction field_fn_;  // empty without a field
  VehicleState state_;
  AutopilotState autopilot_;
  VehicleCommand command_;
};

}  // namespace deepguide
