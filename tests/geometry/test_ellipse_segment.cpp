// Segment against ellipse (geometry/ellipse_segment.hpp).
//
// Hand cases are chosen so that the crossings are exact: for the unit circle and
// the segment (-2, 0) -> (2, 0), |p(t)| = |4 t - 2| = 1 at t = 1/4 and 3/4. For the
// random cases the reference is the test's own implicit function
// ((local x / a)^2 + (local y / b)^2, < 1 inside) evaluated at 10001 points along
// the segment: a sample clearly inside (below 1 - 1e-6) means the segment
// intersects, all samples clearly outside (above 1 + 1e-6) means it does not;
// a sign change between neighbouring samples brackets a boundary crossing.
// Segments span at most ~7 in the unit-circle frame, so the implicit function,
// a quadratic in t, moves by less than 1e-7 between a sample and the true minimum:
// sampling cannot miss a 1e-6 margin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"
#include "reference_ellipse.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = std::numbers::pi;

// The ellipse frame, from (c, a, b, theta) only (reference_ellipse.hpp).
using test_ref::Frame;

Vec2 lerp(const Vec2& p0, const Vec2& p1, double t) { return p0 + t * (p1 - p0); }

}  // namespace

TEST(EllipseSegment, HorizontalLineThroughCircle) {
  const Ellipse circle{Vec2(0.0, 0.0), 1.0, 1.0, 0.0};
  const std::vector<double> ts = segment_boundary_crossings(circle, Vec2(-2.0, 0.0), Vec2(2.0, 0.0));
  ASSERT_EQ(ts.size(), 2u);
  EXPECT_NEAR(ts[0], 0.25, 1e-15);
  EXPECT_NEAR(ts[1], 0.75, 1e-15);
  EXPECT_TRUE(segment_intersects(circle, Vec2(-2.0, 0.0), Vec2(2.0, 0.0)));
  // Reversed direction: the same crossings, still ascending.
  const std::vector<double> rs = segment_boundary_crossings(circle, Vec2(2.0, 0.0), Vec2(-2.0, 0.0));
  ASSERT_EQ(rs.size(), 2u);
  EXPECT_NEAR(rs[0], 0.25, 1e-15);
  EXPECT_NEAR(rs[1], 0.75, 1e-15);
  // A chord off the centre: y = 0.6 meets the circle at x = +-0.8;
  // the segment (-1.6, 0.6) -> (1.6, 0.6) does so at t = 0.8 / 3.2 = 0.25 and 0.75.
  const std::vector<double> cs = segment_boundary_crossings(circle, Vec2(-1.6, 0.6), Vec2(1.6, 0.6));
  ASSERT_EQ(cs.size(), 2u);
  EXPECT_NEAR(cs[0], 0.25, 1e-15);
  EXPECT_NEAR(cs[1], 0.75, 1e-15);
}

TEST(EllipseSegment, RotatedEllipseAlongItsAxes) {
  // a = 2, b = 1, major axis along north (theta = pi/2), centre (1, 1): the major axis
  // runs from (1, -1) to (1, 3), the minor axis from (0, 1) to (2, 1).
  const Ellipse e{Vec2(1.0, 1.0), 2.0, 1.0, kPi / 2.0};
  // Along the major axis from (1, -3) to (1, 5): crossings at y = -1 and 3, t = 2/8, 6/8.
  const std::vector<double> major = segment_boundary_crossings(e, Vec2(1.0, -3.0), Vec2(1.0, 5.0));
  ASSERT_EQ(major.size(), 2u);
  EXPECT_NEAR(major[0], 0.25, 1e-14);
  EXPECT_NEAR(major[1], 0.75, 1e-14);
  // Along the minor axis from (-3, 1) to (5, 1): crossings at x = 0 and 2, t = 3/8, 5/8.
  const std::vector<double> minor = segment_boundary_crossings(e, Vec2(-3.0, 1.0), Vec2(5.0, 1.0));
  ASSERT_EQ(minor.size(), 2u);
  EXPECT_NEAR(minor[0], 0.375, 1e-14);
  EXPECT_NEAR(minor[1], 0.625, 1e-14);
  // The segment (1.5, -3) -> (1.5, 5) runs parallel to the major axis, 0.5 off it:
  // ((y - 1) / 2)^2 + 0.5^2 = 1 gives y = 1 +- sqrt(3), t = (y + 3) / 8.
  const std::vector<double> off = segment_boundary_crossings(e, Vec2(1.5, -3.0), Vec2(1.5, 5.0));
  ASSERT_EQ(off.size(), 2u);
  EXPECT_NEAR(off[0], (4.0 - std::sqrt(3.0)) / 8.0, 1e-14);
  EXPECT_NEAR(off[1], (4.0 + std::sqrt(3.0)) / 8.0, 1e-14);
}

