#pragma once
// Batch evaluation: every scenario of a suite through every method, one row
// each, in parallel, resumable and shardable (docs/EVALUATION.md).
//
// Parallel: a pool of threads takes (scenario, method) jobs in order; each
// job is a pure function of its scenario and method. The journal takes rows
// as they finish (no result slot waits for a slower job before it, and a
// kill loses no finished row); the rows themselves stay in memory for the
// summary (about 250 B each). At the end rows.csv is rewritten in canonical
// order, so the output is the same for any number of threads (compute_ms
// aside: it is a measurement; --no-timing writes it as 0).
// Resumable: rows.csv in the output folder is the run's journal, one flushed
// line per finished row. A run started again on the same folder keeps the
// rows there (a line cut off by the kill is dropped) and computes only the
// missing ones; run.json says which suite (name, size and fingerprint:
// suite.hpp), methods and shard the folder holds, and a different run, or the
// same suite changed since, is refused.
// Shardable: shard K of N (1-based) runs the scenarios whose index i has
// i mod N = K - 1, with all their methods; merge_evaluations joins the
// shards' folders into one, which equals the unsharded run's.
// A scenario that cannot be read or run is skipped (reported in run.json,
// results.json and the summary), and the rest runs.
// The end: rows.csv rewritten in canonical order (scenario, then the methods
// as asked), results.json, summary.md and the report (eval_report.hpp).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/evaluation/eval_method.hpp"
#include "deepguide/evaluation/eval_rows.hpp"
#include "deepguide/evaluation/suite.hpp"

namespace DEEPGUIDE_API deepguide {

struct Shard {
  int index = 1;  ///< K, 1 .. count
  int count = 1;  ///< N
  bool operator==(const Shard&) const = default;
};
/// "K/N" with 1 <= K <= N <= 100000; InputError naming `shard` otherwise.
Shard parse_shard(const std::string& text);
/// The shard of a Slurm array task: K = SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN + 1,
/// N = SLURM_ARRAY_TASK_COUNT (the variables' values; `task_min` may be null:
/// 0). The array's ids must be consecutive. InputError naming the variable otherwise.
Shard slurm_array_shard(const char* task_id, const char* task_min, const char* task_count);
/// Worker threads from SLURM_CPUS_PER_TASK's value (1..1024); 0 (every core)
/// when it is null or not such a number.
int slurm_cpus_per_task(const char* value);
/// One line of progress: a bar, runs done of total, the time elapsed and the
/// time left (estimated from the rate so far), as H:MM:SS.
std::string progress_line(std::size_t done, std::size_t total, double elapsed_s);

struct SkippedRun {
  std::size_t scenario_index = 0;
  std::string scenario;
  std::string method;  ///< empty: the scenario itself could not be read
  std::string error;   ///< one line
};

/// What an output folder holds (run.json).
struct RunManifest {
  std::string suite;              ///< the suite's name
  std::string suite_source;       ///< where it was read (informative)
  std::size_t scenarios = 0;      ///< in the whole suite
  std::string suite_fingerprint;  ///< Suite::fingerprint; empty in folders written before it was kept
  std::vector<std::string> methods;
  Shard shard;
  bool timing = true;
  std::vector<SkippedRun> skipped;
};

struct EvaluateOptions {
  std::vector<EvalMethod> methods;
  int threads = 0;  ///< 0: every core
  Shard shard;
  bool timing = true;  ///< false: compute_ms written as 0 (byte-identical reruns)
  bool fresh = false;  ///< discard the rows of an earlier run in the folder
  bool report = true;  ///< write the report's figures and page (eval_report.hpp)
  /// Write maps/ of the scenarios where the methods came closest to an
  /// obstacle or collided, linked from the report (eval_maps.hpp).
  bool maps = false;
  /// Called from the calling thread after each row is written: rows done, rows to do.
  std::function<void(std::size_t done, std::size_t total)> progress;
  /// Called from the calling thread with a line for each skipped run as it happens.
  std::function<void(const std::string& line)> warn;
  /// Test hook: stop (as if killed) after this many new rows; 0 = never.
  std::size_t stop_after = 0;
};

struct EvaluationRun {
  RunManifest manifest;
  std::vector<EvalRow> rows;  ///< canonical order, read back from the rows as written
  std::size_t resumed = 0;    ///< rows kept from an earlier run
  std::size_t computed = 0;   ///< rows computed now
  bool complete = true;       ///< false when stop_after cut the run short
};

/// Runs the suite into `out_dir` (created if missing). Throws InputError for
/// no methods, a duplicated method, a folder holding another run, or an
/// unwritable folder.
EvaluationRun evaluate_suite(const Suite& suite, const std::string& out_dir, const EvaluateOptions& options);

/// Joins the shards' folders into `out_dir`: the same suite and methods, each
/// shard K of N once, all N present, every shard complete. Throws InputError
/// naming the folder and what differs or is missing.
/// `out_dir` must be new or empty unless `overwrite` (which replaces the run
/// files there, nothing else). Both evaluate_suite and this lock the output
/// folder (core/folder_lock.hpp): a second process on it is an InputError.
EvaluationRun merge_evaluations(const std::vector<std::string>& shard_dirs, const std::string& out_dir,
                                bool report = true, bool overwrite = false);

/// Reads an output folder's run.json and rows.csv (strict).
EvaluationRun read_evaluation(const std::string& dir);

}  // namespace deepguide
