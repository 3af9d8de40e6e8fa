// Mission control (mission/mission_control.hpp) and what it stands on: the
// plan spliced by distance along (mission/plan_splice.hpp), goal points
// before and past a danger (mission/goal_point.hpp), the sea floor's no-go
// polygons (charts/no_go.hpp), and the independent plan checker
// (mission/plan_check.hpp). Evasions are measured against the hand-derived
// shortest way round a disc; unavoidable conflicts are kept with why.
#include <gtest/gtest.h>

#include <boost/geometry.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "deepguide/charts/no_go.hpp"
#include "deepguide/mission/evasion_planner.hpp"
#include "deepguide/mission/goal_point.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/mission/plan_check.hpp"
#include "deepguide/mission/plan_splice.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

Mission mission_from(ScratchDir& dir, const std::string& body) {
  return read_mission(dir.write("m.yaml", "crs: EPSG:32632\nstart: {x: 0, y: 0, depth_m: 8}\n" + body));
}

void expect_continuous(const MissionPlan& plan) {
  double along = 0.0;
  for (std::size_t i = 0; i < plan.basics.size(); ++i) {
    const BasicManoeuvre& b = plan.basics[i];
    if (i > 0) {
      ASSERT_LT((b.from - plan.basics[i - 1].to).norm(), 1e-6) << i;
      ASSERT_NEAR(b.from_depth_m, plan.basics[i - 1].depth_m, 1e-9) << i;
    }
    ASSERT_NEAR(b.start_m, along, 1e-6) << i;
    if (b.kind == BasicManoeuvre::Kind::line) {
      ASSERT_NEAR(b.length_m, (b.to - b.from).norm(), 1e-6) << i;
    }
    along += b.length_m;
  }
  EXPECT_NEAR(plan.length_m, along, 1e-6);
}

// The shortest way from a to b round a disc (centre c, radius r) that blocks the straight line.
double around_disc(const Vec2& a, const Vec2& b, const Vec2& c, double r) {
  const double da = (a - c).norm(), db = (b - c).norm();
  const double ta = std::sqrt(da * da - r * r), tb = std::sqrt(db * db - r * r);
  const double between = std::acos((a - c).dot(b - c) / (da * db));
  const double arc = between - std::acos(r / da) - std::acos(r / db);
  return ta + tb + r * arc;
}

}  // namespace

