#pragma once
// What an evaluation's rows say: per method the counts, medians and 95th
// percentiles of every metric and the wins; and whether the seed's two claims
// hold on them (docs/EVALUATION.md):
//   1. "the visibility graph ... is justified by its smaller computation cost
//      and the form of the determined paths" compared with the quadtree graph:
//      cheaper = a smaller median compute time (with --no-timing: a smaller
//      median graph, vertices + edges); better routes = the visibility route
//      is no longer than the quadtree's in most scenarios and the median
//      length ratio quadtree / visibility is at least 1 (paired, scenarios
//      where both found a route).
//   2. "with the geometrical construction the reference turning rate r
//      possesses substantially smaller maximum values than by the harmonic
//      dipole potentials": the max |r_ref| of geometric below dipole's in most
//      scenarios, and its median below dipole's (paired, every scenario both ran).
// A claim whose methods are not in the run is "not tested".
// Wins: per scenario, the methods that reached the target without a collision
// and spent the least energy (within 1 J; ties win together).

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/evaluation/evaluate.hpp"
#include "deepguide/evaluation/monte_carlo.hpp"

namespace DEEPGUIDE_API deepguide {

struct MethodStats {
  std::string method;
  int runs = 0, reached = 0, collisions = 0, no_route = 0, other_ends = 0, wins = 0;
  int unavoidable = 0;  ///< of the collisions, those no guidance could have avoided (MethodRun::unavoidable)
  Distribution path_length_m, route_length_m, energy_kj, time_s, min_clearance_m;
  Distribution max_rate_ref_deg_s, rms_rate_ref_deg_s, compute_ms, graph_size;
};

struct ClaimCheck {
  std::string claim;                  ///< the seed's words, shortened
  std::string verdict;                ///< "holds", "does not hold" or "not tested"
  std::vector<std::string> evidence;  ///< lines with the numbers
};

struct EvaluationSummary {
  std::vector<MethodStats> methods;  ///< in the run's order
  std::vector<ClaimCheck> claims;    ///< the seed's two claims
};

EvaluationSummary summarize(const EvaluationRun& run);

/// The summary as Markdown (summary.md; also what the terminal shows).
std::string summary_markdown(const EvaluationRun& run, const EvaluationSummary& summary);

/// "wrote DIR/rows.csv, ... (N rows[, K kept from the earlier run])": what a
/// run left in its folder, one line.
std::string outputs_line(const EvaluationRun& run, const std::string& dir, bool with_report);
/// "N run(s) skipped, the first: SCENARIO with METHOD: ERROR"; empty when none was.
std::string skipped_line(const EvaluationRun& run);

/// The methods table's columns: summary.md and report.html draw the same
/// table from this one list. A cell is text ("–" where there is no value).
struct MethodColumn {
  std::string header;
  std::function<std::string(const MethodStats&)> cell;
  bool numeric = true;  ///< right-aligned
};
std::vector<MethodColumn> method_columns(const RunManifest& manifest);

/// What results.json holds: the suite, its methods, the skipped runs, the
/// summary per method, the seed's claims judged and every row.
nlohmann::json results_json(const EvaluationRun& run, const EvaluationSummary& summary);

/// Writes results.json (manifest, rows, summary, claims) and summary.md into `dir`.
void write_results(const std::string& dir, const EvaluationRun& run);

}  // namespace deepguide
