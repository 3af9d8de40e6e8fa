// Obstacle field: clearance of points and segments (world/obstacle_field.hpp).
//
// Hand-derived cases:
//   ellipse a = 5, b = 3 at the origin: (10, 0) -> 5, (0, 10) -> 7, centre -> -3
//   (the closest boundary point of the centre is (0, +-3)); a rotated copy gives
//   the same values at c + 10 u, c + 10 v, c (u, v its axis directions).
//   square [0, 10]^2: (15, 5) -> 5 (edge), (13, 14) -> hypot(3, 4) = 5 (corner),
//   (2, 5) -> -2 (nearest edge x = 0), (10, 5) -> 0; with a hole [4, 6]^2 the
//   point (5, 5) is outside the footprint, 1 from the hole's ring.
//   circle r = 2, horizontal segment at height 5: 5 - 2 = 3 at (0, 5).
//   a segment along the major axis through a = 5, b = 3: its deepest point is the
//   centre, depth b = 3; along the minor axis the same.
//   segment (13, 20) -> (20, 13) past the corner (10, 10) of the square: the line
//   x + y = 33 is 13 / sqrt(2) from the corner, foot (16.5, 16.5) inside the segment.
//   a segment entering the square: minus the depth of its deepest point, e.g.
//   y = 5 across it: depth min(x, 10 - x, 5), 5 at the centre.
//
// Random segment-ellipse reference (independent of the library's distance code):
// for a segment that does not enter the ellipse, min over the segment of the
// distance to the ellipse = min over the boundary x(s) of the distance from x(s)
// to the segment. That 1-D function of s is sampled at 20000 parameters from the
// test's own Frame and the best discrete minima are refined by golden section;
// the point-to-segment distance is the closed form. The reported point on the
// segment is checked with reference_ellipse.hpp's point distance.
//
// Pruning: the R-tree search is compared with a brute force over every obstacle
// (segment_distance_to / distance_to, no R-tree), bitwise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include <boost/geometry/algorithms/correct.hpp>
#include <boost/geometry/algorithms/within.hpp>

#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "geometry/reference_ellipse.hpp"
#include "test_support.hpp"

#include "planning/obstacle_builders.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

BgPolygon make_polygon(std::initializer_list<std::pair<double, double>> outer,
                       std::initializer_list<std::pair<double, double>> hole = {}) {
  BgPolygon poly;
  for (const auto& [x, y] : outer) poly.outer().emplace_back(x, y);
  if (hole.size() > 0) {
    poly.inners().emplace_back();
    for (const auto& [x, y] : hole) poly.inners().back().emplace_back(x, y);
  }
  boost::geometry::correct(poly);
  return poly;
}

BgPolygon square(double x0, double y0, double side) {
  return make_polygon({{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}});
}

ObstacleSet one_ellipse(const Ellipse& e, const std::string& id = "e") {
  ObstacleSet set;
  set.ellipses.push_back({id, e, std::nullopt, std::nullopt});
  return set;
}

ObstacleSet one_polygon(const BgPolygon& p, const std::string& id = "p") {
  ObstacleSet set;
  set.polygons.push_back({id, p, std::nullopt, std::nullopt});
  return set;
}

// Closed-form distance from p to the segment [a, b] (test-side).
double reference_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

// min over the boundary of the distance to the segment: 20000 samples, best
// discrete minima refined by golden section.
double reference_segment_distance(const Ellipse& e, const Vec2& a, const Vec2& b) {
  const test_ref::Frame f(e);
  constexpr int n = 20000;
  const double h = 2.0 * kPi / n;
  const auto g = [&](double s) { return reference_segment_distance(f.point(s), a, b); };
  std::vector<double> values(n);
  for (int k = 0; k < n; ++k) values[k] = g(k * h);
  std::vector<int> minima;
  for (int k = 0; k < n; ++k) {
    if (values[k] <= values[(k + n - 1) % n] && values[k] <= values[(k + 1) % n]) minima.push_back(k);
  }
  std::sort(minima.begin(), minima.end(), [&](int i, int j) { return values[i] < values[j]; });
  if (minima.size() > 4) minima.resize(4);
  double best = values[minima.front()];
  const double phi = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int k : minima) {
    double lo = (k - 1) * h;
    double hi = (k + 1) * h;
    double x1 = hi - phi * (hi - lo);
    double x2 = lo + phi * (hi - lo);
    double f1 = g(x1);
    double f2 = g(x2);
    for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
      if (f1 <= f2) {
        hi = x2, x2 = x1, f2 = f1;
        x1 = hi - phi * (hi - lo), f1 = g(x1);
      } else {
        lo = x1, x1 = x2, f1 = f2;
        x2 = lo + phi * (hi - lo), f2 = g(x2);
      }
    }
    best = std::min({best, f1, f2});
  }
  return best;
}

}  // namespace

