#include "deepguide/reactive/reactive_support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"
#include "deepguide/reactive/reactive_registry.hpp"

namespace deepguide {

void validate(const ReactiveParams& p) {
  auto check = [](bool ok, const char* field, const char* expected, double got) {
    require_param(ok, "reactive", field, expected, got);
  };
  auto finite = [](double v) { return std::isfinite(v); };
  check(finite(p.margin_m) && p.margin_m >= 0.0, "margin_m", "a margin >= 0 m", p.margin_m);
  check(finite(p.speed_mps) && p.speed_mps > 0.0, "speed_mps", "a speed > 0 m/s", p.speed_mps);
  check(finite(p.arrival_radius_m) && p.arrival_radius_m >= 0.0, "arrival_radius_m", "a radius >= 0 m",
        p.arrival_radius_m);
  check(finite(p.influence_m) && p.influence_m > 0.0, "influence_m", "a distance > 0 m", p.influence_m);
  check(finite(p.exit_blend_fraction) && p.exit_blend_fraction > 0.0 && p.exit_blend_fraction <= 1.0,
        "exit_blend_fraction", "a fraction in (0, 1]", p.exit_blend_fraction);
  if (p.turn_rate_limit) {
    check(finite(*p.turn_rate_limit) && *p.turn_rate_limit >= 0.0, "turn_rate_limit", "a rate >= 0 rad/s",
          *p.turn_rate_limit);
  }
  check(finite(p.turn_lag_s) && p.turn_lag_s >= 0.0, "turn_lag_s", "a time >= 0 s", p.turn_lag_s);
  for (const auto& [key, value] : p.tuning) {
    const ReactiveTuning* t = reactive_tuning(key);
    if (t == nullptr) {
      std::string names;
      for (const ReactiveTuning& d : reactive_tunings()) names += (names.empty() ? "" : ", ") + d.key;
      throw InputError("reactive: tuning '" + printable(key) + "': expected a parameter a method declares (" + names +
                       ")");
    }
    if (!(finite(value) && t->holds(value))) check(false, key.c_str(), t->expected().c_str(), value);
  }
}

Ellipse security_ellipse(const Ellipse& object, double margin_m) {
  Ellipse zone = object;
  zone.a = object.a + margin_m;
  zone.b = std::sqrt(zone.a * (margin_m + object.b * object.b / object.a));
  // A circle must come out a circle, not a hair smaller through rounding.
  zone.b = std::min(std::max(zone.b, object.b + margin_m), zone.a);
  return zone;
}

namespace reactive_detail {
namespace {

void require_point(const Vec2& p, const char* field) {
  if (std::isfinite(p.x()) && std::isfinite(p.y())) return;
  std::ostringstream text;
  text << "(" << p.x() << ", " << p.y() << ")";
  throw input_error({"reactive", "", field}, "a finite point", text.str());
}

void require_objects(std::span<const Ellipse> objects) {
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const Ellipse& e = objects[i];
    const bool ok = std::isfinite(e.centre.x()) && std::isfinite(e.centre.y()) && std::isfinite(e.a) &&
                    std::isfinite(e.b) && std::isfinite(e.theta) && e.b > 0.0 && e.a >= e.b;
    if (ok) continue;
    std::ostringstream text;
    text << "a = " << e.a << ", b = " << e.b << ", theta = " << e.theta;
    throw input_error({"reactive", "object " + std::to_string(i), "semi axes"},
                      "finite semi-axes a >= b > 0 and a finite centre and orientation", text.str());
  }
}

}  // namespace

void validate_query(const ReactiveParams& params, const Vec2& point, const Vec2& target,
                    std::span<const Ellipse> objects) {
  validate(params);
  require_point(point, "position");
  require_point(target, "target");
  require_objects(objects);
}

void validate_input(const ReactiveParams& params, const ReactiveInput& input) {
  validate_query(params, input.position, input.target, input.objects);
  if (!std::isfinite(input.course)) {
    throw input_error({"reactive", "", "course"}, "a finite course", std::to_string(input.course));
  }
  if (!std::isfinite(input.turn_rate)) {
    throw input_error({"reactive", "", "turn_rate"}, "a finite turning rate", std::to_string(input.turn_rate));
  }
}

std::vector<Ellipse> security_ellipses(std::span<const Ellipse> objects, double margin_m) {
  std::vector<Ellipse> zones;
  zones.reserve(objects.size());
  for (const Ellipse& e : objects) zones.push_back(security_ellipse(e, margin_m));
  return zones;
}

double zone_gap(const Ellipse& e1, const Ellipse& e2) {
  // Alternating projections onto two convex sets converge to a closest pair.
  auto project_onto = [](const Ellipse& e, const Vec2& x) {
    return e.contains(x) ? x : project_to_ellipse(e, x).point;
  };
  Vec2 x = e2.centre;
  Vec2 y = project_onto(e1, x);
  for (int i = 0; i < 64; ++i) {
    x = project_onto(e2, y);
    const Vec2 y_next = project_onto(e1, x);
    if ((y_next - y).norm() < 1e-9 * (1.0 + e1.a)) break;
    y = y_next;
  }
  return (x - y).norm();
}

SteeringTarget steering_target(std::span<const Ellipse> zones, const Vec2& target) {
  SteeringTarget out{target, false};
  // Overlapping zones can hand the point back and forth; a few rounds settle
  // every practical case and the result is still a point near the target.
  for (std::size_t round = 0; round <= zones.size() && round < 8; ++round) {
    const std::ptrdiff_t k = deepest_zone(zones, out.point);
    if (k < 0) break;
    const Ellipse& zone = zones[static_cast<std::size_t>(k)];
    const EllipseProjection near = project_to_ellipse(zone, out.point);
    Vec2 n = outward_normal(zone, near.point);
    out.point = near.point + kZoneClearance_m * n;
    out.in_zone = true;
  }
  return out;
}

std::optional<ReactiveCommand> arrival_command(const ReactiveParams& params, const ReactiveInput& input,
                                               const SteeringTarget& target) {
  if ((target.point - input.position).norm() > params.arrival_radius_m) return std::nullopt;
  ReactiveCommand c;
  c.course = input.course;
  c.speed_mps = 0.0;
  c.status = target.in_zone ? ReactiveStatus::target_in_zone : ReactiveStatus::arrived;
  return c;
}

ReactiveCommand course_command(const ReactiveParams& params, const ReactiveInput& input, const Vec2& direction,
                               ReactiveStatus status, std::ptrdiff_t object, const SteeringTarget& target) {
  ReactiveCommand c;
  c.course = input.course;
  c.active_object = object;
  if (direction.squaredNorm() == 0.0) {
    c.status = ReactiveStatus::stalled;
    return c;
  }
  c.course = math_angle(direction);
  c.speed_mps = params.speed_mps;
  c.status = (target.in_zone && status == ReactiveStatus::ok) ? ReactiveStatus::target_in_zone : status;
  return c;
}

int side_of(double offset, const Vec2& axis, std::optional<double> course, double band_m) {
  if (std::abs(offset) > band_m && offset != 0.0) return offset > 0.0 ? 1 : -1;
  if (course) {
    const double turn = cross(axis, unit_vector(*course));
    if (turn != 0.0) return turn > 0.0 ? 1 : -1;
  }
  if (offset != 0.0) return offset > 0.0 ? 1 : -1;
  return -1;
}

int axis_side(const Vec2& centre, const Vec2& target, const Vec2& p, std::optional<double> course) {
  Vec2 axis = unit_or_zero(target - centre);
  // Target at the centre (a substitute target on a degenerate zone): any axis will do.
  if (axis.squaredNorm() == 0.0) axis = Vec2(1.0, 0.0);
  return side_of(cross(axis, p - centre), axis, course, 0.0);
}

bool engaged_with(const SideLatch& memory, const Vec2& centre, double match_m) {
  return memory.side != 0 && (memory.engaged_centre - centre).norm() <= match_m;
}

int latched_side(SideLatch& memory, std::ptrdiff_t index, const Vec2& centre, double match_m, int fresh) {
  if (!engaged_with(memory, centre, match_m)) memory.side = fresh;
  memory.engaged_object = index;
  memory.engaged_centre = centre;
  return memory.side;
}

void release(SideLatch& memory) { memory = SideLatch{}; }

std::ptrdiff_t first_zone_hit(std::span<const Ellipse> zones, const Vec2& p, const Vec2& q, std::ptrdiff_t skip) {
  std::ptrdiff_t best = -1;
  double best_t = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < zones.size(); ++i) {
    if (static_cast<std::ptrdiff_t>(i) == skip || !segment_intersects(zones[i], p, q)) continue;
    const std::vector<double> t = segment_boundary_crossings(zones[i], p, q);
    const double enter = t.empty() ? 0.0 : t.front();
    if (enter < best_t) {
      best_t = enter;
      best = static_cast<std::ptrdiff_t>(i);
    }
  }
  return best;
}

