#include "deepguide/simulation/plant.hpp"

#include <limits>
#include <sstream>

#include "deepguide/core/error.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/currents/current_sampling.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"

namespace deepguide {
namespace {

// The field's current where the vehicle is (whose absence is an error, never a zero).
Vec2 field_current(const CurrentSampler& field, const std::string& source, double offset_s, const Vec2& p, double t) {
  const auto c = field.sample(p, offset_s + t);
  if (!c) {
    std::ostringstream s;
    s << "a current field covering the vehicle's track, got no value at x " << p.x() << ", y " << p.y() << " m, t " << t
      << " s";
    throw input_error({source, "", "current_file"}, s.str());
  }
  return *c;
}

}  // namespace

double NearestClearance::at(const Vec2& p) {
  if (obstacles_.empty()) return std::numeric_limits<double>::infinity();
  double best = signed_distance(obstacles_[nearest_].footprint, p);
  std::size_t best_i = nearest_;
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    if (i == nearest_) continue;
    const Ellipse& e = obstacles_[i].footprint;
    if ((p - e.centre).norm() - e.a >= best) continue;
    const double d = signed_distance(e, p);
    if (d < best) {
      best = d;
      best_i = i;
    }
  }
  nearest_ = best_i;
  return best;
}

Plant::Plant(const Scenario& sc, const Vec2& start, double heading, double speed_mps) : scenario_(sc) {
  if (const CurrentSampler* field = sc.current_field.get()) {
    field_fn_ = [field, &sc](const Vec2& p, double, double t) {
      return field_current(*field, sc.source, sc.current_time_offset_s, p, t);
    };
  }
  state_ = make_vehicle_state(start, sc.depth_m, heading, speed_mps, current_at(start, 0.0));
}

Vec2 Plant::current_at(const Vec2& p, double t) const {
  return field_fn_ ? field_fn_(p, scenario_.depth_m, t) : scenario_.current;
}

AutopilotOutput Plant::steer(const AutopilotSetpoint& setpoint) {
  const AutopilotOutput out = autopilot_step(scenario_.vehicle, autopilot_, state_, setpoint, current());
  command_ = out.command;
  return out;
}

void Plant::advance() {
  if (field_fn_) {
    step_vehicle(scenario_.vehicle, state_, command_, field_fn_);
  } else {
    step_vehicle(scenario_.vehicle, state_, command_, scenario_.current);
  }
}

}  // namespace deepguide
