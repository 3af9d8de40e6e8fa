#include "deepguide/evaluation/evaluate.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/folder_lock.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/evaluation/eval_maps.hpp"
#include "deepguide/evaluation/eval_report.hpp"
#include "deepguide/evaluation/eval_summary.hpp"

namespace deepguide {

namespace fs = std::filesystem;

namespace {

constexpr const char* kManifest = "run.json";
constexpr const char* kRows = "rows.csv";

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": expected a readable file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::json manifest_json(const RunManifest& m) {
  nlohmann::json skipped = nlohmann::json::array();
  for (const SkippedRun& s : m.skipped) {
    skipped.push_back(
        {{"scenario_index", s.scenario_index}, {"scenario", s.scenario}, {"method", s.method}, {"error", s.error}});
  }
  return {{"suite", m.suite},
          {"suite_source", m.suite_source},
          {"suite_fingerprint", m.suite_fingerprint},
          {"scenarios", m.scenarios},
          {"methods", m.methods},
          {"shard", std::to_string(m.shard.index) + "/" + std::to_string(m.shard.count)},
          {"timing", m.timing},
          {"skipped", skipped}};
}

RunManifest read_manifest(const fs::path& path) {
  const std::string where = path.string();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_all(path));
    RunManifest m;
    m.suite = j.at("suite").get<std::string>();
    m.suite_source = j.at("suite_source").get<std::string>();
    m.scenarios = j.at("scenarios").get<std::size_t>();
    m.suite_fingerprint = j.value("suite_fingerprint", std::string());
    m.methods = j.at("methods").get<std::vector<std::string>>();
    m.shard = parse_shard(j.at("shard").get<std::string>());
    m.timing = j.at("timing").get<bool>();
    for (const auto& s : j.at("skipped")) {
      m.skipped.push_back({s.at("scenario_index").get<std::size_t>(), s.at("scenario").get<std::string>(),
                           s.at("method").get<std::string>(), s.at("error").get<std::string>()});
    }
    return m;
  } catch (const InputError& e) {
    throw InputError(where + ": shard: " + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where +
                     ": expected deepguide's run manifest (suite, scenarios, methods, shard, timing, "
                     "skipped): " +
                     printable(e.what(), 100));
  }
}

bool in_shard(std::size_t scenario, const Shard& shard) {
  return scenario % static_cast<std::size_t>(shard.count) == static_cast<std::size_t>(shard.index - 1);
}

// Rows in canonical order: scenario, then the methods as asked.
void sort_rows(std::vector<EvalRow>& rows, const std::vector<std::string>& methods) {
  std::map<std::string, std::size_t> order;
  for (std::size_t i = 0; i < methods.size(); ++i) order[methods[i]] = i;
  std::stable_sort(rows.begin(), rows.end(), [&](const EvalRow& a, const EvalRow& b) {
    if (a.scenario_index != b.scenario_index) return a.scenario_index < b.scenario_index;
    return order[a.method] < order[b.method];
  });
}

std::string rows_text(const std::vector<EvalRow>& rows, bool timing) {
  std::string text = eval_rows_header();
  for (const EvalRow& r : rows) text += eval_row_csv(r, timing);
  return text;
}

void sort_skipped(std::vector<SkippedRun>& skipped) {
  std::sort(skipped.begin(), skipped.end(), [](const SkippedRun& a, const SkippedRun& b) {
    return std::tie(a.scenario_index, a.method) < std::tie(b.scenario_index, b.method);
  });
}

// The final files of a finished run: rows in order, manifest, results, summary, report.
// What a run writes into its folder (the rest of a folder is not ours).
bool is_run_file(const std::string& name) {
  return name == kManifest || name == kRows || name == "results.json" || name == "summary.md" ||
         name == "report.html" ||
         (name.rfind("fig_", 0) == 0 && name.size() > 8 && name.substr(name.size() - 4) == ".png");
}

// Removes an earlier run's files, so a new run without a report leaves no old report beside its rows.
void remove_run_files(const fs::path& dir) {
  std::error_code ec;
  std::vector<fs::path> ours;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (is_run_file(e.path().filename().string())) ours.push_back(e.path());
  }
  for (const fs::path& p : ours) fs::remove(p, ec);
  fs::remove_all(dir / "maps", ec);  // an earlier run's scenario pages (eval_maps.hpp)
}