TEST(PlanSplice, AStretchIsReplacedAndTheRestRenumbered) {
  ScratchDir dir;
  // East 400 m at 8 m, then a GPS fix, then east another 200 m at 12 m.
  const Mission m = mission_from(dir,
                                 "manoeuvres:\n  - track: {depth_m: 8, speed_mps: 2, waypoints: [{x: 400, y: 0}]}\n"
                                 "  - gps_update: {hold_s: 100, depth_m: 12}\n"
                                 "  - goto: {speed_mps: 2, position: {x: 600, y: 0}}\n");
  const MissionPlan plan = expand_mission(m, {});
  ASSERT_EQ(plan.basics.size(), 4u);  // line, point (surface), point (dive), line
  const PlanPosition p = position_at(plan, 100.0);
  EXPECT_LT((p.xy - Vec2(100.0, 0.0)).norm(), 1e-9);
  EXPECT_NEAR(p.time_s, 50.0, 1e-9);
  // Past the hold: 400 m / 2 m/s + 100 s + 50 m / 2 m/s.
  const PlanPosition q = position_at(plan, 450.0);
  EXPECT_NEAR(q.time_s, 200.0 + 100.0 + 25.0, 1e-9);
  EXPECT_NEAR(q.depth_m, 12.0, 1e-9);
  EXPECT_TRUE(holds_within(plan, 300.0, 500.0));
  EXPECT_FALSE(holds_within(plan, 100.0, 300.0));
  EXPECT_FALSE(holds_within(plan, 100.0, 400.0));  // the hold at 400 is at the stretch's end: kept

  // Replace [100, 300] by a detour through (200, 50): 2 * sqrt(100^2 + 50^2).
  BasicManoeuvre a, b;
  a.from = {100.0, 0.0};
  a.to = {200.0, 50.0};
  b.from = a.to;
  b.to = {300.0, 0.0};
  a.from_depth_m = a.depth_m = b.from_depth_m = b.depth_m = 8.0;
  a.length_m = b.length_m = std::hypot(100.0, 50.0);
  a.role = b.role = BasicManoeuvre::Role::evasion;
  const MissionPlan spliced = splice_plan(plan, 100.0, 300.0, {a, b});
  expect_continuous(spliced);
  EXPECT_NEAR(spliced.length_m, plan.length_m - 200.0 + 2.0 * std::hypot(100.0, 50.0), 1e-9);
  ASSERT_EQ(spliced.basics.size(), 7u);  // line to 100, two evasion lines, line to 400, two points, line
  EXPECT_EQ(spliced.basics[1].role, BasicManoeuvre::Role::evasion);
  EXPECT_EQ(spliced.basics[3].role, BasicManoeuvre::Role::mission);
  EXPECT_LT((spliced.basics[3].from - Vec2(300.0, 0.0)).norm(), 1e-9);
  EXPECT_DOUBLE_EQ(spliced.basics[4].hold_s, 100.0);

  // A line that changes depth, and an arc, cut part-way.
  const Mission turn =
      mission_from(dir, "manoeuvres:\n  - track: {depth_m: 20, waypoints: [{x: 400, y: 0}, {x: 400, y: 400}]}\n");
  const MissionPlan round = expand_mission(turn, {});
  ASSERT_EQ(round.basics.size(), 3u);
  const double r = round.basics[1].radius_m;
  // The first line descends from 8 m to 20 m over 400 - r metres: at 100 m it is 8 + 12 * 100 / (400 - r).
  EXPECT_NEAR(position_at(round, 100.0).depth_m, 8.0 + 12.0 * 100.0 / (400.0 - r), 1e-9);
  const double mid_arc = round.basics[1].start_m + 0.5 * round.basics[1].length_m;
  BasicManoeuvre c;
  c.from = position_at(round, 100.0).xy;
  c.to = position_at(round, mid_arc).xy;
  c.from_depth_m = position_at(round, 100.0).depth_m;
  c.depth_m = 20.0;
  c.length_m = (c.to - c.from).norm();
  const MissionPlan cut = splice_plan(round, 100.0, mid_arc, {c});
  expect_continuous(cut);
  ASSERT_EQ(cut.basics.size(), 4u);
  EXPECT_EQ(cut.basics[2].kind, BasicManoeuvre::Kind::arc);
  EXPECT_NEAR(cut.basics[2].length_m, 0.5 * round.basics[1].length_m, 1e-9);
  EXPECT_NEAR((cut.basics[2].from - cut.basics[2].centre).norm(), r, 1e-9);
}

