// Batch evaluation: method names, rows that are the same for any number of
// threads, for merged shards and for a run stopped and resumed; a broken
// scenario skipped while the rest runs; a folder holding another run
// refused, and so is the same suite changed since; hand-checked rows; and the CLI's exit codes, including a run
// killed with SIGKILL and started again.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "../test_support.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/folder_lock.hpp"
#include "deepguide/evaluation/eval_summary.hpp"
#include "deepguide/evaluation/evaluate.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<EvalMethod> methods(std::initializer_list<const char*> names) {
  std::vector<EvalMethod> out;
  for (const char* n : names) out.push_back(parse_eval_method(n));
  return out;
}

Suite small_suite(const ScratchDir& tmp, int scenarios = 8) {
  MonteCarloParams p;
  p.scenarios = scenarios;
  p.seed = 21;
  p.max_obstacles = 4;
  write_suite(tmp.file("suite"), "small", p, true, true);
  return read_suite(tmp.file("suite"));
}

EvaluateOptions options(std::initializer_list<const char*> names, int threads) {
  EvaluateOptions o;
  o.methods = methods(names);
  o.threads = threads;
  o.timing = false;
  o.report = false;
  return o;
}

void expect_same_outputs(const std::filesystem::path& a, const std::filesystem::path& b) {
  for (const char* f : {"rows.csv", "results.json", "summary.md"}) {
    const std::string x = slurp(a / f), y = slurp(b / f);
    EXPECT_FALSE(x.empty()) << f;
    EXPECT_EQ(x, y) << f << " differs between " << a << " and " << b;
  }
}

}  // namespace

TEST(EvalMethod, NamesParseToCanonicalForms) {
  EXPECT_EQ(parse_eval_method("geometric").reactive, ReactiveMethod::geometric);
  const EvalMethod q = parse_eval_method("quadtree:dijkstra:length");
  EXPECT_TRUE(q.is_planner());
  EXPECT_EQ(q.graph, GraphKind::quadtree);
  EXPECT_EQ(q.search, SearchAlgorithm::dijkstra);
  EXPECT_EQ(q.name, "quadtree:dijkstra");
  EXPECT_EQ(parse_eval_method("visibility:astar").name, "visibility");
  EXPECT_EQ(parse_eval_method("visibility:energy").name, "visibility:energy");
  EXPECT_EQ(parse_eval_method("visibility-full:dijkstra:time").cost, CostKind::time);
  for (const char* bad : {"", "astar", "visibility:", "visibility:energy:astar", "visibility:fast", "octree",
                          "tangent:energy", "geometric:astar", "visibility:astar:time:x"}) {
    deepguide::test::expect_one_line_error([&] { (void)parse_eval_method(bad); }, "unknown method");
  }
}

TEST(EvalMethod, ListsParseInOrderAndAnEmptyListIsAnError) {
  const std::vector<EvalMethod> m = parse_eval_methods("visibility,geometric,quadtree:dijkstra");
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].name, "visibility");
  EXPECT_EQ(m[1].reactive, ReactiveMethod::geometric);
  EXPECT_EQ(m[2].name, "quadtree:dijkstra");
  deepguide::test::expect_one_line_error([] { (void)parse_eval_methods(""); }, "methods: expected a comma-separated");
  deepguide::test::expect_one_line_error([] { (void)parse_eval_methods("visibility,,geometric"); }, "unknown method");
}

