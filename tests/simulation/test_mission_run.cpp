// The two-level guidance of a mission in simulation (simulation/mission_run.hpp):
// a clear track is sailed in its planned time and length; a hold adds its
// time; an object nobody knew is found by the sonar, the reactive level takes
// over while the evasion is planned, and the vehicle passes it without
// touching it; an object that leaves no way on raises an alarm; the same seed
// gives the same run.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "deepguide/simulation/mission_run.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

Mission mission_from(ScratchDir& dir, const std::string& manoeuvres) {
  return read_mission(
      dir.write("m.yaml", "crs: EPSG:32632\nstart: {x: 0, y: 0, depth_m: 8}\nmanoeuvres:\n" + manoeuvres));
}

bool has_event(const MissionRun& run, const std::string& text) {
  for (const MissionEvent& e : run.events) {
    if (e.what.find(text) != std::string::npos) return true;
  }
  return false;
}

}  // namespace

TEST(MissionRun, AClearTrackIsSailedInItsTimeAndAHoldAddsItsOwn) {
  ScratchDir dir;
  const Mission m = mission_from(dir, "  - track: {depth_m: 8, speed_mps: 2, waypoints: [{x: 1000, y: 0}]}\n");
  const MissionPlan plan = expand_mission(m, {});
  const MissionRun run = run_mission(m, {}, plan, {});
  ASSERT_TRUE(run.completed);
  EXPECT_FALSE(run.collided);
  EXPECT_EQ(run.replans, 0u);
  // 995 m (it ends 5 m short of the end) at 2 m/s, from the plan's speed at the start.
  EXPECT_NEAR(run.length_m, 995.0, 5.0);
  EXPECT_NEAR(run.time_s, 995.0 / 2.0, 10.0);
  for (const MissionSample& s : run.track) EXPECT_LT(std::abs(s.position.y()), 0.5) << s.time_s;

  const Mission fix = mission_from(dir,
                                   "  - track: {depth_m: 8, speed_mps: 2, waypoints: [{x: 500, y: 0}]}\n"
                                   "  - gps_update: {hold_s: 100}\n"
                                   "  - goto: {speed_mps: 2, position: {x: 1000, y: 0}}\n");
  const MissionRun held = run_mission(fix, {}, expand_mission(fix, {}), {});
  ASSERT_TRUE(held.completed);
  EXPECT_NEAR(held.time_s, run.time_s + 100.0, 2.0);
  EXPECT_TRUE(has_event(held, "hold 100 s"));
}

TEST(MissionRun, AnObjectNobodyKnewIsFoundAndPassedWhileTheRouteIsRepaired) {
  ScratchDir dir;
  const Mission m = mission_from(dir, "  - track: {depth_m: 8, speed_mps: 2, waypoints: [{x: 1000, y: 0}]}\n");
  const MissionPlan plan = expand_mission(m, {});
  ObstacleSet unknown;
  unknown.ellipses.push_back(test::disc(500.0, 0.0, 6.0, "container"));
  const MissionRun run = run_mission(m, {}, plan, unknown);
  ASSERT_TRUE(run.completed);
  EXPECT_FALSE(run.collided);
  EXPECT_EQ(run.detected.size(), 1u);
  EXPECT_EQ(run.replans, 1u);
  EXPECT_TRUE(has_event(run, "on no chart"));
  EXPECT_TRUE(has_event(run, "the reactive level takes over"));
  EXPECT_TRUE(has_event(run, "spliced in"));
  // Found within the sonar's 120 m range, before the zone.
  EXPECT_GT(run.events.front().where.x(), 500.0 - 130.0);
  EXPECT_LT(run.events.front().where.x(), 500.0 - 6.0 - 5.5);
  // It keeps clear of the object's footprint by most of the margin.
  EXPECT_GT(run.min_clearance_m, 3.0);
  bool abeam = false;
  for (const MissionSample& s : run.track) {
    if (std::abs(s.position.x() - 500.0) < 3.0) {
      abeam = true;
      EXPECT_GT(std::abs(s.position.y()), 6.0 + 3.0) << s.time_s;
    }
  }
  EXPECT_TRUE(abeam);
  bool reactive = false;
  for (const MissionSample& s : run.track) reactive = reactive || s.reactive;
  EXPECT_TRUE(reactive);
  // The same seed, the same run.
  const MissionRun again = run_mission(m, {}, plan, unknown);
  EXPECT_DOUBLE_EQ(again.time_s, run.time_s);
  EXPECT_DOUBLE_EQ(again.length_m, run.length_m);
}