double depth_fraction(const Ellipse& zone, const Vec2& p) { return 1.0 - std::sqrt(zone.implicit_value(p)); }

std::ptrdiff_t deepest_zone(std::span<const Ellipse> zones, const Vec2& p) {
  std::ptrdiff_t best = -1;
  double best_depth = 0.0;
  for (std::size_t i = 0; i < zones.size(); ++i) {
    // Beyond the semi-major axis from the centre: outside, no transform needed.
    if ((p - zones[i].centre).squaredNorm() >= zones[i].a * zones[i].a) continue;
    const double d = depth_fraction(zones[i], p);
    if (d > best_depth) {
      best_depth = d;
      best = static_cast<std::ptrdiff_t>(i);
    }
  }
  return best;
}

Vec2 outward_normal(const Ellipse& zone, const Vec2& p) {
  // Gradient of |diag(1/a, 1/b) R^T (p - c)|^2, up to the factor 2.
  const Vec2 l = zone.to_local(p);
  const Vec2 g_local(l.x() / (zone.a * zone.a), l.y() / (zone.b * zone.b));
  return unit_or_zero(g_local.x() * zone.major_dir() + g_local.y() * zone.minor_dir());
}

Vec2 exit_direction(const Vec2& along, const Vec2& normal, double depth, double blend_fraction) {
  const double beta = 0.5 * kPi * std::sqrt(std::min(1.0, std::max(0.0, depth) / blend_fraction));
  return unit_or_zero(std::cos(beta) * along + std::sin(beta) * normal);
}

Vec2 unit_or_zero(const Vec2& v) {
  const double n = v.norm();
  return n > 1e-300 ? Vec2(v / n) : Vec2(0.0, 0.0);
}

}  // namespace reactive_detail
}  // namespace deepguide
