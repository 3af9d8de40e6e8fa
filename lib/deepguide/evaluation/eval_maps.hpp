#pragma once
// The scenarios an evaluation's report points at, as web maps
// (`evaluate --html`; render/scenario_web_map.hpp): per method the run that
// came closest to an obstacle, and its collisions (at most five a method,
// twenty pages in all). Each chosen scenario is run again with every method,
// keeping the tracks (the rows keep only statistics; a run is deterministic,
// so it sails what its row measured), and drawn into OUTPUT/maps/ID.html.

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/evaluation/evaluate.hpp"
#include "deepguide/evaluation/suite.hpp"

namespace DEEPGUIDE_API deepguide {

struct EvaluationMap {
  std::string scenario;  ///< its id
  std::string file;      ///< relative to the output folder: "maps/ID.html"
  std::string why;       ///< e.g. "least clearance of dipole (1.20 m); geometric collided"
};

/// Writes the pages into `dir`/maps (made when missing) and returns them,
/// in the order of the suite. Throws what loading a scenario or writing a
/// page throws (InputError, one line).
std::vector<EvaluationMap> write_evaluation_maps(const Suite& suite, const EvaluationRun& run, const std::string& dir);

}  // namespace deepguide