// ---- Points ------------------------------------------------------------------

TEST(ObstacleField, PointClearanceAxisAlignedEllipse) {
  const ObstacleField field(one_ellipse(Ellipse{Vec2(0.0, 0.0), 5.0, 3.0, 0.0}), 0.0);
  EXPECT_NEAR(field.clearance(Vec2(10.0, 0.0)), 5.0, 1e-12);
  EXPECT_NEAR(field.clearance(Vec2(0.0, 10.0)), 7.0, 1e-12);
  EXPECT_NEAR(field.clearance(Vec2(-10.0, 0.0)), 5.0, 1e-12);
  EXPECT_NEAR(field.clearance(Vec2(0.0, 0.0)), -3.0, 1e-12);
}

TEST(ObstacleField, PointClearanceRotatedEllipse) {
  const double theta = 0.7;
  const Vec2 c(1234.5, -678.25);
  const Vec2 u(std::cos(theta), std::sin(theta));
  const Vec2 v(-std::sin(theta), std::cos(theta));
  const ObstacleField field(one_ellipse(Ellipse{c, 5.0, 3.0, theta}), 0.0);
  EXPECT_NEAR(field.clearance(c + 10.0 * u), 5.0, 1e-9);
  EXPECT_NEAR(field.clearance(c - 10.0 * u), 5.0, 1e-9);
  EXPECT_NEAR(field.clearance(c + 10.0 * v), 7.0, 1e-9);
  EXPECT_NEAR(field.clearance(c), -3.0, 1e-9);
}

TEST(ObstacleField, PointClearanceSquarePolygon) {
  const ObstacleField field(one_polygon(square(0.0, 0.0, 10.0)), 0.0);
  EXPECT_DOUBLE_EQ(field.clearance(Vec2(15.0, 5.0)), 5.0);              // edge
  EXPECT_DOUBLE_EQ(field.clearance(Vec2(13.0, 14.0)), 5.0);             // corner (10, 10)
  EXPECT_DOUBLE_EQ(field.clearance(Vec2(-1.0, -1.0)), std::sqrt(2.0));  // corner (0, 0)
  EXPECT_DOUBLE_EQ(field.clearance(Vec2(2.0, 5.0)), -2.0);              // inside, edge x = 0
  EXPECT_DOUBLE_EQ(field.clearance(Vec2(5.0, 5.0)), -5.0);              // centre
  EXPECT_DOUBLE_EQ(field.clearance(Vec2(10.0, 5.0)), 0.0);              // on the ring
}

TEST(ObstacleField, PointClearancePolygonWithHole) {
  const BgPolygon p = make_polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 4}, {6, 4}, {6, 6}, {4, 6}});
  const ObstacleField field(one_polygon(p), 0.0);
  EXPECT_DOUBLE_EQ(field.clearance(Vec2(5.0, 5.0)), 1.0);   // in the hole: free water
  EXPECT_DOUBLE_EQ(field.clearance(Vec2(3.0, 5.0)), -1.0);  // in the ring band: 1 from the hole
  EXPECT_DOUBLE_EQ(field.clearance(Vec2(1.0, 5.0)), -1.0);  // 1 from the outer ring
}