TEST(GoalPoints, LeadBeforeAndPastTheDangerRunsJoinedWithinTheLead) {
  ScratchDir dir;
  const Mission m = mission_from(dir, "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 1000, y: 0}]}\n");
  const MissionPlan plan = expand_mission(m, {});
  ObstacleSet set;
  set.ellipses.push_back(test::disc(500.0, 0.0, 20.0, "rock"));
  const auto stretch_for = [&](const ObstacleSet& s, double lead) {
    const ObstacleField field(s, 5.7);
    const WaterVolume volume(field, nullptr, {2.0, 0.0, std::numeric_limits<double>::infinity()});
    const TrackDanger danger = track_danger(plan, volume, 2.0);
    return goal_points(danger, 500.0 - 25.7, lead, 0.0);
  };
  // The zone (radius 25.7) covers x in [474.3, 525.7]; pieces are 2 m.
  auto s = stretch_for(set, 50.0);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->depart_m, 474.0 - 50.0, 1e-9);
  EXPECT_NEAR(s->rendezvous_m, 526.0 + 50.0, 1e-9);
  // A second rock 48.6 m past the first zone's end: one run.
  set.ellipses.push_back(test::disc(600.0, 0.0, 20.0, "rock 2"));
  s = stretch_for(set, 50.0);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->rendezvous_m, 626.0 + 50.0, 1e-9);
  // With a lead of 40 m they are two runs.
  s = stretch_for(set, 40.0);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->rendezvous_m, 526.0 + 40.0, 1e-9);
  // A rock at the mission's end: nothing to rejoin.
  ObstacleSet end;
  end.ellipses.push_back(test::disc(1010.0, 0.0, 5.0, "at the end"));
  const ObstacleField field(end, 5.7);
  const WaterVolume volume(field, nullptr, {2.0, 0.0, std::numeric_limits<double>::infinity()});
  std::string why;
  EXPECT_FALSE(goal_points(track_danger(plan, volume, 2.0), 1010.0 - 10.7, 50.0, 0.0, &why));
  EXPECT_NE(why.find("mission's end"), std::string::npos) << why;
}

TEST(NoGo, TheSeaFloorsShallowCellsBecomePolygons) {
  // Nodes 50 m apart, 12 m deep except the column x = 300 at 9 m: at 8 m
  // with 2 m clearance (10 m) the cells either side of it, x in [250, 350],
  // are no-go over the grid's 200 m height.
  std::vector<double> depths;
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 11; ++i) depths.push_back(i == 6 ? 9.0 : 12.0);
  }
  const SeaFloor floor({0.0, -100.0}, 50.0, 11, 5, depths);
  NoGoOptions o;
  o.operating_depth_m = 8.0;
  o.vertical_clearance_m = 2.0;
  o.simplify_tolerance_m = 0.0;
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  NoGoArea area = compute_no_go(floor, frame, o);
  ASSERT_EQ(area.polygons.size(), 1u);
  EXPECT_NEAR(area.area_m2, 100.0 * 200.0, 1e-6);
  EXPECT_EQ(area.no_go_cells, 8u);
  EXPECT_TRUE(boost::geometry::within(to_bg(Vec2(300.0, 0.0)), area.polygons[0].footprint));
  EXPECT_FALSE(boost::geometry::within(to_bg(Vec2(240.0, 0.0)), area.polygons[0].footprint));
  // At 7 m (9 m needed) the floor is deep enough everywhere.
  o.operating_depth_m = 7.0;
  EXPECT_TRUE(compute_no_go(floor, frame, o).polygons.empty());
  o.operating_depth_m = -1.0;
  EXPECT_THROW(compute_no_go(floor, frame, o), InputError);
}