void finish(const fs::path& dir, EvaluationRun& run, bool report, const Suite* maps_of = nullptr) {
  sort_rows(run.rows, run.manifest.methods);
  sort_skipped(run.manifest.skipped);
  const std::string text = rows_text(run.rows, run.manifest.timing);
  // Read back: every summary is made from the rows as written (eval_rows.hpp).
  run.rows = parse_eval_rows(text, (dir / kRows).string(), false);
  write_text_file(dir / kRows, text, "rows");
  write_text_file(dir / kManifest, manifest_json(run.manifest).dump(2) + "\n", "run manifest");
  write_results(dir.string(), run);
  std::vector<EvaluationMap> maps;
  if (maps_of != nullptr) maps = write_evaluation_maps(*maps_of, run, dir.string());
  if (report) write_report(dir.string(), run, maps);
}

// One job's outcome: a row, or why the run was skipped.
struct JobResult {
  std::optional<EvalRow> row;
  std::optional<SkippedRun> skipped;
};

}  // namespace

int slurm_cpus_per_task(const char* value) {
  if (value == nullptr) return 0;
  char* end = nullptr;
  const long n = std::strtol(value, &end, 10);
  return end != value && *end == '\0' && n >= 1 && n <= 1024 ? static_cast<int>(n) : 0;
}

std::string progress_line(std::size_t done, std::size_t total, double elapsed_s) {
  if (total == 0) return {};
  done = std::min(done, total);
  constexpr std::size_t kWidth = 30;
  const std::size_t filled = kWidth * done / total;
  const double eta = done > 0 ? elapsed_s * static_cast<double>(total - done) / static_cast<double>(done) : 0.0;
  return "[" + std::string(filled, '#') + std::string(kWidth - filled, '.') + "] " + std::to_string(done) + "/" +
         std::to_string(total) + " runs " + fixed(100.0 * static_cast<double>(done) / static_cast<double>(total), 1) +
         " %  " + clock_text(elapsed_s) + " elapsed  ETA " + (done > 0 ? clock_text(eta) : std::string("-:--:--"));
}

Shard slurm_array_shard(const char* task_id, const char* task_min, const char* task_count) {
  if (task_id == nullptr || task_count == nullptr) {
    throw InputError(
        "`shard` slurm: expected SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT (run it as a task of a "
        "Slurm job array, sbatch --array)");
  }
  const auto whole = [](const char* t, const char* name) {
    const std::string s(t);
    if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos) {
      throw InputError(std::string("`shard` slurm: ") + name + ": expected a whole number, got '" + printable(s) + "'");
    }
    return std::stol(s);
  };
  const long id = whole(task_id, "SLURM_ARRAY_TASK_ID");
  const long min = task_min ? whole(task_min, "SLURM_ARRAY_TASK_MIN") : 0;
  const long count = whole(task_count, "SLURM_ARRAY_TASK_COUNT");
  // Shards are the array's tasks in order: an array of consecutive ids (--array=0-15 or 1-16).
  return parse_shard(std::to_string(id - min + 1) + "/" + std::to_string(count));
}

Shard parse_shard(const std::string& text) {
  Shard s;
  const auto slash = text.find('/');
  auto whole = [](const std::string& t, int& v) {
    if (t.empty() || t.size() > 6 || t.find_first_not_of("0123456789") != std::string::npos) return false;
    v = std::stoi(t);
    return true;
  };
  if (slash == std::string::npos || !whole(text.substr(0, slash), s.index) || !whole(text.substr(slash + 1), s.count) ||
      s.count < 1 || s.count > 100000 || s.index < 1 || s.index > s.count) {
    throw InputError("`shard`: expected K/N with 1 <= K <= N <= 100000 (e.g. 3/8), got '" + printable(text) + "'");
  }
  return s;
}

