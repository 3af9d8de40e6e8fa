// The offline simulation: the statistics' definitions on hand-built
// trajectories, the loop's invariants (open water, one obstacle, same seed ->
// same bits), the edge cases (target in an obstacle, start in the security
// zone, overlapping obstacles, no sonar, a current faster than the vehicle),
// the contact memory, the scenario reader's errors and the CLI.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "deepguide/core/error.hpp"
#include "deepguide/simulation/contacts.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/simulation/simulation.hpp"
#include "deepguide/simulation/trajectory_io.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

using test::error_of;
using test::expect_error;
using test::ScratchDir;

constexpr ReactiveMethod kMethods[] = {ReactiveMethod::dipole, ReactiveMethod::geometric, ReactiveMethod::potential};

EllipticCylinder disc(const std::string& id, Vec2 c, double r) { return {id, {c, r, r, 0.0}, {}, {}}; }

// Exact sonar (no noise): association and contacts become deterministic by construction.
Scenario exact_scenario(Vec2 start, Vec2 target, std::vector<EllipticCylinder> obstacles) {
  Scenario sc;
  sc.name = "test";
  sc.start = start;
  sc.target = target;
  sc.obstacles = std::move(obstacles);
  sc.reactive.speed_mps = sc.vehicle.cruise_speed_mps;
  sc.sonar.position_sigma_m = sc.sonar.position_sigma_per_m = 0.0;
  sc.sonar.size_sigma_m = sc.sonar.size_sigma_per_m = 0.0;
  return sc;
}

// ---------------------------------------------------------------- statistics

TrajectorySample sample(double t, Vec2 p, double rate_ref, double speed, double clearance, bool unreachable = false) {
  TrajectorySample s;
  s.time_s = t;
  s.position = p;
  s.rate_ref = rate_ref;
  s.rate = 0.5 * rate_ref;
  s.speed_mps = speed;
  s.clearance_m = clearance;
  s.course_unreachable = unreachable;
  return s;
}

TEST(SimulationStats, HandBuiltTrajectory) {
  // dt = 1 s. Path: 5 + 0 + 5 + 0 = 10 m. r_ref = 0, .1, 0, -.1, 0:
  // trapezoid integral of r^2 = 4 x 0.005 = 0.02 over 4 s -> RMS sqrt(0.005).
  // Power 1050 + 60 v^3: 1110 W at 1 m/s, 1530 W at 2 m/s; trapezoid energy
  // 1110 + 1320 + 1530 + 1530 = 5490 J. One reversal (+0.1 then -0.1).
  const std::vector<TrajectorySample> traj = {sample(0, {0, 0}, 0.0, 1, 5.0), sample(1, {3, 4}, 0.1, 1, 3.0, true),
                                              sample(2, {3, 4}, 0.0, 2, -0.5, true), sample(3, {6, 8}, -0.1, 2, 2.0),
                                              sample(4, {6, 8}, 0.0, 2, 4.0)};
  StatsOptions o;
  o.target = {6, 13};
  o.arrival_radius_m = 5.0;
  const SimulationStats s = trajectory_stats(traj, o);
  EXPECT_DOUBLE_EQ(s.time_s, 4.0);
  EXPECT_DOUBLE_EQ(s.path_length_m, 10.0);
  EXPECT_NEAR(s.energy_j, 5490.0, 1e-9);
  EXPECT_DOUBLE_EQ(s.min_clearance_m, -0.5);
  EXPECT_TRUE(s.collided);
  EXPECT_TRUE(s.reached);  // exactly on the arrival radius
  EXPECT_DOUBLE_EQ(s.max_abs_rate_ref, 0.1);
  EXPECT_NEAR(s.rms_rate_ref, std::sqrt(0.005), 1e-15);
  EXPECT_DOUBLE_EQ(s.max_abs_rate, 0.05);
  EXPECT_NEAR(s.rms_rate, 0.5 * std::sqrt(0.005), 1e-15);
  EXPECT_EQ(s.heading_reversals, 1);
  EXPECT_DOUBLE_EQ(s.course_unreachable_s, 2.0);  // the intervals starting at t = 1 and t = 2

  o.arrival_radius_m = 4.999;
  EXPECT_FALSE(trajectory_stats(traj, o).reached);
}

TEST(SimulationStats, ReversalsIgnoreTheDeadBand) {
  StatsOptions o;  // dead band 0.5 deg/s = 0.00873 rad/s
  auto reversals = [&](std::initializer_list<double> rates) {
    std::vector<TrajectorySample> traj;
    double t = 0.0;
    for (double r : rates) traj.push_back(sample(t++, {0, 0}, r, 1, 1));
    return trajectory_stats(traj, o).heading_reversals;
  };
  EXPECT_EQ(reversals({0.005, -0.005, 0.005, -0.005}), 0);    // all inside the band
  EXPECT_EQ(reversals({0.02, 0.005, -0.005, 0.0, 0.02}), 0);  // a dip into the band is no reversal
  EXPECT_EQ(reversals({0.02, -0.02, 0.02}), 2);
  EXPECT_EQ(reversals({0.02, 0.0, -0.0087, -0.0088, 0.03}), 2);  // -0.0088 is outside the band
  o.reversal_dead_band = 0.0;
  EXPECT_EQ(reversals({0.005, -0.005, 0.005, -0.005}), 3);
}