TEST(EllipseSegment, OneEndInside) {
  const Ellipse circle{Vec2(0.0, 0.0), 1.0, 1.0, 0.0};
  // From the centre to (3, 0): one crossing at t = 1/3.
  const std::vector<double> ts = segment_boundary_crossings(circle, Vec2(0.0, 0.0), Vec2(3.0, 0.0));
  ASSERT_EQ(ts.size(), 1u);
  EXPECT_NEAR(ts[0], 1.0 / 3.0, 1e-15);
  EXPECT_TRUE(segment_intersects(circle, Vec2(0.0, 0.0), Vec2(3.0, 0.0)));
  // Ending exactly on the boundary: t = 1 is reported.
  const std::vector<double> end = segment_boundary_crossings(circle, Vec2(0.0, 0.0), Vec2(1.0, 0.0));
  ASSERT_EQ(end.size(), 1u);
  EXPECT_EQ(end[0], 1.0);
  // Starting exactly on the boundary and going outwards: t = 0, and no interior point.
  const std::vector<double> start = segment_boundary_crossings(circle, Vec2(0.0, 1.0), Vec2(0.0, 3.0));
  ASSERT_EQ(start.size(), 1u);
  EXPECT_EQ(start[0], 0.0);
  EXPECT_FALSE(segment_intersects(circle, Vec2(0.0, 1.0), Vec2(0.0, 3.0)));
}

TEST(EllipseSegment, TangentSegmentTouchesButDoesNotIntersect) {
  // y = 1 touches the unit circle at (0, 1), the middle of the segment.
  const Ellipse circle{Vec2(0.0, 0.0), 1.0, 1.0, 0.0};
  EXPECT_FALSE(segment_intersects(circle, Vec2(-2.0, 1.0), Vec2(2.0, 1.0)));
  const std::vector<double> ts = segment_boundary_crossings(circle, Vec2(-2.0, 1.0), Vec2(2.0, 1.0));
  ASSERT_EQ(ts.size(), 1u);  // a double root is reported once
  EXPECT_EQ(ts[0], 0.5);
  // x = 5 touches the axis-aligned ellipse a = 5, b = 3 at (5, 0).
  const Ellipse e{Vec2(0.0, 0.0), 5.0, 3.0, 0.0};
  EXPECT_FALSE(segment_intersects(e, Vec2(5.0, -4.0), Vec2(5.0, 4.0)));
  EXPECT_FALSE(segment_intersects(e, Vec2(-8.0, 3.0), Vec2(8.0, 3.0)));  // y = 3 at (0, 3)
  // Moved inwards by 1e-9 it intersects, outwards it does not.
  EXPECT_TRUE(segment_intersects(e, Vec2(5.0 - 1e-9, -4.0), Vec2(5.0 - 1e-9, 4.0)));
  EXPECT_FALSE(segment_intersects(e, Vec2(5.0 + 1e-9, -4.0), Vec2(5.0 + 1e-9, 4.0)));
  EXPECT_TRUE(segment_boundary_crossings(e, Vec2(5.0 + 1e-9, -4.0), Vec2(5.0 + 1e-9, 4.0)).empty());
}

