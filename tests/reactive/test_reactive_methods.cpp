// The reactive methods (lib/deepguide/reactive): hand-derived courses, the
// geometric tangency, dipole streamlines, side latches and the single-disc numbers
// with a kinematic vehicle (perfect course tracking).

#include <gtest/gtest.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <vector>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/reactive/dipole_field.hpp"
#include "deepguide/reactive/geometric_construction.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/reactive/side_latch.hpp"

namespace deepguide {
namespace {

constexpr ReactiveMethod kMethods[] = {ReactiveMethod::dipole, ReactiveMethod::geometric, ReactiveMethod::potential};

Ellipse disc(double x, double y, double r) { return Ellipse{Vec2(x, y), r, r, 0.0}; }

double cross2(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

/// Distance from point c to the line through p with direction angle `course`, signed: > 0 if c lies left.
double line_offset(const Vec2& p, double course, const Vec2& c) { return cross2(unit_vector(course), c - p); }

/// The side latch a method keeps in its memory (the geometric method's is
/// part of its GeometricMemory); none for a method that keeps none.
const SideLatch& latch(const ReactiveMemory& memory) {
  static const SideLatch none;
  if (const auto* g = std::any_cast<GeometricMemory>(&memory.state)) return *g;
  if (const auto* d = std::any_cast<SideLatch>(&memory.state)) return *d;
  return none;
}

ReactiveCommand command(const ReactiveMethod& m, const ReactiveParams& params, ReactiveMemory& memory, const Vec2& p,
                        double course, const Vec2& target, const std::vector<Ellipse>& objects) {
  ReactiveInput in;
  in.position = p;
  in.course = course;
  in.speed_mps = params.speed_mps;
  in.target = target;
  in.objects = objects;
  return reactive_command(m, params, memory, in);
}

/// A kinematic vehicle that takes every commanded course at once.
struct Flight {
  std::vector<Vec2> path;  ///< positions, path[0] = start
  std::vector<ReactiveCommand> commands;
  std::vector<int> sides;  ///< latch(memory).side after each command
  double length = 0.0;
  double max_rate = 0.0;  ///< max |r| from successive commanded courses (rad/s)
  double rms_rate = 0.0;
  ReactiveStatus last = ReactiveStatus::ok;
  std::vector<double> rates;
};

Flight fly(const ReactiveMethod& m, const ReactiveParams& params, Vec2 p, double course, const Vec2& target,
           const std::vector<Ellipse>& objects, double dt, int max_steps = 20000) {
  Flight f;
  ReactiveMemory memory;
  f.path.push_back(p);
  double sum2 = 0.0;
  for (int k = 0; k < max_steps; ++k) {
    const ReactiveCommand c = command(m, params, memory, p, course, target, objects);
    f.commands.push_back(c);
    f.sides.push_back(latch(memory).side);
    f.last = c.status;
    if (c.speed_mps == 0.0) break;
    if (k > 0) {
      const double r = wrap_pi(c.course - course) / dt;
      f.rates.push_back(r);
      f.max_rate = std::max(f.max_rate, std::abs(r));
      sum2 += r * r;
    }
    course = c.course;
    p += c.speed_mps * dt * unit_vector(course);
    f.length += c.speed_mps * dt;
    f.path.push_back(p);
  }
  if (!f.rates.empty()) f.rms_rate = std::sqrt(sum2 / static_cast<double>(f.rates.size()));
  return f;
}

/// Smallest signed distance of the path to the zones (negative: entered one).
double min_clearance(const std::vector<Vec2>& path, const std::vector<Ellipse>& objects, double margin) {
  double m = std::numeric_limits<double>::infinity();
  for (const Ellipse& o : objects) {
    const Ellipse z = security_ellipse(o, margin);
    for (const Vec2& p : path) m = std::min(m, signed_distance(z, p));
  }
  return m;
}

ReactiveParams params_for(double margin, double speed, double arrival) {
  return {.margin_m = margin, .speed_mps = speed, .arrival_radius_m = arrival};
}

// ---------------------------------------------------------------------------

TEST(ReactiveMethod, NamesRoundTrip) {
  for (const ReactiveMethod& m : kMethods) EXPECT_EQ(parse_reactive_method(to_string(m)), m);
  EXPECT_FALSE(parse_reactive_method("Dipole").has_value());
  EXPECT_FALSE(parse_reactive_method("").has_value());
  EXPECT_EQ(to_string(ReactiveStatus::target_in_zone), "target_in_zone");
  EXPECT_EQ(to_string(ReactiveStatus::stalled), "stalled");
}

TEST(SecurityEllipse, CircleGrowsByTheMargin) {
  const Ellipse z = security_ellipse(disc(3, 4, 10), 5);
  EXPECT_DOUBLE_EQ(z.a, 15.0);
  EXPECT_DOUBLE_EQ(z.b, 15.0);
  EXPECT_EQ(z.centre, Vec2(3, 4));
}

TEST(SecurityEllipse, ContainsTheOffsetZoneAndTouchesItAtTheTips) {
  // a = 10, b = 2, d = 5: b' = sqrt(15 * (5 + 4/10)) = 9 (not b + d = 7, which would cut into the offset zone).
  const Ellipse object{Vec2(1, -2), 10, 2, 0.7};
  const Ellipse z = security_ellipse(object, 5);
  EXPECT_DOUBLE_EQ(z.a, 15.0);
  EXPECT_NEAR(z.b, 9.0, 1e-12);
  double max_value = 0.0;
  for (int i = 0; i < 3600; ++i) {
    const double t = 2.0 * kPi * i / 3600.0;
    const Vec2 offset_point = object.point_at(t) + 5.0 * object.normal_at(t);
    max_value = std::max(max_value, z.implicit_value(offset_point));
  }
  EXPECT_LE(max_value, 1.0 + 1e-12);
  EXPECT_NEAR(max_value, 1.0, 1e-9);  // touches at t = 0 (the tip)
  // The naive (a + d, b + d) ellipse does not contain the offset curve.
  const Ellipse naive{object.centre, 15, 7, object.theta};
  EXPECT_GT(naive.implicit_value(object.point_at(0.6) + 5.0 * object.normal_at(0.6)), 1.0);
}

TEST(ReactiveMethods, OpenWaterPointsStraightAtTheTarget) {
  const ReactiveParams params = params_for(10, 2, 5);
  // One object far out of every method's reach (more than influence_m + zone away, off the line of sight).
  const std::vector<Ellipse> far{disc(0, 500, 10)};
  for (const ReactiveMethod& m : kMethods) {
    for (const auto& objects : {std::vector<Ellipse>{}, far}) {
      ReactiveMemory memory;
      const ReactiveCommand c = command(m, params, memory, Vec2(0, 0), 2.0, Vec2(30, 40), objects);
      EXPECT_NEAR(c.course, std::atan2(40.0, 30.0), 1e-12) << to_string(m);
      EXPECT_EQ(c.status, ReactiveStatus::ok);
      EXPECT_EQ(c.speed_mps, 2.0);
      EXPECT_EQ(c.active_object, -1);
      const Vec2 g = reactive_gradient(m, params, Vec2(0, 0), Vec2(30, 40), objects);
      EXPECT_NEAR(g.x(), 0.6, 1e-12);
      EXPECT_NEAR(g.y(), 0.8, 1e-12);
    }
  }
}

TEST(ReactiveMethods, ArrivedStopsWithinTheRadius) {
  const ReactiveParams params = params_for(10, 2, 5);
  for (const ReactiveMethod& m : kMethods) {
    ReactiveMemory memory;
    const ReactiveCommand c = command(m, params, memory, Vec2(96, 3), 0.3, Vec2(100, 0), {});
    EXPECT_EQ(c.status, ReactiveStatus::arrived);
    EXPECT_EQ(c.speed_mps, 0.0);
    EXPECT_EQ(c.course, 0.3);  // held
    const ReactiveCommand d = command(m, params, memory, Vec2(94, 3), 0.3, Vec2(100, 0), {});
    EXPECT_EQ(d.status, ReactiveStatus::ok);  // 6.7 m > 5 m
    EXPECT_EQ(reactive_gradient(m, params, Vec2(100, 0), Vec2(100, 0), {}), Vec2(0, 0));
  }
}

// --- (b) geometric construction, one disc: R = 10 + 10 = 20 at the origin, target (150, 0) ---

class GeometricDisc : public ::testing::Test {
 protected:
  ReactiveParams params = params_for(10, 2, 5);
  std::vector<Ellipse> objects{disc(0, 0, 10)};
  Vec2 target{150, 0};
  ReactiveMemory memory;
  ReactiveCommand at(const Vec2& p, double course = 0.0) {
    return command(ReactiveMethod::geometric, params, memory, p, course, target, objects);
  }
  /// The command at p, checked for its sector and status and the side latched after it.
  ReactiveCommand expect_at(const Vec2& p, int sector, ReactiveStatus status, int side) {
    const ReactiveCommand c = at(p);
    EXPECT_EQ(c.sector, sector);
    EXPECT_EQ(c.status, status);
    EXPECT_EQ(latch(memory).side, side);
    return c;
  }
};

TEST_F(GeometricDisc, Sector2LineOfSightFreeGoesStraight) {
  // From (-100, 50) the line to the target passes 7500 / |(250, -50)| = 29.4 m > 20 from the centre.
  const ReactiveCommand c = expect_at(Vec2(-100, 50), 2, ReactiveStatus::ok, 0);
  EXPECT_NEAR(c.course, std::atan2(-50.0, 250.0), 1e-12);
}

TEST_F(GeometricDisc, Sector1IsTheTangentOnTheVehiclesSide) {
  // p = (-100, 5): line of sight passes 17.9 m from the centre: blocked. North of the axis: side +1.
  const Vec2 p(-100, 5);
  const ReactiveCommand c = expect_at(p, 1, ReactiveStatus::ok, 1);
  EXPECT_EQ(c.active_object, 0);
  // bearing to the centre atan2(-5, 100) turned left by asin(R / |p|).
  EXPECT_NEAR(c.course, std::atan2(-5.0, 100.0) + std::asin(20.0 / std::hypot(100.0, 5.0)), 1e-9);
  // Tangency: the course line passes exactly R from the centre, with the centre on its right.
  EXPECT_NEAR(line_offset(p, c.course, Vec2(0, 0)), -20.0, 1e-9);
  // South of the axis: mirrored, the centre on the left.
  ReactiveMemory other;
  const ReactiveCommand s = command(ReactiveMethod::geometric, params, other, Vec2(-100, -5), 0.0, target, objects);
  EXPECT_NEAR(line_offset(Vec2(-100, -5), s.course, Vec2(0, 0)), 20.0, 1e-9);
  EXPECT_EQ(latch(other).side, -1);
}

TEST_F(GeometricDisc, LatchedSideIsKeptAcrossTheAxis) {
  EXPECT_EQ(at(Vec2(-100, 5)).sector, 1);
  ASSERT_EQ(latch(memory).side, 1);
  // Pushed across the axis (a current, say): still passes north.
  const Vec2 p(-60, -2);
  const ReactiveCommand c = at(p);
  EXPECT_EQ(latch(memory).side, 1);
  EXPECT_NEAR(line_offset(p, c.course, Vec2(0, 0)), -20.0, 1e-9);
  // The memoryless field takes the side of the axis instead.
  const double g = math_angle(reactive_gradient(ReactiveMethod::geometric, params, p, target, objects));
  EXPECT_NEAR(line_offset(p, g, Vec2(0, 0)), 20.0, 1e-9);
  // Sector 2 releases the latch.
  EXPECT_EQ(at(Vec2(-100, 50)).sector, 2);
  EXPECT_EQ(latch(memory).side, 0);
}

TEST_F(GeometricDisc, OnTheAxisTheCourseBreaksTheTie) {
  ReactiveMemory m1, m2, m3;
  command(ReactiveMethod::geometric, params, m1, Vec2(-100, 0), 0.05, target, objects);
  command(ReactiveMethod::geometric, params, m2, Vec2(-100, 0), -0.05, target, objects);
  const ReactiveCommand c = command(ReactiveMethod::geometric, params, m3, Vec2(-100, 0), 0.0, target, objects);
  EXPECT_EQ(latch(m1).side, 1);
  EXPECT_EQ(latch(m2).side, -1);
  EXPECT_EQ(latch(m3).side, -1);  // no hint: starboard
  EXPECT_NEAR(c.course, -std::asin(0.2), 1e-12);
}

TEST_F(GeometricDisc, Sector3LeadsOutAndMeetsTheTangentAtTheBoundary) {
  // p = (-15, 3): |p| = 15.297 < 20. depth = 1 - 15.297/20 = 0.2352, beta = (pi/2) sqrt(0.2352 / 0.25).
  const Vec2 p(-15, 3);
  const ReactiveCommand c = expect_at(p, 3, ReactiveStatus::leaving_zone, 1);
  const Vec2 n = p.normalized();
  const double beta = 0.5 * kPi * std::sqrt((1.0 - p.norm() / 20.0) / 0.25);
  const Vec2 along(n.y(), -n.x());  // clockwise round the centre for side +1
  const Vec2 expected = std::cos(beta) * along + std::sin(beta) * n;
  EXPECT_NEAR(c.course, math_angle(expected), 1e-9);
  EXPECT_GT(unit_vector(c.course).dot(n), 0.99);  // nearly radial this deep
  // Deeper than a quarter of R: straight out.
  ReactiveMemory deep;
  const ReactiveCommand d = command(ReactiveMethod::geometric, params, deep, Vec2(-10, 2), 0, target, objects);
  EXPECT_NEAR(d.course, std::atan2(2.0, -10.0), 1e-12);
  // At the boundary: inside and outside agree with the tangent (continuity, no chatter). 1e-12 R out,
  // the tangent point is sqrt(2 R 2e-11) = 2.8e-5 m ahead (1.4e-6 rad); 1e-12 R in, beta = 3.1e-6 rad.
  for (double angle : {2.0, 2.5, 3.0}) {
    ReactiveMemory in_m, out_m;
    const Vec2 in = 20.0 * (1.0 - 1e-12) * unit_vector(angle);
    const Vec2 out = 20.0 * (1.0 + 1e-12) * unit_vector(angle);
    const ReactiveCommand ci = command(ReactiveMethod::geometric, params, in_m, in, 0, target, objects);
    const ReactiveCommand co = command(ReactiveMethod::geometric, params, out_m, out, 0, target, objects);
    EXPECT_EQ(ci.sector, 3);
    EXPECT_EQ(co.sector, 1);
    EXPECT_NEAR(wrap_pi(ci.course - co.course), 0.0, 1e-5);
    EXPECT_NEAR(wrap_pi(co.course - (angle - kPi / 2.0)), 0.0, 1e-5);  // the clockwise tangent
  }
}

TEST_F(GeometricDisc, StartingInsideTheZoneLeadsOutAndArrives) {
  const Flight f = fly(ReactiveMethod::geometric, params, Vec2(-15, 3), kPi, target, objects, 0.1);
  EXPECT_EQ(f.commands.front().status, ReactiveStatus::leaving_zone);
  EXPECT_EQ(f.last, ReactiveStatus::arrived);
  // Never deeper than at the start, and out within a few metres.
  double start = f.path.front().norm();
  std::size_t k = 0;
  for (; k < f.path.size() && f.path[k].norm() < 20.0; ++k) EXPECT_GE(f.path[k].norm(), start - 1e-9);
  EXPECT_LT(static_cast<double>(k) * 0.2, 10.0);
}

TEST(Geometric, ElongatedObjectTangentToTheSecurityEllipse) {
  // An ellipse along the line: the course is tangent to the security ellipse
  // (a' = 35, b' = sqrt(35 * 5.3) = 13.6), far inside the enclosing circle R = 35.
  const ReactiveParams params = params_for(5, 2, 5);
  const std::vector<Ellipse> objects{Ellipse{Vec2(0, 0), 30, 3, 0.0}};
  const Ellipse z = security_ellipse(objects[0], 5);
  const Vec2 p(-100, 0);
  ReactiveMemory memory;
  const ReactiveCommand c = command(ReactiveMethod::geometric, params, memory, p, 0.02, Vec2(100, 0), objects);
  ASSERT_EQ(c.sector, 1);
  EXPECT_EQ(latch(memory).side, 1);
  // The line through p along the course, normal nu to its left: the zone lies right of it and touches it.
  const Vec2 u = unit_vector(c.course);
  const Vec2 nu(-u.y(), u.x());
  EXPECT_NEAR(z.support(nu), nu.dot(p), 1e-9);
  // Tangent to the ellipse 35 x 13.6 from 100 m behind its centre: slope b'/sqrt(100^2 - a'^2) (in the unit frame).
  const double q = 100.0 / 35.0;  // p in the unit-circle frame is (-q, 0)
  const double t = std::acos(1.0 / q);
  const Vec2 touch = z.from_unit(Vec2(-std::cos(t), std::sin(t)));
  EXPECT_NEAR(c.course, math_angle(touch - p), 1e-9);
  EXPECT_LT(c.course, std::asin(35.0 / 100.0) - 0.1);  // much flatter than the circle's tangent
}

// --- several objects (geometric) ---

TEST(Geometric, TangentBlockedByASecondZoneTakesThatZonesTangent) {
  // A: disc r 5 at the origin (zone R 15), first on the line of sight; B: disc r 20 at (20, 20) (zone R 30),
  // overlapping A's zone. A's north tangent from p = (-100, 1) touches at about (-2.1, 14.9), inside B's zone:
  // the course must be B's north tangent: bearing atan2(19, 120) + asin(30 / |(120, 19)|). The vehicle
  // heads 0.3 rad, so the north side (0.41 rad) is the smaller turn than the south (-0.15 rad).
  const ReactiveParams params = params_for(10, 2, 5);
  const std::vector<Ellipse> objects{disc(0, 0, 5), disc(20, 20, 20)};
  const Vec2 p(-100, 1);
  ReactiveMemory memory;
  const ReactiveCommand c = command(ReactiveMethod::geometric, params, memory, p, 0.3, Vec2(150, 0), objects);
  EXPECT_EQ(c.sector, 1);
  EXPECT_EQ(c.active_object, 1);
  EXPECT_EQ(latch(memory).engaged_object, 0);  // A is the one engaged (first on the line of sight)
  EXPECT_NEAR(c.course, std::atan2(19.0, 120.0) + std::asin(30.0 / std::hypot(120.0, 19.0)), 1e-9);
  EXPECT_NEAR(line_offset(p, c.course, Vec2(20, 20)), -30.0, 1e-9);
  EXPECT_LT(line_offset(p, c.course, Vec2(0, 0)), -15.0);
}

// A zone engaged afresh is passed on the side that is the smaller turn from
// the present course, even against the symmetry-axis rule; once latched, the
// side stays although the other becomes the smaller turn.
TEST(Geometric, FreshEngagementTakesTheSmallerTurn) {
  const ReactiveParams params = params_for(10, 2, 5);  // zone R = 15
  const std::vector<Ellipse> objects{disc(0, 0, 5)};
  const Vec2 p(-100, 1);  // north of the axis: the axis rule says north
  const double tangent = std::asin(15.0 / std::hypot(100.0, 1.0));
  const double to_centre = std::atan2(-1.0, 100.0);
  ReactiveMemory memory;
  ReactiveCommand c = command(ReactiveMethod::geometric, params, memory, p, -0.2, Vec2(150, 0), objects);
  EXPECT_EQ(c.sector, 1);
  EXPECT_EQ(latch(memory).side, -1);  // heading south of the centre: the south tangent is the smaller turn
  EXPECT_NEAR(c.course, to_centre - tangent, 1e-9);
  c = command(ReactiveMethod::geometric, params, memory, p, 0.2, Vec2(150, 0), objects);
  EXPECT_EQ(latch(memory).side, -1);  // latched: kept although north is now the smaller turn
  EXPECT_NEAR(c.course, to_centre - tangent, 1e-9);
  ReactiveMemory fresh;
  c = command(ReactiveMethod::geometric, params, fresh, p, 0.2, Vec2(150, 0), objects);
  EXPECT_EQ(latch(fresh).side, 1);
  EXPECT_NEAR(c.course, to_centre + tangent, 1e-9);
}

// Two zones 5.4 m apart (less than geometric_passage_m) are one group: the
// north tangent is the group's (B's), not A's, which would lead into the
// 5 m pocket between them. With passage 0 they are apart again.
TEST(Geometric, ZonesCloserThanThePassageArePassedAsOne) {
  ReactiveParams params = params_for(10, 2, 5);  // zones R = 15
  const std::vector<Ellipse> objects{disc(0, 0, 5), disc(5, 35, 5)};
  const Vec2 p(-100, 1);
  const double to_a = std::atan2(-1.0, 100.0), to_b = std::atan2(34.0, 105.0);
  const double group_course = to_b + std::asin(15.0 / std::hypot(105.0, 34.0));
  ReactiveMemory memory;
  ReactiveCommand c = command(ReactiveMethod::geometric, params, memory, p, 0.3, Vec2(150, 0), objects);
  EXPECT_EQ(c.sector, 1);
  EXPECT_EQ(latch(memory).side, 1);
  EXPECT_EQ(c.active_object, 1);
  EXPECT_NEAR(c.course, group_course, 1e-9);
  params.tuning["geometric_passage_m"] = 0.0;
  ReactiveMemory apart;
  c = command(ReactiveMethod::geometric, params, apart, p, 0.3, Vec2(150, 0), objects);
  EXPECT_EQ(latch(apart).side, 1);
  EXPECT_EQ(c.active_object, 0);
  EXPECT_NEAR(c.course, to_a + std::asin(15.0 / std::hypot(100.0, 1.0)), 1e-9);
  params.tuning["geometric_passage_m"] = -1.0;
  EXPECT_THROW(command(ReactiveMethod::geometric, params, apart, p, 0.3, Vec2(150, 0), objects), InputError);
}

TEST(Geometric, OverlappingObjectsArePassedWithoutEnteringEither) {
  const ReactiveParams params = params_for(10, 2, 5);
  const std::vector<std::vector<Ellipse>> cases{
      {disc(0, 0, 5), disc(20, 20, 20)},
      {disc(0, -8, 10), disc(0, 8, 10)},
      {Ellipse{Vec2(0, 0), 25, 4, 0.8}, Ellipse{Vec2(10, -5), 25, 4, -0.8}},
  };
  for (const auto& objects : cases) {
    for (double y0 : {-3.0, 0.0, 1.0, 10.0}) {
      const Flight f = fly(ReactiveMethod::geometric, params, Vec2(-120, y0), 0.0, Vec2(150, 0), objects, 0.1);
      EXPECT_EQ(f.last, ReactiveStatus::arrived) << y0;
      EXPECT_GT(min_clearance(f.path, objects, 10), -1e-9) << y0;
      EXPECT_LT(f.length, 330.0);
    }
  }
}

TEST(Geometric, WideWallOfOverlappingObjectsIsRoundedAsOne) {
  // Five discs r 10 at x = 0, y = -40..40: their zones (R 20) overlap into one wall 120 m wide.
  std::vector<Ellipse> wall;
  for (int i = -2; i <= 2; ++i) wall.push_back(disc(0, 20.0 * i, 10));
  const ReactiveParams params = params_for(10, 2, 5);
  const Flight f = fly(ReactiveMethod::geometric, params, Vec2(-150, 0), 0.0, Vec2(150, 0), wall, 0.1);
  EXPECT_EQ(f.last, ReactiveStatus::arrived);
  EXPECT_GT(min_clearance(f.path, wall, 10), -1e-9);
  // Shortest way round the hull: two tangents to the end zones (0, +-40) R 20 and the arc between.
  const double tangent = std::sqrt(150.0 * 150.0 + 40.0 * 40.0 - 400.0);
  const double arc = 20.0 * (kPi + 2.0 * std::atan2(40.0, 150.0) - 2.0 * std::acos(20.0 / std::hypot(150.0, 40.0)));
  EXPECT_NEAR(f.length, 2.0 * tangent + arc - 5.0, 1.0);
}

TEST(Geometric, EnclosedByARingOfZonesStalls) {
  std::vector<Ellipse> ring;
  for (int i = 0; i < 8; ++i) ring.push_back(disc(40.0 * std::cos(i * kPi / 4), 40.0 * std::sin(i * kPi / 4), 10));
  const ReactiveParams params = params_for(10, 2, 5);
  ReactiveMemory memory;
  const ReactiveCommand c = command(ReactiveMethod::geometric, params, memory, Vec2(0, 1), 0.0, Vec2(200, 0), ring);
  EXPECT_EQ(c.status, ReactiveStatus::stalled);
  EXPECT_EQ(c.speed_mps, 0.0);
  EXPECT_EQ(c.course, 0.0);
}

TEST(Geometric, ReorderedObjectsKeepTheLatchedSide) {
  const ReactiveParams params = params_for(10, 2, 5);
  std::vector<Ellipse> objects{disc(0, 0, 10), disc(0, 300, 10)};
  ReactiveMemory memory;
  command(ReactiveMethod::geometric, params, memory, Vec2(-100, 0.5), 0.0, Vec2(150, 0), objects);
  ASSERT_EQ(latch(memory).side, 1);
  std::swap(objects[0], objects[1]);
  objects[1].centre.x() += 0.3;  // re-estimated a little off
  const ReactiveCommand c =
      command(ReactiveMethod::geometric, params, memory, Vec2(-95, -0.5), 0.0, Vec2(150, 0), objects);
  EXPECT_EQ(latch(memory).side, 1);
  EXPECT_EQ(latch(memory).engaged_object, 1);
  EXPECT_EQ(c.active_object, 1);
  EXPECT_LT(line_offset(Vec2(-95, -0.5), c.course, objects[1].centre), 0.0);  // still passing north
}

// --- (a) dipole ---

TEST(Dipole, SingleCircleIsTheClassicalUniformFlowPastACylinder) {
  // With the target far along +x from p and no taper, V = (1 - R^2/z^2)^* (circle in a uniform flow):
  // v_r = (1 - R^2/r^2) cos th, v_th = -(1 + R^2/r^2) sin th, R = 20.
  ReactiveParams params = params_for(10, 2, 5);
  params.influence_m = 1e9;
  const std::vector<Ellipse> objects{disc(0, 0, 10)};
  for (double th : {2.0, 2.8, -2.5, 1.2}) {
    const double r = 27.0;
    const Vec2 p = r * unit_vector(th);
    const Vec2 g = reactive_gradient(ReactiveMethod::dipole, params, p, p + Vec2(1e7, 0), objects);
    const double vr = (1 - 400 / (r * r)) * std::cos(th);
    const double vt = -(1 + 400 / (r * r)) * std::sin(th);
    const Vec2 expected = (vr * unit_vector(th) + vt * unit_vector(th + kPi / 2)).normalized();
    EXPECT_NEAR(g.x(), expected.x(), 1e-9) << th;
    EXPECT_NEAR(g.y(), expected.y(), 1e-9) << th;
  }
}

TEST(Dipole, ZoneBoundaryIsAStreamline) {
  // Circle and tilted ellipse, any target direction: the field on the zone is tangent to it.
  const ReactiveParams params = params_for(10, 2, 5);
  for (const Ellipse& object : {disc(0, 0, 10), Ellipse{Vec2(5, -3), 30, 4, 0.6}}) {
    const Ellipse z = security_ellipse(object, 10);
    for (int i = 0; i < 36; ++i) {
      const double t = 2 * kPi * (i + 0.3) / 36;
      const Vec2 x = z.point_at(t) + 1e-9 * z.normal_at(t);
      const Vec2 g = reactive_gradient(ReactiveMethod::dipole, params, x, Vec2(140, 30), {&object, 1});
      EXPECT_NEAR(g.dot(z.normal_at(t)), 0.0, 1e-6) << t;
    }
  }
}

TEST(Dipole, GradientLinesNeverEnterTheZone) {
  // Streamlines from many start points upstream, integrated with small midpoint steps.
  const ReactiveParams params = params_for(10, 2, 5);
  for (const Ellipse& object : {disc(0, 0, 10), Ellipse{Vec2(0, 0), 25, 4, 1.0}}) {
    const Ellipse z = security_ellipse(object, 10);
    const std::vector<Ellipse> objects{object};
    const Vec2 target(150, 0);
    double worst = std::numeric_limits<double>::infinity();
    for (int k = -10; k <= 10; ++k) {
      Vec2 p(-90, 4.0 * k + 0.37);
      for (int step = 0; step < 2000 && (p - target).norm() > 5.0; ++step) {
        const Vec2 g1 = reactive_gradient(ReactiveMethod::dipole, params, p, target, objects);
        if (g1.squaredNorm() == 0.0) break;
        const Vec2 g2 = reactive_gradient(ReactiveMethod::dipole, params, p + 0.1 * g1, target, objects);
        p += 0.2 * g2;
        worst = std::min(worst, signed_distance(z, p));
      }
      EXPECT_LT((p - target).norm(), 5.0 + 1e-9) << k;  // every line reaches the target
    }
    EXPECT_GT(worst, -0.01);
    EXPECT_LT(worst, 0.5);  // the lines near the dividing streamline do hug the zone
  }
}

TEST(Dipole, OnTheAxisTheMemorylessFieldStagnatesAtTheFrontPoint) {
  const ReactiveParams params = params_for(10, 2, 5);
  const std::vector<Ellipse> objects{disc(0, 0, 10)};
  // Ahead of the front stagnation point (-20, 0) the field points straight at it ...
  const Vec2 g = reactive_gradient(ReactiveMethod::dipole, params, Vec2(-60, 0), Vec2(150, 0), objects);
  EXPECT_NEAR(g.x(), 1.0, 1e-12);
  EXPECT_NEAR(g.y(), 0.0, 1e-12);
  // ... and vanishes there.
  EXPECT_EQ(reactive_gradient(ReactiveMethod::dipole, params, Vec2(-20.0 - 1e-9, 0), Vec2(150, 0), objects),
            Vec2(0, 0));
}

TEST(Dipole, StallsAtTheFrontStagnationPointWithoutTheTieBreak) {
  // 1e-9 m in front of (-20, 0) the field is 2e-9/20: vanished. Without the band: stalled, speed 0,
  // course held. With it the vehicle is steered as if 0.5 m to starboard: a course well to the south.
  ReactiveParams params = params_for(10, 2, 5);
  const std::vector<Ellipse> objects{disc(0, 0, 10)};
  const Vec2 front(-20.0 - 1e-9, 0.0);
  params.tuning["dipole_axis_band_m"] = 0.0;
  ReactiveMemory m1;
  const ReactiveCommand c = command(ReactiveMethod::dipole, params, m1, front, 0.1, Vec2(150, 0), objects);
  EXPECT_EQ(c.status, ReactiveStatus::stalled);
  EXPECT_EQ(c.speed_mps, 0.0);
  EXPECT_EQ(c.course, 0.1);
  params.tuning["dipole_axis_band_m"] = 0.5;
  ReactiveMemory m2;
  const ReactiveCommand d = command(ReactiveMethod::dipole, params, m2, front, 0.0, Vec2(150, 0), objects);
  EXPECT_EQ(d.status, ReactiveStatus::ok);
  EXPECT_EQ(latch(m2).side, -1);
  EXPECT_LT(d.course, -1.0);
}

TEST(Dipole, TieBreakClampsWithinTheBandOnly) {
  // p = (-40, 0) on the axis, course 0: side -1 (starboard); the flow is the one at Im Z = -band = -0.5.
  ReactiveParams params = params_for(10, 2, 5);
  params.influence_m = 1e9;  // no taper: the classical formula below applies exactly
  const std::vector<Ellipse> objects{disc(0, 0, 10)};
  ReactiveMemory memory;
  const Vec2 target(1e7, 0);
  const ReactiveCommand c = command(ReactiveMethod::dipole, params, memory, Vec2(-40, 0), 0.0, target, objects);
  EXPECT_EQ(latch(memory).side, -1);
  EXPECT_EQ(c.active_object, 0);
  const Vec2 q(-40, -0.5);
  const std::complex<double> z(q.x(), q.y());
  const std::complex<double> v = std::conj(1.0 - 400.0 / (z * z));
  EXPECT_NEAR(c.course, std::atan2(v.imag(), v.real()), 1e-6);
  EXPECT_LT(c.course, 0.0);
  // 0.3 m north, within the band: a course to the south decides; along the axis, the side it is on.
  ReactiveMemory south, north;
  const ReactiveCommand cs = command(ReactiveMethod::dipole, params, south, Vec2(-40, 0.3), -0.01, target, objects);
  const ReactiveCommand cn = command(ReactiveMethod::dipole, params, north, Vec2(-40, 0.3), 0.0, target, objects);
  EXPECT_EQ(latch(south).side, -1);
  EXPECT_EQ(latch(north).side, 1);
  EXPECT_NEAR(cs.course, c.course, 1e-6);  // both evaluated at (-40, -0.5) in the circle plane
  EXPECT_NEAR(cn.course, -c.course, 1e-6);
  // Outside the band the natural field is used: equal to the memoryless gradient.
  const Vec2 p(-40, 3);
  ReactiveMemory m2;
  const ReactiveCommand d = command(ReactiveMethod::dipole, params, m2, p, 0.0, target, objects);
  EXPECT_EQ(latch(m2).side, 1);
  EXPECT_NEAR(d.course, math_angle(reactive_gradient(ReactiveMethod::dipole, params, p, target, objects)), 1e-12);
}

TEST(Dipole, CloseObjectsMergeIntoOneCircle) {
  // Zones R 20 at (0, +-15) overlap: one circle enclosing both circles, centre 0, radius 35.
  const std::vector<Ellipse> objects{disc(0, -15, 10), disc(0, 15, 10), disc(300, 0, 10)};
  const std::vector<DipoleZone> zones = dipole_zones(objects, 10, 5);
  ASSERT_EQ(zones.size(), 2u);
  EXPECT_NEAR(zones[0].shape.a, 35.0, 1e-12);
  EXPECT_NEAR(zones[0].shape.centre.norm(), 0.0, 1e-12);
  EXPECT_EQ(zones[0].members, (std::vector<std::ptrdiff_t>{0, 1}));
  // A gap of 4 m < dipole_blend 5 m merges, a gap of 6 m does not.
  EXPECT_EQ(dipole_zones(std::vector<Ellipse>{disc(0, 0, 10), disc(44, 0, 10)}, 10, 5).size(), 1u);
  EXPECT_EQ(dipole_zones(std::vector<Ellipse>{disc(0, 0, 10), disc(46, 0, 10)}, 10, 5).size(), 2u);
}

TEST(Dipole, SeveralObjectsAreNotEnteredAndTheTargetIsReached) {
  const ReactiveParams params = params_for(10, 2, 5);
  const std::vector<std::vector<Ellipse>> cases{
      {disc(0, 0, 10), disc(60, 25, 10)},  // a passage 65 - 40 = 25 m wide between zones
      {disc(0, -8, 10), disc(0, 8, 10)},   // overlapping: merged
      {Ellipse{Vec2(0, 0), 25, 4, 0.8}, disc(70, -30, 12)},
  };
  for (const auto& objects : cases) {
    for (double y0 : {-7.0, 0.0, 3.0, 20.0}) {
      const Flight f = fly(ReactiveMethod::dipole, params, Vec2(-150, y0), 0.0, Vec2(150, 0), objects, 0.1);
      EXPECT_EQ(f.last, ReactiveStatus::arrived) << y0;
      EXPECT_GT(min_clearance(f.path, objects, 10), -tuning_value(params, "dipole_axis_band_m")) << y0;
    }
  }
}

// --- no dithering: a kinematic vehicle aimed at the centre (step 0.1 s, 2 m/s) ---

TEST(ReactiveMethods, HeadOnVehiclePicksASideOnceAndKeepsIt) {
  const ReactiveParams params = params_for(10, 2, 5);
  const std::vector<Ellipse> objects{disc(0, 0, 10)};
  for (const ReactiveMethod& m : {ReactiveMethod::geometric, ReactiveMethod::dipole}) {
    for (double heading_off : {0.0, 1e-3, -1e-3}) {
      const Flight f = fly(m, params, Vec2(-100, 0), heading_off, Vec2(100, 0), objects, 0.1);
      ASSERT_EQ(f.last, ReactiveStatus::arrived) << to_string(m);
      // Geometric: engaged at once, the course decides (starboard if straight). Dipole: engaged on
      // entering the influence, by then its course is exactly along the axis: starboard.
      const int expected = (m == ReactiveMethod::geometric && heading_off > 0.0) ? 1 : -1;
      const auto first = std::find_if(f.sides.begin(), f.sides.end(), [](int s) { return s != 0; });
      ASSERT_NE(first, f.sides.end());
      EXPECT_EQ(*first, expected) << to_string(m) << " " << heading_off;
      // The latch: once set, only ever that side (it is released after passing).
      EXPECT_TRUE(std::all_of(f.sides.begin(), f.sides.end(), [&](int s) { return s == 0 || s == expected; }))
          << to_string(m) << " " << heading_off;
      // The vehicle stays on that side of the line until abeam of the centre, and the commanded
      // course's deviation from the line changes sign once (away, then back), never left-right-left.
      int flips = 0;
      double last = 0.0;
      for (std::size_t k = 0; k < f.path.size(); ++k) {
        if (f.path[k].x() <= 0.0) {
          EXPECT_GE(expected * f.path[k].y(), 0.0) << to_string(m) << " step " << k;
        }
        const double dev = std::sin(f.commands[k].course);
        if (std::abs(dev) < 1e-9) continue;
        if (last != 0.0 && (dev > 0) != (last > 0)) ++flips;
        last = dev;
      }
      EXPECT_EQ(flips, 1) << to_string(m) << " " << heading_off;
      EXPECT_GT(min_clearance(f.path, objects, 10), m == ReactiveMethod::dipole ? -0.5 : -1e-9);
    }
  }
}

// --- the single-disc table, kinematic: R = 20 disc, target (150, 0), start (-150, y0), U = 2.06 m/s ---

/// Exact shortest path length round the disc on the vehicle's side, minus the 2 m stop distance.
double optimum_minus_stop(double y0) {
  const double R = 20.0, ra = std::hypot(150.0, y0);
  const double arc = R * (std::abs(std::atan2(y0, -150.0)) - std::acos(R / ra) - std::acos(R / 150.0));
  return std::sqrt(ra * ra - R * R) + std::sqrt(150.0 * 150.0 - R * R) + arc - 2.0;
}

TEST(ReactiveMethods, Notes9TableKinematic) {
  const ReactiveParams params = params_for(10, 2.06, 2.0);
  const std::vector<Ellipse> objects{disc(0, 0, 10)};
  const double dt = 0.05;  // 20 Hz
  const double arc_rate = 2.06 / 20.0;
  EXPECT_NEAR(optimum_minus_stop(0.0), 302.67 - 2.0, 0.01);  // 2 sqrt(150^2 - 20^2) + 20 (pi - 2 acos(20/150))
  for (double y0 : {0.0, 1.0, 5.0, 15.0}) {
    const Flight geo = fly(ReactiveMethod::geometric, params, Vec2(-150, y0), 0.0, Vec2(150, 0), objects, dt);
    const Flight dip = fly(ReactiveMethod::dipole, params, Vec2(-150, y0), 0.0, Vec2(150, 0), objects, dt);
    ASSERT_EQ(geo.last, ReactiveStatus::arrived);
    ASSERT_EQ(dip.last, ReactiveStatus::arrived);  // y0 = 0 too: the axis tie-break
    // Geometric: the shortest path (within 0.1 %), within 1 % of the axis optimum 302.67 - 2 m.
    EXPECT_NEAR(geo.length, optimum_minus_stop(y0), 0.003 * optimum_minus_stop(y0)) << y0;
    EXPECT_NEAR(geo.length, 300.67, 0.01 * 300.67) << y0;
    EXPECT_GT(min_clearance(geo.path, objects, 10), -1e-9);
    // On the arc (riding within 1 mm) the reference rate is U/R on average: a discrete vehicle passes
    // each tangent point and then alternates a long and a short turn (8.2 and 3.6 deg/s for y0 = 0),
    // which is also the peak: under 2 U/R.
    double turned = 0.0;
    int on_arc = 0;
    for (std::size_t k = 0; k < geo.rates.size(); ++k) {
      if (geo.path[k + 1].norm() < 20.001 && geo.path[k + 2].norm() < 20.001) {
        turned += geo.rates[k];
        ++on_arc;
      }
    }
    if (on_arc > 10) {
      EXPECT_NEAR(std::abs(turned) / on_arc, arc_rate, 0.1 * arc_rate) << y0;  // 0.93-0.95 U/R: the ends of the ride
    }
    EXPECT_GT(geo.max_rate, 0.9 * arc_rate);
    EXPECT_LT(geo.max_rate, 2.0 * arc_rate);
    // Dipole: longer, and near the axis much sharper than the geometric method (the seed's Fig. 12 claim).
    EXPECT_GT(dip.length, geo.length) << y0;
    if (y0 < 10.0) {
      EXPECT_GT(dip.max_rate, 1.5 * geo.max_rate) << y0;
    }
    EXPECT_GT(min_clearance(dip.path, objects, 10), -tuning_value(params, "dipole_axis_band_m"));
    std::printf(
        "notes9 y0=%4.1f geometric len %.2f max|r| %.2f rms %.2f deg/s | dipole len %.2f max|r| %.2f rms %.2f\n", y0,
        geo.length, rad_to_deg(geo.max_rate), rad_to_deg(geo.rms_rate), dip.length, rad_to_deg(dip.max_rate),
        rad_to_deg(dip.rms_rate));
  }
}

// --- (c) potential field ---

TEST(Potential, SingleZoneForceBalancesAtHalfTheInfluence) {
  // On the axis the attraction (1) meets the repulsion m(rho) = (1/4)(rho0/rho - 1)(rho0/rho)^2 = 1 at rho = 30.
  const ReactiveParams params = params_for(10, 2, 5);
  const std::vector<Ellipse> objects{disc(0, 0, 10)};
  const Flight f = fly(ReactiveMethod::potential, params, Vec2(-150, 0), 0.0, Vec2(150, 0), objects, 0.1);
  EXPECT_EQ(f.last, ReactiveStatus::stalled);
  EXPECT_NEAR(f.path.back().x(), -50.0, 0.3);
  EXPECT_EQ(f.commands.back().speed_mps, 0.0);
  // At rho = 40 the net pull is 1 - (1/4)(1.5 - 1)(2.25) = 0.71875, straight at the target.
  ReactiveMemory memory;
  const ReactiveCommand c =
      command(ReactiveMethod::potential, params, memory, Vec2(-60, 0), 0.0, Vec2(150, 0), objects);
  EXPECT_EQ(c.status, ReactiveStatus::ok);
  EXPECT_NEAR(c.course, 0.0, 1e-12);
}

TEST(Potential, StallsInFrontOfAWideWall) {
  std::vector<Ellipse> wall;
  for (int i = -2; i <= 2; ++i) wall.push_back(disc(0, 20.0 * i, 10));
  const ReactiveParams params = params_for(10, 2, 5);
  for (double y0 : {0.0, 7.0, -12.0}) {
    const Flight f = fly(ReactiveMethod::potential, params, Vec2(-150, y0), 0.0, Vec2(150, 0), wall, 0.1, 5000);
    EXPECT_EQ(f.last, ReactiveStatus::stalled) << y0;
    EXPECT_LT(f.path.back().x(), -20.0) << y0;  // never got past the wall
  }
  // The same wall is no trap for the other two.
  for (const ReactiveMethod& m : {ReactiveMethod::geometric, ReactiveMethod::dipole}) {
    const Flight f = fly(m, params, Vec2(-150, 7), 0.0, Vec2(150, 0), wall, 0.1);
    EXPECT_EQ(f.last, ReactiveStatus::arrived) << to_string(m);
  }
}

TEST(Potential, OscillatesInANarrowCorridor) {
  // A corridor 120 m long: discs r 10 every 20 m at y = +-27, zones R 20, 14 m of free water between them.
  // With the default reach (60 m) the potential field does not even enter (blocked entrance: stalled);
  // with a 10 m reach it enters, and its course swings from wall to wall. The geometric method goes
  // straight through (the line of sight at y = 6 is free).
  std::vector<Ellipse> corridor;
  for (int i = 0; i < 6; ++i) {
    corridor.push_back(disc(20.0 * i, -27, 10));
    corridor.push_back(disc(20.0 * i, 27, 10));
  }
  ReactiveParams params = params_for(10, 2, 5);
  auto swings = [](const Flight& f) {
    int n = 0;
    double last = 0.0;
    for (double r : f.rates) {
      if (std::abs(r) < deg_to_rad(0.5)) continue;
      if (last != 0.0 && (r > 0) != (last > 0)) ++n;
      last = r;
    }
    return n;
  };
  const Flight blocked = fly(ReactiveMethod::potential, params, Vec2(-150, 6), 0.0, Vec2(250, 6), corridor, 0.1);
  EXPECT_EQ(blocked.last, ReactiveStatus::stalled);
  EXPECT_LT(blocked.path.back().x(), -10.0);
  params.influence_m = 10.0;
  const Flight pot = fly(ReactiveMethod::potential, params, Vec2(-150, 6), 0.0, Vec2(250, 6), corridor, 0.1);
  const Flight geo = fly(ReactiveMethod::geometric, params, Vec2(-150, 6), 0.0, Vec2(250, 6), corridor, 0.1);
  EXPECT_EQ(pot.last, ReactiveStatus::arrived);
  EXPECT_EQ(geo.last, ReactiveStatus::arrived);
  EXPECT_GE(swings(pot), 8);
  EXPECT_EQ(swings(geo), 0);
  EXPECT_EQ(geo.max_rate, 0.0);
}

TEST(Potential, InsideAZoneGoesStraightOut) {
  const ReactiveParams params = params_for(10, 2, 5);
  ReactiveMemory memory;
  const ReactiveCommand c = command(ReactiveMethod::potential, params, memory, Vec2(-12, 5), 0.0, Vec2(150, 0),
                                    std::vector<Ellipse>{disc(0, 0, 10)});
  EXPECT_EQ(c.status, ReactiveStatus::leaving_zone);
  EXPECT_NEAR(c.course, std::atan2(5.0, -12.0), 1e-12);
}

// --- edge cases, every method ---

TEST(ReactiveMethods, TargetInsideAZoneStopsAtItsBoundary) {
  // Target (12, 0) lies in the zone R 20 round the disc: the nearest boundary point is (20, 0).
  const ReactiveParams params = params_for(10, 2, 5);
  const std::vector<Ellipse> objects{disc(0, 0, 10)};
  for (const ReactiveMethod& m : {ReactiveMethod::geometric, ReactiveMethod::dipole}) {
    for (const Vec2& start : {Vec2(100, 3), Vec2(-100, 3)}) {
      const Flight f = fly(m, params, start, 0.0, Vec2(12, 0), objects, 0.1);
      EXPECT_EQ(f.last, ReactiveStatus::target_in_zone) << to_string(m);
      EXPECT_EQ(f.commands.back().speed_mps, 0.0);
      EXPECT_LE((f.path.back() - Vec2(20, 0)).norm(), 5.0 + 1e-9) << to_string(m);
      EXPECT_GT(min_clearance(f.path, objects, 10), -0.5) << to_string(m);
      for (std::size_t k = 0; k + 1 < f.commands.size(); ++k) {
        EXPECT_EQ(f.commands[k].status, ReactiveStatus::target_in_zone) << to_string(m) << " " << k;
      }
    }
  }
  // The potential field cannot get near it (the repulsion balances the pull 30 m out): it stalls outside.
  const Flight p = fly(ReactiveMethod::potential, params, Vec2(100, 3), kPi, Vec2(12, 0), objects, 0.1);
  EXPECT_EQ(p.last, ReactiveStatus::stalled);
  EXPECT_GT(min_clearance(p.path, objects, 10), 25.0);
}

TEST(ReactiveMethods, StartingInsideTheZoneEveryMethodLeavesIt) {
  const ReactiveParams params = params_for(10, 2, 5);
  const std::vector<Ellipse> objects{disc(0, 0, 10)};
  for (const ReactiveMethod& m : kMethods) {
    const Flight f = fly(m, params, Vec2(-12, 4), 0.0, Vec2(150, 0), objects, 0.1, 300);
    EXPECT_EQ(f.commands.front().status, ReactiveStatus::leaving_zone) << to_string(m);
    EXPECT_GE(f.path.back().norm(), 20.0) << to_string(m);
    for (std::size_t k = 1; k < f.path.size() && f.path[k].norm() < 20.0; ++k) {
      EXPECT_GT(f.path[k].norm(), f.path[k - 1].norm()) << to_string(m) << " " << k;  // straight out, no dwelling
    }
  }
}

TEST(ReactiveMethods, BadInputIsRejected) {
  const std::vector<Ellipse> good{disc(0, 0, 10)};
  auto throws = [&](const ReactiveParams& p, const Vec2& pos, const Vec2& target, const std::vector<Ellipse>& objs,
                    const char* field) {
    for (const ReactiveMethod& m : kMethods) {
      ReactiveMemory memory;
      try {
        command(m, p, memory, pos, 0.0, target, objs);
        ADD_FAILURE() << "no error for " << field;
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
      }
      EXPECT_THROW(reactive_gradient(m, p, pos, target, objs), InputError) << field;
    }
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  ReactiveParams p;
  const Vec2 a(-100, 0), b(100, 0);
  ReactiveParams q = p;
  q.margin_m = -1;
  throws(q, a, b, good, "margin_m");
  q = p;
  q.speed_mps = 0;
  throws(q, a, b, good, "speed_mps");
  q = p;
  q.influence_m = nan;
  throws(q, a, b, good, "influence_m");
  q = p;
  q.exit_blend_fraction = 1.5;
  throws(q, a, b, good, "exit_blend_fraction");
  q = p;
  q.tuning["potential_stall_fraction"] = 1.0;
  throws(q, a, b, good, "potential_stall_fraction");
  throws(p, Vec2(nan, 0), b, good, "position");
  throws(p, a, Vec2(0, inf), good, "target");
  throws(p, a, b, {Ellipse{Vec2(0, 0), 2, 5, 0}}, "object 0");                 // a < b
  throws(p, a, b, {disc(0, 0, 1), Ellipse{Vec2(0, 0), 2, 0, 0}}, "object 1");  // b = 0
  throws(p, a, b, {Ellipse{Vec2(inf, 0), 2, 1, 0}}, "object 0");
  ReactiveMemory memory;
  ReactiveInput in;
  in.position = a;
  in.target = b;
  in.course = nan;
  EXPECT_THROW(reactive_command(ReactiveMethod::geometric, p, memory, in), InputError);
  EXPECT_NO_THROW(validate(p));
}

}  // namespace
}  // namespace deepguide
