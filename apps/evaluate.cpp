// deepguide evaluate SUITE --methods LIST -o OUTDIR [--threads N] [--shard K/N|slurm] [--allow-skips]
// deepguide evaluate merge -o OUTDIR SHARD_DIR... [--overwrite] [--allow-skips]
// Exit 0 when every scenario ran (or some were skipped with --allow-skips);
// 4 when some were skipped (each is named on stderr and in the outputs); 1
// for bad input (an unknown method, a suite that cannot be read, a folder
// holding another run or written by another process); 2 for usage.

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/evaluation/eval_summary.hpp"
#include "deepguide/evaluation/evaluate.hpp"
#include "deepguide/evaluation/suite.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/reactive/reactive_registry.hpp"

namespace deepguide::app {
namespace {

struct EvaluateArgs {
  std::string suite;
  std::string methods;
  std::string output;
  int threads = 0;
  std::string shard = "1/1";
  bool fresh = false;
  bool no_timing = false;
  bool no_report = false;
  bool html = false;
  bool quiet = false;
  bool allow_skips = false;
  bool overwrite = false;
  std::vector<std::string> merge_dirs;
  std::string merge_output;
};

// A progress bar with ETA on stderr, only when stderr is a terminal.
struct ProgressBar {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last;
  bool active = isatty(STDERR_FILENO) != 0;

  void operator()(std::size_t done, std::size_t total) {
    if (!active || total == 0) return;
    const auto now = std::chrono::steady_clock::now();
    if (done < total && now - last < std::chrono::milliseconds(100)) return;
    last = now;
    const double elapsed = std::chrono::duration<double>(now - start).count();
    std::fprintf(stderr, "\r%s %s", progress_line(done, total, elapsed).c_str(), done == total ? "\n" : "");
    std::fflush(stderr);
  }
  // A warning on its own line, the bar redrawn after it.
  void warn(const std::string& line) {
    if (active) std::fprintf(stderr, "\r\033[K");
    std::fprintf(stderr, "deepguide: warning: %s\n", rename_parameters(line, flag_of_parameter).c_str());
  }
};

void report(const EvaluationRun& run, const std::string& out_dir, const EvaluateArgs& o) {
  if (!o.quiet) std::cout << summary_markdown(run, summarize(run));
  std::cout << "\n" << outputs_line(run, out_dir, !o.no_report) << "\n";
  const std::string skipped = skipped_line(run);
  if (skipped.empty()) return;
  if (!o.allow_skips) throw PartialError(skipped);
  std::cerr << "deepguide: warning: " << rename_parameters(skipped, flag_of_parameter)
            << " (listed in summary.md; exit 0 with --allow-skips)\n";
}

}  // namespace

void register_evaluate(CLI::App& app) {
  auto o = std::make_shared<EvaluateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "evaluate", "Run every scenario of a suite through planners and reactive methods; tables, summary and report");
  cmd->add_option("SUITE", o->suite, "Suite folder, its suite.yaml, or one scenario file (docs/EVALUATION.md)");
  cmd->add_option("--methods", o->methods,
                  "Comma-separated methods: " + reactive_method_names_text() + ", or GRAPH[:SEARCH][:COST] (" +
                      graph_names_text([](const GraphEntry& e) { return !e.can.in_depth; }) +
                      "; astar, dijkstra; length, time, energy)");
  cmd->add_option("-o,--output", o->output, "Output folder (rows.csv, results.json, summary.md, report.html)");
  cmd->add_option("--threads", o->threads, "Worker threads (default: SLURM_CPUS_PER_TASK when set, else every core)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--shard", o->shard,
                  "Run shard K of N (K/N): scenarios i with i mod N = K - 1; `slurm`: this Slurm array task's "
                  "(SLURM_ARRAY_TASK_ID, _MIN and _COUNT)")
      ->capture_default_str();
  cmd->add_flag("--allow-skips", o->allow_skips,
                "Exit 0 when broken scenarios were skipped (they are listed in the outputs), so a Slurm "
                "afterok dependency goes on");
  cmd->add_flag("--fresh", o->fresh, "Discard the rows of an earlier run in the output folder instead of resuming");
  cmd->add_flag("--no-timing", o->no_timing, "Write compute_ms as 0, so reruns are byte-identical");
  cmd->add_flag("--no-report", o->no_report, "Skip the figures and report.html");
  cmd->add_flag("--html", o->html,
                "Also write maps/: web maps of the scenarios where each method came closest to an obstacle or "
                "collided, each method's track over the obstacles, linked from report.html (docs/WEB_MAP.md)");
  cmd->add_flag("-q,--quiet", o->quiet, "Do not print the summary");
  CLI::App* merge = cmd->add_subcommand("merge", "Join the output folders of all shards of a run into one");
  merge->add_option("SHARD_DIR", o->merge_dirs, "The shards' output folders")->required();
  merge->add_option("-o,--output", o->merge_output, "Output folder")->required();
  merge->add_flag("--no-report", o->no_report, "Skip the figures and report.html");
  merge->add_flag("-q,--quiet", o->quiet, "Do not print the summary");
  merge->add_flag("--overwrite", o->overwrite, "Replace the run in an output folder that holds one");
  merge->add_flag("--allow-skips", o->allow_skips, "Exit 0 when the shards skipped broken scenarios (listed)");
  merge->callback([o] {
    const EvaluationRun run = merge_evaluations(o->merge_dirs, o->merge_output, !o->no_report, o->overwrite);
    std::cout << "merged " << o->merge_dirs.size() << " shard folder(s) into " << o->merge_output << "\n";
    report(run, o->merge_output, *o);
  });
  cmd->callback([o, cmd] {
    if (cmd->got_subcommand("merge")) return;
    if (o->suite.empty()) throw CLI::RequiredError("SUITE");
    if (o->methods.empty()) throw CLI::RequiredError("--methods");
    if (o->output.empty()) throw CLI::RequiredError("--output");
    EvaluateOptions options;
    options.methods = parse_eval_methods(o->methods);
    options.shard = o->shard == "slurm"
                        ? slurm_array_shard(std::getenv("SLURM_ARRAY_TASK_ID"), std::getenv("SLURM_ARRAY_TASK_MIN"),
                                            std::getenv("SLURM_ARRAY_TASK_COUNT"))
                        : parse_shard(o->shard);
    options.threads = o->threads > 0 ? o->threads : slurm_cpus_per_task(std::getenv("SLURM_CPUS_PER_TASK"));
    options.fresh = o->fresh;
    options.timing = !o->no_timing;
    options.report = !o->no_report;
    options.maps = o->html;
    auto bar = std::make_shared<ProgressBar>();
    options.progress = [bar](std::size_t done, std::size_t total) { (*bar)(done, total); };
    options.warn = [bar](const std::string& line) { bar->warn(line); };
    const Suite suite = read_suite(o->suite);
    const EvaluationRun run = evaluate_suite(suite, o->output, options);
    report(run, o->output, *o);
  });
}

}  // namespace deepguide::app
