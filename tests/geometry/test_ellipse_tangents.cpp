// Tangents from a point and common tangents of two ellipses
// (geometry/ellipse_tangents.hpp).
//
// Everything is checked with the test's own geometry: the implicit function
// (local x / a)^2 + (local y / b)^2, its gradient for the normal, the support value
// sqrt((a n.u)^2 + (b n.v)^2) for placing nearly touching pairs, and a dense
// sampling of the boundary for "the ellipse lies on one side of the line".
//
// Left/right (tangent_points): "left of the ray from p through the centre" means
// cross(c - p, x - p) > 0 with cross(u, w) = u.x w.y - u.y w.x. Unit circle, p = (2, 0):
// the ray points along -x, whose left is -y, and the tangent points are at polar
// angle +-acos(1/2) = +-60 deg, so left = (0.5, -sqrt(3)/2), right = (0.5, +sqrt(3)/2).
//
// Common tangents of unit circles at (0, 0) and (4, 0): outer y = +-1, touching
// (0, +-1) and (4, +-1); inner through (2, 0), touching the first circle at polar
// angle +-60 deg (cos = 1 / 2 since the distance from the centre to (2, 0) is 2) and
// the second at the mirrored point: (0.5, +-sqrt(3)/2) with (3.5, -+sqrt(3)/2).
// The normal puts circle 1 on the side n.x <= n.p1, so it is the outward normal of
// circle 1 at p1: (0, +-1) for the outer ones, (0.5, +-sqrt(3)/2) for the inner ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/geometry/ellipse_tangents.hpp"
#include "reference_ellipse.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = std::numbers::pi;

// The ellipse frame, from (c, a, b, theta) only (reference_ellipse.hpp).
using test_ref::Frame;

Ellipse random_ellipse(std::mt19937& rng, double max_b = 5.0) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  Ellipse e;
  e.b = 0.2 + max_b * u01(rng);
  const double pick = u01(rng);
  e.a = e.b * (pick < 0.15 ? 1.0 : (pick < 0.25 ? 20.0 : std::exp(std::log(20.0) * u01(rng))));
  e.theta = -kPi + 2.0 * kPi * u01(rng);
  e.centre = Vec2(-100.0 + 200.0 * u01(rng), -100.0 + 200.0 * u01(rng));
  return e;
}

}  // namespace

// ---- Tangents from a point ------------------------------------------------------

TEST(PointTangents, UnitCircleHandCase) {
  const Ellipse circle{Vec2(0.0, 0.0), 1.0, 1.0, 0.0};
  const std::optional<PointTangents> t = tangent_points(circle, Vec2(2.0, 0.0));
  ASSERT_TRUE(t.has_value());
  const double h = std::sqrt(3.0) / 2.0;
  EXPECT_NEAR(t->left.x(), 0.5, 1e-15);
  EXPECT_NEAR(t->left.y(), -h, 1e-15);
  EXPECT_NEAR(t->right.x(), 0.5, 1e-15);
  EXPECT_NEAR(t->right.y(), h, 1e-15);
  // The convention itself: left has a positive cross product with the ray p -> centre.
  EXPECT_GT(cross(Vec2(-2.0, 0.0), t->left - Vec2(2.0, 0.0)), 0.0);
  EXPECT_LT(cross(Vec2(-2.0, 0.0), t->right - Vec2(2.0, 0.0)), 0.0);

  // Seen from the north, (0, 2): the ray points south, whose left is east (+x).
  const std::optional<PointTangents> n = tangent_points(circle, Vec2(0.0, 2.0));
  ASSERT_TRUE(n.has_value());
  EXPECT_NEAR(n->left.x(), h, 1e-15);
  EXPECT_NEAR(n->left.y(), 0.5, 1e-15);
  EXPECT_NEAR(n->right.x(), -h, 1e-15);
  EXPECT_NEAR(n->right.y(), 0.5, 1e-15);
}

