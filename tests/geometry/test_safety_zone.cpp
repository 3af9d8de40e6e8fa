// The safety zone of an ellipse and its enclosing polygon (geometry/safety_zone.hpp).
//
// Independent references, all computed in the tests (here and in reference_ellipse.hpp)
// from (c, a, b, theta, d):
//  * the zone boundary is the offset curve x(t) + d n(t), with x(t) = c + R diag(a, b)
//    (cos t, sin t) and n(t) the outward unit normal (the implicit gradient
//    R (cos t / a, sin t / b), normalised), sampled at 6000 parameters;
//  * the distance of a point to the ellipse by dense sampling of x(t) (20000 samples)
//    and golden-section + Newton refinement around the best discrete minima: the
//    reference of reference_ellipse.hpp, validated by test_ellipse_distance.cpp;
//  * the zone's support value h(n) = n.c + sqrt((a n.u)^2 + (b n.v)^2) + d.
// The polygon (counter-clockwise per the header) must contain every offset-curve sample
// (each edge's half-plane, 1e-9 tolerance), keep each vertex within [d, d + tol] of the
// ellipse, have every edge on a support line of the zone, and be convex and CCW.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/geometry/algorithms/area.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/geometry/safety_zone.hpp"
#include "reference_ellipse.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = std::numbers::pi;

// The ellipse frame and the dense-sampling distance reference (reference_ellipse.hpp).
using test_ref::Frame;
using test_ref::reference_distance;

struct PolygonReport {
  std::size_t vertices = 0;
  double max_excess = 0.0;  // max over vertices of (distance to ellipse - d)
  double min_excess = 0.0;  // min over vertices of (distance to ellipse - d)
};

// All checks (a)-(d) of one polygon; failures through gtest.
PolygonReport check_polygon(const SafetyZone& zone, const std::vector<Vec2>& poly, double tol) {
  const Frame f(zone.ellipse);
  const double d = zone.margin;
  const double scale = zone.ellipse.centre.norm() + zone.ellipse.a + d;
  const std::size_t n = poly.size();
  PolygonReport rep;
  rep.vertices = n;
  EXPECT_GE(n, 8u);
  if (n < 3) return rep;

  // (d) Convex and counter-clockwise: every turn is to the left, the turns add up to
  // one full turn (so the boundary does not wind twice), positive area.
  double turning = 0.0;
  double area2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& p0 = poly[i];
    const Vec2& p1 = poly[(i + 1) % n];
    const Vec2& p2 = poly[(i + 2) % n];
    const Vec2 e0 = p1 - p0;
    const Vec2 e1 = p2 - p1;
    EXPECT_GT(e0.norm(), 0.0) << "repeated vertex " << i;
    EXPECT_GT(cross(e0, e1), 0.0) << "not a left turn at vertex " << (i + 1) % n;
    turning += std::atan2(cross(e0, e1), e0.dot(e1));
    area2 += cross(p0, p1);
  }
  EXPECT_NEAR(turning, 2.0 * kPi, 1e-9);
  EXPECT_GT(area2, 0.0);

  // Every edge lies on a support line of the zone: n_i.v_i = h(n_i), n_i the outward
  // edge normal (edge direction turned clockwise).
  std::vector<Vec2> normals(n);
  std::vector<double> offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e = poly[(i + 1) % n] - poly[i];
    normals[i] = Vec2(e.y(), -e.x()).normalized();
    offsets[i] = normals[i].dot(poly[i]);
    EXPECT_NEAR(offsets[i], f.zone_support(normals[i], d), 1e-9 * scale) << "edge " << i;
  }

  // (a) Every sampled offset-curve point is inside or on the polygon.
  constexpr int kOffsetSamples = 6000;
  double worst = -1e300;
  for (int k = 0; k < kOffsetSamples; ++k) {
    const Vec2 q = f.offset_point(2.0 * kPi * k / kOffsetSamples, d);
    for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, normals[i].dot(q) - offsets[i]);
  }
  EXPECT_LE(worst, 1e-9 * scale) << "offset curve leaves the polygon";

  // (b), (c): each vertex is at distance d .. d + tol from the ellipse (own reference).
  rep.max_excess = -1e300;
  rep.min_excess = 1e300;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_GT(f.implicit(poly[i]), 1.0) << "vertex inside the ellipse";
    const double excess = reference_distance(f, poly[i]).distance - d;
    rep.max_excess = std::max(rep.max_excess, excess);
    rep.min_excess = std::min(rep.min_excess, excess);
    EXPECT_LE(excess, tol + 1e-9) << "vertex " << i << " too far out";
    EXPECT_GE(excess, -1e-9) << "vertex " << i << " inside the zone";
  }
  return rep;
}