TEST(ObstacleField, NearestOfSeveralAndEmptyField) {
  ObstacleSet set = one_ellipse(Ellipse{Vec2(0.0, 0.0), 5.0, 3.0, 0.0}, "near");
  set.ellipses.push_back({"", Ellipse{Vec2(100.0, 0.0), 5.0, 3.0, 0.0}, std::nullopt, std::nullopt});
  set.polygons.push_back({"", square(0.0, 50.0, 10.0), std::nullopt, std::nullopt});
  const ObstacleField field(set, 1.0);
  EXPECT_NEAR(field.clearance(Vec2(90.0, 0.0)), 5.0, 1e-12);  // the second ellipse, not the first
  EXPECT_NEAR(field.clearance(Vec2(5.0, 45.0)), 5.0, 1e-12);  // the square's bottom edge
  EXPECT_EQ(field.obstacle_name(0), "near");
  EXPECT_EQ(field.obstacle_name(1), "ellipse #1");
  EXPECT_EQ(field.obstacle_name(2), "polygon #0");
  const auto n = field.segment_clearance(Vec2(95.0, 20.0), Vec2(105.0, 20.0));
  EXPECT_EQ(n.obstacle, 1u);
  EXPECT_NEAR(n.distance, 17.0, 1e-12);

  const ObstacleField empty(ObstacleSet{}, 5.0);
  EXPECT_EQ(empty.clearance(Vec2(1.0, 2.0)), kInf);
  EXPECT_TRUE(empty.is_free(Vec2(1.0, 2.0)));
  const auto none = empty.segment_clearance(Vec2(0.0, 0.0), Vec2(10.0, 0.0));
  EXPECT_EQ(none.distance, kInf);
  EXPECT_TRUE(empty.segment_free(Vec2(0.0, 0.0), Vec2(10.0, 0.0)));
}

TEST(ObstacleField, RejectsBadMarginAndObstacles) {
  const ObstacleSet set = one_ellipse(Ellipse{Vec2(0.0, 0.0), 5.0, 3.0, 0.0});
  EXPECT_THROW(ObstacleField(set, -1.0), InputError);
  EXPECT_THROW(ObstacleField(set, std::nan("")), InputError);
  EXPECT_THROW(ObstacleField(set, kInf), InputError);
  EXPECT_THROW(ObstacleField(one_ellipse(Ellipse{Vec2(0.0, 0.0), 3.0, 5.0, 0.0}), 1.0), InputError);
  EXPECT_THROW(ObstacleField(one_ellipse(Ellipse{Vec2(0.0, 0.0), 5.0, 0.0, 0.0}), 1.0), InputError);
  EXPECT_THROW(ObstacleField(one_ellipse(Ellipse{Vec2(std::nan(""), 0.0), 5.0, 3.0, 0.0}), 1.0), InputError);
  EXPECT_THROW(ObstacleField(one_polygon(BgPolygon{}), 1.0), InputError);
  EXPECT_THROW(ObstacleField(one_polygon(make_polygon({{0, 0}, {kInf, 0}, {1, 1}})), 1.0), InputError);
  try {
    ObstacleField(one_ellipse(Ellipse{Vec2(0.0, 0.0), 3.0, 5.0, 0.0}, "c7"), 1.0);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c7"), std::string::npos) << e.what();
  }
}

// ---- Segments: hand cases -------------------------------------------------------

TEST(ObstacleField, SegmentAboveCircle) {
  const ObstacleField field(one_ellipse(Ellipse{Vec2(0.0, 0.0), 2.0, 2.0, 0.0}), 0.0);
  const auto n = field.segment_clearance(Vec2(-10.0, 5.0), Vec2(10.0, 5.0));
  EXPECT_NEAR(n.distance, 3.0, 1e-12);
  EXPECT_EQ(n.obstacle, 0u);
  EXPECT_NEAR(n.point_on_segment.x(), 0.0, 1e-6);
  EXPECT_DOUBLE_EQ(n.point_on_segment.y(), 5.0);
}

TEST(ObstacleField, SegmentCrossingEllipseIsNegative) {
  const ObstacleField field(one_ellipse(Ellipse{Vec2(0.0, 0.0), 5.0, 3.0, 0.0}), 0.0);
  const auto major = field.segment_clearance(Vec2(-10.0, 0.0), Vec2(10.0, 0.0));
  EXPECT_NEAR(major.distance, -3.0, 1e-9);
  EXPECT_NEAR(major.point_on_segment.x(), 0.0, 1e-5);
  const auto minor = field.segment_clearance(Vec2(0.0, -10.0), Vec2(0.0, 10.0));
  EXPECT_NEAR(minor.distance, -3.0, 1e-9);

  // A rotated ellipse crossed off-centre: negative, and agrees with the crossing test.
  const Ellipse e{Vec2(50.0, 20.0), 12.0, 4.0, 0.4};
  const ObstacleField rotated(one_ellipse(e), 0.0);
  const Vec2 a = e.centre + Vec2(-20.0, 1.0);
  const Vec2 b = e.centre + Vec2(20.0, 3.0);
  ASSERT_TRUE(segment_intersects(e, a, b));
  EXPECT_LT(rotated.segment_clearance(a, b).distance, -1.0);
  // A chord that only just dips in stays negative.
  const Vec2 top = e.centre + 4.0 * e.minor_dir();
  const Vec2 dip = top - 1e-9 * e.minor_dir();
  const auto grazing = rotated.segment_clearance(dip - 30.0 * e.major_dir(), dip + 30.0 * e.major_dir());
  EXPECT_LT(grazing.distance, 0.0);
  EXPECT_GT(grazing.distance, -2e-9);
}