TEST(Evaluate, ProgressLineAndSlurmThreads) {
  // 3 of 12 runs after 30 s: a quarter of the bar (7 of 30), 90 s to go.
  EXPECT_EQ(progress_line(3, 12, 30.0),
            "[#######.......................] 3/12 runs 25.0 %  0:00:30 elapsed  ETA 0:01:30");
  EXPECT_EQ(progress_line(0, 5, 2.0), "[..............................] 0/5 runs 0.0 %  0:00:02 elapsed  ETA -:--:--");
  EXPECT_EQ(progress_line(5, 5, 3725.0).substr(0, 33), "[##############################] ");
  EXPECT_NE(progress_line(5, 5, 3725.0).find("1:02:05 elapsed  ETA 0:00:00"), std::string::npos);
  EXPECT_EQ(progress_line(1, 0, 1.0), "");
  EXPECT_EQ(slurm_cpus_per_task(nullptr), 0);
  EXPECT_EQ(slurm_cpus_per_task("8"), 8);
  for (const char* bad : {"", "0", "-2", "8x", "1025", "two"}) EXPECT_EQ(slurm_cpus_per_task(bad), 0) << bad;
}

TEST(Evaluate, HandCheckedRowsWithoutObstacles) {
  ScratchDir tmp;
  const std::string file = tmp.write("open.yaml", "start: {x: 0, y: 0}\ntarget: {x: 300, y: 400}\n");
  const Suite suite = read_suite(file);
  const EvaluationRun run = evaluate_suite(suite, tmp.file("out"), options({"visibility", "quadtree", "geometric"}, 1));
  ASSERT_EQ(run.rows.size(), 3u);
  const MethodRun& vis = run.rows[0].run;
  EXPECT_EQ(run.rows[0].method, "visibility");
  EXPECT_DOUBLE_EQ(vis.route_length_m, 500.0);  // the straight line, to the mm the CSV keeps
  for (const EvalRow& r : run.rows) {
    EXPECT_EQ(r.run.end, "reached") << r.method;
    EXPECT_FALSE(r.run.collided);
    EXPECT_TRUE(std::isinf(r.run.min_clearance_m));
    // Sailed straight at cruise (2.058 m/s), stopping within the 5 m arrival radius.
    EXPECT_NEAR(r.run.path_length_m, 495.0, 1.0) << r.method;
    EXPECT_NEAR(r.run.time_s, 495.0 / (4.0 * 1852.0 / 3600.0), 2.0) << r.method;
    EXPECT_LT(r.run.max_rate_ref, 1e-6) << r.method;
  }
}

TEST(Evaluate, ACollisionsClassAndCauseSurviveTheRowsFile) {
  EvalRow row;
  row.scenario_index = 7;
  row.scenario = "scenario-0007";
  row.method = "geometric";
  row.run.end = "reached";
  row.run.reached = row.run.collided = row.run.unavoidable = true;
  row.run.min_clearance_m = -1.25;
  row.run.note =
      "rock came into the sonar's view 8.0 m away at 0.0 s; a hard-over turn either way would still have "
      "met it: unavoidable";
  const std::string text = eval_rows_header() + eval_row_csv(row, false);
  const std::vector<EvalRow> back = parse_eval_rows(text, "rows", false);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_TRUE(back[0].run.collided);
  EXPECT_TRUE(back[0].run.unavoidable);
  EXPECT_EQ(back[0].run.note, row.run.note);
  EXPECT_DOUBLE_EQ(back[0].run.min_clearance_m, -1.25);
  // Counted apart in the summary: 2 collisions, 1 unavoidable.
  EvaluationRun run;
  run.manifest.methods = {"geometric"};
  run.rows = back;
  row.scenario_index = 8;
  row.run.unavoidable = false;
  run.rows.push_back(row);
  const EvaluationSummary s = summarize(run);
  ASSERT_EQ(s.methods.size(), 1u);
  EXPECT_EQ(s.methods[0].collisions, 2);
  EXPECT_EQ(s.methods[0].unavoidable, 1);
  // A rows file from before the column is refused with the header it should have.
  std::string old = text;
  old.replace(old.find("collided,unavoidable,"), 21, "collided,");
  try {
    (void)parse_eval_rows(old, "rows.csv", false);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rows.csv: line 1: expected the evaluation rows' header"), std::string::npos)
        << e.what();
  }
}