struct ZoneCase {
  const char* name;
  Ellipse ellipse;
  double d;
};

const ZoneCase kCases[] = {
    {"a10 b2 d5", {Vec2(0.0, 0.0), 10.0, 2.0, 0.0}, 5.0},
    {"a30 b3 d10", {Vec2(0.0, 0.0), 30.0, 3.0, 0.0}, 10.0},
    {"a20 b1 d20", {Vec2(0.0, 0.0), 20.0, 1.0, 0.0}, 20.0},
    {"a10 b2 d5 rotated", {Vec2(100.0, -50.0), 10.0, 2.0, 0.7}, 5.0},
    {"a30 b3 d10 rotated", {Vec2(-300.0, 250.0), 30.0, 3.0, -2.0}, 10.0},
    {"a20 b1 d20 north", {Vec2(12.0, 34.0), 20.0, 1.0, kPi / 2.0}, 20.0},
    {"a10 b2 d0 rotated", {Vec2(-5.0, 7.0), 10.0, 2.0, 1.1}, 0.0},
    {"circle r10 d3", {Vec2(5.0, 5.0), 10.0, 10.0, 0.3}, 3.0},
};

}  // namespace

TEST(SafetyZone, HandCases) {
  // a = 5, b = 3 at the origin, margin 2: the zone reaches x = +-7 and y = +-5.
  const SafetyZone z{Ellipse{Vec2(0.0, 0.0), 5.0, 3.0, 0.0}, 2.0};
  EXPECT_NEAR(z.signed_distance(Vec2(0.0, 0.0)), -5.0, 1e-14);  // -3 - 2
  EXPECT_NEAR(z.signed_distance(Vec2(10.0, 0.0)), 3.0, 1e-14);  // 5 - 2
  EXPECT_NEAR(z.signed_distance(Vec2(0.0, 10.0)), 5.0, 1e-14);  // 7 - 2
  EXPECT_NEAR(z.signed_distance(Vec2(4.0, 0.0)), -3.0, 1e-14);  // -1 - 2
  EXPECT_NEAR(z.signed_distance(Vec2(7.0, 0.0)), 0.0, 1e-14);
  EXPECT_TRUE(z.contains(Vec2(0.0, 0.0)));
  EXPECT_TRUE(z.contains(Vec2(6.9, 0.0)));
  EXPECT_FALSE(z.contains(Vec2(7.1, 0.0)));
  EXPECT_TRUE(z.contains(Vec2(0.0, -4.9)));
  EXPECT_FALSE(z.contains(Vec2(0.0, -5.1)));
  EXPECT_FALSE(z.contains(Vec2(7.0, 0.0)));  // the boundary is not inside
  // Off the axes: the offset-curve point at t = pi/4 is on the zone boundary; pushed
  // 1e-6 along the normal inwards it is inside, outwards it is outside.
  const Frame f(z.ellipse);
  const Vec2 q = f.offset_point(kPi / 4.0, 2.0);
  EXPECT_NEAR(z.signed_distance(q), 0.0, 1e-12);
  EXPECT_TRUE(z.contains(q - 1e-6 * f.normal(kPi / 4.0)));
  EXPECT_FALSE(z.contains(q + 1e-6 * f.normal(kPi / 4.0)));
  // Support: h(u) = sqrt(a^2 u_x^2 + b^2 u_y^2) + d.
  EXPECT_NEAR(z.support(Vec2(1.0, 0.0)), 7.0, 1e-14);
  EXPECT_NEAR(z.support(Vec2(0.0, -1.0)), 5.0, 1e-14);
  EXPECT_NEAR(z.support(Vec2(std::sqrt(0.5), std::sqrt(0.5))), std::sqrt(17.0) + 2.0, 1e-14);
  // A rotated, shifted zone: same distances along its own axes.
  const double th = -0.4;
  const Vec2 c(20.0, -10.0);
  const Vec2 u(std::cos(th), std::sin(th));
  const Vec2 v(-std::sin(th), std::cos(th));
  const SafetyZone r{Ellipse{c, 5.0, 3.0, th}, 2.0};
  EXPECT_NEAR(r.signed_distance(c + 10.0 * u), 3.0, 1e-13);
  EXPECT_NEAR(r.signed_distance(c - 10.0 * v), 5.0, 1e-13);
  EXPECT_TRUE(r.contains(c + 6.9 * u));
  EXPECT_FALSE(r.contains(c + 7.1 * u));
  EXPECT_NEAR(r.support(u), u.dot(c) + 7.0, 1e-13);
  // Zero margin: the zone is the ellipse.
  const SafetyZone z0{Ellipse{Vec2(0.0, 0.0), 5.0, 3.0, 0.0}, 0.0};
  EXPECT_TRUE(z0.contains(Vec2(4.9, 0.0)));
  EXPECT_FALSE(z0.contains(Vec2(5.1, 0.0)));
}

