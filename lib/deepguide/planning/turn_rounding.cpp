#include "deepguide/planning/turn_rounding.hpp"

#include <cmath>
#include <numbers>

#include "deepguide/geometry/polygon_ops.hpp"

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {
namespace {

// How far each circle reaches beyond the corner it rounds (m).
constexpr double kPush = 1e-6;

}  // namespace

std::vector<TurningCircle> turning_circles(const ObstacleSet& obstacles, double margin, double turn_radius) {
  if (!std::isfinite(turn_radius) || turn_radius <= 0.0) {
    throw InputError("turn radius: expected a radius > 0 m, got " + general(turn_radius));
  }
  if (!std::isfinite(margin) || margin < 0.0) {
    throw InputError("margin: expected a safety margin >= 0 m, got " + general(margin));
  }
  std::vector<TurningCircle> out;
  const double inset = turn_radius - margin;  // from the corner to the circle's centre
  if (inset <= 0.0) return out;

  for (std::size_t i = 0; i < obstacles.ellipses.size(); ++i) {
    const Ellipse& e = obstacles.ellipses[i].footprint;
    if (e.b * e.b / e.a + margin >= turn_radius) continue;
    for (double side : {1.0, -1.0}) {
      out.push_back({e.centre + side * (e.a + margin + kPush - turn_radius) * e.major_dir(), i});
    }
  }
  for (std::size_t k = 0; k < obstacles.polygons.size(); ++k) {
    const std::size_t index = obstacles.ellipses.size() + k;
    // Rings are stored with the obstacle on the right of the direction of
    // travel (outer clockwise, holes anticlockwise): a right turn is a corner
    // that points into the water.
    auto ring = [&](const auto& r) {
      std::vector<Vec2> pts;  // the closed ring without its repeated points
      for (const auto& q : r) {
        const Vec2 p = to_eigen(q);
        if (pts.empty() || (p - pts.back()).norm() > 0.0) pts.push_back(p);
      }
      while (pts.size() > 1 && (pts.front() - pts.back()).norm() == 0.0) pts.pop_back();
      const std::size_t n = pts.size();
      if (n < 3) return;
      for (std::size_t j = 0; j < n; ++j) {
        const Vec2& v = pts[j];
        const Vec2 e1 = (v - pts[(j + n - 1) % n]).normalized(), e2 = (pts[(j + 1) % n] - v).normalized();
        if (!(e1.x() * e2.y() - e1.y() * e2.x() < -1e-12))
          continue;  // straight on, or a corner the water does not wrap
        // Outward normals are the edges turned left.
        const Vec2 w = (Vec2(-e1.y(), e1.x()) + Vec2(-e2.y(), e2.x())).normalized();
        out.push_back({v - (inset - kPush) * w, index});
      }
    };
    ring(obstacles.polygons[k].footprint.outer());
    for (const auto& inner : obstacles.polygons[k].footprint.inners()) ring(inner);
  }
  return out;
}

BgMultiPolygon rounded_zone_polygons(const BgMultiPolygon& zones, const ObstacleSet& obstacles, double margin,
                                     double turn_radius, double tolerance) {
  const std::vector<TurningCircle> circles = turning_circles(obstacles, margin, turn_radius);
  if (circles.empty()) return zones;
  std::vector<BgPolygon> parts(zones.begin(), zones.end());
  // The circumradius that puts the sides on the circle of R + tolerance.
  const double step = 2.0 * std::numbers::pi / kTurningPolygonSides;
  const double corner = (turn_radius + tolerance) / std::cos(0.5 * step);
  for (const TurningCircle& c : circles) {
    BgPolygon ring;
    for (int k = 0; k <= kTurningPolygonSides; ++k) {  // clockwise, closed
      const double a = -step * (k % kTurningPolygonSides);
      ring.outer().push_back(to_bg(c.centre + corner * Vec2(std::cos(a), std::sin(a))));
    }
    parts.push_back(std::move(ring));
  }
  BgMultiPolygon out;
  for (BgPolygon& p : merge_overlapping(std::move(parts))) out.push_back(std::move(p));
  return out;
}

}  // namespace deepguide
