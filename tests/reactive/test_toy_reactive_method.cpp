// A reactive method added from outside the library, through its public
// interface only (reactive/reactive_registry.hpp): this file and its
// registration are all it takes for reactive_command, a scenario file's
// `reactive:` keys, `simulate --method brake` and `evaluate --methods brake`
// (run in-process, app::run) to use it.
//
// The toy method, "brake": straight at the target, and stop (stalled) as
// soon as a security zone lies across the line of sight within
// `toy_stop_m` of the vehicle. It never passes an object, so it never
// collides with one it has seen: the property the tests check. Its memory
// counts its steps, to show a method's own state kept between calls.
#include <gtest/gtest.h>

#include <algorithm>
#include <any>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/in_process_cli.hpp"
#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"
#include "deepguide/reactive/geometric_construction.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/simulation/scenario_writer.hpp"
#include "deepguide/simulation/simulation.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

struct ToyMemory {
  int steps = 0;
};

/// The first zone across the segment p -> p + reach towards the target, or -1.
std::ptrdiff_t blocking(const ReactiveParams& params, const Vec2& p, const Vec2& target,
                        std::span<const Ellipse> objects, double reach) {
  const Vec2 to = target - p;
  const Vec2 end = to.norm() <= reach ? target : Vec2(p + reach * to.normalized());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (segment_intersects(security_ellipse(objects[i], params.margin_m), p, end))
      return static_cast<std::ptrdiff_t>(i);
  }
  return -1;
}

ReactiveCommand toy_command(const ReactiveParams& params, ReactiveMemory& memory, const ReactiveInput& in) {
  ++method_state<ToyMemory>(memory).steps;
  ReactiveCommand c;
  c.course = in.course;
  if ((in.target - in.position).norm() <= params.arrival_radius_m) {
    c.status = ReactiveStatus::arrived;
    return c;
  }
  c.active_object = blocking(params, in.position, in.target, in.objects, tuning_value(params, "toy_stop_m"));
  if (c.active_object >= 0) {
    c.status = ReactiveStatus::stalled;
    return c;
  }
  c.course = math_angle(in.target - in.position);
  c.speed_mps = params.speed_mps;
  return c;
}

Vec2 toy_gradient(const ReactiveParams& params, const Vec2& p, const Vec2& target, std::span<const Ellipse> objects) {
  if (blocking(params, p, target, objects, tuning_value(params, "toy_stop_m")) >= 0) return {0.0, 0.0};
  return (target - p).norm() > 0.0 ? Vec2((target - p).normalized()) : Vec2(0.0, 0.0);
}

const bool kRegistered = [] {
  register_reactive_method({"brake",
                            "straight at the target, stops before a zone",
                            0x000000,
                            {{"toy_stop_m", 30.0, 0.0, 1e4, false, true, "a distance in metres"}},
                            toy_command,
                            toy_gradient});
  return true;
}();

// Not "toy": the toy graph (planning/test_toy_graph.cpp) is registered in this
// program too, and evaluate would take the reactive method for it.
const ReactiveMethod kToy{"brake"};

ReactiveInput input_at(const Vec2& p, const Vec2& target, std::span<const Ellipse> objects) {
  ReactiveInput in;
  in.position = p;
  in.target = target;
  in.objects = objects;
  return in;
}

}  // namespace

TEST(ToyReactiveMethod, StepsThroughTheRegistryWithItsOwnParameterAndMemory) {
  ASSERT_TRUE(kRegistered);
  ASSERT_EQ(parse_reactive_method("brake"), kToy);
  const std::vector<Ellipse> rock{Ellipse{Vec2(100.0, 0.0), 10.0, 10.0, 0.0}};
  ReactiveParams params;  // margin 10: the zone reaches x = 80
  ReactiveMemory memory;
  memory.state = GeometricMemory{};  // another method's memory is replaced, not misread
  // 50 m from the zone, beyond the default 30 m: straight on, east.
  ReactiveCommand c = reactive_command(kToy, params, memory, input_at({30.0, 0.0}, {200.0, 0.0}, rock));
  EXPECT_EQ(c.status, ReactiveStatus::ok);
  EXPECT_NEAR(c.course, 0.0, 1e-15);
  EXPECT_EQ(c.speed_mps, params.speed_mps);
  // 25 m from it: stopped, the rock named.
  c = reactive_command(kToy, params, memory, input_at({55.0, 0.0}, {200.0, 0.0}, rock));
  EXPECT_EQ(c.status, ReactiveStatus::stalled);
  EXPECT_EQ(c.speed_mps, 0.0);
  EXPECT_EQ(c.active_object, 0);
  // Its own parameter, given by name: a reach of 20 m lets it go on from 25 m.
  params.tuning["toy_stop_m"] = 20.0;
  c = reactive_command(kToy, params, memory, input_at({55.0, 0.0}, {200.0, 0.0}, rock));
  EXPECT_EQ(c.status, ReactiveStatus::ok);
  EXPECT_EQ(std::any_cast<ToyMemory>(memory.state).steps, 3);
  // The same checks of the parameter as the built-in methods': out of range, unknown.
  params.tuning["toy_stop_m"] = 0.0;
  EXPECT_THROW(validate(params), InputError);
  params.tuning.clear();
  params.tuning["toy_stopp_m"] = 20.0;
  EXPECT_THROW(validate(params), InputError);
  // The memoryless gradient through the registry too.
  EXPECT_EQ(reactive_gradient(kToy, {}, {55.0, 0.0}, {200.0, 0.0}, rock), Vec2(0.0, 0.0));
  EXPECT_EQ(reactive_gradient(kToy, {}, {55.0, 30.0}, {200.0, 30.0}, rock), Vec2(1.0, 0.0));
}

