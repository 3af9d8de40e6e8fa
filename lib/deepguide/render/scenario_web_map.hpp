#pragma once
// A scenario and what each method did in it, as a web map
// (render/web_map.hpp): the pages `evaluate --html` links from its report.
//
// Layers: the obstacles (their true footprints, named by a click) and their
// security zones at the reactive margin, the start and the target, and per
// method its track sailed (and a planner's route), each with its end, least
// clearance and whether it collided. A scenario with a CRS is drawn in
// lon/lat; one without (a generated suite's) on a plain plane in metres.

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/render/web_map.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace DEEPGUIDE_API deepguide {

/// What one method did in the scenario (local frame).
struct ScenarioTrack {
  std::string method;
  std::string end;   ///< reached, collided, no_route, ...
  std::string note;  ///< why there is no route, what it collided with
  bool collided = false;
  double min_clearance_m = 0.0;
  double path_length_m = 0.0;
  std::vector<Vec2> route;  ///< a planner's (empty for a reactive method)
  std::vector<Vec2> track;  ///< sailed
};

WebMap scenario_web_map(const Scenario& scenario, const std::string& title, const std::vector<ScenarioTrack>& runs);

}  // namespace deepguide