TEST(PointTangents, EllipseHandCases) {
  // a = 2, b = 1, axis-aligned, p = (4, 0): in the unit-circle frame p is (2, 0), the
  // tangent points there are (0.5, -+sqrt(3)/2), i.e. (1, -+sqrt(3)/2) on the ellipse.
  // Check: the tangent at (x0, y0) is x x0 / 4 + y y0 = 1, and (4, 0) satisfies it.
  const double h = std::sqrt(3.0) / 2.0;
  const Ellipse e{Vec2(0.0, 0.0), 2.0, 1.0, 0.0};
  const std::optional<PointTangents> t = tangent_points(e, Vec2(4.0, 0.0));
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(t->left.x(), 1.0, 1e-15);
  EXPECT_NEAR(t->left.y(), -h, 1e-15);
  EXPECT_NEAR(t->right.x(), 1.0, 1e-15);
  EXPECT_NEAR(t->right.y(), h, 1e-15);

  // The same ellipse with its major axis north (theta = pi/2) and centre (1, 2);
  // p = (1, 6) is 4 along the major axis. Local (x, y) maps to world (1 - y, 2 + x):
  // left (local (1, -h)) is (1 + h, 3), right is (1 - h, 3). The ray from p to the
  // centre points south, whose left is east: consistent.
  const Ellipse r{Vec2(1.0, 2.0), 2.0, 1.0, kPi / 2.0};
  const std::optional<PointTangents> tr = tangent_points(r, Vec2(1.0, 6.0));
  ASSERT_TRUE(tr.has_value());
  EXPECT_NEAR(tr->left.x(), 1.0 + h, 1e-14);
  EXPECT_NEAR(tr->left.y(), 3.0, 1e-14);
  EXPECT_NEAR(tr->right.x(), 1.0 - h, 1e-14);
  EXPECT_NEAR(tr->right.y(), 3.0, 1e-14);
}

TEST(PointTangents, InsideOrOnTheEllipseHasNone) {
  const Ellipse e{Vec2(0.0, 0.0), 5.0, 3.0, 0.0};
  EXPECT_FALSE(tangent_points(e, Vec2(0.0, 0.0)).has_value());
  EXPECT_FALSE(tangent_points(e, Vec2(4.9, 0.0)).has_value());
  EXPECT_FALSE(tangent_points(e, Vec2(1.0, -2.5)).has_value());
  // On the boundary (exact in double).
  EXPECT_FALSE(tangent_points(e, Vec2(5.0, 0.0)).has_value());
  EXPECT_FALSE(tangent_points(e, Vec2(-5.0, 0.0)).has_value());
  EXPECT_FALSE(tangent_points(e, Vec2(0.0, 3.0)).has_value());
  EXPECT_FALSE(tangent_points(e, Vec2(0.0, -3.0)).has_value());
  const Ellipse circle{Vec2(0.0, 0.0), 1.0, 1.0, 0.0};
  EXPECT_FALSE(tangent_points(circle, Vec2(1.0, 0.0)).has_value());
  // Just outside: tangents exist.
  EXPECT_TRUE(tangent_points(e, Vec2(5.0 + 1e-9, 0.0)).has_value());
  // Random inside points of rotated ellipses.
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const Ellipse r = random_ellipse(rng);
    const Frame f(r);
    const double rho = 0.999999 * std::sqrt(u01(rng));
    const double phi = 2.0 * kPi * u01(rng);
    const Vec2 p = r.centre + r.a * rho * std::cos(phi) * f.u + r.b * rho * std::sin(phi) * f.v;
    ASSERT_LT(f.implicit(p), 1.0);
    EXPECT_FALSE(tangent_points(r, p).has_value()) << i;
  }
}

