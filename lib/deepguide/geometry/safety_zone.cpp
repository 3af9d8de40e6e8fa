#include "deepguide/geometry/safety_zone.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "deepguide/geometry/ellipse_distance.hpp"

namespace deepguide {

double SafetyZone::support(const Vec2& u) const { return ellipse.support(u) + margin; }

double SafetyZone::signed_distance(const Vec2& p) const { return deepguide::signed_distance(ellipse, p) - margin; }

bool SafetyZone::contains(const Vec2& p) const { return signed_distance(p) < 0.0; }

namespace {

struct Line {
  Vec2 n;    // unit normal
  double k;  // n.x = k
};

Line support_line(const SafetyZone& z, double phi) {
  const Vec2 n(std::cos(phi), std::sin(phi));
  return {n, z.support(n)};
}

Vec2 intersect(const Line& l1, const Line& l2) {
  const double det = l1.n.x() * l2.n.y() - l1.n.y() * l2.n.x();
  return {(l1.k * l2.n.y() - l2.k * l1.n.y()) / det, (l1.n.x() * l2.k - l2.n.x() * l1.k) / det};
}

// Appends the vertices strictly after phi0 up to and including the vertex
// between phi0 and phi1, refining the interval while its vertex is too far out.
void refine(const SafetyZone& z, double phi0, double phi1, const Line& l0, const Line& l1, double tol, int depth,
            std::vector<Vec2>& out) {
  const Vec2 v = intersect(l0, l1);
  if (depth > 0 && z.signed_distance(v) > tol) {
    const double mid = 0.5 * (phi0 + phi1);
    const Line lm = support_line(z, mid);
    refine(z, phi0, mid, l0, lm, tol, depth - 1, out);
    refine(z, mid, phi1, lm, l1, tol, depth - 1, out);
    return;
  }
  out.push_back(v);
}

}  // namespace

std::vector<Vec2> enclosing_polygon(const SafetyZone& zone, const ZonePolygonOptions& options) {
  if (!(options.tolerance > 0.0)) {
    throw std::invalid_argument("enclosing_polygon: tolerance must be positive");
  }
  // Start with 8 normals aligned with the ellipse axes (an edge, not a vertex,
  // at each axis end keeps the polygon symmetric), then refine each interval.
  constexpr int kStart = 8;
  const int depth =
      std::max(0, static_cast<int>(std::floor(std::log2(std::max(1.0, double(options.max_vertices) / kStart)))));
  std::vector<Vec2> out;
  const double step = 2.0 * std::numbers::pi / kStart;
  for (int k = 0; k < kStart; ++k) {
    const double phi0 = zone.ellipse.theta + k * step;
    const double phi1 = phi0 + step;
    refine(zone, phi0, phi1, support_line(zone, phi0), support_line(zone, phi1), options.tolerance, depth, out);
  }
  return out;
}

BgPolygon enclosing_bg_polygon(const SafetyZone& zone, const ZonePolygonOptions& options) {
  const std::vector<Vec2> ccw = enclosing_polygon(zone, options);
  BgPolygon poly;
  for (auto it = ccw.rbegin(); it != ccw.rend(); ++it) poly.outer().push_back(to_bg(*it));
  poly.outer().push_back(poly.outer().front());
  return poly;
}

}  // namespace deepguide
