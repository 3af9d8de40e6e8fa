// Mission files (mission/mission.hpp) and the Missionplanhandler
// (mission/basic_manoeuvres.hpp): the sample mission reads, corners become
// arcs of the turn radius with hand-derived lengths, a survey over a
// rectangle is its lines and U-turns, a GPS update surfaces and dives, going
// around keeps the distance, and bad files are one line naming the place.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/evaluation/suite.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/collision_observation.hpp"
#include "deepguide/mission/mission.hpp"
#include "deepguide/mission/mission_environment.hpp"
#include "deepguide/mission/plan_export.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

const std::string kHeader = "crs: EPSG:32632\nstart: {x: 500000, y: 6000000, depth_m: 0}\n";

std::string error_of(const std::string& path) {
  try {
    read_mission(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

// Consecutive basic manoeuvres join, and the distances along add up.
void expect_continuous(const MissionPlan& plan) {
  double along = 0.0;
  for (std::size_t i = 0; i < plan.basics.size(); ++i) {
    const BasicManoeuvre& b = plan.basics[i];
    if (i > 0) {
      ASSERT_LT((b.from - plan.basics[i - 1].to).norm(), 1e-9) << i;
      ASSERT_DOUBLE_EQ(b.from_depth_m, plan.basics[i - 1].depth_m) << i;
    }
    ASSERT_NEAR(b.start_m, along, 1e-6) << i;
    if (b.kind == BasicManoeuvre::Kind::arc) {
      ASSERT_NEAR((b.from - b.centre).norm(), b.radius_m, 1e-9) << i;
      ASSERT_NEAR((b.to - b.centre).norm(), b.radius_m, 1e-9) << i;
      ASSERT_LT((b.point_at(b.length_m) - b.to).norm(), 1e-6) << i;
    }
    along += b.length_m;
  }
  EXPECT_NEAR(plan.length_m, along, 1e-6);
}

}  // namespace

TEST(Mission, TheSampleMissionReads) {
  const Mission m = read_mission(deepguide::test::source_file("data/missions/sample_mission.yaml"));
  EXPECT_EQ(m.name, "Kiel Bight sample survey");
  EXPECT_EQ(m.frame.id(), "EPSG:32632");
  EXPECT_EQ(m.charts.size(), 2u);
  EXPECT_EQ(m.obstacles.size(), 2u);
  ASSERT_EQ(m.manoeuvres.size(), 5u);
  EXPECT_EQ(m.manoeuvres[0].type, "track");
  EXPECT_EQ(m.manoeuvres[1].type, "survey");
  EXPECT_EQ(m.manoeuvres[2].type, "gps_update");
  EXPECT_EQ(m.manoeuvres[3].type, "identify");
  EXPECT_EQ(m.manoeuvres[4].type, "goto");
  EXPECT_NEAR(m.manoeuvres[0].speed_mps, 3.0 * 1852.0 / 3600.0, 1e-12);
  EXPECT_DOUBLE_EQ(m.manoeuvres[1].depth_m, 18.0);
  EXPECT_NEAR(m.start.x(), 580700.0, 1e-9);
  EXPECT_EQ(std::get<TrackSpec>(m.manoeuvres[0].spec).waypoints.size(), 3u);
}

TEST(Mission, ACornerBecomesAnArcOfTheTurnRadius) {
  // From (0, 0) east 400 m, then north 400 m, at 4 kn: R = 2.0578 / (5 deg/s) = 23.58 m.
  ScratchDir dir;
  const std::string path = dir.write("m.yaml",
                                     "crs: EPSG:32632\nstart: {x: 0, y: 0, depth_m: 0}\nmanoeuvres:\n"
                                     "  - track: {depth_m: 10, speed_kn: 4, waypoints: [{x: 400, y: 0}, "
                                     "{x: 400, y: 400}]}\n");
  const Mission m = read_mission(path);
  const MissionPlan plan = expand_mission(m, {});
  const double r = turn_radius(m.vehicle, 4.0 * 1852.0 / 3600.0);
  EXPECT_NEAR(r, 23.58, 0.01);
  ASSERT_EQ(plan.basics.size(), 3u);
  EXPECT_EQ(plan.basics[1].kind, BasicManoeuvre::Kind::arc);
  EXPECT_EQ(plan.basics[1].turn, 1);  // a left turn
  EXPECT_NEAR((plan.basics[1].centre - Vec2(400.0 - r, r)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(plan.length_m, 2.0 * (400.0 - r) + 0.5 * M_PI * r, 1e-9);
  EXPECT_DOUBLE_EQ(plan.basics[0].from_depth_m, 0.0);  // the first line dives
  EXPECT_DOUBLE_EQ(plan.basics[0].depth_m, 10.0);
  expect_continuous(plan);
  EXPECT_TRUE(plan.warnings.empty());
}

TEST(Mission, ASurveyIsItsLinesAndUTurns) {
  // A 500 m x 300 m rectangle, lines north-south 100 m apart at 3 kn (R = 17.68 m):
  // five lines at x = 50 .. 450, each 300 m, four U-turns of two quarter arcs and 100 - 2R.
  ScratchDir dir;
  const std::string path =
      dir.write("m.yaml",
                "crs: EPSG:32632\nstart: {x: 500050, y: -100, depth_m: 0}\nmanoeuvres:\n"
                "  - survey:\n      depth_m: 20\n      speed_kn: 3\n      line_spacing_m: 100\n      heading_deg: 0\n"
                "      area: [{x: 500000, y: 0}, {x: 500500, y: 0}, {x: 500500, y: 300}, {x: 500000, y: 300}]\n");
  const Mission m = read_mission(path);
  const MissionPlan plan = expand_mission(m, {});
  expect_continuous(plan);
  const double r = turn_radius(m.vehicle, 3.0 * 1852.0 / 3600.0);
  // On the zone's central meridian at the equator true north is grid north.
  const double expected = 100.0 /* transit */ + 5 * 300.0 + 4 * (M_PI * r + (100.0 - 2.0 * r));
  EXPECT_NEAR(plan.length_m, expected, 1e-6);
  const auto arcs = std::count_if(plan.basics.begin(), plan.basics.end(),
                                  [](const BasicManoeuvre& b) { return b.kind == BasicManoeuvre::Kind::arc; });
  EXPECT_EQ(arcs, 8);
  // Survey lines lie inside the area (all but the transit and the turns beyond its edge).
  for (const BasicManoeuvre& b : plan.basics) {
    if (b.kind != BasicManoeuvre::Kind::line || b.length_m < 250.0) continue;
    for (const Vec2& p : {b.from, b.to}) {
      EXPECT_GT(p.x(), 500000.0 - 1e-6);
      EXPECT_LT(p.x(), 500500.0 + 1e-6);
      EXPECT_GT(p.y(), -1e-6);
      EXPECT_LT(p.y(), 300.0 + 1e-6);
    }
  }
  // Spacing under twice the radius is refused.
  const std::string tight = dir.write(
      "t.yaml",
      "crs: EPSG:32632\nstart: {x: 50, y: -100}\nmanoeuvres:\n"
      "  - survey: {speed_kn: 3, line_spacing_m: 20, area: [{x: 0, y: 0}, {x: 500, y: 0}, {x: 500, y: 300}]}\n");
  try {
    expand_mission(read_mission(tight), {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("twice the turn radius"), std::string::npos) << e.what();
  }
}

TEST(Mission, AGpsUpdateSurfacesAndDivesAndGoingAroundKeepsTheDistance) {
  ScratchDir dir;
  const std::string path = dir.write("m.yaml",
                                     "crs: EPSG:32632\nstart: {x: 0, y: 0, depth_m: 10}\nmanoeuvres:\n"
                                     "  - gps_update: {hold_s: 90, depth_m: 12}\n"
                                     "  - identify: {object: rock, mode: around, distance_m: 25, speed_kn: 2}\n");
  const Mission m = read_mission(path);
  ObstacleSet set;
  set.ellipses.push_back(test::disc(300.0, 0.0, 20.0, "rock"));
  set.ellipses.back().footprint.a = 40.0;  // an ellipse 40 x 20
  const MissionPlan plan = expand_mission(m, set);
  expect_continuous(plan);
  ASSERT_GE(plan.basics.size(), 3u);
  EXPECT_EQ(plan.basics[0].kind, BasicManoeuvre::Kind::point);
  EXPECT_DOUBLE_EQ(plan.basics[0].depth_m, 0.0);
  EXPECT_DOUBLE_EQ(plan.basics[0].hold_s, 90.0);
  EXPECT_DOUBLE_EQ(plan.basics[1].depth_m, 12.0);
  // The approach ends on the path; the lap is arcs (no 72 short lines) that
  // stay within kLapTolerance_m of 25 m from the outline, join without a
  // corner, turn no tighter than the path (b^2/a + D = 35 m) and close.
  const ObstacleField field(set, 0.0);
  EXPECT_NEAR(field.clearance(plan.basics[2].to), 25.0, 1e-6);
  const auto tangent = [](const BasicManoeuvre& b, const Vec2& at) {
    const Vec2 r = (at - b.centre).normalized();
    return Vec2(-b.turn * r.y(), b.turn * r.x());
  };
  double lap_length = 0.0;
  for (std::size_t i = 3; i < plan.basics.size(); ++i) {
    const BasicManoeuvre& b = plan.basics[i];
    ASSERT_EQ(b.kind, BasicManoeuvre::Kind::arc) << i;
    EXPECT_EQ(b.turn, +1) << i;
    EXPECT_GE(b.radius_m, 35.0 - 0.5) << i;
    for (int k = 0; k <= 8; ++k) {
      EXPECT_NEAR(field.clearance(b.point_at(b.length_m * k / 8)), 25.0, kLapTolerance_m) << i;
    }
    if (i > 3) {
      EXPECT_LT((tangent(plan.basics[i - 1], b.from) - tangent(b, b.from)).norm(), 1e-9) << i;
    }
    lap_length += b.length_m;
  }
  EXPECT_LE(plan.basics.size() - 3, 32u);
  EXPECT_LT((plan.basics.back().to - plan.basics[2].to).norm(), 1e-6);  // one closed lap
  // Its length against Steiner's formula: the offset curve of a convex curve
  // at D is as long as the curve plus 2 pi D; the ellipse's perimeter by
  // Ramanujan's second approximation (relative error ~1e-6 for 40 x 20).
  const double h = std::pow((40.0 - 20.0) / (40.0 + 20.0), 2.0);
  const double ellipse = M_PI * (40.0 + 20.0) * (1.0 + 3.0 * h / (10.0 + std::sqrt(4.0 - 3.0 * h)));
  EXPECT_NEAR(lap_length, ellipse + 2.0 * M_PI * 25.0, 0.002 * lap_length);
  // An object that is not there.
  const std::string missing = dir.write("x.yaml", kHeader + "manoeuvres:\n  - identify: {object: nowhere}\n");
  try {
    expand_mission(read_mission(missing), set);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'nowhere'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("line 4"), std::string::npos) << e.what();
  }
}

TEST(Mission, BadFilesAreOneLineNamingThePlace) {
  ScratchDir dir;
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {kHeader + "manoeuvres:\n  - hover: {depth_m: 5}\n", {"line 4", "hover", "track, survey"}},
      {kHeader + "manoeuvres:\n  - survey: {line_spacing_m: 50, area: [{x: 0, y: 0}, {x: 100, y: 100}, "
                 "{x: 100, y: 0}, {x: 0, y: 100}]}\n",
       {"line 4", "area", "simple polygon"}},
      {kHeader + "manoeuvres:\n  - track: {waypoints: [{x: 1, y: 2}\n", {"line", "column", "YAML"}},
      {kHeader + "manoeuvres:\n  - track: {speed_kn: 40, waypoints: [{x: 1, y: 2}]}\n", {"speed_kn", "max_speed"}},
      {kHeader + "manoeuvres:\n  - track: {waypoints: [{x: 1, y: 2}], colour: red}\n", {"colour", "unknown key"}},
      {kHeader + "manoeuvres: []\n", {"manoeuvres", "at least one"}},
      {"start: {x: 1, y: 2}\nmanoeuvres:\n  - goto: {position: {x: 1, y: 2}}\n", {"start", "crs"}},
      {kHeader + "environment: {charts: [nowhere.tif]}\nmanoeuvres:\n  - goto: {position: {x: 1, y: 2}}\n",
       {"nowhere.tif", "existing file"}},
      {kHeader + "manoeuvres:\n  - goto: {position: {x: 1, y: 2}, depth_m: -3}\n", {"depth_m", "positive down"}},
      {kHeader + "manoeuvres:\n  - track: {waypoints: [{x: 1, y: 2}], route_file: r.rtz}\n",
       {"route_file", "one of them", "both"}},
      {kHeader + "manoeuvres:\n  - track: {depth_m: 5}\n", {"waypoints or a route_file", "neither"}},
      {kHeader + "manoeuvres:\n  - track: {route_file: nowhere.rtz}\n", {"nowhere.rtz", "existing"}},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string path = dir.write("bad" + std::to_string(k) + ".yaml", cases[k].first);
    const std::string e = error_of(path);
    EXPECT_EQ(std::count(e.begin(), e.end(), '\n'), 0) << e;
    EXPECT_NE(e.find(path), std::string::npos) << e;
    for (const std::string& w : cases[k].second) EXPECT_NE(e.find(w), std::string::npos) << k << ": " << e;
  }
  EXPECT_NE(error_of(dir.file("missing.yaml")).find("existing mission file"), std::string::npos);
}

TEST(CollisionObservation, ObstaclesAndShoalsOnTheTrackWithWhereTheDangerBegins) {
  ScratchDir dir;
  const std::string path = dir.write("m.yaml",
                                     "crs: EPSG:32632\nstart: {x: 0, y: 0, depth_m: 8}\nmanoeuvres:\n"
                                     "  - track: {depth_m: 8, waypoints: [{x: 400, y: 0}]}\n");
  const Mission m = read_mission(path);
  const MissionPlan plan = expand_mission(m, {});
  ObservationOptions o;  // margin 5 + half width 0.5 (+ 0.1 for arcs' chords): corridor 5.6 m
  // A disc of radius 20 whose centre is 24 m off the track: the track enters the
  // corridor where (x - 200)^2 + 24^2 = 25.6^2, at x = 200 - 8.908.
  ObstacleSet set;
  set.ellipses.push_back(test::disc(200.0, 24.0, 20.0, "rock"));
  std::vector<Conflict> c = observe_collisions(plan, set, nullptr, o);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].with, "rock");
  EXPECT_NEAR(c[0].along_m, 200.0 - std::sqrt(25.6 * 25.6 - 24.0 * 24.0), 1e-6);
  EXPECT_NEAR(c[0].depth_m, 8.0, 1e-9);
  // With its top at 10 m the vehicle at 8 m passes over it (8 <= 10 - 2, just); at 9.5 m it does not.
  set.ellipses[0].top_depth_m = 10.0;
  EXPECT_TRUE(observe_collisions(plan, set, nullptr, o).empty());
  set.ellipses[0].top_depth_m = 9.5;
  EXPECT_EQ(observe_collisions(plan, set, nullptr, o).size(), 1u);
  // A shoal: 12 m deep, 9 m along x = 300 (nodes 50 m apart): the floor is 10 m,
  // 2 m under the vehicle, at x = 250 + 50 * 2 / 3.
  std::vector<double> depths;
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 11; ++i) depths.push_back(i == 6 ? 9.0 : 12.0);
  }
  const SeaFloor floor({-0.0, -100.0}, 50.0, 11, 5, depths);
  c = observe_collisions(plan, {}, &floor, o);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].with, "the sea floor");
  EXPECT_NEAR(c[0].along_m, 250.0 + 50.0 * 2.0 / 3.0, 1e-6);
}