TEST(PointTangents, RandomRotatedEllipses) {
  std::mt19937 rng(20240606);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  double worst_on = 0.0;
  double worst_cos = 0.0;
  constexpr int kCases = 2000;
  for (int i = 0; i < kCases; ++i) {
    const Ellipse e = random_ellipse(rng);
    const Frame f(e);
    // Outside: radius 1.001 .. 20 in the unit-circle frame.
    const double rho = 1.001 + 19.0 * u01(rng) * u01(rng);
    const double phi = 2.0 * kPi * u01(rng);
    const Vec2 p = e.centre + e.a * rho * std::cos(phi) * f.u + e.b * rho * std::sin(phi) * f.v;
    SCOPED_TRACE(::testing::Message() << "case " << i << " a=" << e.a << " b=" << e.b << " theta=" << e.theta
                                      << " rho=" << rho);
    const std::optional<PointTangents> t = tangent_points(e, p);
    ASSERT_TRUE(t.has_value());
    const Vec2 ray = e.centre - p;
    for (const Vec2& x : {t->left, t->right}) {
      // On the ellipse.
      const double on = std::abs(f.implicit(x) - 1.0);
      worst_on = std::max(worst_on, on);
      EXPECT_LT(on, 1e-12);
      // Tangent: p - x is perpendicular to the normal at x.
      const double c = std::abs((x - p).normalized().dot(f.normal(x)));
      worst_cos = std::max(worst_cos, c);
      EXPECT_LT(c, 1e-9);
    }
    EXPECT_GT(cross(ray, t->left - p), 0.0);
    EXPECT_LT(cross(ray, t->right - p), 0.0);
    // The two tangent points differ and the whole ellipse lies between the two
    // tangent lines: every boundary point is right of p->left and left of p->right.
    EXPECT_GT((t->left - t->right).norm(), 0.0);
    const double scale = (p - e.centre).norm() + e.a;
    for (int k = 0; k < 360; ++k) {
      const Vec2 x = f.point(2.0 * kPi * k / 360.0);
      ASSERT_LE(cross(t->left - p, x - p), 1e-9 * scale * scale) << k;
      ASSERT_GE(cross(t->right - p, x - p), -1e-9 * scale * scale) << k;
    }
  }
  std::printf("[ tangents ] %d point cases: worst |implicit - 1| %.3g, worst |cos| %.3g\n", kCases, worst_on,
              worst_cos);
}

// ---- Common tangents -----------------------------------------------------------

