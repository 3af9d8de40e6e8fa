// periodic_two_roots: the bracketing TOMS 748 path (g returns a double) and
// the Newton path (g returns a ValueSlope) against roots known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "deepguide/core/angles.hpp"
#include "deepguide/geometry/periodic_roots.hpp"

namespace deepguide {
namespace {

constexpr double kPi = std::numbers::pi;

// Sorted roots in [0, 2 pi).
std::pair<double, double> wrapped(double a, double b) {
  a = wrap_two_pi(a);
  b = wrap_two_pi(b);
  return a < b ? std::pair{a, b} : std::pair{b, a};
}

// g(phi) = cos(phi - c) - k has roots c +- acos(k), for |k| < 1.
TEST(PeriodicRoots, ShiftedCosineBothPathsAgreeWithClosedForm) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> centre(-kPi, kPi), level(-0.999, 0.999), hint(-kPi, kPi);
  for (int trial = 0; trial < 500; ++trial) {
    const double c = centre(rng), k = level(rng), h = hint(rng);
    const auto expect = wrapped(c + std::acos(k), c - std::acos(k));
    auto g = [&](double phi) { return std::cos(phi - c) - k; };
    auto gs = [&](double phi) { return ValueSlope{std::cos(phi - c) - k, -std::sin(phi - c)}; };
    double a = 0, b = 0;
    ASSERT_TRUE(periodic_two_roots(g, a, b, h));
    auto got = wrapped(a, b);
    EXPECT_NEAR(got.first, expect.first, 1e-12) << "toms748, trial " << trial;
    EXPECT_NEAR(got.second, expect.second, 1e-12) << "toms748, trial " << trial;
    ASSERT_TRUE(periodic_two_roots(gs, a, b, h));
    got = wrapped(a, b);
    EXPECT_NEAR(got.first, expect.first, 1e-12) << "newton, trial " << trial;
    EXPECT_NEAR(got.second, expect.second, 1e-12) << "newton, trial " << trial;
  }
}

TEST(PeriodicRoots, NoSignChangeMeansNoRoots) {
  double a = 0, b = 0;
  EXPECT_FALSE(periodic_two_roots([](double phi) { return ValueSlope{2.0 + std::cos(phi), -std::sin(phi)}; }, a, b));
  EXPECT_FALSE(periodic_two_roots([](double phi) { return -2.0 + std::cos(phi); }, a, b));
}

// A narrow positive window (nearly touching sets): g = cos(phi) - 0.99999
// is positive only within 4.5 mrad of phi = 0, between the coarse samples.
TEST(PeriodicRoots, NarrowWindowIsFound) {
  const double k = 0.99999;
  double a = 0, b = 0;
  ASSERT_TRUE(periodic_two_roots([&](double phi) { return ValueSlope{std::cos(phi) - k, -std::sin(phi)}; }, a, b, 2.0));
  const auto got = wrapped(a, b);
  EXPECT_NEAR(got.first, std::acos(k), 1e-9);
  EXPECT_NEAR(got.second, 2.0 * kPi - std::acos(k), 1e-9);
}

// A slope that is zero, not a number, of the wrong sign or a few times off
// must not break the Newton path: steps leaving the bracket or failing to
// halve fall back to bisection. (A slope wildly too steep would make the
// steps, and so the stopping test, too small: callers give exact slopes.)
TEST(PeriodicRoots, WrongSlopeStillConverges) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double bad : {0.0, 1e-300, -5.0, 5.0, nan}) {
    double a = 0, b = 0;
    ASSERT_TRUE(periodic_two_roots([&](double phi) { return ValueSlope{std::cos(phi) - 0.5, bad}; }, a, b, 0.3));
    const auto got = wrapped(a, b);
    // Bisection stops at a bracket of 1e-12 rad x |angle|; a step made
    // small by a wrong slope stops early by the same factor.
    EXPECT_NEAR(got.first, kPi / 3.0, 1e-10) << "slope " << bad;
    EXPECT_NEAR(got.second, 5.0 * kPi / 3.0, 1e-10) << "slope " << bad;
  }
  double a = 0, b = 0;  // three times the true slope: converges, only slower
  ASSERT_TRUE(periodic_two_roots(
      [&](double phi) {
        return ValueSlope{std::cos(phi) - 0.5, -3.0 * std::sin(phi)};
      },
      a, b, 0.3));
  const auto got = wrapped(a, b);
  EXPECT_NEAR(got.first, kPi / 3.0, 1e-10);
  EXPECT_NEAR(got.second, 5.0 * kPi / 3.0, 1e-10);
}

}  // namespace
}  // namespace deepguide