TEST(EllipseSegment, TangentToRotatedEllipseWithinRounding) {
  // The tangent at boundary parameter s of a rotated ellipse, shifted by +-1e-9 along
  // the normal: outside never intersects, inside always does.
  const Ellipse e{Vec2(3.0, -7.0), 6.0, 1.5, 0.9};
  const Frame f(e);
  for (int k = 0; k < 36; ++k) {
    const double s = 2.0 * kPi * k / 36.0 + 0.01;
    const Vec2 x = f.from_unit(std::cos(s), std::sin(s));
    const Vec2 tangent = (-f.a * std::sin(s) * f.u + f.b * std::cos(s) * f.v).normalized();
    const Vec2 normal(tangent.y(), -tangent.x());  // outward for a ccw parameterisation
    for (double off : {1e-9, 1e-6}) {
      EXPECT_FALSE(segment_intersects(e, x + off * normal - 3.0 * tangent, x + off * normal + 2.0 * tangent)) << s;
      EXPECT_TRUE(segment_intersects(e, x - off * normal - 3.0 * tangent, x - off * normal + 2.0 * tangent)) << s;
    }
  }
}

TEST(EllipseSegment, SegmentFullyInside) {
  const Ellipse e{Vec2(10.0, 20.0), 4.0, 2.0, 0.3};
  const Vec2 p0(10.5, 20.2);
  const Vec2 p1(9.0, 19.8);
  ASSERT_LT(Frame(e).implicit(p0), 1.0);
  ASSERT_LT(Frame(e).implicit(p1), 1.0);
  EXPECT_TRUE(segment_intersects(e, p0, p1));
  EXPECT_TRUE(segment_boundary_crossings(e, p0, p1).empty());
}

TEST(EllipseSegment, DisjointSegments) {
  const Ellipse circle{Vec2(0.0, 0.0), 1.0, 1.0, 0.0};
  EXPECT_FALSE(segment_intersects(circle, Vec2(3.0, 3.0), Vec2(4.0, 5.0)));
  EXPECT_TRUE(segment_boundary_crossings(circle, Vec2(3.0, 3.0), Vec2(4.0, 5.0)).empty());
  // On a line through the circle but stopping short of it (roots at t = 2 and 4).
  EXPECT_FALSE(segment_intersects(circle, Vec2(-3.0, 0.0), Vec2(-2.0, 0.0)));
  EXPECT_TRUE(segment_boundary_crossings(circle, Vec2(-3.0, 0.0), Vec2(-2.0, 0.0)).empty());
  // And after it (roots at t = -4, -2).
  EXPECT_FALSE(segment_intersects(circle, Vec2(2.0, 0.0), Vec2(3.0, 0.0)));
  EXPECT_TRUE(segment_boundary_crossings(circle, Vec2(2.0, 0.0), Vec2(3.0, 0.0)).empty());
  // Passing by a rotated elongated ellipse: a = 10, b = 1 along the diagonal; the
  // segment along the other diagonal at distance 2 from the centre misses it.
  const Ellipse diag{Vec2(0.0, 0.0), 10.0, 1.0, kPi / 4.0};
  const Vec2 n(std::sqrt(0.5), std::sqrt(0.5));   // the major direction
  const Vec2 m(-std::sqrt(0.5), std::sqrt(0.5));  // the minor direction
  EXPECT_FALSE(segment_intersects(diag, 12.0 * n - 5.0 * m, 12.0 * n + 5.0 * m));
  EXPECT_TRUE(segment_intersects(diag, 9.0 * n - 5.0 * m, 9.0 * n + 5.0 * m));
  EXPECT_FALSE(segment_intersects(diag, 1.5 * m - 20.0 * n, 1.5 * m + 20.0 * n));
  EXPECT_TRUE(segment_intersects(diag, 0.5 * m - 20.0 * n, 0.5 * m + 20.0 * n));
}

TEST(EllipseSegment, DegenerateSegment) {
  const Ellipse e{Vec2(1.0, 2.0), 3.0, 2.0, 0.4};
  const Vec2 inside(1.5, 2.5);
  const Vec2 outside(5.0, 5.0);
  ASSERT_LT(Frame(e).implicit(inside), 1.0);
  ASSERT_GT(Frame(e).implicit(outside), 1.0);
  EXPECT_TRUE(segment_intersects(e, inside, inside));
  EXPECT_FALSE(segment_intersects(e, outside, outside));
  EXPECT_TRUE(segment_boundary_crossings(e, inside, inside).empty());
  EXPECT_TRUE(segment_boundary_crossings(e, outside, outside).empty());
  // A point exactly on the boundary is not strictly inside.
  const Ellipse circle{Vec2(0.0, 0.0), 1.0, 1.0, 0.0};
  EXPECT_FALSE(segment_intersects(circle, Vec2(1.0, 0.0), Vec2(1.0, 0.0)));
  EXPECT_TRUE(segment_boundary_crossings(circle, Vec2(1.0, 0.0), Vec2(1.0, 0.0)).empty());
}

