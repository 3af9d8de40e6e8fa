#pragma once
// A mission's route quality on ENCs, phase by phase: what an ECDIS's route
// check reports (charts/enc_route_quality.hpp) for each complex manoeuvre of
// a plan (a phase: a track, a survey, a goto, an identification with the
// evasions mission control put into it), judged at that phase's required
// depth: its deepest depth plus the mission's vertical clearance. The no-go
// the nearest feature is found in is read once per distinct required depth,
// with the chart options the command was given.

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "deepguide/charts/chart_options.hpp"
#include "deepguide/charts/enc_route_quality.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/mission.hpp"

namespace DEEPGUIDE_API deepguide {

struct PhaseQuality {
  std::size_t manoeuvre = 0;  ///< index into Mission::manoeuvres
  std::string type, name;
  double depth_m = 0.0;           ///< the deepest the phase goes
  double required_depth_m = 0.0;  ///< depth_m + the mission's vertical clearance
  double from_m = 0.0;            ///< where it begins along the plan
  RouteQuality quality;
};

/// One entry per complex manoeuvre of `plan` that moves (a phase that only
/// holds a point has no route); empty when the mission names no S-57 cells.
/// Throws what enc_no_go throws.
std::vector<PhaseQuality> phase_quality(const Mission& mission, const MissionPlan& plan, const ChartOptions& chart);

/// [{"manoeuvre": 1-based, "type", "name", "depth_m", "required_depth_m", "from_m",
///   "length_m", and RouteQuality::to_json's fields}, ...]
nlohmann::json phase_quality_json(const std::vector<PhaseQuality>& phases, const LocalFrame& frame);
/// A "phase N" line per phase, each followed by its quality's lines; "" for none.
std::string phase_quality_text(const std::vector<PhaseQuality>& phases, const LocalFrame& frame);

}  // namespace deepguide