TEST(ObstacleField, SegmentEndpointIsNearest) {
  const ObstacleField ellipse(one_ellipse(Ellipse{Vec2(0.0, 0.0), 5.0, 3.0, 0.0}), 0.0);
  const auto e = ellipse.segment_clearance(Vec2(10.0, 0.0), Vec2(20.0, 3.0));
  EXPECT_DOUBLE_EQ(e.distance, 5.0);
  EXPECT_EQ(e.point_on_segment, Vec2(10.0, 0.0));
  const auto e2 = ellipse.segment_clearance(Vec2(0.0, 30.0), Vec2(0.0, 10.0));  // the far end first
  EXPECT_DOUBLE_EQ(e2.distance, 7.0);
  EXPECT_EQ(e2.point_on_segment, Vec2(0.0, 10.0));

  const ObstacleField poly(one_polygon(square(0.0, 0.0, 10.0)), 0.0);
  const auto p = poly.segment_clearance(Vec2(25.0, 5.0), Vec2(15.0, 5.0));
  EXPECT_DOUBLE_EQ(p.distance, 5.0);
  EXPECT_EQ(p.point_on_segment, Vec2(15.0, 5.0));
}

TEST(ObstacleField, SegmentPastPolygonCorner) {
  const ObstacleField field(one_polygon(square(0.0, 0.0, 10.0)), 0.0);
  const auto n = field.segment_clearance(Vec2(13.0, 20.0), Vec2(20.0, 13.0));
  EXPECT_NEAR(n.distance, 13.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(n.point_on_segment.x(), 16.5, 1e-12);
  EXPECT_NEAR(n.point_on_segment.y(), 16.5, 1e-12);
  // Parallel to an edge: every point of the overlap is nearest; any is 5 away.
  const auto par = field.segment_clearance(Vec2(-5.0, 15.0), Vec2(20.0, 15.0));
  EXPECT_DOUBLE_EQ(par.distance, 5.0);
  EXPECT_DOUBLE_EQ(par.point_on_segment.y(), 15.0);
  EXPECT_GE(par.point_on_segment.x(), 0.0);
  EXPECT_LE(par.point_on_segment.x(), 10.0);
}

TEST(ObstacleField, SegmentMeetingPolygon) {
  const ObstacleField field(one_polygon(square(0.0, 0.0, 10.0)), 0.0);
  // Inside the square along y = 5 the depth is min(x, 10 - x, 5): deepest, 5, at
  // the centre. Its ridge there is a kink, so the depth is good to Brent's
  // 3e-8 of the segment length.
  const auto cross = field.segment_clearance(Vec2(-5.0, 5.0), Vec2(15.0, 5.0));
  EXPECT_NEAR(cross.distance, -5.0, 1e-5);
  EXPECT_NEAR(cross.point_on_segment.x(), 5.0, 1e-5);
  const auto back = field.segment_clearance(Vec2(15.0, 5.0), Vec2(-5.0, 5.0));
  EXPECT_NEAR(back.distance, -5.0, 1e-5);
  // One end inside: still the deepest point, not that end's depth (-2).
  const auto inside = field.segment_clearance(Vec2(2.0, 5.0), Vec2(20.0, 5.0));
  EXPECT_NEAR(inside.distance, -5.0, 1e-5);
  // Clipping a corner: along x + y = 19 from (9, 10) to (10, 9) the depth is
  // min(10 - x, 10 - y) = 0.5 at (9.5, 9.5).
  const auto corner = field.segment_clearance(Vec2(7.0, 12.0), Vec2(12.0, 7.0));
  EXPECT_NEAR(corner.distance, -0.5, 1e-6);
  // Touching a corner or running along an edge: 0, at the first contact.
  const auto touch = field.segment_clearance(Vec2(10.0, 10.0), Vec2(20.0, 30.0));
  EXPECT_EQ(touch.distance, 0.0);
  EXPECT_EQ(touch.point_on_segment, Vec2(10.0, 10.0));
  const auto along = field.segment_clearance(Vec2(-5.0, 10.0), Vec2(15.0, 10.0));
  EXPECT_EQ(along.distance, 0.0);
  EXPECT_EQ(along.point_on_segment, Vec2(0.0, 10.0));
}

// ---- Boundary semantics ------------------------------------------------------------

TEST(ObstacleField, BoundaryOfTheSafetyZoneIsFree) {
  const double margin = 5.0;
  const ObstacleField circle(one_ellipse(Ellipse{Vec2(0.0, 0.0), 2.0, 2.0, 0.0}), margin);
  EXPECT_DOUBLE_EQ(circle.clearance(Vec2(7.0, 0.0)), margin);
  EXPECT_TRUE(circle.is_free(Vec2(7.0, 0.0)));
  EXPECT_FALSE(circle.is_free(Vec2(7.0 - 1e-6, 0.0)));
  EXPECT_TRUE(circle.segment_free(Vec2(7.0, 0.0), Vec2(30.0, 0.0)));
  EXPECT_FALSE(circle.segment_free(Vec2(7.0 - 1e-6, 0.0), Vec2(30.0, 0.0)));
  EXPECT_TRUE(circle.segment_free(Vec2(-20.0, 7.0 + 1e-6), Vec2(20.0, 7.0 + 1e-6)));
  EXPECT_FALSE(circle.segment_free(Vec2(-20.0, 7.0 - 1e-6), Vec2(20.0, 7.0 - 1e-6)));
  EXPECT_NEAR(circle.segment_clearance(Vec2(-20.0, 7.0), Vec2(20.0, 7.0)).distance, margin, 1e-12);

  const ObstacleField poly(one_polygon(square(0.0, 0.0, 10.0)), margin);
  EXPECT_TRUE(poly.is_free(Vec2(15.0, 5.0)));
  EXPECT_FALSE(poly.is_free(Vec2(15.0 - 1e-6, 5.0)));
  EXPECT_TRUE(poly.segment_free(Vec2(15.0, -20.0), Vec2(15.0, 30.0)));
  EXPECT_FALSE(poly.segment_free(Vec2(15.0 - 1e-6, -20.0), Vec2(15.0 - 1e-6, 30.0)));
  EXPECT_FALSE(poly.segment_free(Vec2(5.0, 5.0), Vec2(5.0, 5.0)));  // degenerate, inside

  // Margin 0: touching is free, entering is not.
  const ObstacleField zero(one_polygon(square(0.0, 0.0, 10.0)), 0.0);
  EXPECT_TRUE(zero.segment_free(Vec2(10.0, -5.0), Vec2(10.0, 15.0)));
  EXPECT_FALSE(zero.segment_free(Vec2(9.0, -5.0), Vec2(9.0, 15.0)));
}

// ---- Segments against a rotated ellipse: random cases ---------------------------------

TEST(ObstacleField, SegmentEllipseMatchesReference) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int disjoint = 0;
  int crossing = 0;
  double worst = 0.0;
  for (int iter = 0; disjoint < test::cases(300); ++iter) {
    ASSERT_LT(iter, 2000) << "case generation stalled";
    const double a = 1.0 + 49.0 * unit(rng);
    const double b = a * (0.05 + 0.95 * unit(rng));
    const Ellipse e{Vec2(-500.0 + 1000.0 * unit(rng), -500.0 + 1000.0 * unit(rng)), a, b,
                    kPi * (2.0 * unit(rng) - 1.0)};
    const test_ref::Frame f(e);
    // A point at a random offset off a random boundary point; the segment runs
    // through it in a random direction, over random lengths on either side.
    const double s = 2.0 * kPi * unit(rng);
    const double offset = iter % 4 == 0 ? 1e-3 * unit(rng) : 30.0 * unit(rng) * unit(rng);
    const Vec2 q = f.offset_point(s, offset);
    const double phi = 2.0 * kPi * unit(rng);
    const Vec2 dir(std::cos(phi), std::sin(phi));
    const Vec2 p0 = q - 100.0 * unit(rng) * dir;
    const Vec2 p1 = q + 100.0 * unit(rng) * dir;
    const ObstacleField field(one_ellipse(e), 0.0);
    const auto n = field.segment_clearance(p0, p1);
    const double ref = reference_segment_distance(e, p0, p1);
    // The test's own inside test on the segment's dense samples.
    bool enters = false;
    for (int k = 0; k <= 10000 && !enters; ++k) enters = f.implicit(p0 + (k / 10000.0) * (p1 - p0)) < 1.0 - 1e-9;
    if (enters) {
      ++crossing;
      EXPECT_LT(n.distance, 0.0) << "iter " << iter;
      EXPECT_NEAR(ref, 0.0, 1e-7) << "iter " << iter;
      continue;
    }
    if (ref < 1e-6) continue;  // grazing within the sampling's doubt: neither class
    ++disjoint;
    EXPECT_NEAR(n.distance, ref, 1e-7) << "iter " << iter << " a " << a << " b " << b;
    worst = std::max(worst, std::abs(n.distance - ref));
    // The reported point is on the segment and at the reported distance.
    EXPECT_NEAR(reference_segment_distance(n.point_on_segment, p0, p1), 0.0, 1e-9);
    EXPECT_NEAR(test_ref::reference_distance(f, n.point_on_segment).distance, n.distance, 1e-7) << "iter " << iter;
  }
  EXPECT_GE(crossing, test::cases(20));
  RecordProperty("worst_abs_error", std::to_string(worst));
}