TEST(SimulationStats, SingleSampleAndNoObstacles) {
  const std::vector<TrajectorySample> one = {sample(0, {1, 1}, 0.2, 1, std::numeric_limits<double>::infinity())};
  const SimulationStats s = trajectory_stats(one, {});
  EXPECT_EQ(s.time_s, 0.0);
  EXPECT_EQ(s.path_length_m, 0.0);
  EXPECT_EQ(s.energy_j, 0.0);
  EXPECT_EQ(s.rms_rate_ref, 0.0);  // defined as 0 for a zero-length run
  EXPECT_EQ(s.max_abs_rate_ref, 0.2);
  EXPECT_TRUE(std::isinf(s.min_clearance_m));
  EXPECT_FALSE(s.collided);
}

// ---------------------------------------------------------------- contacts

Detection detection(const Ellipse& e, double range, double t) {
  Detection d;
  d.estimate = e;
  d.range_m = range;
  d.time_s = t;
  d.obstacle = 99;  // ground truth must not matter
  return d;
}

TEST(Contacts, HausdorffDistanceOfEllipses) {
  const Ellipse a{{0, 0}, 10, 4, 0.0};
  EXPECT_EQ(ellipse_hausdorff_distance(a, a), 0.0);
  Ellipse shifted = a;
  shifted.centre = {3, 4};
  EXPECT_NEAR(ellipse_hausdorff_distance(a, shifted), 5.0, 0.2);  // a translation by 5 m (16 directions)
  const Ellipse crossed{{0, 0}, 10, 4, kPi / 2};
  EXPECT_NEAR(ellipse_hausdorff_distance(a, crossed), 6.0, 1e-12);  // a - b along the axes
  // A near-circle whose axes the sonar swapped (theta + 90 deg) is the same contact.
  const Ellipse c1{{0, 0}, 10.1, 10.0, 0.3}, c2{{0, 0}, 10.1, 10.0, 0.3 + kPi / 2};
  EXPECT_LT(ellipse_hausdorff_distance(c1, c2), 0.11);
}

TEST(Contacts, CrossedObstaclesWithOneCentreStayTwoContacts) {
  // One scan sees only one arm, the next only the other: a centre-distance
  // association would merge them into one contact.
  SonarParams exact;
  exact.position_sigma_m = exact.position_sigma_per_m = exact.size_sigma_m = exact.size_sigma_per_m = 0.0;
  ContactMemory memory({}, exact);
  const Ellipse arm1{{50, 0}, 30, 5, 0.0}, arm2{{50, 0}, 30, 5, kPi / 2};
  for (int scan = 0; scan < 6; ++scan) {
    const Detection d = detection(scan % 2 ? arm2 : arm1, 20.0, 0.5 * scan);
    memory.update(std::span(&d, 1), d.time_s);
  }
  ASSERT_EQ(memory.size(), 2u);
  EXPECT_EQ(memory.ellipses()[0].theta, 0.0);
  EXPECT_EQ(memory.ellipses()[1].theta, kPi / 2);
}

TEST(Contacts, NewestEstimateWithinTheGateNewContactBeyondAndForgetting) {
  SonarParams sonar;  // sigma 0.5 m + 1 % and 0.25 m + 1 %: s(r) = 0.75 + 0.02 r
  ContactMemory memory({2.0, 10.0}, sonar);
  const Ellipse first{{100, 0}, 10, 10, 0.0};
  Detection d = detection(first, 100.0, 0.0);
  memory.update(std::span(&d, 1), 0.0);
  // Gate at ranges 100 and 50: 2 + 3 (2.75 + 1.75) = 15.5 m. A 12 m shift is the same contact...
  Ellipse moved = first;
  moved.centre = {112, 0};
  d = detection(moved, 50.0, 1.0);
  memory.update(std::span(&d, 1), 1.0);
  ASSERT_EQ(memory.size(), 1u);
  EXPECT_EQ(memory.ellipses()[0].centre, Vec2(112, 0));  // the newest estimate
  // ... a 17 m shift at ranges 50 and 50 (gate 2 + 3 x 3.5 = 12.5 m) is a new one.
  Ellipse far = moved;
  far.centre = {129, 0};
  d = detection(far, 50.0, 2.0);
  memory.update(std::span(&d, 1), 2.0);
  ASSERT_EQ(memory.size(), 2u);
  // memory_s = 10: at t = 11.5 the contact last seen at t = 1 is forgotten, the one from t = 2 kept.
  memory.update({}, 11.5);
  ASSERT_EQ(memory.size(), 1u);
  EXPECT_EQ(memory.ellipses()[0].centre, Vec2(129, 0));
}

TEST(Contacts, OneScanNeverMergesTwoDetections) {
  SonarParams exact;
  exact.position_sigma_m = exact.position_sigma_per_m = exact.size_sigma_m = exact.size_sigma_per_m = 0.0;
  ContactMemory memory({5.0, std::numeric_limits<double>::infinity()}, exact);
  const Detection both[] = {detection({{0, 0}, 5, 5, 0}, 10, 0), detection({{3, 0}, 5, 5, 0}, 10, 0)};
  memory.update(both, 0.0);
  memory.update(both, 0.5);
  EXPECT_EQ(memory.size(), 2u);
}

