// check_route_file, the library call behind `check route`, in-process: every
// line of a file is checked, the verdict names the part, JSON and text come
// from one report, and bad requests are one-line errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/route_file_check.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

const std::string kSample = deepguide::test::source_file("data/sample_obstacles.geojson");

// Haversine on the WGS 84 mean radius: an independent length for short lines.
double haversine_m(double lon0, double lat0, double lon1, double lat1) {
  constexpr double kRad = 3.14159265358979323846 / 180.0;
  const double a = std::pow(std::sin((lat1 - lat0) * kRad / 2), 2) +
                   std::cos(lat0 * kRad) * std::cos(lat1 * kRad) * std::pow(std::sin((lon1 - lon0) * kRad / 2), 2);
  return 2.0 * 6371008.8 * std::asin(std::sqrt(a));
}

}  // namespace

TEST(RouteFileCheck, ASecondLineThroughAnObstacleMakesTheFileUnsafe) {
  ScratchDir dir;
  // The first line keeps well clear, east of every obstacle; the second runs
  // through the centre of disc c2 (10.256 E, 54.453 N, radius 25 m).
  RouteFileCheckOptions o;
  o.route = dir.write("two.geojson", R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{"name":"clear"},"geometry":{"type":"LineString","coordinates":[[10.28,54.44],[10.28,54.46]]}},
    {"type":"Feature","properties":{"name":"through"},"geometry":{"type":"LineString","coordinates":[[10.255,54.453],[10.257,54.453]]}}]})");
  o.obstacles = {kSample};
  const RouteFileCheckReport r = check_route_file(o);
  EXPECT_FALSE(r.safe);
  EXPECT_NE(r.why.find("'c2'"), std::string::npos) << r.why;
  const nlohmann::json j = r.to_json();
  EXPECT_EQ(j["lines"], 2);
  EXPECT_FALSE(j["safe"].get<bool>());
  EXPECT_EQ(j["worst_obstacle"], "c2");
  EXPECT_NE(j["worst_part"].get<std::string>(), "");
  EXPECT_NE(r.why.find(j["worst_part"].get<std::string>()), std::string::npos) << r.why;
  // Through the disc's centre: the clearance to its footprint is minus its
  // radius there (to 1 cm: the line is straight in UTM, not on the parallel).
  EXPECT_NEAR(j["min_clearance_m"].get<double>(), -25.0, 0.01);
  EXPECT_EQ(r.to_text(), "unsafe: " + r.why);
  // The first line's figures, not the unsafe one's.
  EXPECT_EQ(r.waypoints, 2u);
  EXPECT_NEAR(r.length_m, haversine_m(10.28, 54.44, 10.28, 54.46), 0.005 * r.length_m);
}

TEST(RouteFileCheck, ASafeRouteSaysHowCloseItComesInTextAndJson) {
  ScratchDir dir;
  RouteFileCheckOptions o;
  o.route = dir.write("clear.geojson", R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{},"geometry":{"type":"LineString","coordinates":[[10.28,54.44],[10.28,54.46]]}}]})");
  o.obstacles = {kSample};
  o.margin_m = 10.0;
  const RouteFileCheckReport r = check_route_file(o);
  ASSERT_TRUE(r.safe) << r.why;
  const nlohmann::json j = r.to_json();
  EXPECT_EQ(j["margin_m"], 10.0);
  EXPECT_EQ(j["points"], 0);
  EXPECT_GT(j["min_clearance_m"].get<double>(), 10.0);
  EXPECT_EQ(j["crs"], "EPSG:32632");
  const std::string text = r.to_text();
  EXPECT_EQ(text.rfind("safe: ", 0), 0u) << text;
  EXPECT_NE(text.find("(2 waypoints, "), std::string::npos) << text;
}

TEST(RouteFileCheck, BadRequestsAreOneLineErrors) {
  ScratchDir dir;
  RouteFileCheckOptions o;
  o.route = dir.write("r.geojson", R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{},"geometry":{"type":"LineString","coordinates":[[10.28,54.44],[10.28,54.46]]}}]})");
  const auto message = [](const RouteFileCheckOptions& opts) {
    return deepguide::test::error_of([&] { check_route_file(opts); });
  };
  EXPECT_NE(message(o).find("expected obstacle files or charts"), std::string::npos);
  o.obstacles = {kSample};
  o.margin_m = -1.0;
  EXPECT_NE(message(o).find("margin: expected a safety margin >= 0 m"), std::string::npos);
  o.margin_m = std::nan("");
  EXPECT_NE(message(o).find("margin"), std::string::npos);
  o.margin_m = 5.0;
  o.obstacles.clear();
  o.charts = {dir.file("none.000")};
  EXPECT_NE(message(o).find("operating depth: expected"), std::string::npos);
  o.operating_depth_m = 10.0;
  const std::string missing = message(o);
  EXPECT_NE(missing.find("none.000"), std::string::npos) << missing;
  EXPECT_EQ(missing.find('\n'), std::string::npos) << missing;
}
