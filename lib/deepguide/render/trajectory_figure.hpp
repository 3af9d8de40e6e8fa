#pragma once
// The methods' trajectories through one scenario (the seed's Fig. 11): the
// simulated tracks over ground of each method (simulation.hpp: vehicle,
// autopilot, sonar, contacts) on the reactive map (reactive_map.hpp), one
// colour per method, a cross where a run ended short of the target, a red
// ring where a run that collided was deepest inside an obstacle, and a
// legend line per method with its outcome: why it ended, time, path length,
// the smallest clearance to the true footprints and the largest turning rate.
//
// The zones drawn are the true obstacles' security zones; the methods steered
// by the sonar's noisy contacts, so a track may touch a drawn zone or keep
// off it by a little.

#include <span>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/render/reactive_map.hpp"
#include "deepguide/simulation/simulation.hpp"

namespace DEEPGUIDE_API deepguide {

struct TrajectoryFigure {
  ReactiveMap map;
  std::vector<SimulationResult> runs;  ///< with trajectories
  int width_px = 1200;
};

/// Simulates `scenario` with each of `methods` (recording the trajectories)
/// and titles the figure with the scenario's name.
TrajectoryFigure trajectory_figure_for(const Scenario& scenario, std::span<const ReactiveMethod> methods);

/// The legend line of a run: "geometric: reached in 195.3 s, 401.9 m, min clearance 10.1 m, max |r| 2.0 °/s".
std::string run_summary(const SimulationResult& run);

/// Draws the figure to `path` (.png or .svg), atomically; returns the layout.
/// Throws InputError (one line, prefixed by the path) for no runs, an empty
/// trajectory, a bad width or a bad extension.
ReactiveMapLayout render_trajectory_figure(const TrajectoryFigure& figure, const std::string& path);

}  // namespace deepguide