// ---- The quick verdicts of segment_free / is_free near the zone boundary ------------
// segment_free decides most ellipses without the exact distance (the ellipse
// grown by k = 1 + margin / b holds the zone; the ellipse (a + margin,
// b + margin) lies inside it). Near the zone's boundary, between those two,
// the answer must still be the exact one.

TEST(ObstacleField, SegmentFreeMatchesReferenceAroundTheZone) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int free_cases = 0, blocked_cases = 0;
  for (int iter = 0; iter < test::cases(1500); ++iter) {
    const double a = 1.0 + 49.0 * unit(rng);
    const double b = a * (0.05 + 0.95 * unit(rng));
    const double margin = 0.5 + 20.0 * unit(rng);
    const Ellipse e{Vec2(-500.0 + 1000.0 * unit(rng), -500.0 + 1000.0 * unit(rng)), a, b,
                    kPi * (2.0 * unit(rng) - 1.0)};
    const test_ref::Frame f(e);
    const ObstacleField field(one_ellipse(e), margin);
    // A point near the zone's boundary (inside or outside by up to 1 m, or by
    // a micrometre), a segment through it in a random direction.
    const double s = 2.0 * kPi * unit(rng);
    const double off = (iter % 3 == 0 ? 1e-6 : 1.0) * (2.0 * unit(rng) - 1.0);
    const Vec2 q = f.offset_point(s, margin + off);
    const double phi = 2.0 * kPi * unit(rng);
    const Vec2 dir(std::cos(phi), std::sin(phi));
    const bool point = iter % 5 == 0;  // some points
    const Vec2 p0 = point ? q : Vec2(q - 60.0 * unit(rng) * dir);
    const Vec2 p1 = point ? q : Vec2(q + 60.0 * unit(rng) * dir);
    // The reference measures to the boundary; the segments stay outside the
    // ellipse itself (checked), so that is their distance to the footprint.
    bool enters = false;
    for (int k = 0; k <= 2000 && !enters; ++k) enters = f.implicit(p0 + (k / 2000.0) * (p1 - p0)) < 1.0;
    if (enters) continue;
    const double ref = reference_segment_distance(e, p0, p1);
    if (std::abs(ref - margin) < 1e-7) continue;  // within the references' doubt
    const bool expect_free = ref > margin;
    (expect_free ? free_cases : blocked_cases) += 1;
    EXPECT_EQ(field.segment_free(p0, p1), expect_free)
        << "iter " << iter << ": a " << a << " b " << b << " margin " << margin << " ref " << ref;
    if (p0 == p1) {
      EXPECT_EQ(field.is_free(p0), expect_free) << "iter " << iter;
    }
    // Skipping the only obstacle makes everything free.
    EXPECT_TRUE(field.segment_free(p0, p1, 0));
  }
  EXPECT_GE(free_cases, test::cases(150));  // 208 and 600-odd with this seed
  EXPECT_GE(blocked_cases, test::cases(300));
}