// ---------------------------------------------------------------- the loop

TEST(Simulation, OpenWaterGoesStraightToTheTarget) {
  Scenario sc = exact_scenario({0, 0}, {300, 400}, {});
  for (const ReactiveMethod& m : kMethods) {
    const SimulationResult r = simulate(sc, m);
    SCOPED_TRACE(std::string(to_string(m)));
    EXPECT_EQ(r.end, SimulationEnd::reached);
    EXPECT_TRUE(r.stats.reached);
    EXPECT_FALSE(r.stats.collided);
    // It heads for the target from the start and stops within 5 m of it; the last
    // step covers at most 0.21 m: 495 <= path <= 495.21.
    EXPECT_GE(r.stats.path_length_m, 495.0 - 1e-6);
    EXPECT_LE(r.stats.path_length_m, 495.0 + 0.21);
    EXPECT_TRUE(std::isinf(r.stats.min_clearance_m));
    EXPECT_EQ(r.stats.heading_reversals, 0);
    EXPECT_LT(r.stats.max_abs_rate_ref, 1e-9);
    // Constant speed: E = P(v) t exactly up to rounding, t = path / v.
    const double v = sc.reactive.speed_mps;
    EXPECT_NEAR(r.stats.time_s, r.stats.path_length_m / v, 1e-6);
    EXPECT_NEAR(r.stats.energy_j, (1050.0 + 60.0 * v * v * v) * r.stats.time_s, 1e-6);
    ASSERT_EQ(r.trajectory.size(), r.samples);
    EXPECT_EQ(r.trajectory.front().position, sc.start);
    EXPECT_NEAR(r.trajectory[1].time_s, 0.1, 1e-15);
  }
}

