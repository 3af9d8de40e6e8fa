// union_no_go: the union of no-go areas through edge cancellation and GEOS,
// checked on tiles that share edges, a tile given twice (parity would cancel
// it: the union must fall back and keep it), a ring of tiles round free water
// (a hole), and overlapping other areas.

#include <gtest/gtest.h>

#include <boost/geometry.hpp>

#include "deepguide/world/no_go_union.hpp"

namespace deepguide {
namespace {

BgPolygon box(double x0, double y0, double x1, double y1) {
  BgPolygon p;
  for (const Vec2& q : {Vec2(x0, y0), Vec2(x0, y1), Vec2(x1, y1), Vec2(x1, y0), Vec2(x0, y0)})
    p.outer().push_back(to_bg(q));
  boost::geometry::correct(p);
  return p;
}

double area(const std::vector<BgPolygon>& ps) {
  double a = 0.0;
  for (const BgPolygon& p : ps) a += boost::geometry::area(p);
  return a;
}

TEST(NoGoUnion, SharedEdgesCancelAndAHoleStays) {
  // A 3 x 3 grid of unit tiles without the centre: one polygon with a hole.
  std::vector<BgPolygon> tiles;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (i != 1 || j != 1) tiles.push_back(box(i, j, i + 1, j + 1));
    }
  }
  std::vector<const BgPolygon*> ptrs;
  for (const BgPolygon& t : tiles) ptrs.push_back(&t);
  const std::vector<BgPolygon> u = union_no_go(ptrs, {});
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u.front().inners().size(), 1u);
  EXPECT_NEAR(area(u), 8.0, 1e-9);
  EXPECT_FALSE(boost::geometry::covered_by(BgPoint(1.5, 1.5), u.front()));
}

TEST(NoGoUnion, ATileGivenTwiceIsKept) {
  const BgPolygon a = box(0, 0, 1, 1), b = box(1, 0, 2, 1);
  const std::vector<BgPolygon> u = union_no_go({&a, &a, &b}, {});
  EXPECT_NEAR(area(u), 2.0, 1e-9) << "the duplicate's edges cancel, the fallback keeps it";
}

TEST(NoGoUnion, OtherAreasMayOverlapAnything) {
  const BgPolygon a = box(0, 0, 2, 2), b = box(2, 0, 4, 2), other = box(1, 1, 5, 3), far = box(10, 10, 11, 11);
  const std::vector<BgPolygon> u = union_no_go({&a, &b}, {&other, &far});
  EXPECT_EQ(u.size(), 2u);
  EXPECT_NEAR(area(u), 8.0 + 8.0 - 3.0 + 1.0, 1e-9);  // the overlap is [1, 4] x [1, 2]
}

}  // namespace
}  // namespace deepguide
