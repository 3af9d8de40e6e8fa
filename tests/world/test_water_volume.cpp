// The water volume (world/water_volume.hpp): points and legs against the
// depth band, the sea floor and obstacle tops, with hand-derived crossings,
// and bad bands.
#include <gtest/gtest.h>

#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/world/water_volume.hpp"
#include "planning/obstacle_builders.hpp"

using namespace deepguide;
using deepguide::test::box;
using deepguide::test::disc;

namespace {

SeaFloor flat(double depth) { return SeaFloor({-500.0, -500.0}, 50.0, 21, 21, std::vector<double>(21 * 21, depth)); }

}  // namespace

TEST(WaterVolume, PointsAgainstBandFloorAndObstacleTops) {
  ObstacleSet set;
  set.ellipses.push_back(disc(0.0, 0.0, 10.0, "rock"));
  set.ellipses.back().top_depth_m = 20.0;
  set.ellipses.push_back(disc(200.0, 0.0, 10.0, "tower"));  // no top: the whole column
  set.ellipses.push_back(disc(-200.0, 0.0, 10.0, "mound"));
  set.ellipses.back().height_m = 30.0;  // on a 100 m floor: top at 70 m
  const ObstacleField field(set, 5.0);
  const SeaFloor floor = flat(100.0);
  const WaterVolume volume(field, &floor, {2.0, 5.0, 200.0});
  EXPECT_DOUBLE_EQ(volume.zone_top(0), 18.0);
  EXPECT_TRUE(std::isinf(volume.zone_top(1)));
  EXPECT_DOUBLE_EQ(volume.zone_top(2), 68.0);

  EXPECT_TRUE(volume.is_free({0.0, 0.0, 18.0}));  // exactly the clearance over the rock
  EXPECT_FALSE(volume.is_free({0.0, 0.0, 18.5}));
  EXPECT_TRUE(volume.is_free({15.0, 0.0, 50.0}));  // on the zone's edge, beside the rock
  EXPECT_FALSE(volume.is_free({14.9, 0.0, 50.0}));
  EXPECT_FALSE(volume.is_free({200.0, 0.0, 6.0}));  // the tower fills the column
  EXPECT_TRUE(volume.is_free({-200.0, 0.0, 68.0}));
  EXPECT_FALSE(volume.is_free({-200.0, 0.0, 69.0}));
  EXPECT_TRUE(volume.is_free({100.0, 100.0, 98.0}));  // 2 m over the floor
  EXPECT_FALSE(volume.is_free({100.0, 100.0, 98.5}));
  EXPECT_FALSE(volume.is_free({100.0, 100.0, 4.0}));  // above the band
  const WaterVolume::Verdict v = volume.check_point({0.0, 0.0, 25.0});
  EXPECT_TRUE(v.blocked);
  EXPECT_NE(v.reason.find("'rock'"), std::string::npos) << v.reason;
}