TEST(ToyReactiveMethod, TheRegistryRefusesWhatWouldBeAmbiguous) {
  ASSERT_TRUE(kRegistered);
  const auto entry = [](std::string name, std::string key) {
    return ReactiveMethodEntry{
        std::move(name), "x", 0, {{std::move(key), 1.0, 0.0, 2.0, false, true, "a number"}}, toy_command, toy_gradient};
  };
  EXPECT_THROW(register_reactive_method(entry("brake", "toy2_m")), InputError);  // the name is taken
  EXPECT_THROW(register_reactive_method(entry("to,y", "toy2_m")), InputError);
  EXPECT_THROW(register_reactive_method(entry("to\ny", "toy2_m")),
               InputError);  // a name shown in help and messages          // evaluate's list syntax
  EXPECT_THROW(register_reactive_method(entry("toy2", "potential_gain")), InputError);  // the key is the potential's
  ReactiveMethodEntry stepless = entry("toy2", "toy2_m");
  stepless.command = nullptr;
  EXPECT_THROW(register_reactive_method(stepless), InputError);  // no step function
  EXPECT_EQ(reactive_method_names_text(), "dipole, geometric, potential or brake");
  EXPECT_THROW(reactive_method_named("toy2", "--method"), InputError);
}

TEST(ToyReactiveMethod, AScenarioFileCarriesItsParameter) {
  ASSERT_TRUE(kRegistered);
  test::ScratchDir dir;
  const std::string path = dir.file("toy.yaml");
  auto write = [&](const std::string& reactive) {
    std::ofstream(path) << "name: toy\nstart: {x: 0, y: 0}\ntarget: {x: 300, y: 0}\n"
                        << "obstacles:\n  - {id: rock, x: 150, y: 0, semi_major_m: 10, semi_minor_m: 10}\n"
                        << "reactive: " << reactive << "\n";
  };
  write("{margin_m: 10, toy_stop_m: 45}");
  const Scenario sc = read_scenario_file(path);
  EXPECT_EQ(tuning_value(sc.reactive, "toy_stop_m"), 45.0);
  EXPECT_EQ(tuning_value(sc.reactive, "geometric_passage_m"), 20.0);  // not given: the default
  // Written back with every method's parameters, and read back the same.
  const std::string again = dir.file("again.yaml");
  std::ofstream(again) << scenario_yaml(sc);
  const Scenario back = read_scenario_file(again);
  for (const ReactiveTuning& t : reactive_tunings()) {
    EXPECT_EQ(tuning_value(back.reactive, t.key), tuning_value(sc.reactive, t.key)) << t.key;
  }
  write("{toy_stop_m: -1}");
  test::expect_one_line_error([&] { (void)read_scenario_file(path); }, "reactive.toy_stop_m");
  write("{toy_stop: 3}");
  test::expect_one_line_error([&] { (void)read_scenario_file(path); }, "toy_stop");
}

TEST(ToyReactiveMethod, SimulateAndEvaluateRunIt) {
  ASSERT_TRUE(kRegistered);
  // It stops short of the boulder and never touches it; the geometric method passes it.
  const std::string scenario = test::source_file("data/scenarios/one_obstacle.yaml");
  const Scenario sc = read_scenario_file(scenario);
  const SimulationResult toy = simulate(sc, kToy);
  EXPECT_EQ(toy.end, SimulationEnd::stalled);
  EXPECT_FALSE(toy.stats.collided);
  // It coasts on after the stop (the plant slows down, it does not halt) and
  // the sonar's estimate is noisy: inside the security zone, clear of the rock.
  EXPECT_GT(toy.stats.min_clearance_m, 0.0);
  EXPECT_LT(toy.stats.min_clearance_m, sc.reactive.margin_m + tuning_value(sc.reactive, "toy_stop_m"));
  const test::CliRun run = test::deepguide_cli({"simulate", scenario, "--method", "brake", "--json"});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(nlohmann::json::parse(run.out).at("end"), "stalled");
  const test::CliRun help = test::deepguide_cli({"simulate", "--help"});
  EXPECT_NE(help.out.find("dipole, geometric, potential or brake"), std::string::npos) << help.out;

  test::ScratchDir dir;
  const std::string suite = dir.file("suite"), out = dir.file("out");
  ASSERT_EQ(test::deepguide_cli({"suite", "generate", suite, "--scenarios", "3", "--seed", "5"}).code, 0);
  const test::CliRun r = test::deepguide_cli(
      {"evaluate", suite, "--methods", "brake,geometric", "--threads", "1", "--no-report", "-q", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(out + "/rows.csv");
  const auto fields = [](const std::string& line) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    return f;
  };
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = fields(line);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t method = column("method"), collided = column("collided"), end = column("end");
  ASSERT_LT(std::max({method, collided, end}), header.size()) << line;
  int toy_rows = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> row = fields(line);
    ASSERT_GT(row.size(), std::max({method, collided, end})) << line;
    if (row[method] != "brake") continue;
    ++toy_rows;
    EXPECT_EQ(row[collided], "0") << line;  // it stops rather than pass an object
    EXPECT_TRUE(row[end] == "reached" || row[end] == "stalled") << line;
  }
  EXPECT_EQ(toy_rows, 3);
}
