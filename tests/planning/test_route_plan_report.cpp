// plan_route_request, the library call behind `plan` on the 2-D graphs,
// in-process: a route round one disc against its hand-derived length, the
// report's text and JSON from one source, a time route in a current with the
// shortest route priced beside it, the route file it writes read back, and
// bad requests.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/route_plan_export.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/planning/route_plan_report.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

// A disc of radius 40 m at the origin between (-300, 0) and (300, 0); margin 5 m.
RoutePlanRequest round_one_disc() {
  RoutePlanRequest r;
  r.obstacles.ellipses.push_back(test::disc(0.0, 0.0, 40.0, "rock"));
  r.problem.start = {-300.0, 0.0};
  r.problem.goal = {300.0, 0.0};
  r.margin_m = 5.0;
  return r;
}

// The shortest way from (-L, 0) to (L, 0) round a disc of radius r at the
// origin: two tangents of sqrt(L^2 - r^2) and the arc between their touching
// points, pi - 2 acos(r / L) wide.
double round_disc_length(double L, double r) {
  return 2.0 * std::sqrt(L * L - r * r) + r * (std::numbers::pi - 2.0 * std::acos(r / L));
}

}  // namespace

TEST(RoutePlanReport, TheTangentRoundOneDiscHasItsHandDerivedLength) {
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  RoutePlanRequest r = round_one_disc();
  r.graph = GraphKind::tangent;
  const RoutePlanReport report = plan_route_request(frame, r);
  const nlohmann::json j = report.to_json();
  EXPECT_NEAR(j.at("exact_length_m").get<double>(), round_disc_length(300.0, 45.0), 1e-3);
  EXPECT_EQ(j.at("arcs").get<int>(), 1);
  EXPECT_EQ(j.at("lines").get<int>(), 2);
  EXPECT_NEAR(j.at("min_clearance_m").get<double>(), 5.0, 1e-6);  // the arc keeps exactly the margin
  EXPECT_EQ(j.at("graph"), "tangent");
  EXPECT_EQ(j.at("crs"), "EPSG:32632");
  EXPECT_EQ(j.at("obstacles"), 1);
  // The polyline keeps outside the arc: no shorter than the exact route.
  EXPECT_GE(report.route.length(), j.at("exact_length_m").get<double>() - 1e-9);
}

