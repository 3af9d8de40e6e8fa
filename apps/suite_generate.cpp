// deepguide suite generate DIR ...: a seeded scenario suite for deepguide evaluate

#include <iostream>
#include <memory>
#include <utility>

#include "commands.hpp"
#include "deepguide/evaluation/suite.hpp"

namespace deepguide::app {

void register_suite(CLI::App& app) {
  CLI::App* suite = app.add_subcommand("suite", "Scenario suites for deepguide evaluate");
  suite->require_subcommand(1);
  auto o = std::make_shared<std::pair<std::string, MonteCarloParams>>();
  auto name = std::make_shared<std::string>();
  auto flags = std::make_shared<std::pair<bool, bool>>(false, false);  // on demand, overwrite
  CLI::App* cmd = suite->add_subcommand("generate", "Write a seeded random suite (scenario files and suite.yaml)");
  MonteCarloParams& p = o->second;
  cmd->add_option("DIR", o->first, "Folder to create")->required();
  cmd->add_option("--name", *name, "Suite name (default: the folder's name)");
  cmd->add_option("--scenarios", p.scenarios, "How many scenarios")->capture_default_str();
  cmd->add_option("--seed", p.seed, "Random seed")->capture_default_str();
  cmd->add_option("--min-obstacles", p.min_obstacles, "Fewest obstacles per scenario")->capture_default_str();
  cmd->add_option("--max-obstacles", p.max_obstacles, "Most obstacles per scenario")->capture_default_str();
  cmd->add_option("--min-size", p.min_size_m, "Smallest semi-major axis (m)")->capture_default_str();
  cmd->add_option("--max-size", p.max_size_m, "Largest semi-major axis (m)")->capture_default_str();
  cmd->add_option("--spread", p.cross_track_sigma_m,
                  "Cross-track spread of the obstacles, sigma (m); with the count, the density")
      ->capture_default_str();
  cmd->add_option("--max-current", p.max_current_mps, "Fastest uniform current (m/s)")->capture_default_str();
  cmd->add_option("--sonar-noise", p.sonar_noise, "Factor on the sonar's error sigmas (0 = exact)")
      ->capture_default_str();
  cmd->add_flag("--on-demand", flags->first, "Write only suite.yaml: evaluate makes the scenarios as it runs");
  cmd->add_flag("--overwrite", flags->second, "Replace the folder if it exists");
  cmd->callback([o, name, flags] {
    const std::string n = write_suite(o->first, *name, o->second, !flags->first, flags->second);
    std::cout << "wrote suite " << n << " to " << o->first << ": " << o->second.scenarios << " scenarios"
              << (flags->first ? " (made on demand from suite.yaml)" : "") << "\n";
  });
}

}  // namespace deepguide::app