// What `simulate` prints is the JSON's values, one a line: the text and the
// JSON come from one run and say the same.
TEST(Simulation, TextSaysWhatTheJsonSays) {
  const Scenario sc = exact_scenario({10, 10}, {12, 10}, {});
  const SimulationResult r = simulate(sc, ReactiveMethod::geometric);
  const std::string text = simulation_text(sc, r);
  const auto j = simulation_json(sc, r);
  EXPECT_EQ(text.rfind("scenario " + sc.name + ", method geometric, seed " + std::to_string(sc.sonar.seed) + "\n", 0),
            0u)
      << text;
  EXPECT_NE(text.find("  end                      reached\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  time_s                   0.000\n"), std::string::npos) << text;
  // One line per value but the three in the first line.
  EXPECT_EQ(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')), j.size() - 3 + 1) << text;
}

TEST(Simulation, StartOnTheTargetEndsAtOnce) {
  const SimulationResult r = simulate(exact_scenario({10, 10}, {12, 10}, {}), ReactiveMethod::geometric);
  EXPECT_EQ(r.end, SimulationEnd::reached);
  EXPECT_EQ(r.samples, 1u);
  EXPECT_EQ(r.stats.time_s, 0.0);
}

TEST(Simulation, OneObstacleIsPassedAndAvoided) {
  // The single disc of test_reactive_methods.cpp (R = 20 m), started off the axis (the dipole's stagnation
  // line), margin 10 m, the inexact sonar on. Every method arrives; the
  // geometric and potential methods keep clear. The dipole method is not held
  // to clearance here: its field turns faster near the disc than the vehicle
  // can (5 deg/s), the seed's Fig. 12 point.
  Scenario sc = exact_scenario({-150, 5}, {150, 0}, {disc("rock", {0, 0}, 20)});
  sc.sonar = SonarParams{};
  for (const ReactiveMethod& m : kMethods) {
    SCOPED_TRACE(std::string(to_string(m)));
    const SimulationResult r = simulate(sc, m);
    EXPECT_EQ(r.end, SimulationEnd::reached);
    EXPECT_GT(r.stats.path_length_m, 295.0);  // longer than the straight 295 m to the arrival circle
    EXPECT_EQ(r.contacts, 1u);                // the noisy detections stay one contact
    if (m == ReactiveMethod::dipole) continue;
    EXPECT_FALSE(r.stats.collided);
    EXPECT_GT(r.stats.min_clearance_m, 0.0);
  }
  // The geometric method keeps its margin to within the sonar's error.
  EXPECT_GT(simulate(sc, ReactiveMethod::geometric).stats.min_clearance_m, 9.0);
}

// The commanded course's rate is its own finite difference; the autopilot's
// reference r_ref stays within its limit, and r within the hard limit.
TEST(Simulation, TurningRatesAreTheCommandsTheAutopilotsAndTheVehicles) {
  Scenario sc = exact_scenario({-150, 5}, {150, 0}, {disc("rock", {0, 0}, 20)});
  sc.sonar = SonarParams{};
  for (const ReactiveMethod& m : kMethods) {
    SCOPED_TRACE(std::string(to_string(m)));
    const SimulationResult r = simulate(sc, m);
    ASSERT_GT(r.trajectory.size(), 100u);
    EXPECT_EQ(r.trajectory[0].rate_cmd, 0.0);
    const double h = sc.vehicle.step_s;
    double max_ref = 0.0;
    for (std::size_t k = 1; k < r.trajectory.size(); ++k) {
      const TrajectorySample& x = r.trajectory[k];
      ASSERT_EQ(x.rate_cmd, wrap_pi(x.course_cmd - r.trajectory[k - 1].course_cmd) / h) << "sample " << k;
      ASSERT_LE(std::abs(x.rate_ref), sc.vehicle.autopilot.max_reference_turn_rate * (1 + 1e-12)) << "sample " << k;
      ASSERT_LE(std::abs(x.rate), sc.vehicle.max_turn_rate * (1 + 1e-12)) << "sample " << k;
      max_ref = std::max(max_ref, std::abs(x.rate_ref));
    }
    EXPECT_EQ(r.stats.max_abs_rate_ref, max_ref);
    // Passing the rock asks for some turning.
    EXPECT_GT(max_ref, deg_to_rad(0.5));
  }
}

TEST(Simulation, SameSeedSameBitsOtherSeedOtherTrajectory) {
  Scenario sc = exact_scenario({-150, 5}, {150, 0}, {disc("rock", {0, 0}, 20), disc("b", {60, 30}, 10)});
  sc.sonar = SonarParams{};
  sc.sonar.seed = 7;
  for (const ReactiveMethod& m : kMethods) {
    SCOPED_TRACE(std::string(to_string(m)));
    const SimulationResult a = simulate(sc, m), b = simulate(sc, m);
    ASSERT_EQ(a.trajectory.size(), b.trajectory.size());
    EXPECT_TRUE(a.trajectory == b.trajectory);  // operator== on doubles: bit for bit (no NaN in a trajectory)
    Scenario other = sc;
    other.sonar.seed = 8;
    const SimulationResult c = simulate(other, m);
    EXPECT_FALSE(a.trajectory == c.trajectory) << "the sonar's noise should reach the course";
    // The statistics do not depend on keeping the trajectory.
    const SimulationResult d = simulate(sc, m, {false});
    EXPECT_TRUE(d.trajectory.empty());
    EXPECT_EQ(d.samples, a.samples);
    EXPECT_EQ(d.stats.path_length_m, a.stats.path_length_m);
    EXPECT_EQ(d.stats.rms_rate_ref, a.stats.rms_rate_ref);
  }
}

TEST(Simulation, TargetInsideAnObstacleIsRefused) {
  const Scenario sc = exact_scenario({-150, 0}, {150, 0}, {disc("rock", {150, 3}, 20)});
  expect_error(error_of([&] { simulate(sc, ReactiveMethod::geometric); }),
               {"field 'target'", "outside every obstacle", "inside obstacle 'rock'"});
}

TEST(Simulation, TargetInsideTheSecurityZoneButOutsideTheObstacle) {
  // Target 4 m off the rock (margin 10): the method heads for the nearest
  // point of the zone and stops there (target_in_zone, speed 0), and the run
  // ends at once with the target not reached. Every method's run ends by a
  // stop rule, never by the time limit.
  Scenario sc = exact_scenario({-150, 0}, {150, 0}, {disc("rock", {150, 24}, 20)});
  for (const ReactiveMethod& m : kMethods) {
    SCOPED_TRACE(std::string(to_string(m)));
    const SimulationResult r = simulate(sc, m);
    EXPECT_NE(r.end, SimulationEnd::time_out);
    EXPECT_FALSE(r.stats.reached);
    if (m == ReactiveMethod::dipole) continue;  // its field circles the point (see OneObstacleIsPassedAndAvoided)
    EXPECT_EQ(r.end, SimulationEnd::target_in_zone);
    EXPECT_FALSE(r.stats.collided);
    EXPECT_EQ(r.trajectory.back().status, ReactiveStatus::target_in_zone);
    // The zone's nearest point is 6 m from the target; the vehicle still makes way when it stops the run.
    EXPECT_LT((r.trajectory.back().position - sc.target).norm(), 12.0);
  }
}

TEST(Simulation, StartInsideTheSecurityZoneLeavesIt) {
  // 7 m from a disc of R = 20 (margin 10), heading north along it (the sonar
  // sees its edge 42 deg to starboard); target behind the disc.
  Scenario sc = exact_scenario({-27, 0}, {150, 0}, {disc("rock", {0, 0}, 20)});
  sc.start_heading = kPi / 2;
  const SimulationResult g = simulate(sc, ReactiveMethod::geometric);
  EXPECT_EQ(g.trajectory.front().status, ReactiveStatus::leaving_zone);
  EXPECT_EQ(g.trajectory.front().sector, 3);
  for (const ReactiveMethod& m : kMethods) {
    SCOPED_TRACE(std::string(to_string(m)));
    const SimulationResult r = simulate(sc, m);
    EXPECT_FALSE(r.stats.collided);
    EXPECT_EQ(r.end, SimulationEnd::reached);
  }
  // Inside the obstacle itself the scenario is refused.
  sc.start = {-19, 0};
  expect_error(error_of([&] { simulate(sc, ReactiveMethod::geometric); }), {"field 'start'", "inside obstacle 'rock'"});
}

TEST(Simulation, OverlappingObstaclesAreTwoContactsAndAvoided) {
  const Scenario sc = exact_scenario({-150, 3}, {150, 0}, {disc("north", {0, 12}, 15), disc("south", {0, -12}, 15)});
  for (const ReactiveMethod& m : kMethods) {
    SCOPED_TRACE(std::string(to_string(m)));
    const SimulationResult r = simulate(sc, m);
    EXPECT_EQ(r.end, SimulationEnd::reached);
    EXPECT_EQ(r.contacts, 2u);  // exact sonar: one contact per obstacle, never merged
    if (m != ReactiveMethod::dipole) {
      EXPECT_FALSE(r.stats.collided);
    }
  }
}

TEST(Simulation, ZeroSonarRangeSeesNothingAndCollides) {
  // Blind, the vehicle runs straight through the disc's centre: the minimum
  // clearance is -R up to the 0.21 m between samples.
  Scenario sc = exact_scenario({-150, 0}, {150, 0}, {disc("rock", {0, 0}, 20)});
  sc.sonar.range_m = 0.0;
  const SimulationResult r = simulate(sc, ReactiveMethod::geometric);
  EXPECT_EQ(r.contacts, 0u);
  EXPECT_TRUE(r.stats.collided);
  EXPECT_NEAR(r.stats.min_clearance_m, -20.0, 0.11);
  EXPECT_EQ(r.end, SimulationEnd::reached);  // a point passes through; the run goes on
  EXPECT_NEAR(r.stats.path_length_m, 295.0, 0.21);
}

TEST(Simulation, CurrentFasterThanTheVehicleEndsWithoutProgress) {
  // 3 m/s against a 2.06 m/s vehicle: the course cannot be made good, the
  // vehicle drifts back, and after no_progress_s (300 s) the run ends.
  Scenario sc = exact_scenario({0, 0}, {500, 0}, {});
  sc.current = {-3.0, 0.0};
  const SimulationResult r = simulate(sc, ReactiveMethod::geometric);
  EXPECT_EQ(r.end, SimulationEnd::no_progress);
  EXPECT_FALSE(r.stats.reached);
  EXPECT_NEAR(r.stats.time_s, 300.0, 1e-6);
  // Unreachable most of the time: the autopilot's reference starts at the course over
  // ground (drifting west, which it can make good) and needs a while to swing east.
  EXPECT_GT(r.stats.course_unreachable_s, 250.0);
  EXPECT_LT(r.trajectory.back().position.x(), -250.0);  // drifted at about 3 - 2.06 m/s
  for (const TrajectorySample& x : r.trajectory) ASSERT_TRUE(x.position.allFinite() && std::isfinite(x.rate_ref));
}

TEST(Simulation, MaxTimeEndsTheRun) {
  Scenario sc = exact_scenario({0, 0}, {5000, 0}, {});
  sc.max_time_s = 10.0;
  const SimulationResult r = simulate(sc, ReactiveMethod::geometric);
  EXPECT_EQ(r.end, SimulationEnd::time_out);
  EXPECT_EQ(r.samples, 101u);
  EXPECT_NEAR(r.stats.time_s, 10.0, 1e-9);
  EXPECT_DOUBLE_EQ(default_max_time_s(sc), 3.0 * 5000.0 / sc.reactive.speed_mps + 300.0);
}

// ---------------------------------------------------------------- CSV and JSON

TEST(TrajectoryIo, CsvColumnsUnitsAndNauticalSigns) {
  TrajectorySample x;
  x.time_s = 1.5;
  x.position = {12.3456, -7.0};
  x.heading = 0.0;         // east: 90 deg
  x.course_cmd = kPi / 2;  // north: 0 deg
  x.rate_cmd = deg_to_rad(0.5);
  x.rate_ref = deg_to_rad(2.0);  // counter-clockwise = to port: -2 deg/s nautical
  x.rate = -deg_to_rad(1.0);     // to starboard: +1 deg/s
  x.speed_mps = 2.0;
  x.clearance_m = std::numeric_limits<double>::infinity();
  x.sector = 2;
  x.status = ReactiveStatus::leaving_zone;
  x.course_unreachable = true;
  const std::string csv = trajectory_csv(std::span(&x, 1));
  EXPECT_EQ(csv,
            "time_s,x_m,y_m,heading_deg,course_cmd_deg,rate_cmd_deg_s,rate_ref_deg_s,rate_deg_s,speed_mps,"
            "clearance_m,sector,status,course_unreachable\n"
            "1.500,12.346,-7.000,90.000,0.000,-0.5000,-2.0000,1.0000,2.0000,inf,2,leaving_zone,1\n");
}

TEST(TrajectoryIo, WritesAtomically) {
  ScratchDir dir;
  const std::vector<TrajectorySample> traj(3);
  const std::string path = dir.file("t.csv");
  write_trajectory_csv(path, traj);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4);
  EXPECT_THROW(write_trajectory_csv(dir.file("missing/t.csv"), traj), InputError);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);  // no temporary left
}

