// Point-to-ellipse distance (geometry/ellipse_distance.hpp).
//
// The reference (reference_ellipse.hpp) is computed without the library's distance
// code or the Ellipse member functions: the boundary
// x(t) = c + R(theta) diag(a, b) (cos t, sin t) is sampled at 20000 parameters,
// every discrete local minimum of |p - x(t)|^2 (the best few) is refined by
// golden-section search on the bracketing sample interval and polished with
// safeguarded Newton steps on d/dt |p - x(t)|^2 = 0, and the smallest refined
// distance wins. Inside/outside comes from the implicit equation
// (local x / a)^2 + (local y / b)^2 < 1, also from that header.
//
// Hand-derived cases (axis-aligned a = 5, b = 3 unless stated):
//   centre -> closest (0, +-3), distance b = 3;  (10, 0) -> 5;  (0, 10) -> 7;
//   on the major axis inside, the closest point leaves the axis while |x0| is
//   below the evolute cusp (a^2 - b^2) / a = 3.2; then the closest point is
//   x = a^2 x0 / (a^2 - b^2) and the distance is b sqrt(1 - x0^2 / (a^2 - b^2))
//   (e.g. x0 = 2: sqrt(6.75)); beyond the cusp (x0 = 4) it is (5, 0), distance 1.
//   Circle radius r: distance = | |p - c| - r |.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "reference_ellipse.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = std::numbers::pi;

// The independent reference (Frame, dense-sampling reference_distance) is in
// reference_ellipse.hpp.
using test_ref::Frame;
using test_ref::reference_distance;
using test_ref::RefResult;

// ---- Case generation -------------------------------------------------------
//
// Points are placed in the ellipse's own frame (x along the major axis) and mapped
// to the world with the test's Frame. For rotated ellipses "on an axis" then means
// within rounding (~1e-15) of it; some ellipses are axis-aligned so that it is exact.

enum class Kind {
  general_outside,      // anywhere outside, up to 4x the size
  general_inside,       // anywhere inside
  near_boundary,        // within 1e-4 (relative) of the boundary, both sides
  major_axis_outer,     // on the major axis (or within 1e-6 of it), beyond the evolute cusp
  major_axis_moderate,  // inside the cusp, 1e-3 b .. 1e-1 b off the major axis
  on_minor_axis,        // on the minor axis, inside and outside
  near_minor_axis,      // within 1e-6 of the minor axis
  centre,               // exactly the centre
  near_cusp,            // around the cusp (a^2 - b^2) / a, 1e-4 b .. 1e-3 b off the axis
  // Precision regressions, see RandomNearMajorAxisInsideCuspMatchesReference below:
  major_axis_inner,  // on the major axis, inside the cusp
  near_major_axis,   // within 1e-6 of the major axis, inside the cusp
  near_centre,       // within 1e-6 of the centre
};

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::general_outside: return "general_outside";
    case Kind::general_inside: return "general_inside";
    case Kind::near_boundary: return "near_boundary";
    case Kind::major_axis_outer: return "major_axis_outer";
    case Kind::major_axis_moderate: return "major_axis_moderate";
    case Kind::on_minor_axis: return "on_minor_axis";
    case Kind::near_minor_axis: return "near_minor_axis";
    case Kind::centre: return "centre";
    case Kind::near_cusp: return "near_cusp";
    case Kind::major_axis_inner: return "major_axis_inner";
    case Kind::near_major_axis: return "near_major_axis";
    case Kind::near_centre: return "near_centre";
  }
  return "?";
}

struct Case {
  Ellipse e;
  Vec2 p;
};

