// deepguide simulate SCENARIO.yaml --method dipole|geometric|potential [-o TRAJ.csv] [--json] [--seed N]
// Exit 0 when the simulation ran, whatever its outcome (reached, collided are
// results); 1 for a bad scenario, an unknown method or an unwritable output;
// 2 for usage.

#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "deepguide/core/output_paths.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/simulation/simulation.hpp"
#include "deepguide/simulation/trajectory_io.hpp"

namespace deepguide::app {
namespace {
struct SimulateOptions {
  std::string scenario;
  std::string method;
  std::string output;
  std::optional<std::uint64_t> seed;
  bool json = false;
};
}  // namespace

void register_simulate(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Simulate the reactive level: vehicle, autopilot, sonar and one reactive method in a scenario");
  cmd->add_option("SCENARIO", o->scenario, "Scenario file (YAML, see data/scenarios/one_obstacle.yaml)")->required();
  cmd->add_option("--method", o->method, "Reactive method: " + reactive_method_names_text())->required();
  cmd->add_option("-o,--output", o->output, "Trajectory file to write (CSV)");
  cmd->add_option("--seed", o->seed, "Sonar seed (overrides the scenario's seed)");
  cmd->add_flag("--json", o->json, "Print the statistics as JSON");
  cmd->callback([o] {
    const ReactiveMethod method = reactive_method_option("--method", o->method);
    check_outputs_apart({{"SCENARIO", o->scenario}}, {{"-o", o->output}});
    Scenario scenario = read_scenario_file(o->scenario);
    if (o->seed) scenario.sonar.seed = *o->seed;
    const SimulationResult result = simulate(scenario, method, {!o->output.empty()});
    if (!o->output.empty()) write_trajectory_csv(o->output, result.trajectory);
    std::cout << (o->json ? simulation_json(scenario, result).dump(2) + "\n" : simulation_text(scenario, result));
  });
}

}  // namespace deepguide::app