TEST(RoutePlanReport, TextAndJsonSayTheSame) {
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  const RoutePlanReport report = plan_route_request(frame, round_one_disc());
  const nlohmann::json j = report.to_json();
  const std::string text = report.to_text();
  EXPECT_EQ(text.rfind("length           " + fixed(j.at("length_m").get<double>(), 2) + " m, " +
                           std::to_string(j.at("waypoints").get<std::size_t>()) + " waypoints\n",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("min clearance    " + fixed(j.at("min_clearance_m").get<double>(), 2) + " m (margin 5.00 m)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("graph            visibility over 1 of 1 obstacles, "), std::string::npos) << text;
  // Still water at cruise: a time and an energy, no clock times, no leg table.
  EXPECT_TRUE(j.at("feasible").get<bool>());
  EXPECT_FALSE(j.contains("depart"));
  EXPECT_EQ(text.find("leg "), std::string::npos) << text;
  ASSERT_EQ(j.at("legs").size(), report.route.points.size() - 1);
  double legs = 0.0;
  for (const auto& leg : j.at("legs")) legs += leg.at("length_m").get<double>();
  EXPECT_NEAR(legs, j.at("length_m").get<double>(), 1e-6);
  // The route file's properties are the flat part of the JSON.
  nlohmann::json flat = j;
  flat.erase("legs");
  EXPECT_EQ(flat, report.route_properties());
  // Per waypoint: time and energy so far grow along the route.
  const auto waypoints = report.waypoint_properties();
  ASSERT_EQ(waypoints.size(), report.route.points.size());
  EXPECT_EQ(waypoints.front().at("cum_time_s").get<double>(), 0.0);
  EXPECT_NEAR(waypoints.back().at("cum_time_s").get<double>(), j.at("time_s").get<double>(), 1e-6);
  EXPECT_TRUE(report.warnings().empty());
  EXPECT_FALSE(report.stop_reason().has_value());
}

TEST(RoutePlanReport, ATimeRouteInACurrentIsComparedWithTheShortest) {
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  RoutePlanRequest r = round_one_disc();
  r.cost = CostKind::time;
  r.current = std::make_shared<const CurrentField>(parse_constant_current("0.5,90", "current"));
  r.current_source = "0.5 m/s east";
  const RoutePlanReport report = plan_route_request(frame, r);
  const nlohmann::json j = report.to_json();
  EXPECT_EQ(j.at("cost"), "time");
  EXPECT_EQ(j.at("current"), "0.5 m/s east");
  EXPECT_NEAR(j.at("max_current_mps").get<double>(), 0.5, 1e-9);
  ASSERT_TRUE(j.contains("shortest_time_s"));
  // A uniform current favours no side: the time route is the shortest, no slower.
  EXPECT_LE(j.at("time_s").get<double>(), j.at("shortest_time_s").get<double>() + 1e-6);
  EXPECT_NEAR(j.at("length_m").get<double>(), j.at("shortest_length_m").get<double>(), 0.5);
  // With the current behind, the time is the length over cruise + 0.5 m/s on a straight-ish route.
  const double cruise = VehicleParams{}.cruise_speed_mps;
  EXPECT_LT(j.at("time_s").get<double>(), j.at("length_m").get<double>() / cruise);
  EXPECT_NE(report.to_text().find("shortest route   "), std::string::npos);
}

// A field whose time axis ends before the vehicle can arrive: the reason is
// the axis, with both times, not "the current is stronger than the vehicle"
// (a 0.5 m/s field; issue 39).
TEST(RoutePlanReport, ATimeRoutePastTheFieldsTimeAxisSaysSo) {
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  RoutePlanRequest r = round_one_disc();
  r.cost = CostKind::time;
  CurrentField f;
  f.source = "short.nc";
  f.crs = "EPSG:32632";
  f.crs_wkt = frame.wkt();
  f.geographic = false;
  for (double c = -1000.0; c <= 1000.0; c += 500.0) f.x.push_back(c), f.y.push_back(c);
  f.times_s = {1.7e9, 1.7e9 + 100.0};  // 100 s; the route is 600 m
  f.u.assign(f.x.size() * f.y.size() * 2, 0.5);
  f.v.assign(f.u.size(), 0.0);
  f.extent = {4.49, 4.51, -0.01, 0.01};
  r.current = std::make_shared<const CurrentField>(f);
  try {
    plan_route_request(frame, r);
    FAIL() << "planned past the field's last time";
  } catch (const NoRouteError& e) {
    const std::string what = e.what();
    for (const char* w : {"time axis", "2023-11-14", "ends before the vehicle can arrive", "at the earliest"})
      EXPECT_NE(what.find(w), std::string::npos) << what;
    EXPECT_EQ(what.find("stronger than the vehicle"), std::string::npos) << what;
  }
}

TEST(RoutePlanReport, TheRouteFileCarriesTheReport) {
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  test::ScratchDir dir;
  const std::string path = dir.file("round.geojson");
  RoutePlanRequest r = round_one_disc();
  r.route_file = path;
  const RoutePlanReport report = plan_route_request(frame, r);
  write_route_plan(report, path);
  const Route back = read_route(path, frame);
  ASSERT_EQ(back.points.size(), report.route.points.size());
  for (std::size_t i = 0; i < back.points.size(); ++i) {
    EXPECT_LT((back.points[i] - report.route.points[i]).norm(), 0.01) << i;  // lon/lat to 1e-7 deg and back
  }
  std::ifstream in(path);
  const nlohmann::json file = nlohmann::json::parse(in);
  EXPECT_NEAR(file["features"][0]["properties"]["length_m"].get<double>(), report.route.length(), 1e-9);
  // A name no route format has: refused before anything is written.
  EXPECT_THROW(write_route_plan(report, dir.file("round.txt")), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("round.txt")));
}

TEST(RoutePlanReport, BadRequestsAreOneLineErrors) {
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  auto message = [&](RoutePlanRequest r) -> std::string {
    try {
      plan_route_request(frame, r);
    } catch (const InputError& e) {
      return e.what();
    } catch (const NoRouteError& e) {
      return std::string("no route: ") + e.what();
    }
    return "";
  };
  RoutePlanRequest heading = round_one_disc();
  heading.problem.start_heading = 0.0;
  heading.turn_radius_m = 20.0;
  EXPECT_NE(message(heading).find("expected `graph` tangent"), std::string::npos) << message(heading);
  heading.graph = GraphKind::tangent;
  heading.turn_radius_m.reset();
  EXPECT_NE(message(heading).find("`turn_radius_m` or `vehicle`"), std::string::npos) << message(heading);
  RoutePlanRequest smooth = round_one_disc();
  smooth.smooth = true;
  EXPECT_NE(message(smooth).find("`smooth`"), std::string::npos);
  RoutePlanRequest radius = round_one_disc();
  radius.turn_radius_m = -1.0;
  EXPECT_NE(message(radius).find("> 0 m, got -1"), std::string::npos) << message(radius);
  RoutePlanRequest speed = round_one_disc();
  speed.speed = "fast";
  EXPECT_NE(message(speed).find("got 'fast'"), std::string::npos) << message(speed);
  RoutePlanRequest inside = round_one_disc();
  inside.problem.start = {10.0, 0.0};  // inside the rock's zone
  EXPECT_EQ(message(inside).rfind("no route: ", 0), 0u) << message(inside);
  EXPECT_NE(message(inside).find("rock"), std::string::npos) << message(inside);
  for (const std::string& m : {message(heading), message(smooth), message(radius), message(speed)}) {
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}