namespace {

// Resume: the rows of the same run already in `dir` go into run.rows (a
// line cut off by a kill is dropped); returns the (scenario, method) pairs done.
std::set<std::pair<std::size_t, std::string>> keep_earlier_rows(const fs::path& dir, const std::string& out_dir,
                                                                const Suite& suite, const EvaluateOptions& options,
                                                                EvaluationRun& run) {
  std::set<std::pair<std::size_t, std::string>> done;
  const RunManifest& manifest = run.manifest;
  std::error_code ec;
  const bool earlier = fs::exists(dir / kManifest, ec) || fs::exists(dir / kRows, ec);
  if (earlier && !options.fresh) {
    if (!fs::exists(dir / kManifest, ec)) {
      throw InputError(out_dir + ": expected run.json beside rows.csv (`fresh` starts over)");
    }
    const RunManifest before = read_manifest(dir / kManifest);
    if (before.suite != manifest.suite || before.scenarios != manifest.scenarios ||
        before.methods != manifest.methods || before.shard != manifest.shard || before.timing != manifest.timing) {
      throw InputError(out_dir + ": holds another run (suite " + before.suite + ", " +
                       std::to_string(before.scenarios) + " scenarios, shard " + std::to_string(before.shard.index) +
                       "/" + std::to_string(before.shard.count) +
                       "): set `fresh` to discard it, or write into another folder");
    }
    if (!before.suite_fingerprint.empty() && before.suite_fingerprint != manifest.suite_fingerprint) {
      throw InputError(out_dir + ": holds a run of suite " + before.suite + " with other scenarios (fingerprint " +
                       before.suite_fingerprint + ", now " + manifest.suite_fingerprint +
                       ": regenerated, edited, or files instead of on demand): set `fresh` to discard the old "
                       "rows, or write into another folder");
    }
    std::size_t dropped = 0;
    // run.json is written first: a kill before rows.csv leaves an empty journal.
    const std::string journal = fs::exists(dir / kRows, ec) ? read_all(dir / kRows) : eval_rows_header();
    for (EvalRow& r : parse_eval_rows(journal, (dir / kRows).string(), true, &dropped)) {
      const bool known =
          r.scenario_index < suite.scenarios.size() && suite.scenarios[r.scenario_index].id == r.scenario &&
          in_shard(r.scenario_index, options.shard) &&
          std::find(manifest.methods.begin(), manifest.methods.end(), r.method) != manifest.methods.end();
      if (known && done.insert({r.scenario_index, r.method}).second) run.rows.push_back(std::move(r));
    }
    run.resumed = run.rows.size();
  }
  return done;
}

}  // namespace

EvaluationRun evaluate_suite(const Suite& suite, const std::string& out_dir, const EvaluateOptions& options) {
  if (options.methods.empty()) throw InputError("`methods`: expected at least one method");
  RunManifest manifest;
  manifest.suite = suite.name;
  manifest.suite_source = suite.source;
  manifest.scenarios = suite.scenarios.size();
  manifest.suite_fingerprint = suite.fingerprint;
  manifest.shard = options.shard;
  manifest.timing = options.timing;
  for (const EvalMethod& m : options.methods) {
    if (std::find(manifest.methods.begin(), manifest.methods.end(), m.name) != manifest.methods.end()) {
      throw InputError("`methods`: expected each method once, got '" + m.name + "' twice");
    }
    manifest.methods.push_back(m.name);
  }

  const fs::path dir(out_dir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir, ec))
    throw InputError(out_dir + ": expected a folder for the results (could not create it)");
  const FolderLock lock(dir, "evaluate");
  if (options.fresh) remove_run_files(dir);

  EvaluationRun run;
  run.manifest = manifest;
  const std::set<std::pair<std::size_t, std::string>> done = keep_earlier_rows(dir, out_dir, suite, options, run);
  // The journal starts as the kept rows; every new row is appended and flushed.
  sort_rows(run.rows, manifest.methods);
  write_text_file(dir / kManifest, manifest_json(manifest).dump(2) + "\n", "run manifest");
  write_text_file(dir / kRows, rows_text(run.rows, options.timing), "rows");

  struct Job {
    std::size_t scenario;
    std::size_t method;
  };
  std::vector<Job> jobs;
  for (std::size_t i = 0; i < suite.scenarios.size(); ++i) {
    if (!in_shard(i, options.shard)) continue;
    for (std::size_t j = 0; j < options.methods.size(); ++j) {
      if (!done.count({i, options.methods[j].name})) jobs.push_back({i, j});
    }
  }

  // Finished jobs wait here for the writer, in the order they finish: only
  // the rows in flight are held, and a kill loses none that were finished.
  std::deque<JobResult> finished;
  std::mutex mutex;
  std::condition_variable ready;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  auto work = [&] {
    for (;;) {
      const std::size_t k = next.fetch_add(1);
      if (k >= jobs.size() || stop) return;
      const Job& job = jobs[k];
      const SuiteScenario& s = suite.scenarios[job.scenario];
      const EvalMethod& method = options.methods[job.method];
      JobResult out;
      std::string stage;
      try {
        const Scenario sc = load_suite_scenario(suite, job.scenario);
        stage = method.name;
        validate(sc);
        out.row = EvalRow{job.scenario, s.id, method.name, run_method(sc, method)};
      } catch (const std::exception& e) {
        out.skipped = SkippedRun{job.scenario, s.id, stage, printable(e.what(), 400)};
      }
      {
        std::lock_guard lock(mutex);
        finished.push_back(std::move(out));
      }
      ready.notify_one();
    }
  };
  const int threads =
      options.threads > 0 ? options.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  // Declared after everything the workers use, so it is destroyed (joined)
  // first; on an error in the writing loop the workers stop after their job.
  struct Pool {
    std::atomic<bool>& stop;
    std::vector<std::jthread> threads;
    ~Pool() {
      stop = true;
      threads.clear();
    }
  } pool{stop, {}};
  for (int t = 0; t < std::min<int>(threads, static_cast<int>(std::max<std::size_t>(jobs.size(), 1))); ++t) {
    pool.threads.emplace_back(work);
  }

  std::ofstream journal(dir / kRows, std::ios::binary | std::ios::app);
  if (!journal) throw InputError((dir / kRows).string() + ": could not open the rows for appending");
  std::set<std::size_t> unreadable;  // scenarios already reported as unreadable
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    JobResult r;
    {
      std::unique_lock lock(mutex);
      ready.wait(lock, [&] { return !finished.empty(); });
      r = std::move(finished.front());
      finished.pop_front();
    }
    if (r.row) {
      journal << eval_row_csv(*r.row, options.timing);
      journal.flush();
      if (!journal) throw InputError((dir / kRows).string() + ": could not write a row");
      run.rows.push_back(std::move(*r.row));
    } else {
      SkippedRun& s = *r.skipped;
      if (!s.method.empty() || unreadable.insert(s.scenario_index).second) {  // an unreadable scenario once
        if (options.warn) {
          options.warn("skipped " + s.scenario + (s.method.empty() ? "" : " with " + s.method) + ": " + s.error);
        }
        run.manifest.skipped.push_back(std::move(s));
      }
    }
    ++run.computed;
    if (options.progress) options.progress(k + 1, jobs.size());
    if (options.stop_after > 0 && k + 1 >= options.stop_after && k + 1 < jobs.size()) {
      stop = true;
      run.complete = false;
      break;
    }
  }
  journal.close();
  pool.threads.clear();  // joins
  if (!run.complete) return run;
  finish(dir, run, options.report, options.maps ? &suite : nullptr);
  return run;
}