TEST(MissionControl, ARockOnTheTrackIsEvadedTheShortestWayRound) {
  ScratchDir dir;
  const Mission m = mission_from(dir, "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 1000, y: 0}]}\n");
  MissionEnvironment env;
  env.obstacles.ellipses.push_back(test::disc(500.0, 10.0, 20.0, "rock"));
  const MissionPlan initial = expand_mission(m, env.obstacles);
  ASSERT_EQ(observe_collisions(initial, env.obstacles, nullptr, observation_options(m)).size(), 1u);
  const PlannedMission planned = plan_mission(m, env, initial);
  ASSERT_EQ(planned.resolutions.size(), 1u);
  const Resolution& r = planned.resolutions[0];
  ASSERT_TRUE(r.resolved) << r.problem;
  EXPECT_EQ(r.reaction, ControlRules::Reaction::evade);
  EXPECT_TRUE(planned.remaining.empty());
  expect_continuous(planned.plan);
  const MissionPlanCheck verdict = check_mission_plan(planned.plan, env, observation_options(m));
  EXPECT_TRUE(verdict.safe) << verdict.problem;
  // The evasion is within 0.5 % of the shortest way round the zone (radius
  // 20 + 5 + 0.5 + 0.2), and no shorter.
  const double rendezvous = r.rendezvous_m - r.added_m;
  const double best = around_disc({r.depart_m, 0.0}, {rendezvous, 0.0}, {500.0, 10.0}, 25.7);
  const double evasion = r.rendezvous_m - r.depart_m;
  EXPECT_GE(evasion, best - 1e-6);
  EXPECT_LE(evasion, best * 1.005);
  EXPECT_NEAR(planned.plan.length_m, 1000.0 + r.added_m, 1e-6);
  // It goes round the far side from the centre (y < 0) and only evasion lines replace the stretch.
  bool evaded = false;
  for (const BasicManoeuvre& b : planned.plan.basics) {
    if (b.role != BasicManoeuvre::Role::evasion) continue;
    evaded = true;
    EXPECT_LE(b.to.y(), 1e-9);
    EXPECT_DOUBLE_EQ(b.depth_m, 8.0);
  }
  EXPECT_TRUE(evaded);
  // The checker is not blind: the original plan fails it where the rock is.
  const MissionPlanCheck before = check_mission_plan(initial, env, observation_options(m));
  EXPECT_FALSE(before.safe);
  EXPECT_NEAR(before.where.x(), 500.0, 30.0);
}

TEST(MissionControl, ARockToIdentifyIsGoneRoundAtTheIdentificationDistance) {
  ScratchDir dir;
  const Mission m = mission_from(dir,
                                 "control: {identify: [rock], identify_distance_m: 30}\n"
                                 "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 1000, y: 0}]}\n");
  ASSERT_EQ(m.control.identify.size(), 1u);
  MissionEnvironment env;
  env.obstacles.ellipses.push_back(test::disc(500.0, 10.0, 20.0, "rock"));
  const PlannedMission planned = plan_mission(m, env, expand_mission(m, env.obstacles));
  ASSERT_EQ(planned.resolutions.size(), 1u);
  ASSERT_TRUE(planned.resolutions[0].resolved) << planned.resolutions[0].problem;
  EXPECT_EQ(planned.resolutions[0].reaction, ControlRules::Reaction::identify);
  EXPECT_TRUE(planned.remaining.empty());
  expect_continuous(planned.plan);
  // Round a disc the path is a circle, and its biarcs are that circle: 8 arcs
  // of radius 50 m about the rock's centre, one lap.
  std::size_t lap = 0;
  double swept = 0.0;
  for (const BasicManoeuvre& b : planned.plan.basics) {
    if (b.role != BasicManoeuvre::Role::identification) continue;
    ++lap;
    ASSERT_EQ(b.kind, BasicManoeuvre::Kind::arc);
    EXPECT_NEAR(b.radius_m, 50.0, 1e-6);
    EXPECT_LT((b.centre - Vec2(500.0, 10.0)).norm(), 1e-6);
    EXPECT_NEAR((b.to - Vec2(500.0, 10.0)).norm(), 50.0, 1e-6);
    swept += b.length_m / b.radius_m;
  }
  EXPECT_EQ(lap, 8u);
  EXPECT_NEAR(swept, 2.0 * M_PI, 1e-6);
  EXPECT_TRUE(check_mission_plan(planned.plan, env, observation_options(m)).safe);
  // A rule naming an object that is not an elliptic cylinder (or the sea floor) evades.
  EXPECT_EQ(choose_reaction(m.control, env.obstacles, 0), ControlRules::Reaction::identify);
  ObstacleSet boxes;
  boxes.polygons.push_back(test::box(0, 0, 1, 1, "rock"));
  EXPECT_EQ(choose_reaction(m.control, boxes, 0), ControlRules::Reaction::evade);
}