TEST(Evaluate, OneAndTwoThreadsAndMergedShardsWriteTheSameBytes) {
  ScratchDir tmp;
  const Suite suite = small_suite(tmp);
  const auto names = {"visibility", "quadtree", "geometric", "dipole"};
  const EvaluationRun one = evaluate_suite(suite, tmp.file("one"), options(names, 1));
  const EvaluationRun two = evaluate_suite(suite, tmp.file("two"), options(names, 2));
  ASSERT_EQ(one.rows.size(), 32u);
  expect_same_outputs(tmp.path() / "one", tmp.path() / "two");
  std::vector<std::string> shards;
  for (int k = 1; k <= 3; ++k) {
    EvaluateOptions o = options(names, 2);
    o.shard = {k, 3};
    const std::string dir = tmp.file("shard" + std::to_string(k));
    const EvaluationRun part = evaluate_suite(suite, dir, o);
    for (const EvalRow& r : part.rows) EXPECT_EQ(r.scenario_index % 3, static_cast<std::size_t>(k - 1));
    shards.push_back(dir);
  }
  std::swap(shards[0], shards[2]);  // any order
  merge_evaluations(shards, tmp.file("merged"), false);
  EXPECT_EQ(slurp(tmp.path() / "merged" / "rows.csv"), slurp(tmp.path() / "one" / "rows.csv"));
  EXPECT_EQ(slurp(tmp.path() / "merged" / "summary.md"), slurp(tmp.path() / "one" / "summary.md"));

  // Every route the planners sailed stayed out of every obstacle, and every
  // visibility route is no longer than the quadtree's on the same scenario.
  for (std::size_t i = 0; i < one.rows.size(); i += 4) {
    EXPECT_FALSE(one.rows[i].run.collided) << one.rows[i].scenario;
    EXPECT_FALSE(one.rows[i + 1].run.collided) << one.rows[i + 1].scenario;
    EXPECT_LE(one.rows[i].run.route_length_m, one.rows[i + 1].run.route_length_m + 1e-3) << one.rows[i].scenario;
  }

  // Bad merges: a shard missing, one given twice, shards of another run.
  using deepguide::test::expect_one_line_error;
  expect_one_line_error([&] { merge_evaluations({shards[0], shards[1]}, tmp.file("m2"), false); }, "is missing");
  expect_one_line_error(
      [&] {
        merge_evaluations({shards[0], shards[0], shards[1]}, tmp.file("m3"), false);
      },
      "given already");
  expect_one_line_error([&] { merge_evaluations({shards[0], tmp.file("one")}, tmp.file("m4"), false); }, "same run");
  // An output that is a shard, or holds one, even when told to overwrite (issue 39): the shard stays.
  const std::string rows_before = slurp(std::filesystem::path(shards[1]) / "rows.csv");
  expect_one_line_error([&] { merge_evaluations(shards, shards[1], false, true); }, "got the shard");
  expect_one_line_error([&] { merge_evaluations(shards, shards[1] + "/./", false, true); }, "got the shard");
  expect_one_line_error([&] { merge_evaluations(shards, tmp.path().string(), false, true); },
                        "got a folder holding the shard");
  EXPECT_EQ(slurp(std::filesystem::path(shards[1]) / "rows.csv"), rows_before);
}