TEST(SafetyZonePolygon, RequiredCaseA10B2D5) {
  const SafetyZone zone{Ellipse{Vec2(0.0, 0.0), 10.0, 2.0, 0.0}, 5.0};
  std::size_t previous = 0;
  for (double tol : {0.5, 0.1, 0.01}) {
    SCOPED_TRACE(tol);
    const std::vector<Vec2> poly = enclosing_polygon(zone, ZonePolygonOptions{tol});
    const PolygonReport rep = check_polygon(zone, poly, tol);
    // A smaller tolerance needs more vertices.
    EXPECT_GT(rep.vertices, previous);
    previous = rep.vertices;
    std::printf("[ zone     ] a=10 b=2 d=5 tol=%g: %zu vertices, excess %.4g .. %.4g\n", tol, rep.vertices,
                rep.min_excess, rep.max_excess);
  }
  // Sane: the finest one is far from the refinement cap.
  EXPECT_LE(previous, 400u);
}

TEST(SafetyZonePolygon, ElongatedRotatedAndCircularZones) {
  for (const ZoneCase& c : kCases) {
    const SafetyZone zone{c.ellipse, c.d};
    std::size_t previous = 0;
    for (double tol : {0.5, 0.1, 0.01}) {
      SCOPED_TRACE(::testing::Message() << c.name << " tol " << tol);
      const std::vector<Vec2> poly = enclosing_polygon(zone, ZonePolygonOptions{tol});
      const PolygonReport rep = check_polygon(zone, poly, tol);
      EXPECT_GE(rep.vertices, previous);
      EXPECT_LE(rep.vertices, 500u);
      previous = rep.vertices;
    }
  }
}

TEST(SafetyZonePolygon, GrownEllipseIsNotEnoughButThePolygonIs) {
  // The pitfall: for a = 10, b = 2, d = 5 the ellipse with semi-axes (a + d, b + d) =
  // (15, 7) does not contain the zone. Its boundary comes within ~4.35 of the ellipse
  // (near t = 0.69), and offset-curve points lie outside it.
  const Ellipse e{Vec2(0.0, 0.0), 10.0, 2.0, 0.0};
  const double d = 5.0;
  const Frame f(e);
  const Ellipse grown{Vec2(0.0, 0.0), 15.0, 7.0, 0.0};
  const Frame g(grown);
  double min_clearance = 1e300;
  for (int k = 0; k < 2000; ++k) {
    const double dist = reference_distance(f, g.point(2.0 * kPi * k / 2000)).distance;
    min_clearance = std::min(min_clearance, dist);
  }
  EXPECT_LT(min_clearance, d);
  EXPECT_NEAR(min_clearance, 4.352, 0.005);
  double max_implicit = 0.0;  // of offset-curve points in the grown ellipse
  int outside = 0;
  for (int k = 0; k < 6000; ++k) {
    const double imp = g.implicit(f.offset_point(2.0 * kPi * k / 6000, d));
    max_implicit = std::max(max_implicit, imp);
    if (imp > 1.0) ++outside;
  }
  EXPECT_GT(max_implicit, 1.1);
  EXPECT_GT(outside, 0);
  // Our polygon contains the whole offset curve, and its vertices are all >= d away.
  const SafetyZone zone{e, d};
  const std::vector<Vec2> poly = enclosing_polygon(zone, ZonePolygonOptions{0.1});
  const PolygonReport rep = check_polygon(zone, poly, 0.1);
  EXPECT_GE(rep.min_excess, -1e-9);
}