TEST(MissionControl, ConflictsThatCannotBeResolvedAreKeptWithWhy) {
  ScratchDir dir;
  // The start is walled in by four overlapping boxes: no way out.
  const Mission m = mission_from(dir, "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 400, y: 0}]}\n");
  MissionEnvironment env;
  env.obstacles.polygons.push_back(test::box(100, -120, 120, 120, "east"));
  env.obstacles.polygons.push_back(test::box(-120, -120, -100, 120, "west"));
  env.obstacles.polygons.push_back(test::box(-120, 100, 120, 120, "north"));
  env.obstacles.polygons.push_back(test::box(-120, -120, 120, -100, "south"));
  const PlannedMission walled = plan_mission(m, env, expand_mission(m, env.obstacles));
  ASSERT_EQ(walled.resolutions.size(), 1u);
  EXPECT_FALSE(walled.resolutions[0].resolved);
  EXPECT_EQ(walled.resolutions[0].conflict.with, "east");
  EXPECT_NE(walled.resolutions[0].problem.find("no safe route"), std::string::npos) << walled.resolutions[0].problem;
  EXPECT_FALSE(walled.remaining.empty());
  EXPECT_FALSE(check_mission_plan(walled.plan, env, observation_options(m)).safe);
  // A rock by the mission's end: nothing past it to rejoin.
  MissionEnvironment end;
  end.obstacles.ellipses.push_back(test::disc(410.0, 0.0, 5.0, "rock"));
  const PlannedMission last = plan_mission(m, end, expand_mission(m, end.obstacles));
  ASSERT_EQ(last.resolutions.size(), 1u);
  EXPECT_FALSE(last.resolutions[0].resolved);
  EXPECT_NE(last.resolutions[0].problem.find("mission's end"), std::string::npos) << last.resolutions[0].problem;
}

TEST(MissionControl, ControlRulesAreCheckedWhenRead) {
  ScratchDir dir;
  const auto error = [&](const std::string& control) {
    try {
      mission_from(dir, control + "manoeuvres:\n  - goto: {position: {x: 10, y: 0}}\n");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no InputError");
  };
  EXPECT_NE(error("control: {unknown_objects: flee}\n").find("evade or identify"), std::string::npos);
  EXPECT_NE(error("control: {identify_distance_m: 3}\n").find("identify_distance_m"), std::string::npos);
  EXPECT_NE(error("control: {identify: rock}\n").find("list of obstacle ids"), std::string::npos);
  EXPECT_NE(error("control: {evade: all}\n").find("line 3"), std::string::npos);
}

TEST(GoalPoints, NeverBeforeTheLastEvasionAndNeverAGuess) {
  ScratchDir dir;
  const Mission m = mission_from(dir, "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 1000, y: 0}]}\n");
  const MissionPlan plan = expand_mission(m, {});
  ObstacleSet set;
  set.ellipses.push_back(test::disc(500.0, 0.0, 20.0, "rock"));
  const ObstacleField field(set, 5.7);
  const WaterVolume volume(field, nullptr, {2.0, 0.0, std::numeric_limits<double>::infinity()});
  const TrackDanger danger = track_danger(plan, volume, 2.0);
  const auto s = goal_points(danger, 474.3, 50.0, 450.0);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->depart_m, 450.0, 1e-9);
  // Where the scan sees no danger it does not invent a stretch.
  std::string why;
  EXPECT_FALSE(goal_points(danger, 100.0, 50.0, 0.0, &why));
  EXPECT_NE(why.find("finds nothing"), std::string::npos) << why;
}

TEST(NoGo, TheSeaFloorsRowsAreNotFlipped) {
  // 12 m everywhere but the northern row of nodes (y = 100) at 9 m: at 8 m
  // (10 m needed) only the northern row of cells, y in [50, 100], is no-go.
  std::vector<double> depths;
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 11; ++i) depths.push_back(j == 4 ? 9.0 : 12.0);
  }
  const SeaFloor floor({0.0, -100.0}, 50.0, 11, 5, depths);
  NoGoOptions o;
  o.operating_depth_m = 8.0;
  o.simplify_tolerance_m = 0.0;
  const NoGoArea area = compute_no_go(floor, LocalFrame::from_user_crs("EPSG:32632"), o);
  ASSERT_EQ(area.polygons.size(), 1u);
  EXPECT_NEAR(area.area_m2, 500.0 * 50.0, 1e-6);
  EXPECT_TRUE(boost::geometry::within(to_bg(Vec2(250.0, 75.0)), area.polygons[0].footprint));
  EXPECT_FALSE(boost::geometry::within(to_bg(Vec2(250.0, 25.0)), area.polygons[0].footprint));
}