// ---- Pruning -------------------------------------------------------------------------

namespace {

ObstacleSet random_obstacles(std::mt19937_64& rng, int count, double extent) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ObstacleSet set;
  for (int i = 0; i < count; ++i) {
    const Vec2 c(extent * unit(rng), extent * unit(rng));
    if (i % 2 == 0) {
      const double a = 2.0 + 28.0 * unit(rng);
      set.ellipses.push_back(
          {"", Ellipse{c, a, a * (0.1 + 0.9 * unit(rng)), kPi * (2.0 * unit(rng) - 1.0)}, std::nullopt, std::nullopt});
    } else {
      // A random star-shaped (possibly non-convex) pentagon around c.
      BgPolygon p;
      for (int k = 0; k < 5; ++k) {
        const double ang = 2.0 * kPi * (k + 0.8 * unit(rng)) / 5.0;
        const double r = 3.0 + 20.0 * unit(rng);
        p.outer().emplace_back(c.x() + r * std::cos(ang), c.y() + r * std::sin(ang));
      }
      boost::geometry::correct(p);
      set.polygons.push_back({"", p, std::nullopt, std::nullopt});
    }
  }
  return set;
}

// Brute force over every obstacle, without the R-tree. The circumscribed circle
// (ellipses) / vertex radius (polygons) bounds the distance from below, so
// obstacles that cannot beat the best are skipped; everything else is exact.
struct Brute {
  double distance = kInf;
  std::size_t obstacle = 0;
};