TEST(EllipseSegment, RandomAgainstDenseSampling) {
  std::mt19937 rng(20240605);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::uniform_real_distribution<double> box(-2.5, 2.5);
  constexpr int kSegSamples = 10000;
  int cases = 0;
  int intersecting = 0;
  int missing = 0;
  int crossing_cases = 0;
  for (int i = 0; i < 2000; ++i) {
    Ellipse e;
    e.b = 0.2 + 5.0 * u01(rng);
    e.a = e.b * (u01(rng) < 0.2 ? 1.0 : std::exp(std::log(20.0) * u01(rng)));
    e.theta = -kPi + 2.0 * kPi * u01(rng);
    e.centre = Vec2(-100.0 + 200.0 * u01(rng), -100.0 + 200.0 * u01(rng));
    const Frame f(e);
    // Endpoints uniform in [-2.5, 2.5]^2 of the unit-circle frame; sometimes a short
    // segment, so that both ends inside (or both outside, close together) occur.
    const Vec2 p0 = f.from_unit(box(rng), box(rng));
    Vec2 p1 = f.from_unit(box(rng), box(rng));
    if (i % 4 == 0) p1 = p0 + 0.1 * (p1 - p0);

    std::vector<double> g(kSegSamples + 1);
    double gmin = 1e300;
    for (int k = 0; k <= kSegSamples; ++k) {
      g[k] = f.implicit(lerp(p0, p1, double(k) / kSegSamples)) - 1.0;
      gmin = std::min(gmin, g[k]);
    }
    SCOPED_TRACE(::testing::Message() << "case " << i << " gmin " << gmin);
    const bool hit = segment_intersects(e, p0, p1);
    if (gmin < -1e-6) {
      EXPECT_TRUE(hit);
      ++intersecting;
    } else if (gmin > 1e-6) {
      EXPECT_FALSE(hit);
      ++missing;
    } else {
      continue;  // grazing within 1e-6: no clear answer
    }
    ++cases;

    const std::vector<double> ts = segment_boundary_crossings(e, p0, p1);
    // Every reported crossing is in [0, 1], ascending, and on the boundary.
    for (std::size_t j = 0; j < ts.size(); ++j) {
      EXPECT_GE(ts[j], 0.0);
      EXPECT_LE(ts[j], 1.0);
      if (j > 0) {
        EXPECT_LT(ts[j - 1], ts[j]);
      }
      EXPECT_NEAR(f.implicit(lerp(p0, p1, ts[j])), 1.0, 1e-9) << ts[j];
    }
    // Sign changes between samples (clear on both sides) bracket the crossings. Skip
    // the count check when an end lies within 1e-6 of the boundary.
    if (std::abs(g.front()) < 1e-6 || std::abs(g.back()) < 1e-6) continue;
    std::vector<int> brackets;
    for (int k = 0; k < kSegSamples; ++k) {
      if ((g[k] < 0.0) != (g[k + 1] < 0.0)) brackets.push_back(k);
    }
    ASSERT_EQ(ts.size(), brackets.size());
    for (std::size_t j = 0; j < ts.size(); ++j) {
      EXPECT_GE(ts[j], double(brackets[j]) / kSegSamples - 1e-12);
      EXPECT_LE(ts[j], double(brackets[j] + 1) / kSegSamples + 1e-12);
    }
    // Crossings without an interior point can only be a tangent, excluded above.
    if (!ts.empty()) {
      ++crossing_cases;
      EXPECT_TRUE(hit);
    }
  }
  EXPECT_GE(cases, 1900);
  EXPECT_GE(intersecting, 500);
  EXPECT_GE(missing, 500);
  EXPECT_GE(crossing_cases, 500);
  std::printf("[ segment  ] %d random cases: %d intersecting, %d missing, %d with crossings\n", cases, intersecting,
              missing, crossing_cases);
}