TEST(MissionControl, AnObjectToIdentifyWhoseDangerJoinsAnEvasionIsSaidSo) {
  ScratchDir dir;
  const Mission m = mission_from(dir,
                                 "control: {identify: [wreck]}\n"
                                 "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 1000, y: 0}]}\n");
  MissionEnvironment env;
  // Zones of radius 15.7 m, 38.6 m apart: closer than the lead (2 x 23.6 + 5.7 m), one stretch.
  env.obstacles.ellipses.push_back(test::disc(450.0, 0.0, 10.0, "rock"));
  env.obstacles.ellipses.push_back(test::disc(520.0, 0.0, 10.0, "wreck"));
  const PlannedMission planned = plan_mission(m, env, expand_mission(m, env.obstacles));
  ASSERT_EQ(planned.resolutions.size(), 2u);
  EXPECT_EQ(planned.resolutions[0].conflict.with, "rock");
  EXPECT_TRUE(planned.resolutions[0].resolved);
  EXPECT_EQ(planned.resolutions[1].conflict.with, "wreck");
  EXPECT_TRUE(planned.resolutions[1].resolved);
  EXPECT_NE(planned.resolutions[1].note.find("to identify, but evaded with rock"), std::string::npos)
      << planned.resolutions[1].note;
  EXPECT_TRUE(planned.remaining.empty());
  EXPECT_TRUE(check_mission_plan(planned.plan, env, observation_options(m)).safe);
}

TEST(MissionControl, AShoalIsEvadedAroundTheSeaFloorsNoGoCells) {
  ScratchDir dir;
  const Mission m = mission_from(dir, "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 1000, y: 0}]}\n");
  // 12 m deep, 6 m at the node (500, 0): the cells round it, x in [450, 550]
  // and y in [-50, 50], are too shallow for 8 m + 2 m.
  std::vector<double> depths;
  for (int j = 0; j < 9; ++j) {
    for (int i = 0; i < 21; ++i) depths.push_back(i == 10 && j == 4 ? 6.0 : 12.0);
  }
  MissionEnvironment env;
  env.floor = std::make_shared<const SeaFloor>(Vec2(0.0, -200.0), 50.0, 21, 9, depths);
  const MissionPlan written = expand_mission(m, env.obstacles);
  ASSERT_EQ(observe_collisions(written, {}, env.floor.get(), observation_options(m)).size(), 1u);
  EXPECT_FALSE(check_mission_plan(written, env, observation_options(m)).safe);
  const PlannedMission planned = plan_mission(m, env, written);
  ASSERT_EQ(planned.resolutions.size(), 1u);
  ASSERT_TRUE(planned.resolutions[0].resolved) << planned.resolutions[0].problem;
  EXPECT_EQ(planned.resolutions[0].conflict.with, "the sea floor");
  EXPECT_TRUE(planned.remaining.empty());
  const MissionPlanCheck verdict = check_mission_plan(planned.plan, env, observation_options(m));
  EXPECT_TRUE(verdict.safe) << verdict.problem;
  EXPECT_GE(verdict.min_floor_gap_m, 2.0 - 1e-6);
  // Abeam of the shoal the evasion is outside the no-go box and its zone.
  int abeam = 0;
  const std::vector<TrackPoint> track = plan_polyline(planned.plan);
  for (std::size_t k = 1; k < track.size(); ++k) {
    const Vec2 a = track[k - 1].xy, b = track[k].xy;
    if ((a.x() - 500.0) * (b.x() - 500.0) > 0.0 || a.x() == b.x()) continue;
    ++abeam;
    const double y = a.y() + (b.y() - a.y()) * (500.0 - a.x()) / (b.x() - a.x());
    EXPECT_GE(std::abs(y), 50.0 + 5.7 - 1e-6) << a.transpose() << " -> " << b.transpose();
  }
  EXPECT_EQ(abeam, 1);
}

