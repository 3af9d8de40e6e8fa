#pragma once
// Scenario suites: the sets of scenarios `deepguide evaluate` runs
// (docs/EVALUATION.md, data/scenarios/suites/).
//
// A suite is a folder. Its scenario files (every *.yaml but suite.yaml, in
// name order) are the suite; a folder without any takes its scenarios from
// the generator in suite.yaml, on demand, so a suite of a million scenarios
// is one small file. suite.yaml, when present:
//   name: small                      (default: the folder's name)
//   generate: {scenarios, seed, min_obstacles, max_obstacles, min_size_m,
//              max_size_m, cross_track_sigma_m, max_current_mps, sonar_noise}
//              (evaluation/monte_carlo.hpp; every key optional but scenarios)
// A generated scenario k is called scenario-NNNN (k, at least 4 digits),
// whether it was written to a file or is made on demand: the two give the
// same rows. A single scenario file is a suite of one.
//
// Reading a suite parses no scenario: a broken scenario file is found when
// it is run (load_suite_scenario throws), so the rest of the suite still runs.
//
// Fingerprint: what the suite's rows depend on, hashed (64-bit FNV-1a), so a
// resumed or merged run can tell that the suite changed under the same name
// and size: every scenario file's id and bytes (an unreadable one, or one
// over the reader's 4 MiB, as such), or, for a suite made on demand, the
// generator's version and every setting at full precision. Files a scenario
// refers to (vehicle, obstacles_file, current_file) are not hashed: a change
// there goes unnoticed. A suite written to files and the same made on demand
// give the same rows but different fingerprints.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/evaluation/monte_carlo.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace DEEPGUIDE_API deepguide {

struct SuiteScenario {
  std::string id;      ///< the file's stem, or scenario-NNNN
  std::string path;    ///< the file; empty when generated on demand
  int generated = -1;  ///< the generator's index when generated on demand
};

struct Suite {
  std::string name;
  std::string source;                         ///< the folder or file given
  std::optional<MonteCarloParams> generator;  ///< from suite.yaml
  std::vector<SuiteScenario> scenarios;
  std::string fingerprint;  ///< "fnv1a64:" and 16 hex digits (header)
};

/// Reads a suite folder, its suite.yaml, or one scenario file. Throws
/// InputError for a missing path, a bad suite.yaml (line and key) or a folder
/// with neither scenario files nor a generator.
Suite read_suite(const std::string& path);

/// Scenario `index` of the suite, read or generated. Throws InputError (the
/// scenario reader's one line) for a broken one.
Scenario load_suite_scenario(const Suite& suite, std::size_t index);

/// The id of generated scenario k of a suite of `count`.
std::string generated_scenario_id(int k, int count);

/// suite.yaml's text for a generated suite.
std::string suite_yaml(const std::string& name, const MonteCarloParams& params);

/// Writes a generated suite to the folder `dir`: suite.yaml, and with
/// `files` every scenario as scenario-NNNN.yaml. The folder must not exist
/// (or, with `overwrite`, is replaced); it appears whole or not at all (it is
/// written beside it under a temporary name and renamed). An empty `name`
/// is the folder's own name. Returns the name written. Throws InputError.
std::string write_suite(const std::string& dir, const std::string& name, const MonteCarloParams& params, bool files,
                        bool overwrite);

}  // namespace deepguide