Ellipse random_ellipse(std::mt19937& rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  Ellipse e;
  e.b = 0.5 + 9.5 * u01(rng);
  const double pick = u01(rng);
  double ratio = 1.0;
  if (pick < 0.15) {
    ratio = 1.0;  // circle, a == b exactly
  } else if (pick < 0.25) {
    ratio = 1.0 + 1e-6 * u01(rng);  // near-circular
  } else if (pick < 0.35) {
    ratio = 20.0;  // the most elongated case
  } else {
    ratio = std::exp(std::log(20.0) * u01(rng));  // log-uniform in [1, 20]
  }
  e.a = e.b * ratio;
  const double tp = u01(rng);
  // Mostly rotated; some exactly axis-aligned so that "on the axis" is exact.
  e.theta = tp < 0.15 ? 0.0 : (tp < 0.2 ? kPi / 2.0 : -kPi + 2.0 * kPi * u01(rng));
  e.centre = Vec2(-50.0 + 100.0 * u01(rng), -50.0 + 100.0 * u01(rng));
  return e;
}

Case random_case(std::mt19937& rng, Kind kind) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::uniform_real_distribution<double> sym(-1.0, 1.0);
  auto sign = [&] { return u01(rng) < 0.5 ? -1.0 : 1.0; };
  Case c{random_ellipse(rng), Vec2::Zero()};
  const double a = c.e.a;
  const double b = c.e.b;
  const double cusp = (a * a - b * b) / a;  // evolute cusp on the major axis
  const double phi = 2.0 * kPi * u01(rng);
  double x = 0.0;
  double y = 0.0;
  switch (kind) {
    case Kind::general_outside: {
      const double rho = 1.001 + 3.0 * u01(rng);  // radius in the unit-circle frame
      x = a * rho * std::cos(phi), y = b * rho * std::sin(phi);
      break;
    }
    case Kind::general_inside: {
      const double rho = 0.999 * std::sqrt(u01(rng));
      x = a * rho * std::cos(phi), y = b * rho * std::sin(phi);
      break;
    }
    case Kind::near_boundary: {
      const double rho = 1.0 + 1e-4 * sym(rng);
      x = a * rho * std::cos(phi), y = b * rho * std::sin(phi);
      break;
    }
    case Kind::major_axis_outer:
      x = sign() * (cusp + (3.0 * a - cusp) * u01(rng));
      y = u01(rng) < 0.5 ? 0.0 : 1e-6 * sym(rng);
      break;
    case Kind::major_axis_moderate:
      x = cusp * sym(rng);
      y = sign() * b * std::pow(10.0, -3.0 + 2.0 * u01(rng));
      break;
    case Kind::on_minor_axis: x = 0.0, y = 3.0 * b * sym(rng); break;
    case Kind::near_minor_axis: x = 1e-6 * sym(rng), y = 3.0 * b * sym(rng); break;
    case Kind::centre: break;
    case Kind::near_cusp:
      x = sign() * (cusp + 0.01 * b * sym(rng));
      y = sign() * b * std::pow(10.0, -4.0 + u01(rng));
      break;
    case Kind::major_axis_inner: x = cusp * sym(rng), y = 0.0; break;
    case Kind::near_major_axis: x = cusp * sym(rng), y = 1e-6 * sym(rng); break;
    case Kind::near_centre: x = 1e-6 * sym(rng), y = 1e-6 * sym(rng); break;
  }
  c.p = Frame(c.e).local_to_world(x, y);
  return c;
}

