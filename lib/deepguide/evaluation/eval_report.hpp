#pragma once
// The evaluation's report: a box plot per metric (render/box_plot.hpp) and
// one HTML page (report.html) with the summary table, the seed's claims and
// the figures, in the output folder. The page is plain HTML with the figures
// beside it as PNG files: it opens in any browser, offline, and prints.
// Figures: fig_path_length.png, fig_energy.png, fig_time.png,
// fig_min_clearance.png, fig_max_rate_ref.png, fig_rms_rate_ref.png,
// fig_compute_ms.png (log axis; only with timing) and fig_graph_size.png
// (log axis; planners only, when the run has one).

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/evaluation/eval_maps.hpp"
#include "deepguide/evaluation/evaluate.hpp"

namespace DEEPGUIDE_API deepguide {

/// Writes the figures and report.html into `dir`; returns the figure file
/// names. `maps` (evaluate --html, eval_maps.hpp) are linked from the page.
std::vector<std::string> write_report(const std::string& dir, const EvaluationRun& run,
                                      const std::vector<EvaluationMap>& maps = {});

}  // namespace deepguide