Brute brute_segment(const ObstacleField& field, const Vec2& a, const Vec2& b) {
  const ObstacleSet& set = field.obstacles();
  Brute best;
  for (std::size_t i = 0; i < field.size(); ++i) {
    double lower = -kInf;
    if (i < set.ellipses.size()) {
      const Ellipse& e = set.ellipses[i].footprint;
      lower = reference_segment_distance(e.centre, a, b) - e.a;
    }
    if (lower > best.distance) continue;
    const double d = field.segment_distance_to(i, a, b).distance;
    if (d < best.distance) best = {d, i};
  }
  return best;
}

}  // namespace

TEST(ObstacleField, RTreePruningMatchesBruteForce) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double extent = 2000.0;
  const ObstacleField field(random_obstacles(rng, 2000, extent), 8.0);
  ASSERT_EQ(field.size(), 2000u);
  int negative = 0;
  int positive = 0;
  for (int k = 0; k < test::cases(200); ++k) {
    // Mostly inside the field, some beyond its edge, lengths from 0 to 600 m.
    const double lo = k % 5 == 0 ? extent + 50.0 : -100.0;
    const double span = k % 5 == 0 ? 500.0 : extent + 200.0;
    const Vec2 a(lo + span * unit(rng), -100.0 + (extent + 200.0) * unit(rng));
    const double len = k % 10 == 0 ? 0.0 : 600.0 * unit(rng) * unit(rng);
    const double phi = 2.0 * kPi * unit(rng);
    const Vec2 b = a + len * Vec2(std::cos(phi), std::sin(phi));
    const auto n = field.segment_clearance(a, b);
    const Brute brute = brute_segment(field, a, b);
    EXPECT_EQ(n.distance, brute.distance) << "segment " << k;
    // Two obstacles may tie exactly (both touched, say); either may be reported.
    EXPECT_EQ(field.segment_distance_to(n.obstacle, a, b).distance, brute.distance) << "segment " << k;
    EXPECT_EQ(field.segment_free(a, b), brute.distance >= field.margin()) << "segment " << k;
    (n.distance < 0.0 ? negative : positive) += 1;

    // Points: clearance against the brute-force minimum too.
    double point_brute = kInf;
    for (std::size_t i = 0; i < field.size(); ++i) point_brute = std::min(point_brute, field.distance_to(i, a));
    EXPECT_EQ(field.clearance(a), point_brute) << "point " << k;
    EXPECT_EQ(field.is_free(a), point_brute >= field.margin()) << "point " << k;
  }
  // Both regimes must be exercised for the comparison to mean something.
  EXPECT_GE(negative, test::cases(20));
  EXPECT_GE(positive, test::cases(40));
}