// Compares the library with the reference on one case. Returns an empty string
// when every check holds, else a description; `rel` receives the relative error
// of the unsigned distance and `inside` whether the point is clearly inside.
std::string check_case(const Case& c, double& rel, double& abs_err, double& dist, bool& inside) {
  const Frame f(c.e);
  const RefResult ref = reference_distance(c.e, c.p);
  const EllipseProjection pr = project_to_ellipse(c.e, c.p);
  std::ostringstream why;
  why.precision(17);

  // Unsigned distance: relative 1e-9 with an absolute floor of 1e-12.
  const double err = std::abs(pr.distance - ref.distance);
  abs_err = err;
  dist = ref.distance;
  rel = std::isfinite(err) ? err / std::max(ref.distance, 1e-12) : std::numeric_limits<double>::infinity();
  if (!(err <= 1e-9 * ref.distance + 1e-12)) {
    why << " distance " << pr.distance << " vs reference " << ref.distance << " (rel " << rel << ");";
  }
  // Sign from the implicit equation (undecided only within rounding of the boundary).
  const double imp = f.implicit(c.p);
  inside = imp < 1.0 - 1e-12;
  if (inside && !(pr.inside && signed_distance(c.e, c.p) < 0.0)) why << " should be inside;";
  if (imp > 1.0 + 1e-12 && !(!pr.inside && signed_distance(c.e, c.p) > 0.0)) {
    why << " should be outside;";
  }
  if (signed_distance(c.e, c.p) != pr.signed_distance() || std::abs(pr.signed_distance()) != pr.distance) {
    why << " signed_distance inconsistent;";
  }
  // The closest point is on the ellipse and at the reported distance.
  const double on = f.implicit(pr.point);
  if (!(std::abs(on - 1.0) <= 1e-12)) why << " closest point implicit value " << on << ";";
  const double dp = (pr.point - c.p).norm();
  if (!(std::abs(dp - pr.distance) <= 1e-12 * (1.0 + pr.distance))) {
    why << " |p - point| = " << dp << " != distance;";
  }
  if (why.str().empty()) return {};
  std::ostringstream out;
  out.precision(17);
  out << "a=" << c.e.a << " b=" << c.e.b << " theta=" << c.e.theta << " c=(" << c.e.centre.x() << ", " << c.e.centre.y()
      << ") p=(" << c.p.x() << ", " << c.p.y() << ") local=(" << f.u.dot(c.p - f.c) << ", " << f.v.dot(c.p - f.c)
      << "):" << why.str();
  return out.str();
}

struct Summary {
  int cases = 0;
  int inside = 0;
  int failed = 0;
  double worst_rel = 0.0;  // over all cases, err / max(d, 1e-12)
  std::string worst_kind;
  double worst_rel_far = 0.0;  // over cases with d >= 1e-3 (away from the boundary)
  double worst_abs = 0.0;      // absolute error over all cases
};

// Runs `per_kind` random cases of each kind; reports the first few failures in full.
Summary run_kinds(std::mt19937& rng, std::initializer_list<Kind> kinds, int per_kind) {
  Summary s;
  for (Kind kind : kinds) {
    int kind_failed = 0;
    for (int i = 0; i < per_kind; ++i) {
      const Case c = random_case(rng, kind);
      double rel = 0.0;
      double abs_err = 0.0;
      double dist = 0.0;
      bool inside = false;
      const std::string why = check_case(c, rel, abs_err, dist, inside);
      s.worst_abs = std::max(s.worst_abs, abs_err);
      if (dist >= 1e-3) s.worst_rel_far = std::max(s.worst_rel_far, rel);
      ++s.cases;
      if (inside) ++s.inside;
      if (rel > s.worst_rel) s.worst_rel = rel, s.worst_kind = kind_name(kind);
      if (!why.empty()) {
        ++s.failed;
        if (++kind_failed <= 3) ADD_FAILURE() << kind_name(kind) << " #" << i << ": " << why;
      }
    }
    if (kind_failed > 0) {
      ADD_FAILURE() << kind_name(kind) << ": " << kind_failed << " of " << per_kind << " cases fail";
    }
  }
  return s;
}

}  // namespace

// ---- Hand-derived cases ----------------------------------------------------

