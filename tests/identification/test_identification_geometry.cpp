// Identification geometry: the lee goal point, the flow-shade areas and the
// offset path, against hand geometry and the independent point-ellipse
// distance (geometry/ellipse_distance.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/identification/lee_goal.hpp"
#include "deepguide/identification/offset_path.hpp"

namespace deepguide {
namespace {

constexpr double kPi = std::numbers::pi;

Vec2 unit(double phi) { return {std::cos(phi), std::sin(phi)}; }

// A = 30, B = 10, major axis 30 degrees north of east.
const Ellipse kSafety{{100.0, -50.0}, 30.0, 10.0, kPi / 6};

TEST(LeeGoal, HandGeometryOnARotatedEllipse) {
  // Along the major axis, the minor axis, and 45 degrees between them (local frame):
  // t* = 1 / sqrt((cos 45 / 30)^2 + (sin 45 / 10)^2) = 13.4164...
  const double th = kPi / 6;
  EXPECT_LT((lee_goal_point(kSafety, unit(th)) - (kSafety.centre + 30.0 * unit(th))).norm(), 1e-12);
  EXPECT_LT((lee_goal_point(kSafety, unit(th + kPi)) - (kSafety.centre - 30.0 * unit(th))).norm(), 1e-12);
  EXPECT_LT((lee_goal_point(kSafety, unit(th + kPi / 2)) - (kSafety.centre + 10.0 * unit(th + kPi / 2))).norm(), 1e-12);
  const double t45 = 1.0 / std::hypot(std::cos(kPi / 4) / 30.0, std::sin(kPi / 4) / 10.0);
  EXPECT_NEAR(t45, 13.416407864998739, 1e-12);
  EXPECT_LT((lee_goal_point(kSafety, unit(th + kPi / 4)) - (kSafety.centre + t45 * unit(th + kPi / 4))).norm(), 1e-12);
}

TEST(LeeGoal, OnTheEllipseAndOnTheDownstreamRayForEveryCurrent) {
  for (int k = 0; k < 72; ++k) {
    const Vec2 e = unit(2 * kPi * k / 72);
    const Vec2 goal = lee_goal_point(kSafety, e);
    const Vec2 d = goal - kSafety.centre;
    EXPECT_NEAR(kSafety.implicit_value(goal), 1.0, 1e-12) << k;
    EXPECT_NEAR(e.x() * d.y() - e.y() * d.x(), 0.0, 1e-9) << k;  // on the line along the current
    EXPECT_GT(d.dot(e), 0.0) << k;                               // downstream
    EXPECT_NEAR(signed_distance(kSafety, goal), 0.0, 1e-9) << k;
  }
}

TEST(LeeGoal, ShadeHalfWidthAndAreas) {
  const double th = kPi / 6;
  EXPECT_NEAR(shade_half_width(kSafety, unit(th)), 10.0, 1e-12);            // current along the major axis
  EXPECT_NEAR(shade_half_width(kSafety, unit(th + kPi / 2)), 30.0, 1e-12);  // across it
  // Current along the major axis: the shade is the strip |across| <= 10 downstream of the centre.
  const Vec2 e = unit(th), n = unit(th + kPi / 2), c = kSafety.centre;
  EXPECT_EQ(align_area(kSafety, e, c + 50.0 * e), AlignArea::positioning);
  EXPECT_EQ(align_area(kSafety, e, c + 50.0 * e + 9.99 * n), AlignArea::positioning);
  EXPECT_EQ(align_area(kSafety, e, c + 50.0 * e - 9.99 * n), AlignArea::positioning);
  EXPECT_EQ(align_area(kSafety, e, c + 50.0 * e + 10.01 * n), AlignArea::evasive);  // beside the shade
  EXPECT_EQ(align_area(kSafety, e, c - 50.0 * e), AlignArea::evasive);              // upstream
  EXPECT_EQ(align_area(kSafety, e, c + 0.01 * e), AlignArea::positioning);          // just past the borderline
  EXPECT_EQ(align_area(kSafety, e, c - 0.01 * e), AlignArea::evasive);
}

TEST(LeeGoal, DirectionFromTheCurrentOrTheNearSide) {
  const Vec2 c(10, 10);
  EXPECT_LT((align_direction(Vec2(0.3, -0.4), 0.05, c, Vec2(0, 0)) - Vec2(0.6, -0.8)).norm(), 1e-15);
  EXPECT_LT((align_direction(Vec2(0.03, 0.0), 0.05, c, Vec2(10, 0)) - Vec2(0, -1)).norm(), 1e-15);  // still water
  EXPECT_LT((align_direction(Vec2(0, 0), 0.0, c, c) - Vec2(1, 0)).norm(), 1e-15);
}

const Ellipse kObject{{-20.0, 35.0}, 20.0, 8.0, -0.7};

TEST(OffsetPath, EveryPointLiesAtTheDistanceFromTheEllipse) {
  for (double d : {0.5, 5.0, 12.0, 40.0}) {
    for (int k = 0; k < 720; ++k) {
      const double t = 2 * kPi * k / 720;
      const Vec2 o = offset_point(kObject, d, t);
      EXPECT_NEAR(signed_distance(kObject, o), d, 1e-9) << d << " " << t;  // the acceptance asks 1 cm
      // The tangent is the curve's derivative direction (central difference) and is normal to o - q.
      const double h = 1e-6;
      const Vec2 fd = (offset_point(kObject, d, t + h) - offset_point(kObject, d, t - h)).normalized();
      EXPECT_LT((offset_tangent(kObject, t) - fd).norm(), 1e-6) << d << " " << t;
      EXPECT_NEAR(offset_tangent(kObject, t).dot(o - kObject.point_at(t)), 0.0, 1e-9);
    }
  }
}

TEST(OffsetPath, SmallestRadiusAtTheMajorAxisEnds) {
  // Circumradius of three close points at t = 0 against b^2 / a + D = 3.2 + 12.
  const double d = 12.0, h = 1e-3;
  const Vec2 p0 = offset_point(kObject, d, -h), p1 = offset_point(kObject, d, 0.0), p2 = offset_point(kObject, d, h);
  const double a = (p1 - p0).norm(), b = (p2 - p1).norm(), c = (p2 - p0).norm();
  const double area2 = std::abs((p1 - p0).x() * (p2 - p0).y() - (p1 - p0).y() * (p2 - p0).x());
  EXPECT_NEAR(a * b * c / (2.0 * area2), 15.2, 1e-4);
  EXPECT_DOUBLE_EQ(offset_min_radius(kObject, d), 15.2);
}

TEST(OffsetPath, ProjectionIsAlongTheNormal) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(-120.0, 120.0);
  const double d = 10.0;
  for (int k = 0; k < 500; ++k) {
    const Vec2 p = kObject.centre + Vec2(pos(rng), pos(rng));
    if (kObject.contains(p)) continue;
    const OffsetProjection q = project_to_offset(kObject, d, p);
    EXPECT_NEAR(signed_distance(kObject, q.point), d, 1e-9) << k;
    EXPECT_NEAR(q.signed_m, signed_distance(kObject, p) - d, 1e-9) << k;
    EXPECT_NEAR((p - q.point).norm(), std::abs(q.signed_m), 1e-6) << k;
    EXPECT_LT((q.point - offset_point(kObject, d, q.t)).norm(), 1e-12) << k;
    EXPECT_NEAR(q.tangent.dot(p - q.point), 0.0, 1e-6 * (1.0 + std::abs(q.signed_m))) << k;
  }
}

TEST(OffsetPath, TooTightForTheVehicleIsAClearError) {
  const Ellipse thin{{0, 0}, 20.0, 5.0, 0.0};  // b^2 / a = 1.25
  EXPECT_NO_THROW(check_offset_path_fits(thin, 20.0, 19.6, "wreck"));
  try {
    check_offset_path_fits(thin, 10.0, 19.6, "wreck");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "object 'wreck': the path 10.00 m around it turns with a radius of 11.25 m at the ends of its major "
                 "axis, tighter than the vehicle's 19.60 m; expected a distance of at least 18.35 m");
  }
}

}  // namespace
}  // namespace deepguide
