// Exact visibility among polygons (planning/polygon_visibility.hpp), on
// hand-built rings.
//
// The wall between two notches: an obstacle square [-10, 20] x [-10, 10]
// with a water notch from the west whose tip is P = (0, 0), and one from the
// east whose lower edge runs from its tip R = (1, d) to Q = (20, 0) on the
// east side, d = 1.5 eps just above the line PQ. PQ leaves P into the wall
// (0.5 m deep at x = 0.5: the tips are the nearest boundary), passes under
// R by d and then runs inside the obstacle just under the lower edge, at
// depth d (19 - (x - 1)) / 19 <= eps from x = 10 on: its midpoint (10, 0)
// is 0.79 eps deep. Neither notch edge is crossed by more than eps, so only
// the pieces' midpoints can reject PQ.
#include <gtest/gtest.h>

#include <boost/geometry/algorithms/correct.hpp>
#include <vector>

#include "deepguide/planning/polygon_visibility.hpp"

using namespace deepguide;

namespace {

constexpr double kEps = 1e-6;

BgPolygon notched_wall(double d) {
  BgPolygon poly;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{-10, -10},
                                                                   {20, -10},
                                                                   {20, 0},
                                                                   {1, d},
                                                                   {20, 1},
                                                                   {20, 10},
                                                                   {-10, 10},
                                                                   {-10, 1},
                                                                   {0, 0},
                                                                   {-10, -1},
                                                                   {-10, -10}}) {
    poly.outer().push_back(BgPoint(x, y));
  }
  boost::geometry::correct(poly);
  return poly;
}

}  // namespace

TEST(PolygonVisibility, ASegmentIntoAWallPastACornerJustBesideItIsBlocked) {
  const double d = 1.5 * kEps;
  const PolygonVisibility vis(BgMultiPolygon{notched_wall(d)}, kEps);
  EXPECT_TRUE(vis.strictly_inside({0.5, 0.0}));    // the wall
  EXPECT_FALSE(vis.strictly_inside({10.0, 0.0}));  // 0.79 eps under the notch's edge
  EXPECT_FALSE(vis.segment_visible({0.0, 0.0}, {20.0, 0.0}));
  EXPECT_FALSE(vis.segment_visible({20.0, 0.0}, {0.0, 0.0}));
  // What stays open: along the notch's edge, into the notches, and the
  // notch's mouth along the east side.
  EXPECT_TRUE(vis.segment_visible({1.0, d}, {20.0, 0.0}));
  EXPECT_TRUE(vis.segment_visible({0.0, 0.0}, {-10.0, 0.0}));
  EXPECT_TRUE(vis.segment_visible({20.0, 0.0}, {20.0, 1.0}));
  EXPECT_TRUE(vis.segment_visible({10.0, 0.3}, {19.0, 0.3}));
}