// ---------------------------------------------------------------- scenario files

std::string scenario_error(const std::string& text) {
  ScratchDir dir;
  const std::string path = dir.write("s.yaml", text);
  return error_of([&] { read_scenario_file(path); });
}

const char* kMinimal = "start: {x: 0, y: 0}\ntarget: {x: 100, y: 0}\n";

TEST(ScenarioFile, SampleScenarioReads) {
  const Scenario sc = read_scenario_file(test::source_file("data/scenarios/one_obstacle.yaml"));
  EXPECT_EQ(sc.name, "one obstacle");
  EXPECT_EQ(sc.vehicle, VehicleParams{});  // deepc.yaml is the defaults written out
  EXPECT_EQ(sc.start, Vec2(-200, 8));
  EXPECT_EQ(sc.target, Vec2(200, 0));
  EXPECT_EQ(sc.depth_m, 50.0);
  ASSERT_EQ(sc.obstacles.size(), 1u);
  EXPECT_EQ(sc.obstacles[0].id, "boulder");
  EXPECT_EQ(sc.obstacles[0].footprint.a, 25.0);
  EXPECT_EQ(sc.obstacles[0].footprint.b, 15.0);
  EXPECT_NEAR(sc.obstacles[0].footprint.theta, deg_to_rad(60.0), 1e-15);  // 30 deg east of north
  EXPECT_EQ(sc.reactive.margin_m, 10.0);
  EXPECT_EQ(sc.reactive.speed_mps, sc.vehicle.cruise_speed_mps);
  EXPECT_EQ(sc.sonar.seed, 1u);
  EXPECT_FALSE(sc.frame.has_value());
  const SimulationResult r = simulate(sc, ReactiveMethod::geometric);
  EXPECT_TRUE(r.stats.reached);
  EXPECT_FALSE(r.stats.collided);
}

