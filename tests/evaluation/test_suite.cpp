// Scenario suites: the scenario writer's round trip, the generator's new
// knobs, suite folders (files, on demand, one file) and their bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../test_support.hpp"
#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/evaluation/suite.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/simulation/scenario_writer.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

double angle_gap(double a, double b) { return std::abs(wrap_pi(a - b)); }

void expect_same(const Scenario& a, const Scenario& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.start, b.start);
  EXPECT_EQ(a.target, b.target);
  EXPECT_EQ(a.depth_m, b.depth_m);
  ASSERT_EQ(a.obstacles.size(), b.obstacles.size());
  for (std::size_t i = 0; i < a.obstacles.size(); ++i) {
    const Ellipse &x = a.obstacles[i].footprint, &y = b.obstacles[i].footprint;
    EXPECT_EQ(a.obstacles[i].id, b.obstacles[i].id);
    EXPECT_EQ(x.centre, y.centre);
    EXPECT_EQ(x.a, y.a);
    EXPECT_EQ(x.b, y.b);
    EXPECT_LT(angle_gap(x.theta, y.theta), 1e-12);
  }
  EXPECT_LT((a.current - b.current).norm(), 1e-14);
  EXPECT_EQ(a.sonar.seed, b.sonar.seed);
  EXPECT_EQ(a.sonar.range_m, b.sonar.range_m);
  EXPECT_EQ(a.sonar.position_sigma_m, b.sonar.position_sigma_m);
  EXPECT_EQ(a.sonar.size_sigma_per_m, b.sonar.size_sigma_per_m);
  EXPECT_EQ(a.reactive.margin_m, b.reactive.margin_m);
  EXPECT_EQ(a.reactive.speed_mps, b.reactive.speed_mps);
  for (const ReactiveTuning& t : reactive_tunings()) {
    EXPECT_EQ(tuning_value(a.reactive, t.key), tuning_value(b.reactive, t.key)) << t.key;
  }
  EXPECT_EQ(a.energy, b.energy);
  EXPECT_EQ(a.stall_time_s, b.stall_time_s);
  EXPECT_EQ(a.no_progress_s, b.no_progress_s);
  EXPECT_EQ(std::isnan(a.max_time_s), std::isnan(b.max_time_s));
}

}  // namespace

TEST(ScenarioWriter, GeneratedScenariosReadBackExactly) {
  MonteCarloParams p;
  p.max_obstacles = 8;
  for (int k = 0; k < 50; ++k) {
    Scenario sc = monte_carlo_scenario(p, k);
    sc.source = "in memory";
    const Scenario back = parse_scenario_yaml(scenario_yaml(sc, "a comment\nover two lines"), "back.yaml", ".");
    sc.name = back.name;  // the generator's name is written, the reader keeps it
    expect_same(sc, back);
  }
}

TEST(ScenarioWriter, HostileNamesAndEverySettingSurvive) {
  Scenario sc = monte_carlo_scenario({}, 3);
  sc.name = "quote \" backslash \\ colon: # hash";
  sc.obstacles.front().id = "id, with \"quotes\"\ttab";
  sc.start_heading = deg_to_rad(30.0);
  sc.max_time_s = 1234.5;
  sc.contacts.memory_s = 60.0;
  sc.depth_m = 12.25;
  const Scenario back = parse_scenario_yaml(scenario_yaml(sc), "back.yaml", ".");
  EXPECT_EQ(back.name, sc.name);
  EXPECT_EQ(back.obstacles.front().id, sc.obstacles.front().id);
  ASSERT_TRUE(back.start_heading.has_value());
  EXPECT_LT(angle_gap(*back.start_heading, *sc.start_heading), 1e-12);
  EXPECT_EQ(back.max_time_s, 1234.5);
  EXPECT_EQ(back.contacts.memory_s, 60.0);
  EXPECT_EQ(back.depth_m, 12.25);
}

TEST(ScenarioWriter, RefusesWhatItCannotWrite) {
  Scenario sc = monte_carlo_scenario({}, 0);
  sc.identify = IdentifySpec{};
  deepguide::test::expect_one_line_error([&] { (void)scenario_yaml(sc); }, "identify section");
}

TEST(SuiteGenerator, KnobsShapeTheScenariosAndDefaultsDrawAsBefore) {
  MonteCarloParams p;
  p.min_obstacles = 4;
  p.max_obstacles = 5;
  p.min_size_m = 10.0;
  p.max_size_m = 12.0;
  p.sonar_noise = 2.0;
  for (int k = 0; k < 40; ++k) {
    const Scenario sc = monte_carlo_scenario(p, k);
    EXPECT_GE(sc.obstacles.size(), 4u);
    EXPECT_LE(sc.obstacles.size(), 5u);
    for (const EllipticCylinder& o : sc.obstacles) {
      EXPECT_GE(o.footprint.a, 10.0);
      EXPECT_LE(o.footprint.a, 12.0);
    }
    EXPECT_DOUBLE_EQ(sc.sonar.position_sigma_m, 2.0 * SonarParams{}.position_sigma_m);
  }
  MonteCarloParams d;
  d.min_obstacles = 0;
  d.max_obstacles = 0;
  EXPECT_TRUE(monte_carlo_scenario(d, 5).obstacles.empty());

  MonteCarloParams bad;
  bad.min_obstacles = 7;
  deepguide::test::expect_one_line_error([&] { validate(bad); }, "min_obstacles");
  bad = {};
  bad.max_size_m = 2.0;
  deepguide::test::expect_one_line_error([&] { validate(bad); }, "max_size_m");
  bad = {};
  bad.max_size_m = 400.0;
  bad.min_size_m = 300.0;
  deepguide::test::expect_one_line_error([&] { (void)monte_carlo_scenario(bad, 0); }, "max_size_m");
}