TEST(Evaluate, StoppedRunResumesWithoutLostOrDuplicatedRows) {
  ScratchDir tmp;
  const Suite suite = small_suite(tmp);
  const auto names = {"visibility", "geometric", "dipole"};
  const EvaluationRun whole = evaluate_suite(suite, tmp.file("whole"), options(names, 2));

  EvaluateOptions o = options(names, 2);
  o.stop_after = 10;
  const EvaluationRun cut = evaluate_suite(suite, tmp.file("cut"), o);
  EXPECT_FALSE(cut.complete);
  EXPECT_EQ(cut.computed, 10u);
  // A kill while a row was being written leaves half a line.
  { std::ofstream(tmp.path() / "cut" / "rows.csv", std::ios::app) << "11,scenario-0003,dipo"; }
  EXPECT_EQ(deepguide::parse_eval_rows(slurp(tmp.path() / "cut" / "rows.csv"), "rows", true).size(), 10u);

  o.stop_after = 0;
  const EvaluationRun resumed = evaluate_suite(suite, tmp.file("cut"), o);
  EXPECT_TRUE(resumed.complete);
  EXPECT_EQ(resumed.resumed, 10u);
  EXPECT_EQ(resumed.computed, 14u);
  expect_same_outputs(tmp.path() / "whole", tmp.path() / "cut");
  std::set<std::pair<std::size_t, std::string>> keys;
  for (const EvalRow& r : resumed.rows) EXPECT_TRUE(keys.insert({r.scenario_index, r.method}).second);
  EXPECT_EQ(keys.size(), 24u);

  // Another run into the same folder is refused, unless --fresh.
  deepguide::test::expect_one_line_error(
      [&] { (void)evaluate_suite(suite, tmp.file("cut"), options({"visibility"}, 1)); }, "holds another run");
  EvaluateOptions fresh = options({"visibility"}, 1);
  fresh.fresh = true;
  EXPECT_EQ(evaluate_suite(suite, tmp.file("cut"), fresh).rows.size(), 8u);
}

// A suite regenerated under the same name and size (another seed) has other
// scenarios: a run begun on the old one is not resumed with it, nor merged
// with a shard of it. The fingerprint follows the files' bytes, and an
// on-demand suite's generator.
TEST(Evaluate, ASuiteChangedUnderTheSameNameIsNotResumedOrMerged) {
  ScratchDir tmp;
  const Suite before = small_suite(tmp, 6);
  EXPECT_EQ(before.fingerprint.rfind("fnv1a64:", 0), 0u);
  EXPECT_EQ(before.fingerprint.size(), 8u + 16u);
  EXPECT_EQ(read_suite(tmp.file("suite")).fingerprint, before.fingerprint) << "the same files, the same fingerprint";

  EvaluateOptions o = options({"visibility"}, 1);
  o.stop_after = 2;
  (void)evaluate_suite(before, tmp.file("cut"), o);
  o.shard = {1, 2};
  o.stop_after = 0;
  (void)evaluate_suite(before, tmp.file("shard1"), o);

  MonteCarloParams p;
  p.scenarios = 6;
  p.seed = 22;  // small_suite's is 21
  p.max_obstacles = 4;
  write_suite(tmp.file("suite"), "small", p, true, true);
  const Suite after = read_suite(tmp.file("suite"));
  ASSERT_EQ(after.name, before.name);
  ASSERT_EQ(after.scenarios.size(), before.scenarios.size());
  EXPECT_NE(after.fingerprint, before.fingerprint);
  deepguide::test::expect_one_line_error(
      [&] { (void)evaluate_suite(after, tmp.file("cut"), options({"visibility"}, 1)); }, "with other scenarios");
  EvaluateOptions fresh = options({"visibility"}, 1);
  fresh.fresh = true;
  EXPECT_EQ(evaluate_suite(after, tmp.file("cut"), fresh).rows.size(), 6u);

  o.shard = {2, 2};
  (void)evaluate_suite(after, tmp.file("shard2"), o);
  deepguide::test::expect_one_line_error(
      [&] {
        (void)merge_evaluations({tmp.file("shard1"), tmp.file("shard2")}, tmp.file("merged"), false);
      },
      "other scenarios");
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "merged" / "rows.csv"));

  // One byte of one file changes it; on demand, the generator does.
  tmp.write("suite/scenario-0004.yaml", slurp(tmp.path() / "suite" / "scenario-0004.yaml") + "\n");
  EXPECT_NE(read_suite(tmp.file("suite")).fingerprint, after.fingerprint);
  write_suite(tmp.file("demand"), "small", p, false, true);
  const std::string demand = read_suite(tmp.file("demand")).fingerprint;
  p.sonar_noise = 2.0;
  write_suite(tmp.file("demand"), "small", p, false, true);
  const std::string noisier = read_suite(tmp.file("demand")).fingerprint;
  EXPECT_NE(noisier, demand);
  // suite.yaml keeps every setting exactly, so one ulp is another suite.
  p.sonar_noise = std::nextafter(2.0, 3.0);
  write_suite(tmp.file("demand"), "small", p, false, true);
  const Suite ulp = read_suite(tmp.file("demand"));
  ASSERT_TRUE(ulp.generator.has_value());
  EXPECT_EQ(ulp.generator->sonar_noise, p.sonar_noise);
  EXPECT_NE(ulp.fingerprint, noisier);

  // A folder written before the fingerprint was kept still resumes.
  const std::filesystem::path manifest = tmp.path() / "cut" / "run.json";
  nlohmann::json j = nlohmann::json::parse(slurp(manifest));
  j.erase("suite_fingerprint");
  std::ofstream(manifest) << j.dump(2);
  const Suite now = read_suite(tmp.file("suite"));
  EXPECT_EQ(evaluate_suite(now, tmp.file("cut"), options({"visibility"}, 1)).resumed, 6u);
}

