// union_no_go: the union of no-go areas through edge cancellation and GEOS,
// checked on tiles that share edges, a tile given twice (parity would cancel
// it: the union must fall back and keep it), a ring of tiles round free water
// (a hole), and overlapping other areas; and on areas that are not valid
// polygons (a bow-tie, a ring that loops over itself, a hole outside its
// shell), on which GEOS's plain union stops with a TopologyException: they
// are repaired, and every polygon returned is valid for Boost.Geometry.
// overlay_no_go: an area less zones sharing its edges, and within them.

#include <gtest/gtest.h>

#include <boost/geometry.hpp>
#include <cmath>
#include <string>

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

BgPolygon from_wkt(const std::string& wkt) {
  BgPolygon p;
  boost::geometry::read_wkt(wkt, p);
  return p;  // not corrected: as a buggy overlay would hand it over
}

TEST(NoGoUnion, InvalidAreasAreRepairedNotRefused) {
  // Each beside a valid box it overlaps; GEOS 3.11's cascaded union of the pair fails (returns nothing).
  const BgPolygon box_area = from_wkt("POLYGON((5 -1,5 11,12 11,12 -1,5 -1))");
  const std::vector<std::string> invalid = {
      "POLYGON((0 0,10 10,10 0,0 10,0 0))",                            // a bow-tie
      "POLYGON((0 0,0 12,6 12,6 -3,4 -3,4 10,10 10,10 0,0 0))",        // a ring looping over itself
      "POLYGON((0 0,0 10,10 10,10 0,0 0),(5 5,15 5,15 15,5 15,5 5))",  // a hole reaching outside
      "POLYGON((0 0,0 8,8 8,8 2,2 2,2 10,10 10,10 0,0 0))",            // a ring overlapping itself
  };
  for (const std::string& wkt : invalid) {
    const BgPolygon bad = from_wkt(wkt);
    ASSERT_FALSE(boost::geometry::is_valid(bad)) << wkt;
    std::vector<BgPolygon> u;
    ASSERT_NO_THROW(u = union_no_go({}, {&bad, &box_area})) << wkt;
    ASSERT_FALSE(u.empty()) << wkt;
    BgMultiPolygon all;
    all.assign(u.begin(), u.end());
    std::string why;
    for (const BgPolygon& p : u) EXPECT_TRUE(boost::geometry::is_valid(p, why)) << wkt << ": " << why;
    // The valid box is kept whole, and so are points well inside the invalid area's body.
    BgMultiPolygon kept;
    boost::geometry::intersection(all, box_area, kept);
    EXPECT_NEAR(boost::geometry::area(kept), 84.0, 1e-6) << wkt;
    EXPECT_TRUE(boost::geometry::covered_by(BgPoint(1.0, 5.0), all)) << wkt;
    // Where the box does not reach either: the water a self-overlapping ring covers twice stays no-go.
    EXPECT_TRUE(boost::geometry::covered_by(BgPoint(3.0, 5.0), all)) << wkt;
  }
}

TEST(NoGoUnion, AGridSnapRoundsEveryVertex) {
  const BgPolygon a = from_wkt(
      "POLYGON((0.00031 0.00042,0.00031 10.1234567,10.9876543 10.1234567,10.9876543 0.00042,"
      "0.00031 0.00042))");
  const BgPolygon b = from_wkt(
      "POLYGON((5.5555555 5.5555555,5.5555555 20.2020202,20.2020202 20.2020202,"
      "20.2020202 5.5555555,5.5555555 5.5555555))");
  const std::vector<BgPolygon> u = union_no_go({}, {&a, &b}, 1e-3);
  ASSERT_EQ(u.size(), 1u);
  EXPECT_TRUE(boost::geometry::is_valid(u.front()));
  for (const BgPoint& q : u.front().outer()) {
    EXPECT_NEAR(q.x() * 1e3, std::round(q.x() * 1e3), 1e-6) << q.x();
    EXPECT_NEAR(q.y() * 1e3, std::round(q.y() * 1e3), 1e-6) << q.y();
  }
  const double exact =
      boost::geometry::area(a) + boost::geometry::area(b) - (10.9876543 - 5.5555555) * (10.1234567 - 5.5555555);
  EXPECT_NEAR(area(u), exact, 81.0 * 0.5e-3) << "each edge (81 m of them) moves by at most half a cell";
}

// A 4 x 2 strip with zones sharing its edges: its left half, and a unit
// square in its lower right corner.
TEST(NoGoUnion, OverlayLessAndWithinZonesSharingEdges) {
  const BgMultiPolygon strip{box(0, 0, 4, 2)};
  const BgPolygon left = box(0, 0, 2, 2), right = box(3, 0, 4, 1);
  const std::vector<BgPolygon> less = overlay_no_go(strip, {&left, &right}, false);
  EXPECT_NEAR(area(less), 8.0 - 4.0 - 1.0, 1e-9);
  EXPECT_FALSE(boost::geometry::covered_by(BgPoint(1.0, 1.0), less.front()));
  const std::vector<BgPolygon> within = overlay_no_go(strip, {&left, &right}, true);
  EXPECT_NEAR(area(within), 5.0, 1e-9);
  for (const BgPolygon& p : within) EXPECT_TRUE(boost::geometry::is_valid(p));
  // No zones: the area itself, or nothing of it.
  EXPECT_NEAR(area(overlay_no_go(strip, {}, false)), 8.0, 1e-9);
  EXPECT_TRUE(overlay_no_go(strip, {}, true).empty());
  // A zone beyond the area cuts nothing.
  const BgPolygon far = box(10, 10, 11, 11);
  EXPECT_NEAR(area(overlay_no_go(strip, {&far}, false)), 8.0, 1e-9);
}

}  // namespace
}  // namespace deepguide