TEST(MissionRun, AnObjectThatLeavesNoWayOnRaisesTheAlarm) {
  ScratchDir dir;
  const Mission m = mission_from(dir, "  - track: {depth_m: 8, speed_mps: 2, waypoints: [{x: 600, y: 0}]}\n");
  ObstacleSet unknown;
  unknown.ellipses.push_back(test::disc(610.0, 0.0, 30.0, "over the end"));
  MissionRunOptions options;
  options.max_time_s = 900.0;
  const MissionRun run = run_mission(m, {}, expand_mission(m, {}), unknown, options);
  EXPECT_FALSE(run.completed);
  bool alarm = false;
  for (const MissionEvent& e : run.events) alarm = alarm || e.alarm;
  EXPECT_TRUE(alarm);
  EXPECT_TRUE(has_event(run, "no evasion could be planned"));
}

TEST(MissionRun, ObjectsNearAheadOrLongAreEvadedNotHit) {
  ScratchDir dir;
  const Mission m = mission_from(dir, "  - track: {depth_m: 8, speed_mps: 2, waypoints: [{x: 1000, y: 0}]}\n");
  const MissionPlan plan = expand_mission(m, {});
  // 40 m ahead at the start: too near for the planner, the reactive level alone.
  ObstacleSet near;
  near.ellipses.push_back(test::disc(40.0, 0.0, 5.0, "near"));
  const MissionRun a = run_mission(m, {}, plan, near);
  EXPECT_TRUE(a.completed);
  EXPECT_FALSE(a.collided);
  EXPECT_GT(a.min_clearance_m, 0.0);
  // A 45 m x 5 m object lying along the track: the rendezvous is past its end.
  ObstacleSet along;
  EllipticCylinder log;
  log.id = "log";
  log.footprint = Ellipse{{500.0, 0.0}, 45.0, 5.0, 0.0};
  along.ellipses.push_back(log);
  const MissionRun b = run_mission(m, {}, plan, along);
  EXPECT_TRUE(b.completed) << (b.events.empty() ? "" : b.events.back().what);
  EXPECT_FALSE(b.collided);
  // Another seed, another sonar noise: the estimate (and so the run) differs.
  MissionRunOptions other;
  other.seed = 7;
  const MissionRun c = run_mission(m, {}, plan, along, other);
  ASSERT_EQ(c.detected.size(), 1u);
  EXPECT_NE(c.detected.ellipses[0].footprint.centre, b.detected.ellipses[0].footprint.centre);
}

TEST(MissionRun, ThePlanLevelKeepsToTheLapsArcs) {
  // A lap of radius 25 m round a rock (22 m from its 3 m outline) at 2 m/s,
  // where the vehicle turns on 22.9 m: entered along a tangent and sailed by
  // path following, the lap is kept to within 1.1 m outside (taking up the
  // turning rate where it begins) and 0.1 m inside. Entered at a right angle
  // and steered at the track a turn radius ahead, the vehicle cut 8.1 m
  // inside the lap; path following alone, with that entry, ran 8.6 m outside
  // after the entry and 1.6 m inside later.
  ScratchDir dir;
  const Mission m = mission_from(dir,
                                 "  - track: {depth_m: 8, speed_mps: 2, waypoints: [{x: 400, y: 0}]}\n"
                                 "  - identify: {object: rock, mode: around, distance_m: 22, speed_mps: 2}\n"
                                 "  - goto: {speed_mps: 2, position: {x: 800, y: 0}}\n");
  MissionEnvironment env;
  const Vec2 rock(500.0, 60.0);
  env.obstacles.ellipses.push_back(test::disc(rock.x(), rock.y(), 3.0, "rock"));
  const MissionPlan plan = expand_mission(m, env.obstacles);
  double lap_from = plan.length_m, lap_to = 0.0;
  for (const BasicManoeuvre& b : plan.basics) {
    if (b.kind != BasicManoeuvre::Kind::arc || b.source != 1) continue;  // the identify manoeuvre's
    lap_from = std::min(lap_from, b.start_m);
    lap_to = std::max(lap_to, b.start_m + b.length_m);
  }
  ASSERT_NEAR(lap_to - lap_from, 2.0 * std::numbers::pi * 25.0, 0.5);
  // The line to the lap meets it along its tangent: no corner there.
  for (std::size_t i = 1; i < plan.basics.size(); ++i) {
    if (plan.basics[i].source == 1 && plan.basics[i].kind == BasicManoeuvre::Kind::arc) {
      EXPECT_TRUE(joins_smoothly(plan.basics[i - 1], plan.basics[i]));
      break;
    }
  }
  const MissionRun run = run_mission(m, env, plan, {});
  ASSERT_TRUE(run.completed);
  double worst = 0.0;
  int samples = 0;
  for (const MissionSample& s : run.track) {
    if (s.along_m < lap_from || s.along_m > lap_to) continue;
    ++samples;
    worst = std::max(worst, std::abs((s.position - rock).norm() - 25.0));
  }
  std::printf("[ mission lap ] %d samples on the lap, farthest %.2f m off it; least clearance %.2f m\n", samples, worst,
              run.min_clearance_m);
  EXPECT_GT(samples, 70);
  EXPECT_LT(worst, 1.5);
  EXPECT_GT(run.min_clearance_m, 22.0 - 0.5);
}

