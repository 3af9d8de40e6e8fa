#pragma once
// The identification run's figure (the seed's Figs. 14-16): the object and
// the other true obstacles on the reactive map (reactive_map.hpp), the
// current as a grid of arrows (at the run's start), and the vehicle's track
// over ground coloured by mode, with a dot and the time at every mode switch.
//   aligning      the safety ellipse (the standoff zone), the borderline
//                 through the object's centre across the current, the
//                 positioning area (the flow shade) shaded downstream of it,
//                 the lee goal point on the safety ellipse and the held point
//                 (the map's target, "held point")
//   going around  the offset path at the requested distance (dashed), and
//                 where the vehicle was first on it (the map's target, "on the path")
// The legend says the mode colours, the current, and the run's outcome
// (identification_run.hpp statistics) in one line.

#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/render/reactive_map.hpp"
#include "deepguide/simulation/identification_run.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace DEEPGUIDE_API deepguide {

struct IdentificationFigure {
  ReactiveMap map;
  Scenario scenario;   ///< with its identify section (the object, the mode, the current)
  IdentifyResult run;  ///< with its trajectory
  int width_px = 1200;
};

/// Runs the scenario's identify section (recording the trajectory) and titles
/// the figure. Throws InputError as simulate_identification does.
IdentificationFigure identification_figure_for(const Scenario& scenario);

/// The legend line of the run, e.g. "held 300 s from 355 s; distance error RMS
/// 0.14 m, station keeping 0.66 m; min clearance 11.0 m".
std::string identification_summary(const IdentifyResult& run);

/// The colour of a mode's stretch of track.
Rgba phase_color(IdentifyPhase phase);

/// Draws the figure to `path` (.png or .svg), atomically; returns the layout.
/// Throws InputError (prefixed by the path) for an empty trajectory, a bad
/// width or a bad extension.
ReactiveMapLayout render_identification_figure(const IdentificationFigure& figure, const std::string& path);

}  // namespace deepguide