EvaluationRun read_evaluation(const std::string& dir_text) {
  const fs::path dir(dir_text);
  std::error_code ec;
  if (!fs::is_regular_file(dir / kManifest, ec) || !fs::is_regular_file(dir / kRows, ec)) {
    throw InputError(dir_text + ": expected an evaluation folder (run.json and rows.csv)");
  }
  EvaluationRun run;
  run.manifest = read_manifest(dir / kManifest);
  run.rows = parse_eval_rows(read_all(dir / kRows), (dir / kRows).string(), false);
  return run;
}

EvaluationRun merge_evaluations(const std::vector<std::string>& shard_dirs, const std::string& out_dir, bool report,
                                bool overwrite) {
  if (shard_dirs.empty()) throw InputError("evaluate merge: expected the shards' folders");
  // A merge makes a new run: never into a folder that holds something, unless told to replace its run,
  // and never into a shard's own folder or one that holds it, whatever it is told: the run it
  // replaced would be one of its inputs (`merge -o sh2 sh1 sh2 --overwrite` replaced shard 2).
  const fs::path dir(out_dir);
  std::error_code ec;
  // Both resolved (links, "..", "."), without a trailing separator.
  const auto resolved = [](const fs::path& p, std::error_code& e) {
    fs::path r = fs::weakly_canonical(p, e);
    return r.has_filename() || !r.has_parent_path() ? r : r.parent_path();
  };
  const fs::path out_real = resolved(dir, ec);
  for (const std::string& d : shard_dirs) {
    std::error_code e2;
    const fs::path shard_real = resolved(fs::path(d), e2);
    if (ec || e2) continue;  // an unreadable shard is refused below, naming it
    const auto [o_end, s_at] = std::mismatch(out_real.begin(), out_real.end(), shard_real.begin(), shard_real.end());
    if (o_end == out_real.end()) {
      throw InputError("`output` " + out_dir + ": expected a folder that is not a shard's nor holds one, got " +
                       (s_at == shard_real.end() ? "the shard " : "a folder holding the shard ") + d);
    }
  }
  ec.clear();
  if (!overwrite && fs::is_directory(dir, ec)) {
    for (const auto& e : fs::directory_iterator(dir, ec)) {
      const std::string name = e.path().filename().string();
      if (name == FolderLock::kFileName) continue;
      throw InputError(out_dir + ": expected a new or empty folder for the merged run, got one holding " +
                       printable(name) + " (`overwrite` replaces the run in it)");
    }
  }
  EvaluationRun merged;
  std::vector<std::string> seen;  // the folder of each shard index
  std::string fingerprint_from;   // the first shard that had a suite fingerprint
  for (const std::string& d : shard_dirs) {
    EvaluationRun part = read_evaluation(d);
    const RunManifest& m = part.manifest;
    if (seen.empty()) {
      merged.manifest = m;
      merged.manifest.shard = Shard{};
      merged.manifest.skipped.clear();
      seen.assign(static_cast<std::size_t>(m.shard.count), "");
    }
    const RunManifest& first = merged.manifest;
    if (m.suite != first.suite || m.scenarios != first.scenarios || m.methods != first.methods ||
        m.timing != first.timing || static_cast<std::size_t>(m.shard.count) != seen.size()) {
      throw InputError(d + ": expected a shard of the same run as " + shard_dirs.front() + " (suite " + first.suite +
                       ", " + std::to_string(first.scenarios) + " scenarios, " + std::to_string(seen.size()) +
                       " shards, the same methods), got suite " + m.suite + ", " + std::to_string(m.scenarios) +
                       " scenarios, shard " + std::to_string(m.shard.index) + "/" + std::to_string(m.shard.count));
    }
    // Shards written before fingerprints were kept have none; the others must agree.
    if (!m.suite_fingerprint.empty()) {
      if (fingerprint_from.empty()) {
        merged.manifest.suite_fingerprint = m.suite_fingerprint;
        fingerprint_from = d;
      } else if (m.suite_fingerprint != merged.manifest.suite_fingerprint) {
        throw InputError(d + ": expected a shard of the same suite as " + fingerprint_from + " (" +
                         merged.manifest.suite_fingerprint + "), got suite " + m.suite + " with other scenarios (" +
                         m.suite_fingerprint + ")");
      }
    }
    std::string& slot = seen[static_cast<std::size_t>(m.shard.index - 1)];
    if (!slot.empty()) {
      throw InputError(d + ": shard " + std::to_string(m.shard.index) + "/" + std::to_string(m.shard.count) +
                       " was given already (" + slot + ")");
    }
    slot = d;
    // Complete: every scenario of the shard has each method's row or a skip.
    std::set<std::pair<std::size_t, std::string>> have;
    for (const EvalRow& r : part.rows) {
      if (!in_shard(r.scenario_index, m.shard) || !have.insert({r.scenario_index, r.method}).second) {
        throw InputError(d + ": rows.csv: scenario " + r.scenario + " with " + r.method +
                         (in_shard(r.scenario_index, m.shard) ? " twice" : " does not belong to this shard"));
      }
    }
    std::set<std::size_t> unreadable;
    for (const SkippedRun& s : m.skipped) {
      if (s.method.empty())
        unreadable.insert(s.scenario_index);
      else
        have.insert({s.scenario_index, s.method});
    }
    for (std::size_t i = 0; i < m.scenarios; ++i) {
      if (!in_shard(i, m.shard) || unreadable.count(i)) continue;
      for (const std::string& method : m.methods) {
        if (!have.count({i, method})) {
          throw InputError(d + ": expected a finished shard, but scenario index " + std::to_string(i) + " with " +
                           method + " has no row (run `deepguide evaluate` on it again to finish it)");
        }
      }
    }
    for (EvalRow& r : part.rows) merged.rows.push_back(std::move(r));
    for (SkippedRun& s : part.manifest.skipped) merged.manifest.skipped.push_back(std::move(s));
  }
  for (std::size_t k = 0; k < seen.size(); ++k) {
    if (seen[k].empty()) {
      throw InputError("evaluate merge: expected all " + std::to_string(seen.size()) + " shards, shard " +
                       std::to_string(k + 1) + "/" + std::to_string(seen.size()) + " is missing");
    }
  }
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir, ec))
    throw InputError(out_dir + ": expected a folder for the results (could not create it)");
  const FolderLock lock(dir, "evaluate merge");
  remove_run_files(dir);
  merged.resumed = merged.rows.size();
  finish(dir, merged, report);
  return merged;
}

}  // namespace deepguide
