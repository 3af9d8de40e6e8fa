// Leg costs in a current (planning/edge_cost.hpp): closed forms for uniform
// currents (across, following, head, none), a current that changes along the
// leg against its integral, infeasible legs, the economical speed against a
// scan, and the A* lower bounds against 500 random legs.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/edge_cost.hpp"

namespace deepguide {
namespace {

const EnergyModel kEnergy;  // 1050 W + 60 W/(m/s)^3
constexpr double kCruise = 4.0 * 1852.0 / 3600.0;
constexpr double kMax = 6.0 * 1852.0 / 3600.0;

CurrentAt uniform(Vec2 c) {
  return [c](const Vec2&) { return c; };
}

TEST(LegCost, UniformCurrentsMatchTheClosedForm) {
  const Vec2 a(100.0, -50.0), b(1100.0, -50.0);  // 1000 m east
  const double v = kCruise, p = kEnergy.power_w(v);
  // 1 m/s across (north): s = sqrt(v^2 - 1).
  LegCost c = leg_cost(a, b, v, uniform({0.0, 1.0}));
  ASSERT_TRUE(c.feasible);
  EXPECT_NEAR(c.time_s, 1000.0 / std::sqrt(v * v - 1.0), 1e-9);
  EXPECT_NEAR(c.energy_j, p * 1000.0 / std::sqrt(v * v - 1.0), 1e-6);
  // Following and head: s = v +- 1.
  EXPECT_NEAR(leg_cost(a, b, v, uniform({1.0, 0.0})).time_s, 1000.0 / (v + 1.0), 1e-9);
  EXPECT_NEAR(leg_cost(a, b, v, uniform({-1.0, 0.0})).time_s, 1000.0 / (v - 1.0), 1e-9);
  // 1 m/s at 30 degrees off the leg, ahead to port: s = cos30 + sqrt(v^2 - sin^2 30).
  const Vec2 oblique(std::cos(M_PI / 6.0), std::sin(M_PI / 6.0));
  EXPECT_NEAR(leg_cost(a, b, v, uniform(oblique)).time_s, 1000.0 / (std::cos(M_PI / 6.0) + std::sqrt(v * v - 0.25)),
              1e-9);
  // No current: L / v and L P(v) / v.
  c = leg_cost(a, b, v, uniform({0.0, 0.0}));
  EXPECT_NEAR(c.time_s, 1000.0 / v, 1e-9);
  EXPECT_NEAR(c.energy_j, 1000.0 * p / v, 1e-6);
  EXPECT_DOUBLE_EQ(c.length_m, 1000.0);
}

TEST(LegCost, ACurrentThatChangesAlongTheLegIsIntegrated) {
  // c = (0, 1.5 x / L) across a leg along x: t = int dx / sqrt(v^2 - (1.5 x / L)^2) = (L / 1.5) asin(1.5 / v).
  const double L = 2000.0, v = kCruise;
  const CurrentAt ramp = [&](const Vec2& p) { return Vec2(0.0, 1.5 * p.x() / L); };
  const double exact = L / 1.5 * std::asin(1.5 / v);
  const LegCost fine = leg_cost({0.0, 0.0}, {L, 0.0}, v, ramp, {1.0, kEnergy});
  EXPECT_NEAR(fine.time_s / exact, 1.0, 1e-6);
  // Sampled once at the middle (one piece), the leg would take L / sqrt(v^2 - 0.75^2): 2 % off.
  const LegCost once = leg_cost({0.0, 0.0}, {L, 0.0}, v, ramp, {L, kEnergy});
  EXPECT_NEAR(once.time_s, L / std::sqrt(v * v - 0.5625), 1e-9);
  EXPECT_GT(std::abs(once.time_s / exact - 1.0), 0.01);
}

TEST(LegCost, LegsTheCurrentForbidsAreInfeasible) {
  const Vec2 a(0.0, 0.0), b(500.0, 0.0);
  for (const Vec2& c : {Vec2(0.0, 2.5), Vec2(-2.5, 0.0), Vec2(-2.06, 0.1)}) {
    const LegCost cost = leg_cost(a, b, kCruise, uniform(c));
    EXPECT_FALSE(cost.feasible) << c.transpose();
    EXPECT_TRUE(std::isinf(cost.time_s));
    EXPECT_TRUE(std::isinf(cost.energy_j));
  }
  // Only part of the leg: still infeasible.
  const CurrentAt jet = [](const Vec2& p) { return p.x() > 300.0 && p.x() < 320.0 ? Vec2(0.0, 3.0) : Vec2(0.0, 0.0); };
  EXPECT_FALSE(leg_cost(a, b, kCruise, jet).feasible);
  // The economical speed finds a way where cruise cannot: 2.5 m/s across needs more than 2.5 m/s.
  const LegCost fast = leg_cost_economical(a, b, 0.5, kMax, uniform({0.0, 2.5}));
  ASSERT_TRUE(fast.feasible);
  EXPECT_GT(fast.speed_mps, 2.5);
  EXPECT_FALSE(leg_cost_economical(a, b, 0.5, kMax, uniform({0.0, 3.2})).feasible);
  EXPECT_THROW(leg_cost(a, b, 0.0, uniform({0, 0})), InputError);
  EXPECT_THROW(leg_cost(a, b, 1.0, uniform({0, 0}), {0.0, kEnergy}), InputError);
  EXPECT_THROW(leg_cost_economical(a, b, 2.0, 1.0, uniform({0, 0})), InputError);
}

TEST(LegCost, TheEconomicalSpeedBeatsEveryOtherSpeed) {
  // Still water: v* = (P_hotel / 2k)^(1/3).
  const LegCost still = leg_cost_economical({0, 0}, {1000, 0}, 0.3, kMax, uniform({0, 0}));
  EXPECT_NEAR(still.speed_mps, kEnergy.economical_speed_mps(), 1e-6);
  EXPECT_NEAR(kEnergy.economical_speed_mps(), 2.06064, 1e-5);  // cbrt(1050 / 120) = cbrt(8.75)
  // Head, following, across and varying currents: no speed on a fine scan does better,
  // and a head current asks for more speed than a following one.
  const CurrentAt swirl = [](const Vec2& p) {
    return Vec2(0.6 * std::sin(p.x() / 150.0), 0.8 * std::cos(p.x() / 90.0));
  };
  for (const CurrentAt& c : {uniform({-1.0, 0.0}), uniform({1.0, 0.0}), uniform({0.3, 1.2}), swirl}) {
    const LegCost best = leg_cost_economical({0, 0}, {1500, 0}, 0.3, kMax, c);
    ASSERT_TRUE(best.feasible);
    for (double v = 0.3; v <= kMax; v += 0.001) {
      const LegCost other = leg_cost({0, 0}, {1500, 0}, v, c);
      if (other.feasible) {
        ASSERT_GE(other.energy_j, best.energy_j * (1.0 - 1e-9)) << v;
      }
    }
  }
  EXPECT_GT(leg_cost_economical({0, 0}, {1000, 0}, 0.3, kMax, uniform({-1.0, 0.0})).speed_mps,
            leg_cost_economical({0, 0}, {1000, 0}, 0.3, kMax, uniform({1.0, 0.0})).speed_mps);
}

TEST(LegCost, LowerBoundsNeverExceedTheCostOf500RandomLegs) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> pos(-2000.0, 2000.0), angle(-M_PI, M_PI), strength(0.0, 1.5);
  const double c_max = 1.5;
  const double per_metre = energy_per_metre_lower_bound(kEnergy, 0.5, kMax, c_max);
  int feasible = 0;
  for (int i = 0; i < 500; ++i) {
    const Vec2 a(pos(rng), pos(rng)), b(pos(rng), pos(rng));
    const double theta = angle(rng);
    const Vec2 c0 = strength(rng) * Vec2(std::cos(theta), std::sin(theta));
    const double k = 1.0 / (300.0 + 700.0 * strength(rng));
    // A current whose speed never exceeds c_max: the magnitude of c0 rotated along the way.
    const CurrentAt c = [&](const Vec2& p) {
      const double t = k * (p.x() + p.y());
      return Vec2(c0.x() * std::cos(t) - c0.y() * std::sin(t), c0.x() * std::sin(t) + c0.y() * std::cos(t));
    };
    const double d = (b - a).norm();
    const LegCost at_cruise = leg_cost(a, b, kCruise, c);
    const LegCost economical = leg_cost_economical(a, b, 0.5, kMax, c);
    if (!economical.feasible) continue;
    ++feasible;
    EXPECT_LE(d * per_metre, economical.energy_j * (1.0 + 1e-12));
    if (at_cruise.feasible) {
      EXPECT_LE(time_lower_bound(d, kCruise, c_max), at_cruise.time_s * (1.0 + 1e-12));
      EXPECT_LE(d * per_metre, at_cruise.energy_j * (1.0 + 1e-12));
    }
  }
  EXPECT_GT(feasible, 450);
  // The bound is tight for a following current of c_max at the best speed.
  const double v = 2.0;  // any
  EXPECT_NEAR(time_lower_bound(1000.0, v, c_max), leg_cost({0, 0}, {1000, 0}, v, uniform({c_max, 0})).time_s, 1e-9);
}

}  // namespace
}  // namespace deepguide