TEST(ScenarioFile, DefaultsAndOptionalKeys) {
  ScratchDir dir;
  const Scenario sc = read_scenario_file(dir.write("my_run.yaml", kMinimal));
  EXPECT_EQ(sc.name, "my_run");
  EXPECT_EQ(sc.current, Vec2(0, 0));
  EXPECT_EQ(sc.sonar.range_m, 120.0);
  EXPECT_TRUE(std::isnan(sc.max_time_s));
  EXPECT_TRUE(std::isinf(sc.contacts.memory_s));
  EXPECT_FALSE(sc.start_heading.has_value());

  const Scenario c = read_scenario_file(
      dir.write("c.yaml", std::string(kMinimal) +
                              "current: \"1,90\"\nstart_heading_deg: 180\nseed: 18446744073709551615\nmax_time_s: 60\n"
                              "obstacles:\n  - {x: 50, y: 30, semi_major_m: 5}\n"));
  EXPECT_NEAR(c.current.x(), 1.0, 1e-15);  // sets towards east
  EXPECT_EQ(c.current.y(), 0.0);
  EXPECT_NEAR(*c.start_heading, -kPi / 2, 1e-15);  // south
  EXPECT_EQ(c.sonar.seed, 18446744073709551615u);
  EXPECT_EQ(c.max_time_s, 60.0);
  EXPECT_EQ(c.obstacles[0].footprint.b, 5.0);  // semi_minor defaults to semi_major
  EXPECT_EQ(c.obstacles[0].id, "obstacle 1");
}

TEST(ScenarioFile, LonLatPositionsAndObstacleFile) {
  ScratchDir dir;
  dir.write("obs.geojson",
            R"({"type": "FeatureCollection", "features": [
{"type": "Feature", "properties": {"id": "c1", "semi_major_m": 40, "semi_minor_m": 15, "orientation_deg": 30},
 "geometry": {"type": "Point", "coordinates": [10.25, 54.45]}}]})");
  const Scenario sc = read_scenario_file(dir.write(
      "ll.yaml", "obstacles_file: obs.geojson\nstart: {lon: 10.24, lat: 54.45}\ntarget: {lon: 10.26, lat: 54.45}\n"));
  ASSERT_TRUE(sc.frame.has_value());
  EXPECT_EQ(sc.frame->id(), "EPSG:32632");
  ASSERT_EQ(sc.obstacles.size(), 1u);
  // 0.02 deg of longitude at 54.45 N is about 1294 m; the obstacle lies midway.
  EXPECT_NEAR((sc.target - sc.start).norm(), 1294.0, 5.0);
  EXPECT_NEAR((sc.obstacles[0].footprint.centre - 0.5 * (sc.start + sc.target)).norm(), 0.0, 2.0);

  // A polygon in the obstacle file is refused: the sonar reports ellipses.
  dir.write("poly.geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
 "geometry": {"type": "Polygon", "coordinates": [[[10.25, 54.45], [10.26, 54.45], [10.26, 54.46], [10.25, 54.45]]]}}]})");
  expect_error(error_of([&] {
                 read_scenario_file(dir.write("p.yaml", std::string(kMinimal) + "obstacles_file: poly.geojson\n"));
               }),
               {"field 'obstacles_file'", "Point", "1 polygon"});
}

// A steady two-band current raster in EPSG:32632 (band 1 east, band 2 north), uniform (u, v),
// nodes every 100 m over [x0, x0 + 100 (n - 1)] x [y0, y0 + 100 (n - 1)].
void write_uniform_current(const std::string& path, double x0, double y0, int n, double u, double v) {
  GDALAllRegister();
  GDALDatasetUniquePtr ds(
      GetGDALDriverManager()->GetDriverByName("GTiff")->Create(path.c_str(), n, n, 2, GDT_Float64, nullptr));
  ASSERT_TRUE(ds);
  double gt[6] = {x0 - 50.0, 100.0, 0.0, y0 + 100.0 * (n - 1) + 50.0, 0.0, -100.0};
  ds->SetGeoTransform(gt);
  OGRSpatialReference srs;
  srs.importFromEPSG(32632);
  ds->SetSpatialRef(&srs);
  for (int b = 1; b <= 2; ++b) {
    std::vector<double> values(static_cast<std::size_t>(n * n), b == 1 ? u : v);
    ASSERT_EQ(ds->GetRasterBand(b)->RasterIO(GF_Write, 0, 0, n, n, values.data(), n, n, GDT_Float64, 0, 0, nullptr),
              CE_None);
  }
}

