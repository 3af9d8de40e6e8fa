#include "deepguide/identification/offset_path.hpp"

#include <cmath>
#include <cstdio>

#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"

namespace deepguide {

Vec2 offset_point(const Ellipse& object, double distance_m, double t) {
  return object.point_at(t) + distance_m * object.normal_at(t);
}

Vec2 offset_tangent(const Ellipse& object, double t) {
  const Vec2 d = -object.a * std::sin(t) * object.major_dir() + object.b * std::cos(t) * object.minor_dir();
  return d.normalized();
}

double offset_curvature(const Ellipse& object, double distance_m, double t) {
  const double s = std::sin(t), c = std::cos(t);
  const double q = object.a * object.a * s * s + object.b * object.b * c * c;
  return 1.0 / (q * std::sqrt(q) / (object.a * object.b) + distance_m);
}

double offset_min_radius(const Ellipse& object, double distance_m) {
  return object.b * object.b / object.a + distance_m;
}

OffsetProjection project_to_offset(const Ellipse& object, double distance_m, const Vec2& p) {
  const EllipseProjection near = project_to_ellipse(object, p);
  const Vec2 l = object.to_local(near.point);
  OffsetProjection out;
  out.t = std::atan2(l.y() / object.b, l.x() / object.a);
  out.point = offset_point(object, distance_m, out.t);
  out.tangent = offset_tangent(object, out.t);
  out.signed_m = near.signed_distance() - distance_m;
  return out;
}

void check_offset_path_fits(const Ellipse& object, double distance_m, double turn_radius_m, const std::string& name) {
  const double rho = offset_min_radius(object, distance_m);
  if (rho >= turn_radius_m) return;
  char text[256];
  std::snprintf(text, sizeof text,
                "object '%s': the path %.2f m around it turns with a radius of %.2f m at the ends of its major axis, "
                "tighter than the vehicle's %.2f m; expected a distance of at least %.2f m",
                name.c_str(), distance_m, rho, turn_radius_m, turn_radius_m - object.b * object.b / object.a);
  throw InputError(text);
}

}  // namespace deepguide