TEST(MissionRun, LapsAreSailedWholeAndAHoldAtTheEndCounts) {
  ScratchDir dir;
  const Mission m = mission_from(dir,
                                 "  - track: {depth_m: 8, speed_mps: 2, waypoints: [{x: 400, y: 0}]}\n"
                                 "  - identify: {object: rock, mode: around, distance_m: 22, speed_mps: 2}\n"
                                 "  - goto: {speed_mps: 2, position: {x: 800, y: 0}}\n"
                                 "  - gps_update: {hold_s: 300}\n");
  MissionEnvironment env;
  env.obstacles.ellipses.push_back(test::disc(500.0, 60.0, 3.0, "rock"));
  const MissionPlan plan = expand_mission(m, env.obstacles);
  const MissionRun run = run_mission(m, env, plan, {});
  ASSERT_TRUE(run.completed);
  EXPECT_FALSE(run.collided);
  // The lap (2 pi 25 m = 157 m) is in the length sailed: within 3 % of the plan's.
  EXPECT_NEAR(run.length_m, plan.length_m, 0.03 * plan.length_m);
  EXPECT_NEAR(run.time_s, plan.length_m / 2.0 + 300.0, 0.03 * plan.length_m / 2.0);
  EXPECT_TRUE(has_event(run, "hold 300 s"));
}

TEST(MissionRun, ObjectsFoundUnderWayGoIntoAKeptMeshAndAreEvadedAsOnTheVisibilityGraph) {
  ScratchDir dir;
  const std::string track = "  - track: {depth_m: 8, speed_mps: 2, waypoints: [{x: 1500, y: 0}]}\n";
  const Mission vis = mission_from(dir, track);
  const Mission mesh = read_mission(dir.write("mesh.yaml",
                                              "crs: EPSG:32632\nstart: {x: 0, y: 0, depth_m: 8}\n"
                                              "control: {evasion_graph: navmesh}\nmanoeuvres:\n" +
                                                  track));
  ASSERT_EQ(mesh.control.evasion_graph, GraphKind{"navmesh"});
  ObstacleSet unknown;
  unknown.ellipses.push_back(test::disc(500.0, 2.0, 6.0, "container"));
  unknown.ellipses.push_back(test::disc(1000.0, -2.0, 6.0, "buoy"));
  const MissionRun a = run_mission(vis, {}, expand_mission(vis, {}), unknown);
  const MissionRun b = run_mission(mesh, {}, expand_mission(mesh, {}), unknown);
  ASSERT_TRUE(b.completed);
  EXPECT_FALSE(b.collided);
  EXPECT_EQ(b.detected.size(), 2u);
  EXPECT_EQ(b.replans, a.replans);
  EXPECT_GT(b.min_clearance_m, 3.0);
  // The second contact's evasion is planned on the mesh the first was cut into: the same ways round.
  EXPECT_NEAR(b.length_m, a.length_m, 0.5);
  EXPECT_NEAR(b.time_s, a.time_s, 0.5);
}