TEST(ScenarioFile, CurrentFieldDrivesTheVehicle) {
  // A uniform field in the frame's own CRS is not rotated: the run equals one
  // with the same uniform current given in code.
  ScratchDir dir;
  write_uniform_current(dir.file("c.tif"), 500000.0, 6030000.0, 21, 0.4, 0.3);
  const std::string text =
      "crs: EPSG:32632\nstart: {x: 500500, y: 6031000}\ntarget: {x: 501500, y: 6031000}\ncurrent_file: c.tif\n";
  const Scenario sc = read_scenario_file(dir.write("f.yaml", text));
  ASSERT_TRUE(sc.current_field);
  Scenario uniform = sc;
  uniform.current_field.reset();
  uniform.current = {0.4, 0.3};
  const SimulationResult a = simulate(sc, ReactiveMethod::geometric), b = simulate(uniform, ReactiveMethod::geometric);
  EXPECT_EQ(a.end, SimulationEnd::reached);
  ASSERT_EQ(a.samples, b.samples);
  EXPECT_NEAR((a.trajectory.back().position - b.trajectory.back().position).norm(), 0.0, 1e-6);
  // The crab: the heading points 0.3 m/s worth into the current, south of east.
  EXPECT_NEAR(math_rad_to_heading_deg(a.trajectory[600].heading), 90.0 + rad_to_deg(std::asin(0.3 / 2.0578)), 0.5);

  // A current that sets the vehicle out of the field (200 m north of the start, at about
  // 3 - 2.06 m/s) ends the run with an error, never a zero current.
  write_uniform_current(dir.file("strong.tif"), 500000.0, 6029200.0, 21, 0.0, 3.0);
  const Scenario out = read_scenario_file(dir.write("s.yaml",
                                                    "crs: EPSG:32632\nstart: {x: 500500, y: 6031000}\n"
                                                    "target: {x: 501500, y: 6031000}\n"
                                                    "current_file: strong.tif\n"));
  expect_error(error_of([&] { simulate(out, ReactiveMethod::geometric); }),
               {"s.yaml", "field 'current_file'", "covering the vehicle's track"});
  // A field that does not cover the start is refused when the scenario is read.
  expect_error(error_of([&] {
                 read_scenario_file(dir.write("far.yaml",
                                              "crs: EPSG:32632\nstart: {x: 400000, y: 6031000}\n"
                                              "target: {x: 501500, y: 6031000}\ncurrent_file: c.tif\n"));
               }),
               {"c.tif"});
}

