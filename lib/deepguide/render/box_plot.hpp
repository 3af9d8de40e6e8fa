#pragma once
// Box plots of one metric per method (the evaluation report's figures,
// evaluation/eval_report.hpp): for each group a box from the first to the
// third quartile, the median across it, whiskers to the 5th and 95th
// percentiles, the values beyond as dots, and the count under the name.
// Optionally on a log axis (compute times spread over decades), ticks at
// the powers of ten; values <= 0 are then left out (and counted in the label).
// Quantiles: nearest rank, as everywhere in the evaluation.
// Layout (design units at width_px / 1000): title 52 | plot | names 2 lines | 12.

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/render/canvas.hpp"

namespace DEEPGUIDE_API deepguide {

struct BoxGroup {
  std::string label;
  std::vector<double> values;
  Rgba color;
};

struct BoxPlot {
  std::string title;
  std::string y_title;
  std::vector<BoxGroup> groups;
  bool log_y = false;
  int width_px = 1000;
  int height_px = 560;
};

/// Draws the plot to `path` (.png or .svg), atomically. Throws InputError
/// naming the path for no groups, a bad size, or no value to draw.
void render_box_plot(const BoxPlot& plot, const std::string& path);

}  // namespace deepguide