TEST(Evaluate, BrokenScenarioIsSkippedAndTheRestRuns) {
  ScratchDir tmp;
  Suite suite = small_suite(tmp, 5);
  tmp.write("suite/scenario-0002.yaml", "start: {x: 0, y: 0}\ntarget: {x: 100, y: 0}\nsonar: {range_m: -4}\n");
  suite = read_suite(tmp.file("suite"));
  std::vector<std::string> warnings;
  EvaluateOptions o = options({"visibility", "geometric"}, 2);
  o.warn = [&](const std::string& line) { warnings.push_back(line); };
  const EvaluationRun run = evaluate_suite(suite, tmp.file("out"), o);
  EXPECT_EQ(run.rows.size(), 8u);
  ASSERT_EQ(run.manifest.skipped.size(), 1u);  // once for the scenario, not once per method
  EXPECT_EQ(run.manifest.skipped[0].scenario, "scenario-0002");
  EXPECT_NE(run.manifest.skipped[0].error.find("range_m"), std::string::npos);
  ASSERT_EQ(warnings.size(), 1u);
  for (const EvalRow& r : run.rows) EXPECT_NE(r.scenario, "scenario-0002");
  EXPECT_EQ(skipped_line(run), "1 run(s) skipped, the first: scenario-0002: " + run.manifest.skipped[0].error);
  EXPECT_EQ(outputs_line(run, "OUT", false), "wrote OUT/rows.csv, run.json, results.json and summary.md (8 rows)");
  const std::string summary = slurp(tmp.path() / "out" / "summary.md");
  EXPECT_NE(summary.find("1 skipped"), std::string::npos);
  EXPECT_NE(summary.find("scenario-0002"), std::string::npos);
}

TEST(Evaluate, ClaimsAreJudgedFromTheRows) {
  ScratchDir tmp;
  const Suite suite = small_suite(tmp);
  const EvaluationRun run =
      evaluate_suite(suite, tmp.file("out"), options({"visibility", "quadtree", "geometric", "dipole"}, 2));
  const EvaluationSummary s = summarize(run);
  ASSERT_EQ(s.claims.size(), 2u);
  // Without timing the first claim's cost is the graph size, which is the
  // visibility graph's smaller here by construction of the suite (few obstacles).
  EXPECT_EQ(s.claims[0].verdict, "holds");
  EXPECT_NE(s.claims[0].evidence.back().find("median"), std::string::npos);
  const EvaluationRun only = evaluate_suite(suite, tmp.file("only"), options({"geometric"}, 1));
  const EvaluationSummary t = summarize(only);
  EXPECT_EQ(t.claims[0].verdict, "not tested");
  EXPECT_EQ(t.claims[1].verdict, "not tested");
  int wins = 0;
  for (const MethodStats& m : s.methods) wins += m.wins;
  EXPECT_GE(wins, 8);  // at least one winner per scenario
}