TEST(CollisionObservation, WaypointsOnLandOrInsideAnObstacleAreRefused) {
  ScratchDir dir;
  const std::string path = dir.write("m.yaml",
                                     "crs: EPSG:32632\nstart: {x: 0, y: 0, depth_m: 8}\nmanoeuvres:\n"
                                     "  - track: {depth_m: 8, waypoints: [{x: 100, y: 0}, {x: 200, y: 0}]}\n");
  const Mission m = read_mission(path);
  MissionEnvironment env;
  env.obstacles.ellipses.push_back(test::disc(200.0, 5.0, 10.0, "rock"));
  try {
    check_positions(m, env);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("waypoint 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("inside 'rock'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("line 4"), std::string::npos) << e.what();
  }
  env.obstacles.ellipses[0].top_depth_m = 5.0;  // its top at 5 m: the waypoint at 8 m is still inside it
  EXPECT_THROW(check_positions(m, env), InputError);
  env.obstacles.ellipses[0].top_depth_m = 9.0;  // at 8 m the vehicle is above it
  EXPECT_NO_THROW(check_positions(m, env));
  env.obstacles = {};
  std::vector<double> depths(9, 20.0);
  depths[4] = -3.0;  // land at (100, 0)
  env.floor = std::make_shared<const SeaFloor>(Vec2(50.0, -50.0), 50.0, 3, 3, depths);
  try {
    check_positions(m, env);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("waypoint 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("on land"), std::string::npos) << e.what();
  }
}

TEST(CollisionObservation, ALaterPassByTheSameRockIsAConflictOfItsOwn) {
  // Out 3 km east past a rock and back along the same line: two conflicts.
  ScratchDir dir;
  const std::string path = dir.write("m.yaml",
                                     "crs: EPSG:32632\nstart: {x: 0, y: 0, depth_m: 8}\nmanoeuvres:\n"
                                     "  - track: {depth_m: 8, waypoints: [{x: 3000, y: 0}, {x: 3000, y: 60}, "
                                     "{x: 0, y: 60}]}\n");
  const Mission m = read_mission(path);
  const MissionPlan plan = expand_mission(m, {});
  ObstacleSet set;
  set.ellipses.push_back(test::disc(100.0, 30.0, 26.0, "rock"));  // 4 m from each leg, inside the 5.6 m corridor
  const std::vector<Conflict> c = observe_collisions(plan, set, nullptr, ObservationOptions{});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_LT(c[0].along_m, 200.0);
  EXPECT_GT(c[1].along_m, 5800.0);
  EXPECT_EQ(c[0].obstacle, 0u);
}

TEST(Mission, EdgeCasesTheReviewFound) {
  ScratchDir dir;
  // A tiny line spacing is refused at once (it once made lines until memory ran out).
  const std::string tiny =
      dir.write("t.yaml", kHeader +
                              "manoeuvres:\n  - survey: {line_spacing_m: 1e-300, area: [{x: 500000, y: 6000000}, "
                              "{x: 500500, y: 6000000}, {x: 500500, y: 6000300}]}\n");
  EXPECT_THROW(expand_mission(read_mission(tiny), {}), InputError);
  // A name with a line break stays one line in messages.
  const std::string named =
      dir.write("n.yaml", kHeader + "manoeuvres:\n  - identify: {name: \"two\\nlines\", object: nowhere}\n");
  try {
    expand_mission(read_mission(named), {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
  // A gps_update with nothing under it takes the defaults; turn_radius_m 0 means the vehicle's.
  const std::string bare =
      dir.write("b.yaml", kHeader +
                              "manoeuvres:\n  - gps_update:\n  - survey: {turn_radius_m: 0, line_spacing_m: 100, area: "
                              "[{x: 500000, y: 6000000}, {x: 500500, y: 6000000}, {x: 500500, y: 6000300}]}\n");
  const Mission m = read_mission(bare);
  EXPECT_DOUBLE_EQ(std::get<GpsUpdateSpec>(m.manoeuvres[0].spec).hold_s, 60.0);
  EXPECT_NO_THROW(expand_mission(m, {}));
  // A current that is not SPEED,DIR and a current file that is not there.
  EXPECT_NE(error_of(dir.write("c.yaml", kHeader + "environment: {current: banana}\nmanoeuvres:\n  - gps_update:\n"))
                .find("current"),
            std::string::npos);
  EXPECT_NE(
      error_of(dir.write("f.yaml", kHeader + "environment: {current_file: nope.nc}\nmanoeuvres:\n  - gps_update:\n"))
          .find("existing file"),
      std::string::npos);
  // A missing vehicle file names the mission and the key too.
  const std::string v = error_of(dir.write("v.yaml", kHeader + "vehicle: nope.yaml\nmanoeuvres:\n  - gps_update:\n"));
  EXPECT_NE(v.find("v.yaml"), std::string::npos) << v;
  EXPECT_NE(v.find("'vehicle'"), std::string::npos) << v;
  // Waypoints given as a mapping say so.
  EXPECT_NE(
      error_of(dir.write("w.yaml", kHeader + "manoeuvres:\n  - track: {waypoints: {x: 1, y: 2}}\n")).find("a mapping"),
      std::string::npos);
}

TEST(Mission, ATrackFollowsARouteFileFromAnEcdisOrOpenCpn) {
  // The sample's plan exported as RTZ and GPX, then sailed again as a track read from each file.
  ScratchDir dir;
  const Mission sample = read_mission(deepguide::test::source_file("data/missions/sample_mission.yaml"));
  const MissionPlan plan = expand_mission(sample, load_environment(sample).obstacles);
  export_plan(sample, plan, dir.file("sample.rtz"), ExportFormat::rtz);
  export_plan(sample, plan, dir.file("sample.gpx"), ExportFormat::gpx);
  // RTZ carries each arc as the corners an ECDIS turns it from; GPX as chords.
  for (const char* file : {"sample.rtz", "sample.gpx"}) {
    const std::vector<ExportWaypoint> want =
        std::string(file).ends_with(".rtz") ? export_corner_waypoints(sample, plan) : export_waypoints(sample, plan);
    const std::string path = dir.write(std::string(file) + ".yaml",
                                       "crs: EPSG:32632\nstart: {x: 580700, y: 6033450, depth_m: 0}\nmanoeuvres:\n"
                                       "  - track: {depth_m: 5, route_file: " +
                                           std::string(file) + "}\n");
    const Mission m = read_mission(path);
    const auto& t = std::get<TrackSpec>(m.manoeuvres.at(0).spec);
    ASSERT_EQ(t.waypoints.size(), want.size()) << file;
    for (std::size_t i = 0; i < want.size(); ++i)
      ASSERT_LT((t.waypoints[i] - want[i].xy).norm(), 0.01) << file << " " << i;
  }
}

TEST(Mission, ASecondYamlDocumentIsRefusedNotIgnored) {
  // YAML::Load reads the first document and drops the rest: a mission, scenario, vehicle or suite
  // file with a second one behind `---` is an error naming the line; a trailing empty one is not.
  ScratchDir dir;
  const std::string mission = kHeader + "manoeuvres:\n  - goto: {position: {x: 500100, y: 6000000}}\n";
  EXPECT_NO_THROW(read_mission(dir.write("one.yaml", mission + "---\n")));
  const std::string two = dir.write("two.yaml", mission + "---\nmanoeuvres: []\n");
  const std::string e = error_of(two);
  EXPECT_NE(e.find("line 6"), std::string::npos) << e;
  EXPECT_NE(e.find("one YAML document"), std::string::npos) << e;
  EXPECT_THROW(parse_vehicle_yaml("name: a\n---\nname: b\n", "v.yaml"), InputError);
  EXPECT_THROW(parse_scenario_yaml("start: {x: 0, y: 0}\n---\nstart: {x: 1, y: 1}\n", "s.yaml", "."), InputError);
  std::filesystem::create_directories(dir.path() / "suite");
  dir.write("suite/suite.yaml", "name: s\n---\nname: t\n");
  EXPECT_THROW(read_suite(dir.file("suite")), InputError);
  // A second document after an empty one is still found.
  EXPECT_THROW(read_mission(dir.write("three.yaml", mission + "---\n---\nmanoeuvres: []\n")), InputError);
}

TEST(Mission, AStrayCommaIsOneLineNotAllTheMemory) {
  // yaml-cpp 0.7's LoadAll loops on "," outside a flow collection, adding
  // empty documents until memory runs out (found by fuzz/fuzz_suite_yaml).
  ScratchDir dir;
  // After a document too: the text past the comma was dropped without a word.
  for (const char* text : {", x", ",\n", "# a comment\n, `deepguide evaluate` makes", "{name: a}, {name: b}"}) {
    const std::string path = dir.write("comma.yaml", text);
    const std::string e = error_of(path);
    EXPECT_NE(e.find("comma.yaml"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    EXPECT_THROW(parse_vehicle_yaml(text, "v.yaml"), InputError);
    EXPECT_THROW(parse_scenario_yaml(text, "s.yaml", "."), InputError);
  }
}
