// Biarcs (geometry/biarc.hpp): a quarter circle and a circle's chords are
// reproduced exactly; random end conditions give two arcs that leave and
// arrive on the given tangents and meet with a common one.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "deepguide/geometry/biarc.hpp"

using namespace deepguide;

namespace {

Vec2 tangent_of(const CircleArc& a, const Vec2& at) {
  const Vec2 r = (at - a.centre).normalized();
  return a.turn * Vec2(-r.y(), r.x());
}

}  // namespace

TEST(Biarc, AQuarterCircleIsItself) {
  const auto b = biarc({0.0, 0.0}, {1.0, 0.0}, {10.0, 10.0}, {0.0, 1.0});
  ASSERT_TRUE(b.has_value());
  for (const CircleArc& a : *b) {
    EXPECT_NEAR(a.radius_m, 10.0, 1e-9);
    EXPECT_NEAR((a.centre - Vec2(0.0, 10.0)).norm(), 0.0, 1e-9);
    EXPECT_EQ(a.turn, +1);
  }
  EXPECT_NEAR((*b)[0].length_m() + (*b)[1].length_m(), 0.5 * M_PI * 10.0, 1e-9);
  // Clockwise the same way: mirrored in the x axis.
  const auto cw = biarc({0.0, 0.0}, {1.0, 0.0}, {10.0, -10.0}, {0.0, -1.0});
  ASSERT_TRUE(cw.has_value());
  EXPECT_EQ((*cw)[0].turn, -1);
  EXPECT_NEAR((*cw)[1].radius_m, 10.0, 1e-9);
  EXPECT_NEAR(((*cw)[1].point_at(0.5) - Vec2(0.0, -10.0)).norm(), 10.0, 1e-9);
}

TEST(Biarc, RandomEndsJoinOnTheirTangents) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> pos(-50.0, 50.0), ang(-M_PI, M_PI);
  int made = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec2 p0(pos(rng), pos(rng)), p1(pos(rng), pos(rng));
    const double a0 = ang(rng), a1 = ang(rng);
    const Vec2 t0(std::cos(a0), std::sin(a0)), t1(std::cos(a1), std::sin(a1));
    const auto b = biarc(p0, t0, p1, t1);
    if (!b) continue;
    ++made;
    const CircleArc &first = (*b)[0], &second = (*b)[1];
    EXPECT_LT((first.from - p0).norm(), 1e-9);
    EXPECT_LT((second.to - p1).norm(), 1e-9);
    EXPECT_LT((first.to - second.from).norm(), 1e-9);
    EXPECT_LT((tangent_of(first, p0) - t0).norm(), 1e-7);
    EXPECT_LT((tangent_of(second, p1) - t1).norm(), 1e-7);
    EXPECT_LT((tangent_of(first, first.to) - tangent_of(second, second.from)).norm(), 1e-7);
    for (const CircleArc& a : *b) {
      EXPECT_NEAR((a.from - a.centre).norm(), a.radius_m, 1e-7 * a.radius_m);
      EXPECT_NEAR((a.to - a.centre).norm(), a.radius_m, 1e-7 * a.radius_m);
      EXPECT_LE(std::abs(a.sweep), M_PI + 1e-12);
      EXPECT_LT((a.point_at(1.0) - a.to).norm(), 1e-7 * std::max(1.0, a.radius_m));
    }
  }
  EXPECT_GT(made, 500);  // most random ends have one
}

TEST(Biarc, NoneWhereTwoArcsCannotDoIt) {
  EXPECT_FALSE(biarc({0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}).has_value());   // the same point
  EXPECT_FALSE(biarc({0.0, 0.0}, {1.0, 0.0}, {10.0, 0.0}, {1.0, 0.0}).has_value());  // a straight line
}