namespace {

// Checks one result of common_tangents for two disjoint ellipses (failures through
// gtest); `worst_on` collects the largest |implicit - 1| of the touch points.
void check_common_tangents(const Ellipse& e1, const Ellipse& e2, const std::vector<CommonTangent>& ts,
                           double& worst_on) {
  const Frame f1(e1);
  const Frame f2(e2);
  ASSERT_EQ(ts.size(), 4u);
  EXPECT_EQ(ts[0].kind, TangentKind::outer);
  EXPECT_EQ(ts[1].kind, TangentKind::outer);
  EXPECT_EQ(ts[2].kind, TangentKind::inner);
  EXPECT_EQ(ts[3].kind, TangentKind::inner);
  const double scale = std::max({e1.centre.norm(), e2.centre.norm(), e1.a, e2.a, (e1.centre - e2.centre).norm()});
  constexpr int kBoundary = 20000;
  for (std::size_t j = 0; j < ts.size(); ++j) {
    const CommonTangent& t = ts[j];
    SCOPED_TRACE(::testing::Message() << "tangent " << j);
    EXPECT_NEAR(t.normal.norm(), 1.0, 1e-12);
    const double on1 = std::abs(f1.implicit(t.p1) - 1.0);
    const double on2 = std::abs(f2.implicit(t.p2) - 1.0);
    worst_on = std::max({worst_on, on1, on2});
    EXPECT_LT(on1, 1e-9);
    EXPECT_LT(on2, 1e-9);
    // The normal is perpendicular to p2 - p1 (both points on the line).
    EXPECT_LE(std::abs(t.normal.dot(t.p2 - t.p1)), 1e-9 * scale);
    // Each touch point's ellipse normal is +-normal (a tangent, not a secant).
    EXPECT_NEAR(std::abs(f1.normal(t.p1).dot(t.normal)), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(f2.normal(t.p2).dot(t.normal)), 1.0, 1e-9);
    // Dense sampling: ellipse 1 on n.x <= k; ellipse 2 on the same side (outer) or
    // the other side (inner). Both come within sampling resolution of the line.
    const double k = t.normal.dot(t.p1);
    const double sign2 = t.kind == TangentKind::outer ? 1.0 : -1.0;
    double max1 = -1e300;
    double max2 = -1e300;
    for (int s = 0; s < kBoundary; ++s) {
      const double tt = 2.0 * kPi * s / kBoundary;
      max1 = std::max(max1, t.normal.dot(f1.point(tt)) - k);
      max2 = std::max(max2, sign2 * (t.normal.dot(f2.point(tt)) - k));
    }
    EXPECT_LE(max1, 1e-9 * scale);
    EXPECT_LE(max2, 1e-9 * scale);
    // Touching: the farthest sample is within (pi a / N)^2 / b-ish of the line.
    EXPECT_GE(max1, -1e-5 * scale);
    EXPECT_GE(max2, -1e-5 * scale);
  }
  // The two lines of each kind differ.
  EXPECT_LT(ts[0].normal.dot(ts[1].normal), 1.0 - 1e-12);
  EXPECT_LT(ts[2].normal.dot(ts[3].normal), 1.0 - 1e-12);
}

}  // namespace

TEST(CommonTangents, TwoUnitCirclesHandCase) {
  const Ellipse c1{Vec2(0.0, 0.0), 1.0, 1.0, 0.0};
  const Ellipse c2{Vec2(4.0, 0.0), 1.0, 1.0, 0.0};
  const std::vector<CommonTangent> ts = common_tangents(c1, c2);
  ASSERT_EQ(ts.size(), 4u);
  const double h = std::sqrt(3.0) / 2.0;
  // Order within a kind is not specified: match by the sign of the normal's y.
  for (int j = 0; j < 4; ++j) {
    const CommonTangent& t = ts[j];
    SCOPED_TRACE(j);
    const double s = t.normal.y() > 0.0 ? 1.0 : -1.0;
    if (j < 2) {
      ASSERT_EQ(t.kind, TangentKind::outer);
      EXPECT_NEAR(t.p1.x(), 0.0, 1e-12);
      EXPECT_NEAR(t.p1.y(), s, 1e-12);
      EXPECT_NEAR(t.p2.x(), 4.0, 1e-12);
      EXPECT_NEAR(t.p2.y(), s, 1e-12);
      EXPECT_NEAR(t.normal.x(), 0.0, 1e-12);
      EXPECT_NEAR(t.normal.y(), s, 1e-12);
    } else {
      ASSERT_EQ(t.kind, TangentKind::inner);
      EXPECT_NEAR(t.p1.x(), 0.5, 1e-12);
      EXPECT_NEAR(t.p1.y(), s * h, 1e-12);
      EXPECT_NEAR(t.p2.x(), 3.5, 1e-12);
      EXPECT_NEAR(t.p2.y(), -s * h, 1e-12);
      EXPECT_NEAR(t.normal.x(), 0.5, 1e-12);
      EXPECT_NEAR(t.normal.y(), s * h, 1e-12);
      // The inner tangent passes through (2, 0).
      EXPECT_NEAR(t.normal.dot(Vec2(2.0, 0.0)), t.normal.dot(t.p1), 1e-12);
    }
  }
  // One of each pair up, the other down.
  EXPECT_LT(ts[0].normal.y() * ts[1].normal.y(), 0.0);
  EXPECT_LT(ts[2].normal.y() * ts[3].normal.y(), 0.0);
  double worst = 0.0;
  check_common_tangents(c1, c2, ts, worst);
}