TEST(EllipseDistance, AxisAlignedHandCases) {
  const Ellipse e{Vec2(0.0, 0.0), 5.0, 3.0, 0.0};

  const EllipseProjection c = project_to_ellipse(e, Vec2(0.0, 0.0));
  EXPECT_NEAR(c.distance, 3.0, 1e-15);
  EXPECT_TRUE(c.inside);
  EXPECT_NEAR(c.point.x(), 0.0, 1e-15);
  EXPECT_NEAR(std::abs(c.point.y()), 3.0, 1e-15);
  EXPECT_NEAR(c.signed_distance(), -3.0, 1e-15);
  EXPECT_NEAR(signed_distance(e, Vec2(0.0, 0.0)), -3.0, 1e-15);

  const EllipseProjection px = project_to_ellipse(e, Vec2(10.0, 0.0));
  EXPECT_NEAR(px.distance, 5.0, 1e-15);
  EXPECT_FALSE(px.inside);
  EXPECT_NEAR(px.point.x(), 5.0, 1e-15);
  EXPECT_NEAR(px.point.y(), 0.0, 1e-15);
  EXPECT_NEAR(signed_distance(e, Vec2(10.0, 0.0)), 5.0, 1e-15);
  EXPECT_NEAR(signed_distance(e, Vec2(-10.0, 0.0)), 5.0, 1e-15);

  const EllipseProjection py = project_to_ellipse(e, Vec2(0.0, 10.0));
  EXPECT_NEAR(py.distance, 7.0, 1e-15);
  EXPECT_NEAR(py.point.x(), 0.0, 1e-15);
  EXPECT_NEAR(py.point.y(), 3.0, 1e-15);
  EXPECT_NEAR(signed_distance(e, Vec2(0.0, -10.0)), 7.0, 1e-15);

  // Inside on the minor axis: straight to the minor vertex.
  EXPECT_NEAR(signed_distance(e, Vec2(0.0, 1.0)), -2.0, 1e-15);

  // Inside on the major axis beyond the cusp (3.2): the major vertex is closest.
  const EllipseProjection beyond = project_to_ellipse(e, Vec2(4.0, 0.0));
  EXPECT_TRUE(beyond.inside);
  EXPECT_NEAR(beyond.distance, 1.0, 1e-15);
  EXPECT_NEAR(beyond.point.x(), 5.0, 1e-15);
  EXPECT_NEAR(beyond.point.y(), 0.0, 1e-15);
  // Exactly at the cusp: both formulas agree, 5 - 3.2 = 1.8.
  EXPECT_NEAR(project_to_ellipse(e, Vec2(3.2, 0.0)).distance, 1.8, 1e-14);

  // Inside on the major axis within the cusp: x0 = 2 -> closest x = 25 * 2 / 16 = 3.125,
  // y = 3 sqrt(1 - (3.125 / 5)^2), distance = 3 sqrt(1 - 4 / 16) = sqrt(6.75).
  const EllipseProjection within = project_to_ellipse(e, Vec2(2.0, 0.0));
  EXPECT_TRUE(within.inside);
  EXPECT_NEAR(within.distance, std::sqrt(6.75), 1e-14);
  EXPECT_NEAR(within.point.x(), 3.125, 1e-14);
  EXPECT_NEAR(std::abs(within.point.y()), 3.0 * std::sqrt(1.0 - 0.625 * 0.625), 1e-14);
  for (double x0 : {-3.0, -1.0, 0.5, 3.0}) {
    EXPECT_NEAR(signed_distance(e, Vec2(x0, 0.0)), -3.0 * std::sqrt(1.0 - x0 * x0 / 16.0), 1e-14) << x0;
  }

  // On the boundary: zero.
  EXPECT_NEAR(project_to_ellipse(e, Vec2(5.0, 0.0)).distance, 0.0, 1e-15);
  EXPECT_NEAR(project_to_ellipse(e, Vec2(0.0, -3.0)).distance, 0.0, 1e-15);
  EXPECT_NEAR(project_to_ellipse(e, Vec2(4.0, 1.8)).distance, 0.0, 1e-14);  // 16/25 + 9/25 = 1
}