TEST(ScenarioFile, BadFilesGiveOneLineErrors) {
  struct Case {
    std::string text;
    std::initializer_list<const char*> parts;
  };
  const std::string m = kMinimal;
  const Case cases[] = {
      {"", {"s.yaml", "empty document"}},
      {"- 1\n- 2\n", {"s.yaml", "mapping of scenario keys", "a scalar or list"}},
      {"start: {x: 0, y: 0}\n", {"field 'target'", "position", "got nothing"}},
      {"start: {x: 0}\ntarget: {x: 1, y: 1}\n", {"field 'start.y'", "got nothing"}},
      {m + "depth_m: deep\n", {"line 3", "field 'depth_m'", "'deep'"}},
      {m + "depth_m: [1, 2]\n", {"field 'depth_m'", "a list or mapping"}},
      {m + "speed: 3\n", {"line 3", "field 'speed'", "unknown key", "start, target"}},
      {m + "sonar: {range: 5}\n", {"field 'sonar.range'", "unknown key", "range_m"}},
      {m + "depth_m: 1\ndepth_m: 2\n", {"line 4", "field 'depth_m'", "duplicate", "line 3"}},
      {m + "sonar: {range_m: -1}\n", {"field 'sonar.range_m'", ">= 0", "-1"}},
      {m + "depth_m: .nan\n", {"field 'depth_m'", "depth", ".nan"}},
      {m + "reactive: {margin_m: -5}\n", {"field 'reactive.margin_m'", "-5"}},
      {m + "reactive: {speed_mps: 4}\n", {"field 'reactive.speed_mps'", "max_speed"}},
      {m + "max_time_s: 1e300\n", {"field 'max_time_s'", "<= 200000", "1e300"}},
      {"start: {x: 1e400, y: 0}\ntarget: {x: 1, y: 1}\n", {"field 'start.x'", "1e400"}},
      {"start: {x: 1e9, y: 0}\ntarget: {x: 1, y: 1}\n", {"field 'start.x'", "<= 100000000"}},
      {m + "obstacles_file: nowhere.geojson\n", {"nowhere.geojson"}},
      {m + "vehicle: nowhere.yaml\n", {"nowhere.yaml", "existing vehicle file"}},
      {m + "obstacles: {x: 1}\n", {"field 'obstacles'", "list of obstacles"}},
      {m + "obstacles:\n  - {x: 50, y: 0, semi_major_m: 5, semi_minor_m: 6}\n",
       {"field 'obstacles[0].semi_minor_m'", "semi_minor_m <= semi_major_m"}},
      {m + "obstacles:\n  - {x: 50, y: 0, semi_major_m: 0}\n", {"field 'obstacles[0].semi_major_m'", "> 0"}},
      {m + "obstacles:\n  - {x: 100, y: 2, semi_major_m: 10}\n", {"field 'target'", "inside obstacle 'obstacle 1'"}},
      {m + "obstacles:\n  - {x: 0, y: 2, semi_major_m: 10, id: rock}\n", {"field 'start'", "inside obstacle 'rock'"}},
      {m + "seed: -1\n", {"field 'seed'", "unsigned integer", "'-1'"}},
      {m + "seed: 1.5\n", {"field 'seed'", "'1.5'"}},
      {m + "current: \"fast\"\n", {"field 'current'", "SPEED_MPS,DIR_DEG", "'fast'"}},
      {m + "current: \"50,0\"\n", {"field 'current'", "at most 20 m/s"}},
      {m + "current: \"1,0\"\ncurrent_file: c.nc\n", {"field 'current_file'", "either current or current_file"}},
      {m + "current_file: c.nc\n", {"field 'current_file'", "geographic frame"}},
      {m + "crs: EPSG:4326\n", {"field 'crs'", "projected"}},
      {"start: {x: 0, y: 0, lon: 1}\ntarget: {x: 1, y: 1}\n", {"field 'start", "either x, y or lon, lat"}},
      {m + "start_heading_deg: 1000\n", {"field 'start_heading_deg'", "1000"}},
      {"start: {x: 0, y: 0}\ntarget: {x: 1, y: 1}\nname: [a]\n", {"field 'name'", "a list or mapping"}},
      {"start: [0, 0\n", {"s.yaml", "YAML scenario file"}},
      {m + "contacts: {memory_s: 0}\n", {"field 'contacts.memory_s'", "> 0"}},
      {m + "energy: {hotel_power_w: -1}\n", {"field 'energy.hotel_power_w'", "-1"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    expect_error(scenario_error(c.text), c.parts);
  }
}

TEST(ScenarioFile, MissingOrHugeFile) {
  ScratchDir dir;
  expect_error(error_of([&] { read_scenario_file(dir.file("none.yaml")); }), {"none.yaml", "existing scenario file"});
  const std::string big = dir.write("big.yaml", std::string(5u << 20, '#'));
  expect_error(error_of([&] { read_scenario_file(big); }), {"big.yaml", "under 4 MiB"});
}

// ---------------------------------------------------------------- CLI

TEST(SimulateCli, JsonCsvAndExitCodes) {
  ScratchDir dir;
  const std::string sc = test::source_file("data/scenarios/one_obstacle.yaml");
  const std::string csv = dir.file("traj.csv");
  const test::RunResult ok = test::run_cli("simulate '" + sc + "' --method geometric -o '" + csv + "' --json --seed 5");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const nlohmann::json j = nlohmann::json::parse(ok.out);
  for (const char* key : {"scenario", "method", "seed", "end", "reached", "collided", "time_s", "path_length_m",
                          "energy_j", "min_clearance_m", "max_abs_rate_ref_deg_s", "rms_rate_ref_deg_s",
                          "max_abs_rate_deg_s", "rms_rate_deg_s", "heading_reversals", "samples", "contacts"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["method"], "geometric");
  EXPECT_EQ(j["seed"], 5);
  EXPECT_EQ(j["reached"], true);
  EXPECT_EQ(j["end"], "reached");
  std::ifstream in(csv);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')), j["samples"].get<std::size_t>() + 1);
  EXPECT_EQ(text.rfind("time_s,x_m,y_m,", 0), 0u);

  const test::RunResult text_out = test::run_cli("simulate '" + sc + "' --method dipole");
  EXPECT_EQ(text_out.exit_code, 0) << text_out.err;
  EXPECT_NE(text_out.out.find("path_length_m"), std::string::npos);

  // An unknown method is bad input, as in `render field` and `plan --graph`; a missing one is usage.
  const test::RunResult magic = test::run_cli("simulate '" + sc + "' --method magic");
  EXPECT_EQ(magic.exit_code, 1);
  EXPECT_EQ(magic.err, "deepguide: error: --method: expected dipole, geometric or potential, got 'magic'\n");
  EXPECT_EQ(test::run_cli("simulate '" + sc + "'").exit_code, 2);

  // Bad input: exit 1, one line on stderr, and the existing output untouched.
  const std::string bad = dir.write("bad.yaml", "start: {x: 0, y: 0}\n");
  const test::RunResult e = test::run_cli("simulate '" + bad + "' --method geometric -o '" + csv + "'");
  EXPECT_EQ(e.exit_code, 1);
  EXPECT_EQ(std::count(e.err.begin(), e.err.end(), '\n'), 1) << e.err;
  EXPECT_NE(e.err.find("field 'target'"), std::string::npos) << e.err;
  std::ifstream again(csv);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(again)), {}), text);
  const test::RunResult nodir =
      test::run_cli("simulate '" + sc + "' --method geometric -o '" + dir.file("no/such/dir.csv") + "'");
  EXPECT_EQ(nodir.exit_code, 1);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 2);  // bad.yaml, traj.csv
}

}  // namespace
}  // namespace deepguide
