// plan_depth_request, the library call behind `plan --graph octree`,
// in-process: the route in open water, the dive angle from the vehicle, the
// report's text and JSON from one source, and bad requests.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/depth_plan_report.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

DepthPlanRequest open_water() {
  DepthPlanRequest r;
  r.start = {0.0, 0.0};
  r.goal = {300.0, 0.0};
  r.start_depth_m = 20.0;
  r.goal_depth_m = 20.0;
  r.max_dive_deg = 20.0;
  r.band_top_m = 10.0;
  r.band_bottom_m = 50.0;
  r.smooth = true;
  return r;
}

}  // namespace

TEST(DepthPlanReport, OpenWaterIsAStraightLevelLegInTextAndJson) {
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  const DepthPlanReport report = plan_depth_request(frame, open_water());
  // Nothing in the way at one depth: the smoothed route is the straight 300 m leg.
  EXPECT_NEAR(report.route().length(), 300.0, 1e-6);
  const nlohmann::json j = report.to_json();
  EXPECT_EQ(j["graph"], "octree");
  EXPECT_EQ(j["search"], "astar");
  EXPECT_EQ(j["crs"], "EPSG:32632");
  EXPECT_FALSE(j["sea_floor"].get<bool>());
  EXPECT_EQ(j["depth_band_m"][0], 10.0);
  EXPECT_EQ(j["depth_band_m"][1], 50.0);
  EXPECT_EQ(j["waypoints"], report.route().points.size());
  EXPECT_FALSE(j.contains("min_floor_gap_m"));  // no floor, no gap
  const std::string text = report.to_text();
  EXPECT_EQ(text.rfind("length           300.00 m in depth, ", 0), 0u) << text;
  EXPECT_NE(
      text.find("depth            20.0 m to 20.0 m; band 10.0 m to 50.0 m; steepest leg 0.0 deg (dive 20.0 deg)\n"),
      std::string::npos)
      << text;
  EXPECT_EQ(text.find("sea floor"), std::string::npos) << text;
  ASSERT_EQ(report.waypoint_properties().size(), report.route().points.size());
  EXPECT_EQ(report.waypoint_properties().front()["depth_m"], 20.0);
}

TEST(DepthPlanReport, TheDiveAngleComesFromTheVehicle) {
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  DepthPlanRequest r = open_water();
  r.max_dive_deg = std::nan("");
  r.band_top_m = std::nan("");  // the volume's own top, 2 m
  const DepthPlanReport report = plan_depth_request(frame, r);
  EXPECT_EQ(report.to_json()["depth_band_m"][0], 2.0);
  const VehicleParams v;
  const double expected = std::asin(v.max_vertical_speed_mps / v.cruise_speed_mps) * 180.0 / 3.14159265358979323846;
  EXPECT_NEAR(report.to_json()["max_dive_deg"].get<double>(), expected, 1e-12);
  // Without a floor the band needs a bottom.
  r.band_bottom_m = std::nan("");
  deepguide::test::expect_one_line_error([&] { plan_depth_request(frame, r); }, "a depth band with a bottom");
}

TEST(DepthPlanReport, BadRequestsAreOneLineErrors) {
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  DepthPlanRequest r = open_water();
  r.goal_depth_m = std::nan("");
  deepguide::test::expect_one_line_error([&] { plan_depth_request(frame, r); },
                                         "expected the start's and the goal's depth");
  r = open_water();
  r.charts = {"/nonexistent/chart.tif"};
  deepguide::test::expect_one_line_error([&] { plan_depth_request(frame, r); }, "/nonexistent/chart.tif");
  r = open_water();
  deepguide::test::ScratchDir dir;
  r.vehicle = dir.write("slow.yaml", "cruise_speed_mps: 1.0\nmax_vertical_speed_mps: 1.5\n");
  r.max_dive_deg = std::nan("");
  deepguide::test::expect_one_line_error([&] { plan_depth_request(frame, r); }, "gives no dive angle");
}
