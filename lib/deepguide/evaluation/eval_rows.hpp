#pragma once
// The rows of an evaluation: one per (scenario, method), as CSV (the run's
// journal and its result, docs/EVALUATION.md) and JSON.
//
// CSV columns, in this order (units in the names; rates in deg/s, their
// magnitudes; "inf" for the clearance of a scenario without obstacles):
//   scenario_index, scenario, method, end, reached, collided, unavoidable,
//   route_length_m, path_length_m, energy_kj, time_s, min_clearance_m, max_rate_ref_deg_s,
//   rms_rate_ref_deg_s, max_rate_deg_s, rms_rate_deg_s, heading_reversals,
//   compute_ms, graph_vertices, graph_edges, note
// Numbers have fixed decimals (mm, J, ms/1000, ...), so the same run writes
// the same bytes; reading a row back gives the numbers as written, and every
// summary is made from rows read back, so a resumed or merged run summarises
// exactly as an uninterrupted one.

#include <cstddef>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/evaluation/eval_method.hpp"

namespace DEEPGUIDE_API deepguide {

struct EvalRow {
  std::size_t scenario_index = 0;  ///< position in the suite
  std::string scenario;            ///< its id
  std::string method;              ///< the method's canonical name
  MethodRun run;
};

/// The header line (with "\n").
std::string eval_rows_header();
/// One row as a CSV line (with "\n"); with `timing` false compute_ms is written as 0.
std::string eval_row_csv(const EvalRow& row, bool timing = true);

/// Parses rows written by eval_row_csv. `source` names the file in errors.
/// With `lenient` a last line without its newline (a run killed while
/// writing) and lines that do not parse are dropped and counted in *dropped;
/// without, they are InputErrors naming the line.
std::vector<EvalRow> parse_eval_rows(const std::string& text, const std::string& source, bool lenient,
                                     std::size_t* dropped = nullptr);

}  // namespace deepguide
