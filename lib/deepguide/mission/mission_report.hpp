#pragma once
// `mission check`, `mission plan` and `mission export` as library calls: a
// mission file read with its environment, its basic manoeuvres, what
// endangers them and what mission control makes of it, returned as reports
// that print themselves as text or JSON and say, as one line, why the
// mission cannot be sailed (a conflict left unresolved, a current the
// vehicle cannot hold, a plan the checker refuses).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "deepguide/core/api.hpp"
#include "deepguide/core/output_paths.hpp"
#include "deepguide/mission/collision_observation.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/mission/mission_environment.hpp"
#include "deepguide/mission/phase_quality.hpp"
#include "deepguide/mission/plan_check.hpp"
#include "deepguide/mission/route_export.hpp"

namespace DEEPGUIDE_API deepguide {

/// What `mission check` reports: the plan as written, its conflicts, which of
/// them mission control cannot resolve, and the legs a constant current beats.
struct MissionCheckReport {
  std::string file;
  LoadedMission loaded;
  ObservationOptions observe;
  std::vector<Conflict> conflicts;
  PlannedMission planned;
  std::vector<BeatenLeg> beaten;
  std::vector<PhaseQuality> chart_quality;  ///< the plan as written, per phase, on S-57 cells

  nlohmann::json to_json() const;
  std::string to_text() const;
  /// Why the mission cannot be sailed (NoRouteError's text), or none.
  std::optional<std::string> failure() const;
};
MissionCheckReport check_mission_file(const std::string& path, const ChartOptions& chart = {});

/// What `mission plan` reports: the plan with every conflict evaded or
/// identified, and the plan checker's verdict on it.
struct MissionPlanReport {
  std::string file;
  LoadedMission loaded;
  PlannedMission planned;
  MissionPlanCheck verdict;
  std::vector<PhaseQuality> chart_quality;  ///< the planned mission, per phase, on S-57 cells

  nlohmann::json to_json() const;
  std::string to_text() const;
  std::optional<std::string> failure() const;
};
MissionPlanReport plan_mission_file(const std::string& path, const ChartOptions& chart = {});

struct MissionExportRequest {
  std::string mission;                 ///< the mission file
  std::string output;                  ///< the file to write
  std::optional<ExportFormat> format;  ///< none: from the output's extension
  ExportOptions options;
  bool as_written = false;  ///< the plan as written, without mission control's changes
  ChartOptions chart;       ///< how S-57 cells are read
};
struct MissionExportReport {
  ExportFormat format = ExportFormat::geojson;
  std::size_t basic_manoeuvres = 0, waypoints = 0;
  double length_m = 0.0;
  std::vector<std::string> warnings;  ///< exporting as written: what is left unresolved
  /// "wrote FILE (FORMAT): N basic manoeuvres, W waypoints, L m"
  std::string to_text(const std::string& output) const;
};
/// Plans the mission (unless as written), refuses with NoRouteError what
/// check_mission_file would, and writes it. The output may not be an input.
MissionExportReport export_mission_file(const MissionExportRequest& request);

/// "FILE: N conflict(s) could not be resolved; the first, with ..." for a
/// conflict mission control could not resolve (or one observation still
/// finds in the planned mission); none when every conflict is resolved.
std::optional<std::string> unresolved_conflicts(const std::string& file, const LoadedMission& loaded,
                                                const PlannedMission& planned);
/// "FILE: the C m/s current beats the vehicle on N basic manoeuvre(s); ..." or none.
std::optional<std::string> legs_beaten(const std::string& file, const LoadedMission& loaded,
                                       const std::vector<BeatenLeg>& beaten);
/// The files a mission reads, named by their keys (none may be an output: check_outputs_apart).
std::vector<NamedPath> mission_input_files(const std::string& file, const Mission& mission);

}  // namespace deepguide
