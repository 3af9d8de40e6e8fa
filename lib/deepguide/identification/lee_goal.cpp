#include "deepguide/identification/lee_goal.hpp"

#include <cmath>

namespace deepguide {

Vec2 align_direction(const Vec2& current_mps, double still_mps, const Vec2& centre, const Vec2& vehicle) {
  const double speed = current_mps.norm();
  if (speed > still_mps && speed > 0.0) return current_mps / speed;
  const Vec2 d = vehicle - centre;
  const double n = d.norm();
  return n > 0.0 ? Vec2(d / n) : Vec2(1.0, 0.0);
}

Vec2 lee_goal_point(const Ellipse& safety, const Vec2& e) {
  const double ux = e.dot(safety.major_dir()) / safety.a;
  const double uy = e.dot(safety.minor_dir()) / safety.b;
  return safety.centre + e / std::hypot(ux, uy);
}

double shade_half_width(const Ellipse& safety, const Vec2& e) {
  const Vec2 n(-e.y(), e.x());
  return std::hypot(safety.a * n.dot(safety.major_dir()), safety.b * n.dot(safety.minor_dir()));
}

AlignArea align_area(const Ellipse& safety, const Vec2& e, const Vec2& p) {
  const Vec2 d = p - safety.centre;
  const double along = d.dot(e), across = std::abs(e.x() * d.y() - e.y() * d.x());
  return along > 0.0 && across <= shade_half_width(safety, e) ? AlignArea::positioning : AlignArea::evasive;
}

}  // namespace deepguide
