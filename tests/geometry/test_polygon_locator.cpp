// PolygonLocator: which polygons hold a point, by ray parity over an R-tree
// of edges, against hand-made polygons with holes, vertices on the ray,
// horizontal edges and points on the boundary; and against Boost's
// covered_by on random points.

#include <gtest/gtest.h>

#include <boost/geometry.hpp>
#include <random>

#include "deepguide/geometry/polygon_locator.hpp"

namespace deepguide {
namespace {

BgPolygon poly(std::initializer_list<Vec2> outer, std::initializer_list<std::initializer_list<Vec2>> holes = {}) {
  BgPolygon p;
  for (const Vec2& q : outer) p.outer().push_back(to_bg(q));
  p.outer().push_back(p.outer().front());
  for (const auto& h : holes) {
    auto& r = p.inners().emplace_back();
    for (const Vec2& q : h) r.push_back(to_bg(q));
    r.push_back(r.front());
  }
  boost::geometry::correct(p);
  return p;
}

TEST(PolygonLocator, HolesVerticesOnTheRayAndBoundaries) {
  // A 10 x 10 square with a 4 x 4 hole, and a diamond whose corners lie on rays at y = 5.
  const BgPolygon square = poly({{0, 0}, {0, 10}, {10, 10}, {10, 0}}, {{{3, 3}, {7, 3}, {7, 7}, {3, 7}}});
  const BgPolygon diamond = poly({{20, 5}, {25, 10}, {30, 5}, {25, 0}});
  const PolygonLocator loc({&square, &diamond});
  using V = std::vector<std::size_t>;
  EXPECT_EQ(loc.covering({1, 1}), V{0});
  EXPECT_EQ(loc.covering({5, 5}), V{}) << "in the hole";
  EXPECT_EQ(loc.covering({1, 5}), V{0}) << "the ray passes the hole's two edges";
  EXPECT_EQ(loc.covering({22, 5}), V{1}) << "the ray runs through the diamond's right corner";
  EXPECT_EQ(loc.covering({15, 5}), V{}) << "the ray runs through both side corners";
  EXPECT_EQ(loc.covering({5, 10}), V{0}) << "on a horizontal edge";
  EXPECT_EQ(loc.covering({0, 4}), V{0}) << "on a vertical edge";
  EXPECT_EQ(loc.covering({3, 5}), V{0}) << "on the hole's edge";
  EXPECT_EQ(loc.covering({20, 5}), V{1}) << "on a corner";
  EXPECT_EQ(loc.covering({-1, 5}), V{});
  EXPECT_EQ(loc.covering({31, 5}), V{});
  EXPECT_DOUBLE_EQ(loc.distance_to_edges({5, 5}), 2.0);
  EXPECT_DOUBLE_EQ(loc.distance_to_edges({1, 1}), 1.0);
  EXPECT_EQ(PolygonLocator({}).covering({0, 0}), V{});
}

TEST(PolygonLocator, AgreesWithBoostOnRandomPoints) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 11.0);
  // A concave comb with a hole in one tooth.
  const BgPolygon comb =
      poly({{0, 0}, {0, 10}, {2, 10}, {2, 3}, {4, 3}, {4, 10}, {6, 10}, {6, 3}, {8, 3}, {8, 10}, {10, 10}, {10, 0}},
           {{{0.5, 5}, {1.5, 5}, {1.5, 8}, {0.5, 8}}});
  const PolygonLocator loc({&comb});
  for (int i = 0; i < 20000; ++i) {
    const Vec2 p(u(rng), u(rng));
    EXPECT_EQ(!loc.covering(p).empty(), boost::geometry::covered_by(to_bg(p), comb)) << p.transpose();
  }
}

}  // namespace
}  // namespace deepguide
