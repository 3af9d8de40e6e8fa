#pragma once
// Turning rate over time for the reactive methods (the seed's Fig. 12): one
// panel per method, stacked on a shared time axis and a shared, symmetric
// rate axis so that the peaks compare at a glance. In each panel the
// autopilot's reference rate r_ref (what the guidance asked the vehicle to
// turn, after the autopilot's reference model), the vehicle's rate r, and the
// vehicle's limit +-r_max dashed. (The commanded course's raw rate is in the
// trajectory CSV; its spikes at sonar scans would flatten everything else.)
//
// Units and sign: deg/s, positive clockwise (a turn to starboard), as the
// trajectory CSV writes them (docs/SIMULATION.md); the library's rates are
// math (counter-clockwise) rad/s, hence r_nautical = -rad_to_deg(r).
// Layout (design units at 1200 px wide): title band 52 | per panel: a label
// line 22 and the panel 170, 14 apart | time numbers and title 52 | legend | 10.

#include <span>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/render/plot_furniture.hpp"
#include "deepguide/simulation/simulation.hpp"

namespace DEEPGUIDE_API deepguide {

struct TurnRatePlot {
  std::vector<SimulationResult> runs;  ///< with trajectories
  double max_turn_rate = 0.0;          ///< the vehicle's limit r_max (rad/s), drawn when > 0
  std::string title;
  int width_px = 1200;
};

/// Simulates `scenario` with each of `methods` (recording the trajectories).
TurnRatePlot turn_rate_plot_for(const Scenario& scenario, std::span<const ReactiveMethod> methods);

struct TurnRateLayout {
  int width = 0;
  int height = 0;
  double unit = 1.0;
  std::vector<PixelRect> panels;  ///< one per run, top to bottom
  PlotAxis time;                  ///< s
  double rate_limit_deg_s = 0.0;  ///< the rate axis runs from -this to +this
  PixelRect legend;
};

/// The layout (panels, axis ranges) for the plot. Throws InputError for no
/// runs, an empty trajectory or a bad width.
TurnRateLayout turn_rate_layout(const TurnRatePlot& plot);

/// The rate axis of one panel.
PlotAxis rate_axis(const TurnRateLayout& layout, std::size_t panel);

/// Draws the plot to `path` (.png or .svg), atomically; errors are one line
/// prefixed by the path.
TurnRateLayout render_turn_rate_plot(const TurnRatePlot& plot, const std::string& path);

}  // namespace deepguide