TEST(EllipseDistance, RotatedHandCases) {
  // The same ellipse rotated by 0.7 rad and moved to (3, -2): distances are unchanged.
  const double th = 0.7;
  const Vec2 c(3.0, -2.0);
  const Ellipse e{c, 5.0, 3.0, th};
  const Vec2 u(std::cos(th), std::sin(th));
  const Vec2 v(-std::sin(th), std::cos(th));
  EXPECT_NEAR(signed_distance(e, c), -3.0, 1e-14);
  EXPECT_NEAR(signed_distance(e, c + 10.0 * u), 5.0, 1e-13);
  EXPECT_NEAR(signed_distance(e, c - 10.0 * v), 7.0, 1e-13);
  EXPECT_NEAR(signed_distance(e, c + 4.0 * u), -1.0, 1e-13);
  EXPECT_NEAR(signed_distance(e, c - 2.0 * u), -std::sqrt(6.75), 1e-13);
  const EllipseProjection pr = project_to_ellipse(e, c + 10.0 * u);
  EXPECT_NEAR((pr.point - (c + 5.0 * u)).norm(), 0.0, 1e-13);
}

TEST(EllipseDistance, CircleIsRadialDistance) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const double r = 0.1 + 20.0 * u01(rng);
    const Ellipse e{Vec2(-30.0 + 60.0 * u01(rng), -30.0 + 60.0 * u01(rng)), r, r, -kPi + 2.0 * kPi * u01(rng)};
    const double phi = 2.0 * kPi * u01(rng);
    const double rho = 3.0 * r * u01(rng);
    const Vec2 p = e.centre + rho * Vec2(std::cos(phi), std::sin(phi));
    const double radial = (p - e.centre).norm();
    const double expected = std::abs(radial - r);
    const EllipseProjection pr = project_to_ellipse(e, p);
    ASSERT_NEAR(pr.distance, expected, 1e-12 * (1.0 + r)) << i;
    ASSERT_EQ(pr.inside, radial < r) << i;
    // The closest point is on the ray from the centre through p.
    if (radial > 1e-9) {
      ASSERT_NEAR((pr.point - (e.centre + r * (p - e.centre) / radial)).norm(), 0.0, 1e-12 * (1.0 + r)) << i;
    }
  }
  // Exactly at the centre of a circle: any boundary point, distance r.
  const Ellipse circle{Vec2(1.0, 2.0), 4.0, 4.0, 0.3};
  const EllipseProjection pc = project_to_ellipse(circle, Vec2(1.0, 2.0));
  EXPECT_NEAR(pc.distance, 4.0, 1e-14);
  EXPECT_TRUE(pc.inside);
  EXPECT_NEAR((pc.point - circle.centre).norm(), 4.0, 1e-14);
}

// ---- The reference itself is checked on the hand cases first ---------------

TEST(EllipseDistance, ReferenceReproducesHandCases) {
  const Ellipse e{Vec2(0.0, 0.0), 5.0, 3.0, 0.0};
  EXPECT_NEAR(reference_distance(e, Vec2(0.0, 0.0)).distance, 3.0, 1e-13);
  EXPECT_NEAR(reference_distance(e, Vec2(10.0, 0.0)).distance, 5.0, 1e-13);
  EXPECT_NEAR(reference_distance(e, Vec2(0.0, 10.0)).distance, 7.0, 1e-13);
  EXPECT_NEAR(reference_distance(e, Vec2(2.0, 0.0)).distance, std::sqrt(6.75), 1e-13);
  EXPECT_NEAR(reference_distance(e, Vec2(4.0, 0.0)).distance, 1.0, 1e-13);
}

// ---- Random rotated ellipses against the dense-sampling reference -------------

TEST(EllipseDistance, RandomRotatedMatchesDenseSamplingReference) {
  std::mt19937 rng(20240603);
  const Summary s =
      run_kinds(rng,
                {Kind::general_outside, Kind::general_inside, Kind::near_boundary, Kind::major_axis_outer,
                 Kind::major_axis_moderate, Kind::on_minor_axis, Kind::near_minor_axis, Kind::centre, Kind::near_cusp},
                150);
  EXPECT_EQ(s.cases, 1350);
  EXPECT_GE(s.inside, 400);
  EXPECT_EQ(s.failed, 0);
  std::printf(
      "[ distance ] %d random cases (%d inside): worst relative error %.3g (%s), "
      "%.3g for distances >= 1e-3, worst absolute error %.3g\n",
      s.cases, s.inside, s.worst_rel, s.worst_kind.c_str(), s.worst_rel_far, s.worst_abs);
}

