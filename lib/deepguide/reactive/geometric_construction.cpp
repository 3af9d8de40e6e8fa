#include "deepguide/reactive/geometric_construction.hpp"

#include <optional>
#include <vector>

#include "deepguide/core/angles.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"
#include "deepguide/geometry/ellipse_tangents.hpp"
#include "deepguide/reactive/reactive_support.hpp"

namespace deepguide {
namespace {

using namespace reactive_detail;

struct Construction {
  Vec2 direction{0.0, 0.0};  ///< unit, zero when stalled
  int sector = 2;
  std::ptrdiff_t object = -1;
};

/// Objects move a little between scans (estimation noise); half the minor
/// semi-axis of the zone recognises the same one without confusing neighbours.
double match_radius(const Ellipse& zone) { return 0.5 * zone.b; }

/// The side for zone k: latched in `memory`, or fresh from the axis rule.
/// `keep_any` keeps a latched side even if it was latched for another zone.
int side_for(const std::vector<Ellipse>& zones, std::ptrdiff_t k, const Vec2& p, const Vec2& g,
             std::optional<double> course, ReactiveMemory* memory, bool keep_any) {
  const Ellipse& zone = zones[static_cast<std::size_t>(k)];
  const int fresh = (keep_any && memory && memory->side != 0) ? memory->side : axis_side(zone.center, g, p, course);
  if (!memory) return fresh;
  return latched_side(*memory, k, zone.center, match_radius(zone), fresh);
}

Construction construct(const std::vector<Ellipse>& zones, const Vec2& p, const Vec2& g, std::optional<double> course,
                       ReactiveMemory* memory, double blend, bool outside_only = false);

/// Sector 3: the outside course at the nearest boundary point, blended outward.
Construction leave_zone(const std::vector<Ellipse>& zones, std::ptrdiff_t k, const Vec2& p, const Vec2& g,
                        std::optional<double> course, ReactiveMemory* memory, double blend) {
  const Ellipse& zone = zones[static_cast<std::size_t>(k)];
  const int side = side_for(zones, k, p, g, course, memory, true);
  Vec2 x = project_to_ellipse(zone, p).point;
  Vec2 n = outward_normal(zone, x);
  if (zone.a == zone.b && (p - zone.center).norm() < 1e-9 * zone.a) {
    // At the very centre of a circle every boundary point is nearest: out on the passing side.
    n = static_cast<double>(side) * left_normal(unit_or_zero(g - zone.center));
    if (n.squaredNorm() == 0.0) n = zone.minor_dir();
    x = zone.center + zone.a * n;
  }
  // The outside course from the boundary point itself (its tangent is the boundary's), with the same
  // side (a copy of the latch: only this call's counts).
  ReactiveMemory probe{side, k, zone.center};
  Vec2 along = construct(zones, x, g, course, &probe, blend, true).direction;
  if (along.squaredNorm() == 0.0 || along.dot(n) < -1e-9) along = along_boundary(n, side);
  return {exit_direction(along, n, depth_fraction(zone, p), blend), 3, k};
}

/// `outside_only`: p is taken as outside every zone (the probe just outside a
/// boundary, which may lie in an overlapping zone): no sector 3 recursion.
Construction construct(const std::vector<Ellipse>& zones, const Vec2& p, const Vec2& g, std::optional<double> course,
                       ReactiveMemory* memory, double blend, bool outside_only) {
  if (!outside_only) {
    if (const std::ptrdiff_t inside = deepest_zone(zones, p); inside >= 0) {
      return leave_zone(zones, inside, p, g, course, memory, blend);
    }
  }
  std::ptrdiff_t active = -1;
  if (memory) {
    for (std::size_t i = 0; i < zones.size() && active < 0; ++i) {
      if (engaged_with(*memory, zones[i].center, match_radius(zones[i])) && segment_intersects(zones[i], p, g)) {
        active = static_cast<std::ptrdiff_t>(i);
      }
    }
  }
  if (active < 0) active = first_zone_hit(zones, p, g);
  if (active < 0) {
    if (memory) release(*memory);
    return {unit_or_zero(g - p), 2, -1};
  }
  // Cascade: the tangent segment p -> T must itself be free.
  auto cascade = [&](int side) -> Construction {
    std::ptrdiff_t k = active;
    for (std::size_t step = 0; step < zones.size(); ++step) {
      const Ellipse& zone = zones[static_cast<std::size_t>(k)];
      const std::optional<PointTangents> tangents = tangent_points(zone, p);
      const Vec2 touch = tangents ? (side > 0 ? tangents->left : tangents->right) : p;  // no tangents: on the boundary
      const std::ptrdiff_t blocker = first_zone_hit(zones, p, touch, k);
      if (blocker < 0) return {along_boundary(outward_normal(zone, touch), side), 1, k};
      k = blocker;
    }
    return {Vec2(0.0, 0.0), 1, active};
  };
  const Ellipse& engaged = zones[static_cast<std::size_t>(active)];
  if (memory && course && !engaged_with(*memory, engaged.center, match_radius(engaged))) {
    // A zone engaged afresh while under way: the side whose course is the
    // smaller turn from the present one. The axis rule alone can ask for a
    // 60 degree turn when a second zone blocks the first's tangent close by,
    // and a vehicle turning at most 5 deg/s sweeps ~20 m while it turns: into
    // the zone (the Monte Carlo's collisions). Far from the zones both rules
    // agree; an even split keeps the axis rule.
    const Construction left = cascade(+1), right = cascade(-1);
    auto turn = [&](const Construction& c) {
      return c.direction.squaredNorm() == 0.0 ? 4.0 : std::abs(wrap_pi(math_angle(c.direction) - *course));
    };
    const double tl = turn(left), tr = turn(right);
    const int side = std::abs(tl - tr) < 1e-9 ? axis_side(engaged.center, g, p, course) : tl < tr ? +1 : -1;
    latched_side(*memory, active, engaged.center, match_radius(engaged), side);
    return side > 0 ? left : right;
  }
  return cascade(side_for(zones, active, p, g, course, memory, false));
}

}  // namespace

ReactiveCommand geometric_command(const ReactiveParams& params, ReactiveMemory& memory, const ReactiveInput& input) {
  validate_input(params, input);
  const std::vector<Ellipse> zones = security_ellipses(input.objects, params.margin_m);
  const SteeringTarget target = steering_target(zones, input.target);
  if (auto stop = arrival_command(params, input, target)) {
    release(memory);
    return *stop;
  }
  const Construction c = construct(zones, input.position, target.point, input.course, &memory,
                                   params.exit_blend_fraction);
  const ReactiveStatus status = c.sector == 3 ? ReactiveStatus::leaving_zone : ReactiveStatus::ok;
  ReactiveCommand cmd = course_command(params, input, c.direction, status, c.object, target);
  cmd.sector = c.sector;
  return cmd;
}

Vec2 geometric_gradient(const ReactiveParams& params, const Vec2& point, const Vec2& target,
                        std::span<const Ellipse> objects) {
  validate_query(params, point, target, objects);
  const std::vector<Ellipse> zones = security_ellipses(objects, params.margin_m);
  const Vec2 g = steering_target(zones, target).point;
  return construct(zones, point, g, std::nullopt, nullptr, params.exit_blend_fraction).direction;
}

}  // namespace deepguide