TEST(SafetyZonePolygon, CircleVertexCount) {
  // A circle r = 10, d = 0: a regular polygon with vertices tol out has
  // N >= pi / acos(r / (r + tol)) = 70.2 vertices. The adaptive bisection of 8 initial
  // 45-degree intervals lands on 2^k intervals: 45/8 deg leaves a vertex 0.0121 out,
  // 45/16 deg 0.0030, so 128 vertices are expected; assert the range [71, 2 * 71].
  const double r = 10.0;
  const double tol = 0.01;
  const SafetyZone zone{Ellipse{Vec2(0.0, 0.0), r, r, 0.0}, 0.0};
  const std::vector<Vec2> poly = enclosing_polygon(zone, ZonePolygonOptions{tol});
  const double bound = kPi / std::acos(r / (r + tol));
  EXPECT_GE(double(poly.size()), std::ceil(bound));
  EXPECT_LE(double(poly.size()), 2.0 * std::ceil(bound));
  check_polygon(zone, poly, tol);
  // A circle of radius 7 with margin 3 is the same zone: the same vertex count.
  const SafetyZone zone3{Ellipse{Vec2(0.0, 0.0), 7.0, 7.0, 0.0}, 3.0};
  const std::vector<Vec2> poly3 = enclosing_polygon(zone3, ZonePolygonOptions{tol});
  EXPECT_EQ(poly3.size(), poly.size());
  for (std::size_t i = 0; i < std::min(poly.size(), poly3.size()); ++i) {
    EXPECT_NEAR((poly[i] - poly3[i]).norm(), 0.0, 1e-12);
  }
  // Fewer vertices for a larger tolerance.
  EXPECT_LT(enclosing_polygon(zone, ZonePolygonOptions{0.1}).size(), poly.size());
  EXPECT_LT(enclosing_polygon(zone, ZonePolygonOptions{0.5}).size(),
            enclosing_polygon(zone, ZonePolygonOptions{0.1}).size());
}

TEST(SafetyZonePolygon, VertexCapStillEncloses) {
  // With max_vertices = 8 no refinement happens: the initial octagon of support lines,
  // which still encloses the zone (but may be farther out than the tolerance).
  const SafetyZone zone{Ellipse{Vec2(3.0, 4.0), 10.0, 2.0, 0.5}, 5.0};
  const std::vector<Vec2> oct = enclosing_polygon(zone, ZonePolygonOptions{0.01, 8});
  EXPECT_EQ(oct.size(), 8u);
  check_polygon(zone, oct, 1e300);
  const std::vector<Vec2> capped = enclosing_polygon(zone, ZonePolygonOptions{0.01, 16});
  EXPECT_LE(capped.size(), 16u);
  check_polygon(zone, capped, 1e300);
}

TEST(SafetyZonePolygon, NonPositiveToleranceThrows) {
  const SafetyZone zone{Ellipse{Vec2(0.0, 0.0), 10.0, 2.0, 0.0}, 5.0};
  for (double tol : {0.0, -0.1, -1e-300, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(enclosing_polygon(zone, ZonePolygonOptions{tol}), std::invalid_argument) << tol;
    EXPECT_THROW(enclosing_bg_polygon(zone, ZonePolygonOptions{tol}), std::invalid_argument) << tol;
  }
  EXPECT_NO_THROW(enclosing_polygon(zone, ZonePolygonOptions{1e-3}));
}

TEST(SafetyZonePolygon, BoostPolygonIsTheSameRingClockwiseAndClosed) {
  const SafetyZone zone{Ellipse{Vec2(100.0, -50.0), 10.0, 2.0, 0.7}, 5.0};
  const std::vector<Vec2> ccw = enclosing_polygon(zone, ZonePolygonOptions{0.1});
  const BgPolygon bg = enclosing_bg_polygon(zone, ZonePolygonOptions{0.1});
  const auto& ring = bg.outer();
  ASSERT_EQ(ring.size(), ccw.size() + 1);
  EXPECT_EQ(ring.front().x(), ring.back().x());
  EXPECT_EQ(ring.front().y(), ring.back().y());
  // Reversed order: clockwise.
  for (std::size_t k = 0; k < ccw.size(); ++k) {
    EXPECT_EQ(ring[k].x(), ccw[ccw.size() - 1 - k].x());
    EXPECT_EQ(ring[k].y(), ccw[ccw.size() - 1 - k].y());
  }
  // Boost's area (positive for a clockwise outer ring, its default orientation)
  // equals the shoelace area of the CCW vertices.
  double area2 = 0.0;
  for (std::size_t i = 0; i < ccw.size(); ++i) area2 += cross(ccw[i], ccw[(i + 1) % ccw.size()]);
  EXPECT_NEAR(boost::geometry::area(bg), 0.5 * area2, 1e-9 * area2);
  EXPECT_GT(boost::geometry::area(bg), 0.0);
  // The zone's area, pi a b + perimeter d + pi d^2 (Steiner), is below the polygon's.
  const Frame f(zone.ellipse);
  double perimeter = 0.0;
  for (int k = 0; k < 20000; ++k) {
    perimeter += (f.point(2.0 * kPi * (k + 1) / 20000) - f.point(2.0 * kPi * k / 20000)).norm();
  }
  const double zone_area = kPi * 10.0 * 2.0 + perimeter * 5.0 + kPi * 25.0;
  EXPECT_GT(boost::geometry::area(bg), zone_area);
  EXPECT_LT(boost::geometry::area(bg), zone_area * 1.02);
}
