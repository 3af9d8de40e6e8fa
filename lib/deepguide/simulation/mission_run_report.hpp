#pragma once
// `mission simulate` as a library call: the mission planned (every known
// conflict resolved), then sailed with the two-level guidance among the
// objects nobody knew (mission_run.hpp), returned as a report that prints
// itself as text or JSON and says, as one line, what went wrong on the way.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "deepguide/core/api.hpp"
#include "deepguide/core/output_paths.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/mission/mission_environment.hpp"
#include "deepguide/simulation/mission_run.hpp"

namespace DEEPGUIDE_API deepguide {

struct MissionRunRequest {
  std::string mission;               ///< the mission file
  std::vector<std::string> unknown;  ///< obstacle files of objects nobody knew (the simulation's truth only)
  MissionRunOptions options;
  /// Files the caller writes (a drawing of the run): none may be one of the mission's inputs.
  std::vector<NamedPath> outputs;
  /// The caller draws the run: the mission must have charts or obstacle files to draw it over.
  bool drawn = false;
  ChartOptions chart;  ///< how S-57 cells are read
};

struct MissionRunReport {
  std::string file;
  LoadedMission loaded;
  PlannedMission planned;
  MissionRun run;

  nlohmann::json to_json() const;
  std::string to_text() const;
  /// The first alarm raised on the way ("FILE: simulation at T into the mission, lon, lat: what"), or none.
  std::optional<std::string> failure() const;
};

/// Throws InputError for a bad mission or obstacle file (or an output that is
/// an input, or nothing to draw over), NoRouteError for a
/// mission that cannot be planned (a conflict left unresolved, a current the
/// vehicle cannot hold) before anything is sailed.
MissionRunReport simulate_mission_file(const MissionRunRequest& request);

}  // namespace deepguide
