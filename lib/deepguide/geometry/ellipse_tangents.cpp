#include "deepguide/geometry/ellipse_tangents.hpp"

#include "deepguide/geometry/periodic_roots.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

namespace deepguide {

std::optional<PointTangents> tangent_points(const Ellipse& e, const Vec2& p) {
  const Vec2 q = e.to_unit(p);
  const double r = q.norm();
  if (!(r > 1.0)) return std::nullopt;
  const double base = std::atan2(q.y(), q.x());
  const double half = std::acos(1.0 / r);
  // Seen from q looking at the origin, the point at base - half lies to the left.
  const Vec2 left = e.from_unit(Vec2(std::cos(base - half), std::sin(base - half)));
  const Vec2 right = e.from_unit(Vec2(std::cos(base + half), std::sin(base + half)));
  return PointTangents{left, right};
}

namespace {

Vec2 unit(double phi) { return {std::cos(phi), std::sin(phi)}; }

}  // namespace

std::vector<CommonTangent> common_tangents(const Ellipse& e1, const Ellipse& e2) {
  const Vec2 dc = e1.centre - e2.centre;
  // Centred support functions h_i(n) = sqrt(n^T A_i n), with the shape matrices
  // computed once (this runs ~150 times per pair).
  const Eigen::Matrix2d A1 = e1.shape_matrix();
  const Eigen::Matrix2d A2 = e2.shape_matrix();
  auto h = [](const Eigen::Matrix2d& A, const Vec2& n) { return std::sqrt(n.dot(A * n)); };
  auto g_outer = [&](double phi) {
    const Vec2 n = unit(phi);
    return n.dot(dc) + h(A1, n) - h(A2, n);
  };
  auto g_inner = [&](double phi) {
    const Vec2 n = unit(phi);
    return n.dot(dc) + h(A1, n) + h(A2, n);
  };
  double o1 = 0, o2 = 0, i1 = 0, i2 = 0;
  // Both functions are positive along dc and, for separated ellipses,
  // negative against it: the hint that spares the sampling.
  const double along = std::atan2(dc.y(), dc.x());
  if (!periodic_two_roots(g_inner, i1, i2, along) || !periodic_two_roots(g_outer, o1, o2, along)) return {};
  std::vector<CommonTangent> out;
  for (double phi : {o1, o2}) {
    const Vec2 n = unit(phi);
    out.push_back({TangentKind::outer, e1.support_point(n), e2.support_point(n), n});
  }
  for (double phi : {i1, i2}) {
    const Vec2 n = unit(phi);
    out.push_back({TangentKind::inner, e1.support_point(n), e2.support_point(-n), n});
  }
  return out;
}

}  // namespace deepguide