TEST(EvaluateCli, UnknownMethodAndBrokenScenarioExitCodes) {
  ScratchDir tmp;
  (void)small_suite(tmp, 3);
  const std::string suite = tmp.file("suite");
  auto r = deepguide::test::run_cli("evaluate '" + suite + "' --methods visibility,astral -o '" + tmp.file("o1") + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("unknown method 'astral'"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("o1")));

  tmp.write("suite/scenario-0001.yaml", "start: {x: 0, y: 0}\n");  // no target
  r = deepguide::test::run_cli("evaluate '" + suite + "' --methods visibility,geometric -q -o '" + tmp.file("o2") +
                               "'");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("skipped scenario-0001"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("target"), std::string::npos) << r.err;
  EXPECT_EQ(deepguide::parse_eval_rows(slurp(tmp.path() / "o2" / "rows.csv"), "rows", false).size(), 4u);
  EXPECT_TRUE(std::filesystem::exists(tmp.path() / "o2" / "report.html"));
}

TEST(EvaluateCli, KilledRunStartedAgainHasEveryRowOnce) {
  ScratchDir tmp;
  const std::string suite = tmp.file("lazy");
  auto r = deepguide::test::run_cli("suite generate '" + suite + "' --scenarios 60 --seed 5 --on-demand");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string args = "evaluate '" + suite + "' --methods geometric,dipole --threads 1 --no-timing -q --no-report";
  r = deepguide::test::run_cli(args + " -o '" + tmp.file("whole") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;

  // Start it in the background, SIGKILL it once 20 rows are down.
  const std::string rows = tmp.file("cut/rows.csv");
  const std::string script =
      tmp.write("kill.sh", "'" + std::string(DEEPGUIDE_CLI) + "' " + args + " -o '" + tmp.file("cut") +
                               "' >/dev/null 2>&1 &\npid=$!\nfor i in $(seq 1 3000); do\n"
                               "  n=$(cat '" +
                               rows +
                               "' 2>/dev/null | wc -l)\n  [ \"$n\" -ge 21 ] && break\n  sleep 0.01\ndone\n"
                               "kill -9 $pid\nwait $pid 2>/dev/null\nexit 0\n");
  ASSERT_EQ(std::system(("bash '" + script + "'").c_str()), 0);
  const std::size_t kept = deepguide::parse_eval_rows(slurp(rows), "rows", true).size();
  EXPECT_GE(kept, 20u);
  EXPECT_LT(kept, 120u) << "the run finished before it was killed: the test proves nothing";

  r = deepguide::test::run_cli(args + " -o '" + tmp.file("cut") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("kept from the earlier run"), std::string::npos) << r.out;
  EXPECT_EQ(slurp(rows), slurp(tmp.file("whole/rows.csv")));
  EXPECT_EQ(deepguide::parse_eval_rows(slurp(rows), "rows", false).size(), 120u);
}

TEST(EvaluateCli, TheDocumentedSlurmChainCompletesWithABrokenScenario) {
  // docs/EVALUATION.md: an array of `evaluate --shard slurm --allow-skips`, then, afterok, `evaluate merge`.
  ScratchDir tmp;
  (void)small_suite(tmp, 4);
  tmp.write("suite/scenario-0002.yaml", "start: {x: 0, y: 0}\n");  // broken: no target
  const std::string suite = tmp.file("suite");
  const std::string args = "evaluate '" + suite + "' --methods visibility,geometric -q --no-report --no-timing";
  std::string warnings;
  for (int task = 0; task < 2; ++task) {  // --array=0-1: ids 0 and 1, min 0, count 2
    setenv("SLURM_ARRAY_TASK_ID", std::to_string(task).c_str(), 1);
    setenv("SLURM_ARRAY_TASK_MIN", "0", 1);
    setenv("SLURM_ARRAY_TASK_COUNT", "2", 1);
    setenv("SLURM_CPUS_PER_TASK", "1", 1);
    const auto r = deepguide::test::run_cli(args + " --shard slurm --allow-skips -o '" +
                                            tmp.file("shard-" + std::to_string(task)) + "'");
    EXPECT_EQ(r.exit_code, 0) << "task " << task << ": " << r.err;  // afterok goes on
    warnings += r.err;
    EXPECT_EQ(r.out.find("report.html"), std::string::npos) << r.out;  // --no-report: not claimed
  }
  EXPECT_NE(warnings.find("skipped scenario-0002"), std::string::npos) << warnings;  // said, and exit 0
  for (const char* v :
       {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_MIN", "SLURM_ARRAY_TASK_COUNT", "SLURM_CPUS_PER_TASK"}) {
    unsetenv(v);
  }
  const EvaluationRun one = read_evaluation(tmp.file("shard-0")), two = read_evaluation(tmp.file("shard-1"));
  EXPECT_EQ(one.manifest.shard, (Shard{1, 2}));
  EXPECT_EQ(two.manifest.shard, (Shard{2, 2}));
  const std::string shards = " '" + tmp.file("shard-0") + "' '" + tmp.file("shard-1") + "'";
  auto r = deepguide::test::run_cli("evaluate merge -q --allow-skips -o '" + tmp.file("merged") + "'" + shards);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_evaluation(tmp.file("merged")).rows.size(), 6u);  // 3 scenarios x 2 methods; the broken one listed
  EXPECT_NE(slurp(tmp.path() / "merged" / "summary.md").find("scenario-0002"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(tmp.path() / "merged" / "report.html"));
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "merged" / FolderLock::kFileName));  // released
  // A folder holding a run is not merged into: exit 1, one line, nothing changed.
  const std::string before = slurp(tmp.path() / "merged" / "rows.csv");
  r = deepguide::test::run_cli("evaluate merge -q --allow-skips -o '" + tmp.file("merged") + "'" + shards);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("--overwrite"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(tmp.path() / "merged" / "rows.csv"), before);
  // --overwrite replaces the run, old report included when the new one has none.
  r = deepguide::test::run_cli("evaluate merge -q --allow-skips --no-report --overwrite -o '" + tmp.file("merged") +
                               "'" + shards);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "merged" / "report.html"));
  // Without --allow-skips a skip is still exit 4.
  r = deepguide::test::run_cli("evaluate merge -q -o '" + tmp.file("merged4") + "'" + shards);
  EXPECT_EQ(r.exit_code, 4) << r.err;
}