TEST(CommonTangents, RandomDisjointRotatedPairs) {
  std::mt19937 rng(20240607);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  double worst_on = 0.0;
  int far_pairs = 0;
  int near_pairs = 0;
  for (int i = 0; i < 450; ++i) {
    const Ellipse e1 = random_ellipse(rng);
    Ellipse e2 = random_ellipse(rng);
    const double phi = 2.0 * kPi * u01(rng);
    const Vec2 n(std::cos(phi), std::sin(phi));
    const bool nearly_touching = i % 3 != 0;
    if (nearly_touching) {
      // Separated by a slab of width gap normal to n: the support values (computed
      // here) of e1 along n and e2 along -n plus the gap. The ellipses are disjoint,
      // their distance is at least the gap and of that order. Gaps of 1e-3 and 1e-6
      // of the size.
      const double size = std::max(e1.a, e2.a);
      const double gap = (i % 3 == 1 ? 1e-3 : 1e-6) * size;
      e2.centre = e1.centre + (Frame(e1).support_centered(n) + Frame(e2).support_centered(n) + gap) * n;
      ++near_pairs;
    } else {
      // Centres farther apart than the sum of the semi-major axes.
      e2.centre = e1.centre + (e1.a + e2.a) * (1.05 + 2.0 * u01(rng)) * n;
      ++far_pairs;
    }
    SCOPED_TRACE(::testing::Message() << "pair " << i << (nearly_touching ? " (near)" : "") << " e1: a=" << e1.a
                                      << " b=" << e1.b << " th=" << e1.theta << " e2: a=" << e2.a << " b=" << e2.b
                                      << " th=" << e2.theta);
    check_common_tangents(e1, e2, common_tangents(e1, e2), worst_on);
    // Swapped roles must work as well.
    check_common_tangents(e2, e1, common_tangents(e2, e1), worst_on);
    if (HasFailure()) break;
  }
  std::printf("[ tangents ] %d far + %d nearly touching pairs: worst |implicit - 1| %.3g\n", far_pairs, near_pairs,
              worst_on);
}

TEST(CommonTangents, OverlappingEllipsesGiveNone) {
  // Hand cases: same centre; a cross; one inside the other; circles overlapping.
  const Ellipse a{Vec2(0.0, 0.0), 5.0, 1.0, 0.0};
  EXPECT_TRUE(common_tangents(a, a).empty());
  EXPECT_TRUE(common_tangents(a, Ellipse{Vec2(0.0, 0.0), 5.0, 1.0, kPi / 2.0}).empty());
  EXPECT_TRUE(common_tangents(a, Ellipse{Vec2(1.0, 0.0), 2.0, 0.5, 0.1}).empty());
  EXPECT_TRUE(common_tangents(Ellipse{Vec2(0.0, 0.0), 1.0, 1.0, 0.0}, Ellipse{Vec2(1.5, 0.0), 1.0, 1.0, 0.0}).empty());
  // Random overlapping pairs: a point P slightly inside both ellipses.
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 300; ++i) {
    const Ellipse e1 = random_ellipse(rng);
    Ellipse e2 = random_ellipse(rng);
    const Frame f1(e1);
    const double depth = i % 2 == 0 ? 0.99 : 0.5;  // how far inside (unit-circle radius)
    const Vec2 p = e1.centre + depth * (f1.point(2.0 * kPi * u01(rng)) - e1.centre);
    const Frame f2(e2);
    e2.centre = p - depth * (f2.point(2.0 * kPi * u01(rng)) - e2.centre);
    ASSERT_LT(Frame(e1).implicit(p), 1.0);
    ASSERT_LT(Frame(e2).implicit(p), 1.0);
    EXPECT_TRUE(common_tangents(e1, e2).empty()) << i;
  }
}