TEST(PlanCheck, ACurrentStrongerThanTheVehicleFailsTheLegsItBeats) {
  // East 100 m, then north 100 m, at 2 m/s through the water.
  MissionPlan plan;
  BasicManoeuvre east;
  east.to = Vec2(100.0, 0.0);
  east.speed_mps = 2.0;
  east.length_m = 100.0;
  BasicManoeuvre north = east;
  north.from = east.to;
  north.to = Vec2(100.0, 100.0);
  north.start_m = 100.0;
  plan.basics = {east, north};
  plan.length_m = 200.0;
  // 2.5 m/s north: no heading holds the east leg (|d x c| = 2.5 > 2); north is a following current.
  std::vector<BeatenLeg> beaten = legs_beaten_by_current(plan, {0.0, 2.5});
  ASSERT_EQ(beaten.size(), 1u);
  EXPECT_EQ(beaten[0].basic, 0u);
  EXPECT_NEAR(beaten[0].along_m, 0.0, 1e-9);
  // 2.5 m/s south: the east leg again, and the north leg goes backwards (s = 2 - 2.5 < 0).
  beaten = legs_beaten_by_current(plan, {0.0, -2.5});
  ASSERT_EQ(beaten.size(), 2u);
  EXPECT_EQ(beaten[1].basic, 1u);
  EXPECT_NEAR(beaten[1].along_m, 100.0, 1e-9);
  // 1.9 m/s across, or 1.4 m/s diagonally: held (crabbing).
  EXPECT_TRUE(legs_beaten_by_current(plan, {0.0, 1.9}).empty());
  EXPECT_TRUE(legs_beaten_by_current(plan, {1.0, -1.0}).empty());
  EXPECT_TRUE(legs_beaten_by_current(plan, {0.0, 0.0}).empty());
  // The plan checker fails the plan there, saying why.
  MissionEnvironment env;
  env.current = Vec2(0.0, -2.5);
  ScratchDir dir;
  const Mission m = mission_from(dir, "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 100, y: 0}]}\n");
  const MissionPlanCheck verdict = check_mission_plan(plan, env, observation_options(m));
  EXPECT_FALSE(verdict.safe);
  EXPECT_EQ(verdict.basic, 0u);
  EXPECT_NE(verdict.problem.find("the 2.50 m/s current beats the vehicle's 2.00 m/s"), std::string::npos)
      << verdict.problem;
  EXPECT_NE(verdict.problem.find("2 basic manoeuvre(s)"), std::string::npos) << verdict.problem;
  env.current = Vec2(0.0, 1.9);
  EXPECT_TRUE(check_mission_plan(plan, env, observation_options(m)).safe);
}

TEST(PlanCheck, TheMissionsCurrentIsTurnedIntoTheLocalFrame) {
  ScratchDir dir;
  const Mission m = mission_from(dir,
                                 "environment: {current: '3,90'}\n"
                                 "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 100, y: 0}]}\n");
  const Vec2 c = constant_current(m);
  EXPECT_NEAR(c.norm(), 3.0, 1e-9);
  // Towards true east; the grid is turned from true north by the convergence at the start.
  const Vec2 true_east = m.frame.from_lonlat(m.frame.to_lonlat(m.start) + Vec2(1e-4, 0.0)) - m.start;
  EXPECT_NEAR(std::atan2(c.y(), c.x()), std::atan2(true_east.y(), true_east.x()), 1e-3);
}