TEST(EvaluateCli, AFolderAnotherProcessWritesIsRefused) {
  ScratchDir tmp;
  (void)small_suite(tmp, 2);
  std::filesystem::create_directories(tmp.path() / "out");
  const FolderLock held(tmp.path() / "out", "test");
  const auto r = deepguide::test::run_cli("evaluate '" + tmp.file("suite") + "' --methods visibility -q -o '" +
                                          tmp.file("out") + "'");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("process " + std::to_string(getpid())), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "out" / "rows.csv"));
}

TEST(Evaluate, SlurmArrayTasksAreShardsInOrder) {
  EXPECT_EQ(slurm_array_shard("0", "0", "16"), (Shard{1, 16}));
  EXPECT_EQ(slurm_array_shard("16", "1", "16"), (Shard{16, 16}));
  EXPECT_EQ(slurm_array_shard("3", nullptr, "8"), (Shard{4, 8}));
  EXPECT_THROW(slurm_array_shard(nullptr, "0", "8"), InputError);
  EXPECT_THROW(slurm_array_shard("x", "0", "8"), InputError);
  EXPECT_THROW(slurm_array_shard("9", "0", "8"), InputError);  // ids not consecutive from the minimum
  // Two locks on one folder: the second is refused until the first ends.
  ScratchDir tmp;
  {
    const FolderLock a(tmp.path(), "a");
    EXPECT_THROW(FolderLock(tmp.path(), "b"), InputError);
  }
  EXPECT_NO_THROW(FolderLock(tmp.path(), "c"));
}
