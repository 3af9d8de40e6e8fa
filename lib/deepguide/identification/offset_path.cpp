#include "deepguide/identification/offset_path.hpp"

#include <algorithm>
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

std::vector<CircleArc> offset_lap_arcs(const Ellipse& object, double distance_m, double t0, double tolerance_m) {
  constexpr int kFirst = 4;     // quarter laps to begin with
  constexpr int kDeepest = 10;  // 4096 pieces at most
  std::vector<CircleArc> out;
  const auto off_path = [&](const CircleArc& a) {
    double worst = 0.0;
    for (const double f : {0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875}) {
      worst = std::max(worst, std::abs(project_to_offset(object, distance_m, a.point_at(f)).signed_m));
    }
    return worst;
  };
  const auto fit = [&](const auto& self, double ta, double tb, int depth) -> void {
    const std::optional<std::array<CircleArc, 2>> pair =
        biarc(offset_point(object, distance_m, ta), offset_tangent(object, ta), offset_point(object, distance_m, tb),
              offset_tangent(object, tb));
    if (pair && (depth >= kDeepest || std::max(off_path((*pair)[0]), off_path((*pair)[1])) <= tolerance_m)) {
      out.push_back((*pair)[0]);
      out.push_back((*pair)[1]);
      return;
    }
    if (depth >= kDeepest) {  // a convex curve has biarcs between near points: only a broken ellipse gets here
      throw InputError("identification lap: expected an ellipse with 0 < b <= a, got a = " + std::to_string(object.a) +
                       ", b = " + std::to_string(object.b));
    }
    self(self, ta, 0.5 * (ta + tb), depth + 1);
    self(self, 0.5 * (ta + tb), tb, depth + 1);
  };
  for (int k = 0; k < kFirst; ++k) {
    fit(fit, t0 + 2.0 * M_PI * k / kFirst, t0 + 2.0 * M_PI * (k + 1) / kFirst, 0);
  }
  // The lap closes exactly where it began.
  out.back().to = out.front().from;
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