TEST(WaterVolume, LegsOverAnObstacleAreJudgedAtTheirDeepestPointInItsZone) {
  // A disc of radius 10, margin 5: the zone reaches 15 m from the centre;
  // its top at 20 m less 2 m clearance is 18 m.
  for (bool polygon : {false, true}) {
    ObstacleSet set;
    if (polygon) {
      set.polygons.push_back(box(-10.0, -10.0, 10.0, 10.0, "rock"));  // a square: its zone is 15 m out along y = 0
      set.polygons.back().top_depth_m = 20.0;
    } else {
      set.ellipses.push_back(disc(0.0, 0.0, 10.0, "rock"));
      set.ellipses.back().top_depth_m = 20.0;
    }
    const ObstacleField field(set, 5.0);
    const WaterVolume volume(field, nullptr, {2.0, 5.0, 200.0});
    SCOPED_TRACE(polygon ? "polygon" : "ellipse");
    // Level over the top: free; level below it: not.
    EXPECT_TRUE(volume.segment_free({-60.0, 0.0, 18.0}, {60.0, 0.0, 18.0}));
    EXPECT_FALSE(volume.segment_free({-60.0, 0.0, 19.0}, {60.0, 0.0, 19.0}));
    // Climbing from 30 m at x = -45 to 12 m at x = 0 (0.4 m per m): it enters
    // the zone at x = -15 at exactly 18 m, and is shallower from there on.
    EXPECT_TRUE(volume.segment_free({-45.0, 0.0, 30.0}, {0.0, 0.0, 12.0}));
    // From 30 m to 15 m: at x = -15 it is at 20 m, 2 m too deep.
    const WaterVolume::Verdict v = volume.check_segment({-45.0, 0.0, 30.0}, {0.0, 0.0, 15.0});
    ASSERT_TRUE(v.blocked);
    EXPECT_NEAR(v.where.x(), -15.0, 1e-6);
    EXPECT_NEAR(v.where.z(), 20.0, 1e-6);
    // Diving the other way: out of the zone at x = 15 at exactly 18 m, free; one more metre deep, not.
    EXPECT_TRUE(volume.segment_free({0.0, 0.0, 12.0}, {45.0, 0.0, 30.0}));
    EXPECT_FALSE(volume.segment_free({0.0, 0.0, 13.0}, {45.0, 0.0, 31.0}));
    // Passing beside the zone at any depth.
    EXPECT_TRUE(volume.segment_free({-60.0, 15.0, 80.0}, {60.0, 15.0, 80.0}));
    EXPECT_FALSE(volume.segment_free({-60.0, 14.9, 80.0}, {60.0, 14.9, 80.0}));
  }
}

TEST(WaterVolume, AZeroMarginStillBlocksLegsThroughAPolygon) {
  ObstacleSet set;
  set.polygons.push_back(box(-10.0, -10.0, 10.0, 10.0, "rock"));
  set.polygons.back().top_depth_m = 20.0;
  const ObstacleField field(set, 0.0);
  const WaterVolume volume(field, nullptr, {2.0, 5.0, 200.0});
  EXPECT_FALSE(volume.segment_free({-60.0, 0.0, 30.0}, {60.0, 0.0, 30.0}));  // straight through at 30 m
  EXPECT_FALSE(volume.segment_free({0.0, 0.0, 12.0}, {20.0, 0.0, 30.0}));    // at x = 10 it is 21 m deep
  EXPECT_TRUE(volume.segment_free({-60.0, 0.0, 18.0}, {60.0, 0.0, 18.0}));
  EXPECT_TRUE(volume.segment_free({-60.0, 10.5, 30.0}, {60.0, 10.5, 30.0}));  // beside it
}

TEST(WaterVolume, ANonFiniteTopIsRefusedAndNonFiniteLegsAreBlocked) {
  ObstacleSet set;
  set.ellipses.push_back(disc(0.0, 0.0, 10.0, "rock"));
  set.ellipses.back().top_depth_m = std::nan("");
  const ObstacleField field(set, 5.0);
  try {
    WaterVolume volume(field, nullptr, {2.0, 5.0, 200.0});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'rock'"), std::string::npos) << e.what();
  }
  const ObstacleField empty(ObstacleSet{}, 5.0);
  const WaterVolume volume(empty, nullptr, {2.0, 5.0, 200.0});
  EXPECT_FALSE(volume.is_free({std::nan(""), 0.0, 10.0}));
  EXPECT_FALSE(volume.segment_free({0.0, 0.0, 10.0}, {INFINITY, 0.0, 10.0}));
}