TEST(Suite, WrittenFilesAndOnDemandGiveTheSameScenarios) {
  ScratchDir tmp;
  MonteCarloParams p;
  p.scenarios = 12;
  p.seed = 9;
  write_suite(tmp.file("files"), "nine", p, true, false);
  write_suite(tmp.file("lazy"), "nine", p, false, false);
  const Suite files = read_suite(tmp.file("files"));
  const Suite lazy = read_suite(tmp.file("lazy") + "/suite.yaml");
  EXPECT_EQ(files.name, "nine");
  EXPECT_EQ(lazy.name, "nine");
  ASSERT_EQ(files.scenarios.size(), 12u);
  ASSERT_EQ(lazy.scenarios.size(), 12u);
  ASSERT_TRUE(lazy.generator.has_value());
  EXPECT_EQ(*lazy.generator, p);
  for (std::size_t i = 0; i < 12; ++i) {
    EXPECT_EQ(files.scenarios[i].id, lazy.scenarios[i].id);
    EXPECT_EQ(files.scenarios[i].id, generated_scenario_id(static_cast<int>(i), 12));
    const Scenario a = load_suite_scenario(files, i), b = load_suite_scenario(lazy, i);
    expect_same(a, b);
  }
  EXPECT_EQ(generated_scenario_id(7, 12), "scenario-0007");
  EXPECT_EQ(generated_scenario_id(7, 100000), "scenario-00007");
  // No silent overwrite; with overwrite the folder is replaced whole.
  deepguide::test::expect_one_line_error([&] { write_suite(tmp.file("files"), "x", p, true, false); }, "`overwrite`");
  p.scenarios = 3;
  write_suite(tmp.file("files"), "three", p, true, true);
  EXPECT_EQ(read_suite(tmp.file("files")).scenarios.size(), 3u);
  // A trailing slash names the same folder; the current folder is never replaced.
  write_suite(tmp.file("slash") + "/", "slash", p, true, false);
  EXPECT_EQ(read_suite(tmp.file("slash")).scenarios.size(), 3u);
  write_suite(tmp.file("slash") + "/", "slash", p, false, true);
  EXPECT_TRUE(read_suite(tmp.file("slash")).generator.has_value());
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(tmp.path() / "slash");
  deepguide::test::expect_one_line_error([&] { write_suite(".", "here", p, true, true); }, "outside the current one");
  EXPECT_EQ(read_suite("suite.yaml").name, "slash");  // suite.yaml of the current folder
  std::filesystem::current_path(cwd);
  // One scenario file is a suite of one.
  const Suite one = read_suite(deepguide::test::source_file("data/scenarios/one_obstacle.yaml"));
  ASSERT_EQ(one.scenarios.size(), 1u);
  EXPECT_EQ(one.scenarios[0].id, "one_obstacle");
}

TEST(Suite, BadSuitesAreOneLineErrors) {
  ScratchDir tmp;
  using deepguide::test::expect_one_line_error;
  expect_one_line_error([&] { (void)read_suite(tmp.file("missing")); }, "missing");
  std::filesystem::create_directories(tmp.path() / "empty");
  expect_one_line_error([&] { (void)read_suite(tmp.file("empty")); }, "empty suite");
  std::filesystem::create_directories(tmp.path() / "a");
  tmp.write("a/suite.yaml", "name: a\ngenerate: {scenarios: 0}\n");
  expect_one_line_error([&] { (void)read_suite(tmp.file("a")); }, "generate.scenarios");
  tmp.write("a/suite.yaml", "name: a\ngenerate: {scenarios: 5, colour: red}\n");
  expect_one_line_error([&] { (void)read_suite(tmp.file("a")); }, "colour");
  tmp.write("a/suite.yaml", "name: a\ngenerate: {scenarios: 5, seed: -3}\n");
  expect_one_line_error([&] { (void)read_suite(tmp.file("a")); }, "seed");
  tmp.write("a/suite.yaml", "name: a\ngenerate: {scenarios: 5, min_obstacles: 9}\n");
  expect_one_line_error([&] { (void)read_suite(tmp.file("a")); }, "min_obstacles");
  tmp.write("a/suite.yaml", "name: [a\n");
  expect_one_line_error([&] { (void)read_suite(tmp.file("a")); }, "suite.yaml: line");
  // A broken scenario file is found when it is loaded, not when the suite is read.
  std::filesystem::create_directories(tmp.path() / "b");
  tmp.write("b/s1.yaml", "start: {x: 0, y: 0}\ntarget: {x: 100, y: 0}\n");
  tmp.write("b/s2.yaml", "start: {x: 0, y: 0}\ntarget: {x: 100, y: 0}\nobstacles: 7\n");
  const Suite b = read_suite(tmp.file("b"));
  ASSERT_EQ(b.scenarios.size(), 2u);
  EXPECT_NO_THROW((void)load_suite_scenario(b, 0));
  expect_one_line_error([&] { (void)load_suite_scenario(b, 1); }, "obstacles");
}
