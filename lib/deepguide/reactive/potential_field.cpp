#include "deepguide/reactive/potential_field.hpp"

#include <vector>

#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/reactive/reactive_support.hpp"

namespace deepguide {
namespace {

using namespace reactive_detail;

struct Force {
  Vec2 value{0.0, 0.0};
  std::ptrdiff_t inside = -1;     ///< the zone p is deepest in, -1 none
  std::ptrdiff_t strongest = -1;  ///< the zone pushing hardest, -1 none
};

Force force(const std::vector<Ellipse>& zones, const Vec2& p, const Vec2& g, const ReactiveParams& params) {
  Force f;
  f.inside = deepest_zone(zones, p);
  if (f.inside >= 0) {
    const Ellipse& z = zones[static_cast<std::size_t>(f.inside)];
    f.value = outward_normal(z, p);
    if (f.value.squaredNorm() == 0.0) f.value = z.minor_dir();  // at the very centre
    f.strongest = f.inside;
    return f;
  }
  const double rho0 = params.influence_m;
  const double eta = potential_params(params).gain * rho0 * rho0 * rho0 / 4.0;
  f.value = unit_or_zero(g - p);
  double strongest = 0.0;
  for (std::size_t i = 0; i < zones.size(); ++i) {
    if ((p - zones[i].centre).norm() - zones[i].a >= rho0) continue;  // cheap: beyond the influence
    const EllipseProjection near = project_to_ellipse(zones[i], p);
    const double rho = near.distance;
    if (rho >= rho0 || rho <= 0.0) continue;  // rho = 0: on the boundary, no direction; the step after has one
    const double m = eta * (1.0 / rho - 1.0 / rho0) / (rho * rho);
    f.value += m * (p - near.point) / rho;
    if (m > strongest) {
      strongest = m;
      f.strongest = static_cast<std::ptrdiff_t>(i);
    }
  }
  return f;
}

}  // namespace

ReactiveCommand potential_command(const ReactiveParams& params, ReactiveMemory& memory, const ReactiveInput& input) {
  validate_input(params, input);
  memory.state.reset();  // the method remembers nothing
  const PotentialParams own = potential_params(params);
  const std::vector<Ellipse> zones = security_ellipses(input.objects, params.margin_m);
  const SteeringTarget target = steering_target(zones, input.target);
  if (auto stop = arrival_command(params, input, target)) return *stop;
  const Force f = force(zones, input.position, target.point, params);
  const bool stalled = f.inside < 0 && f.value.norm() < own.stall_fraction;
  const Vec2 direction = stalled ? Vec2(0.0, 0.0) : unit_or_zero(f.value);
  return course_command(params, input, direction, f.inside >= 0 ? ReactiveStatus::leaving_zone : ReactiveStatus::ok,
                        f.strongest, target);
}

Vec2 potential_gradient(const ReactiveParams& params, const Vec2& point, const Vec2& target,
                        std::span<const Ellipse> objects) {
  validate_query(params, point, target, objects);
  const std::vector<Ellipse> zones = security_ellipses(objects, params.margin_m);
  return unit_or_zero(force(zones, point, steering_target(zones, target).point, params).value);
}

namespace {

const ReactiveTuning kGain{"potential_gain", 1.0, 0.0, 1e6, false, true, "a gain"};
const ReactiveTuning kStall{"potential_stall_fraction", 0.05, 0.0, 1.0, false, false, "a fraction"};

}  // namespace

PotentialParams potential_params(const ReactiveParams& params) {
  return {tuning_value(params, kGain), tuning_value(params, kStall)};
}

ReactiveMethodEntry potential_method_entry() {
  return {"potential",       "attractive and repulsive potentials, the baseline",
          0x009e73,  // bluish green
          {kGain, kStall},   potential_command,
          potential_gradient};
}

}  // namespace deepguide