TEST(WaterVolume, LegsAgainstTheSeaFloorAndTheBand) {
  const ObstacleField field(ObstacleSet{}, 5.0);
  // Floor 100 m deep, rising to 40 m at x = 0 (a ridge along y).
  std::vector<double> d;
  for (int j = 0; j < 21; ++j) {
    for (int i = 0; i < 21; ++i) d.push_back(i == 10 ? 40.0 : 100.0);
  }
  const SeaFloor floor({-500.0, -500.0}, 50.0, 21, 21, d);
  const WaterVolume volume(field, &floor, {2.0, 5.0, 150.0});
  EXPECT_TRUE(volume.segment_free({-100.0, 0.0, 38.0}, {100.0, 0.0, 38.0}));
  const WaterVolume::Verdict v = volume.check_segment({-100.0, 0.0, 39.0}, {100.0, 0.0, 39.0});
  ASSERT_TRUE(v.blocked);
  EXPECT_NE(v.reason.find("sea floor"), std::string::npos) << v.reason;
  EXPECT_NEAR(v.where.x(), 0.0, 1e-9);
  // Over the slope: from 90 m at x = -50 (floor 100) to 38 m at x = 0 (floor 40):
  // the floor rises 60 m in 50 m, the leg 52 m, so the gap shrinks to 2 m at the crest.
  EXPECT_TRUE(volume.segment_free({-50.0, 0.0, 90.0}, {0.0, 0.0, 38.0}));
  EXPECT_FALSE(volume.segment_free({-50.0, 0.0, 99.0}, {0.0, 0.0, 38.0}));     // 1 m gap at x = -50
  EXPECT_FALSE(volume.segment_free({-300.0, 0.0, 4.9}, {-200.0, 0.0, 10.0}));  // starts above the band
  EXPECT_FALSE(volume.segment_free({-300.0, 0.0, 10.0}, {-200.0, 0.0, 150.5}));
}

TEST(WaterVolume, ABandAboveTheSurfaceIsRefused) {
  const ObstacleField field(ObstacleSet{}, 5.0);
  for (const auto& [top, bottom] : {std::pair{-10.0, -2.0}, std::pair{-1.0, 20.0}, std::pair{0.0, 0.0},
                                    std::pair{30.0, 20.0}, std::pair{std::nan(""), 20.0}}) {
    try {
      WaterVolume volume(field, nullptr, {2.0, top, bottom});
      FAIL() << top << " .. " << bottom;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("depth band"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(WaterVolume(field, nullptr, {-1.0, 2.0, 20.0}), InputError);
}

TEST(WaterVolume, TheFirstPointInAZoneSkipsAConcaveOutlinesNotch) {
  // A U open to the north: arms x 300..400 and 800..900 up to y = 50, the
  // bottom bar y -50..-20. Along y = 0 the zone (margin 5) is x 295..405 and
  // 795..905. Diving 0 -> 20 m over x 0 .. 1000, with the top at 14 m less 2 m
  // clearance, the leg is below 12 m from x = 600 on: in the notch, outside
  // the zone; the danger begins at the right arm, x = 795.
  ObstacleSet set;
  PolygonObstacle u;
  u.id = "u";
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {300, -50}, {300, 50}, {400, 50}, {400, -20}, {800, -20}, {800, 50}, {900, 50}, {900, -50}, {300, -50}}) {
    u.footprint.outer().push_back(to_bg({x, y}));
  }
  boost::geometry::correct(u.footprint);
  u.top_depth_m = 14.0;
  set.polygons.push_back(u);
  const ObstacleField field(set, 5.0);
  const WaterVolume volume(field, nullptr, {2.0, 0.0, 200.0});
  const auto t = volume.first_in_zone(0, {0.0, 0.0, 0.0}, {1000.0, 0.0, 20.0});
  ASSERT_TRUE(t);
  EXPECT_NEAR(1000.0 * *t, 795.0, 1e-6);
  // Top at 10 m: below 8 m from x = 400, inside the left arm's zone: there.
  set.polygons[0].top_depth_m = 10.0;
  const ObstacleField field2(set, 5.0);
  const WaterVolume volume2(field2, nullptr, {2.0, 0.0, 200.0});
  EXPECT_NEAR(1000.0 * *volume2.first_in_zone(0, {0.0, 0.0, 0.0}, {1000.0, 0.0, 20.0}), 400.0, 1e-6);
  // Climbing out over the same U: the first point is the left arm's zone edge.
  EXPECT_NEAR(1000.0 * *volume2.first_in_zone(0, {0.0, 0.0, 20.0}, {1000.0, 0.0, 0.0}), 295.0, 1e-6);
}