TEST(MissionControl, TheEvasionGraphIsReadAndAWrongOneNamed) {
  ScratchDir dir;
  const std::string track = "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 1000, y: 0}]}\n";
  EXPECT_EQ(mission_from(dir, track).control.evasion_graph, GraphKind::visibility);
  EXPECT_EQ(mission_from(dir, "control: {evasion_graph: navmesh}\n" + track).control.evasion_graph,
            GraphKind{"navmesh"});
  try {
    mission_from(dir, "control: {evasion_graph: tangent}\n" + track);
    ADD_FAILURE() << "a tangent evasion graph was taken";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("control.evasion_graph"), std::string::npos) << what;
    EXPECT_NE(what.find("visibility, visibility-full or navmesh"), std::string::npos) << what;
    EXPECT_NE(what.find("'tangent'"), std::string::npos) << what;
  }
}

TEST(MissionControl, EvasionsOnAKeptMeshEqualTheVisibilityGraphsAndTakeNewRocksWithoutARebuild) {
  ScratchDir dir;
  const std::string track = "manoeuvres:\n  - track: {depth_m: 8, waypoints: [{x: 1000, y: 0}]}\n";
  const Mission vis = mission_from(dir, track);
  const Mission mesh = mission_from(dir, "control: {evasion_graph: navmesh}\n" + track);
  MissionEnvironment env;
  env.obstacles.ellipses.push_back(test::disc(300.0, 10.0, 20.0, "rock"));
  env.obstacles.ellipses.push_back(test::disc(700.0, -12.0, 15.0, "wreck"));
  const MissionPlan initial = expand_mission(vis, env.obstacles);
  const PlannedMission a = plan_mission(vis, env, initial);
  const PlannedMission b = plan_mission(mesh, env, initial);
  ASSERT_EQ(a.resolutions.size(), 2u);
  ASSERT_EQ(b.resolutions.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_TRUE(b.resolutions[i].resolved) << b.resolutions[i].problem;
    EXPECT_NEAR(b.resolutions[i].added_m, a.resolutions[i].added_m, 1e-6) << i;
  }
  EXPECT_TRUE(b.remaining.empty());
  const MissionPlanCheck verdict = check_mission_plan(b.plan, env, observation_options(mesh));
  EXPECT_TRUE(verdict.safe) << verdict.problem;

  // A rock found later goes into the kept mesh; the route round all three
  // is as long as that of a planner given all three from the start, and of
  // the visibility graph's.
  EvasionPlanner kept(mesh, env);
  std::string problem;
  const std::vector<Vec2> first = kept.route(8.0, {0, 0}, {1000, 0}, problem);
  ASSERT_FALSE(first.empty()) << problem;
  ObstacleSet found;
  found.ellipses.push_back(test::disc(500.0, 4.0, 18.0, "found"));
  kept.add(found);
  EXPECT_EQ(kept.environment().obstacles.ellipses.size(), 3u);
  EXPECT_FALSE(kept.free_at(8.0, {500.0, 4.0 + 18.0 + 5.0}));
  const std::vector<Vec2> again = kept.route(8.0, {0, 0}, {1000, 0}, problem);
  ASSERT_FALSE(again.empty()) << problem;
  MissionEnvironment all = env;
  all.obstacles.ellipses.push_back(found.ellipses.front());
  EvasionPlanner fresh(mesh, all), visibility(vis, all);
  const double want = Route{fresh.route(8.0, {0, 0}, {1000, 0}, problem)}.length();
  EXPECT_NEAR(Route{again}.length(), want, 1e-9 * want);
  EXPECT_NEAR(Route{visibility.route(8.0, {0, 0}, {1000, 0}, problem)}.length(), want, 1e-6 * want);
  EXPECT_GT(Route{again}.length(), Route{first}.length() + 1.0);
  EXPECT_TRUE(check_route(again, ObstacleField(all.obstacles, kept.zone_margin())).safe);
}