// Regression (geometry/ellipse_distance.cpp, project_to_ellipse -> bisect_root).
// For a point inside the evolute (|local x| < (a^2 - b^2) / a) whose local y is
// tiny but not exactly zero, Eberly's root s tends to -1 and s + 1 = y1 / x1 falls
// below the spacing of doubles near -1 (1.1e-16): solving for s, x1 = y1 / (s + 1)
// loses all precision, and when the bisection settles on s == -1 it divides by
// zero. That is exactly a point on the major axis of a ROTATED ellipse (local
// y ~ 1e-16 after the rotation), and any point near the centre. The s-based
// version failed 256 of these 300 cases (distance off by up to 45 %, or inf;
// closest point off the ellipse by up to 1e-10 .. 0.7 in the implicit value).
TEST(EllipseDistance, RandomNearMajorAxisInsideCuspMatchesReference) {
  std::mt19937 rng(20240604);
  const Summary s = run_kinds(rng, {Kind::major_axis_inner, Kind::near_major_axis, Kind::near_centre}, 100);
  EXPECT_EQ(s.failed, 0) << "of " << s.cases << " cases; worst relative error " << s.worst_rel << " (" << s.worst_kind
                         << ")";
  std::printf("[ distance ] near major axis / centre: %d cases, %d failed, worst rel %.3g\n", s.cases, s.failed,
              s.worst_rel);
}

// The same regression on hand cases: a = 5, b = 3, x0 = 2 lies inside the cusp (3.2).
// On the axis the closest points are (3.125, +-y1), y1 = 3 sqrt(1 - 0.625^2), at
// d0 = sqrt(6.75). Moving the query point up by a small y moves it towards the upper
// one: d(y) = d0 - y * y1 / d0 + O(y^2), the O(y^2) term being below
// y^2 / (2 (rho - d0)) < 1e-12 here (rho = 5.41, the radius of curvature there).
// The s-based version gave inf for y = 1e-20, 2.5172 for y = 1e-15, an error of
// 8e-5 for y = 1e-12 and 3e-10 for y = 1e-6.
TEST(EllipseDistance, TinyOffsetFromMajorAxisInsideCusp) {
  const Ellipse e{Vec2(0.0, 0.0), 5.0, 3.0, 0.0};
  const double d0 = std::sqrt(6.75);
  const double y1 = 3.0 * std::sqrt(1.0 - 0.625 * 0.625);
  for (double y : {1e-20, 1e-15, 1e-12, 1e-9, 1e-6}) {
    const EllipseProjection pr = project_to_ellipse(e, Vec2(2.0, y));
    EXPECT_NEAR(pr.distance, d0 - y * y1 / d0, 1e-12) << "y = " << y;
    EXPECT_NEAR(e.implicit_value(pr.point), 1.0, 1e-12) << "y = " << y;
  }
  // Rotated: on the major axis 0.5 from the centre, local y = 1.1e-16 after rounding.
  // Expected 3 sqrt(1 - 0.25 / 16) = 2.97647... (the s-based version: inf).
  const double th = 0.7;
  const Ellipse r{Vec2(3.0, -2.0), 5.0, 3.0, th};
  const Vec2 p = r.centre + 0.5 * Vec2(std::cos(th), std::sin(th));
  EXPECT_NEAR(signed_distance(r, p), -3.0 * std::sqrt(1.0 - 0.25 / 16.0), 1e-12);
  // Near the centre: (1e-15, 1e-15) -> expected 3 (to 1e-15; the s-based version: 2.2518).
  EXPECT_NEAR(signed_distance(e, Vec2(1e-15, 1e-15)), -3.0, 1e-12);
}