// A polygon of many vertices (a coastline) is answered from an edge R-tree
// and a crossing number when the query keeps clear of its rings
// (ObstacleField::segment_distance_to); the free functions scan every edge.
// Both must give the same distance, sign included, for segments and points
// outside, inside, in the hole, crossing and skimming the rings, on two
// ragged rings of 600 and 200 vertices in UTM-sized coordinates.
TEST(ObstacleField, ManyVertexPolygonsAgreeWithTheWholeRingScan) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec2 centre(512345.0, 6543210.0);
  const auto ring = [&](double radius, double wiggle, int n, bool hole) {
    std::vector<BgPoint> out;
    for (int i = 0; i < n; ++i) {
      const double phi = (hole ? -1.0 : 1.0) * 2.0 * kPi * i / n;
      const double r = radius * (1.0 + wiggle * (unit(rng) - 0.5));
      out.push_back(to_bg(centre + r * Vec2(std::cos(phi), std::sin(phi))));
    }
    out.push_back(out.front());
    return out;
  };
  BgPolygon poly;
  const auto hole = ring(300.0, 0.3, 200, true);
  const auto outer = ring(1000.0, 0.4, 600, false);
  poly.outer().assign(outer.begin(), outer.end());
  poly.inners().emplace_back(hole.begin(), hole.end());
  boost::geometry::correct(poly);
  ObstacleSet set;
  set.polygons.push_back({"coast", poly, std::nullopt, std::nullopt});
  const ObstacleField field(set, 5.0);
  int outside = 0, inside = 0, in_hole = 0, crossing = 0;
  for (int k = 0; k < test::cases(2000); ++k) {
    const double r0 = 1500.0 * unit(rng);
    const double phi = 2.0 * kPi * unit(rng);
    const Vec2 a = centre + r0 * Vec2(std::cos(phi), std::sin(phi));
    const double len = k % 7 == 0 ? 0.0 : 400.0 * unit(rng) * unit(rng);
    const double psi = 2.0 * kPi * unit(rng);
    const Vec2 b = a + len * Vec2(std::cos(psi), std::sin(psi));
    const SegmentDistance whole = segment_signed_distance(poly, a, b);
    const SegmentDistance indexed = field.segment_distance_to(0, a, b);
    ASSERT_NEAR(indexed.distance, whole.distance, 1e-9) << "segment " << k;
    ASSERT_EQ(indexed.distance < 0.0, whole.distance < 0.0) << "segment " << k;
    if (whole.distance > 0.0) {
      // The reported point is on the segment and that far from the polygon.
      ASSERT_NEAR(signed_distance(poly, indexed.point_on_segment), whole.distance, 1e-6) << "segment " << k;
      const double r_a = (a - centre).norm();
      (r_a < 450.0 ? in_hole : outside) += 1;
    } else {
      ASSERT_NEAR(field.distance_to(0, a), signed_distance(poly, a), 1e-9) << "point " << k;
      (boost::geometry::within(to_bg(a), poly) && boost::geometry::within(to_bg(b), poly) ? inside : crossing) += 1;
    }
  }
  EXPECT_GE(outside, test::cases(200));
  EXPECT_GE(inside, test::cases(200));
  EXPECT_GE(in_hole, test::cases(20));
  EXPECT_GE(crossing, test::cases(100));
}

TEST(ObstaclesBeyond, WhatAGraphKeptForAPartMustTakeIn) {
  ObstacleSet part;
  part.ellipses.push_back(test::disc(0, 0, 5, "a"));
  part.ellipses.push_back(test::disc(10, 0, 5, "b"));
  const PolygonObstacle box{"", square(0.0, 0.0, 10.0), std::nullopt, std::nullopt};
  part.polygons.push_back(box);
  // The part's obstacles among others, in another order, one of them twice.
  ObstacleSet all;
  all.ellipses.push_back(test::disc(10, 0, 5, "b, renamed"));  // ids do not count, footprints do
  all.ellipses.push_back(test::disc(50, 0, 5, "c"));
  all.ellipses.push_back(test::disc(0, 0, 5, "a"));
  all.ellipses.push_back(test::disc(0, 0, 5, "a again"));
  all.polygons.push_back(box);
  const std::optional<ObstacleSet> beyond = obstacles_beyond(all, part);
  ASSERT_TRUE(beyond);
  ASSERT_EQ(beyond->ellipses.size(), 2u);
  EXPECT_EQ(beyond->ellipses[0].id, "c");
  EXPECT_EQ(beyond->ellipses[1].id, "a again");
  EXPECT_TRUE(beyond->polygons.empty());
  EXPECT_TRUE(obstacles_beyond(part, part)->empty());
  // A footprint a nanometre off is another obstacle: the part is not all there.
  ObstacleSet moved = all;
  moved.ellipses[0].footprint.centre.x() += 1e-9;
  moved.ellipses[3].footprint.centre.x() += 1e-9;
  EXPECT_FALSE(obstacles_beyond(moved, part));
  ObstacleSet without = all;
  without.polygons.clear();
  EXPECT_FALSE(obstacles_beyond(without, part));
}
