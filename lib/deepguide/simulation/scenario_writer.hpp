#pragma once
// A scenario as a YAML document the scenario reader (scenario.hpp) reads back:
// what evaluation suites are made of (evaluation/suite.hpp).
//
// Numbers are written in their shortest form that reads back to the same
// double, so a position, a size or a seed survives the trip exactly; angles
// (orientation, current direction) are converted to nautical degrees and back
// and agree to about 1e-14 rad.
//
// What is written: name, start, target, start_heading_deg (when set),
// depth_m, the obstacles (elliptic cylinders with their vertical extents
// dropped: the reactive level ignores them), a uniform current, the sonar and
// its seed, every reactive parameter, contacts, energy, max_time_s (when
// set), stall_time_s, no_progress_s and reversal_dead_band_deg_s.
// What cannot be written is refused (InputError naming the scenario): a CRS,
// a gridded current field and an identify section. The vehicle is not
// written: the reader's default (DeepC-like) is assumed, which is the only
// vehicle the suite generator uses.

#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace DEEPGUIDE_API deepguide {

/// The scenario as YAML text, with `comment` (lines without '#') on top.
std::string scenario_yaml(const Scenario& scenario, const std::string& comment = "");

}  // namespace deepguide
