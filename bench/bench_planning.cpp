// Planning benchmark: graph build and query times of the three graph kinds on
// random elliptical obstacle fields of 10 .. 1000 obstacles, the full versus
// the reduced visibility graph, the median query on a prebuilt graph, and
// (where OMPL is installed) OMPL's optimal sampling planners on the same
// scenarios. One run prints markdown tables for docs/PERFORMANCE.md.
//
// Run: scripts/bench.sh, or build/bench/bench_planning [options] (--help).
//
// Scenarios (fixed seeds): N ellipses with centres uniform in a square of side
// 150 m * sqrt(N) (one obstacle per 150 m x 150 m), semi-major axis 5..40 m,
// b/a 0.2..1, uniform orientation; margin 5 m, the default polygon tolerance. Start
// on the west edge, goal on the east edge (middle 60 %), both outside every
// safety zone and the straight line between them blocked (checked with
// ObstacleField). Obstacles may overlap, as real clusters do.
//
// Every (scenario, graph kind) build runs in a forked child with a 60 s
// limit, so a graph that takes too long is reported instead of hanging the
// run; the child measures, the parent only collects numbers.
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/planning/single_query.hpp"
#include "deepguide/world/obstacle_field.hpp"

using namespace deepguide;

#ifdef DEEPGUIDE_BENCH_OMPL
// bench/ompl_peer.cpp
namespace deepguide_bench {
std::string ompl_peer_version();
void ompl_peer_init(unsigned seed);
bool ompl_peer_solve(const ObstacleField& field, const Vec2& lo, const Vec2& hi, const Vec2& start, const Vec2& goal,
                     const std::string& planner, double budget_s, std::vector<Vec2>& path, double& elapsed_s);
}  // namespace deepguide_bench
#endif

namespace {

constexpr double kMargin = 5.0;
const double kTolerance = deepguide::PlannerOptions{}.tolerance;  // the planner's default
constexpr double kCoarseTolerance = 1.0;  // second full/reduced comparison where the full graph refuses 0.2 m
constexpr double kCaseTimeoutS = 60.0;    // hard limit per build + query (child killed)
constexpr double kSlowS = 20.0;           // slower than this: one scenario only, and no larger N

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }
// CPU time of this process (ms): unlike wall time it hardly moves with other load on the machine.
double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

std::string loadavg() {  // other load on the machine perturbs every figure: print it
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return in ? a + " " + b + " " + c : "unknown";
}

// ---------------------------------------------------------------- scenarios

struct Scenario {
  int n = 0;
  int index = 0;
  double side = 0.0;  // obstacle centres lie in [0, side]^2
  ObstacleSet obstacles;
  Vec2 start{0.0, 0.0}, goal{0.0, 0.0};
};

unsigned scenario_seed(int n, int index) { return static_cast<unsigned>(1000003u * n + 7919u * index + 17u); }

Scenario make_scenario(int n, int index) {
  Scenario sc;
  sc.n = n;
  sc.index = index;
  sc.side = 150.0 * std::sqrt(static_cast<double>(n));
  std::mt19937_64 rng(scenario_seed(n, index));
  std::uniform_real_distribution<double> pos(0.0, sc.side), semi(5.0, 40.0), ratio(0.2, 1.0),
      ang(-std::numbers::pi, std::numbers::pi), edge(0.2 * sc.side, 0.8 * sc.side);
  for (int i = 0; i < n; ++i) {
    EllipticCylinder e;
    e.id = "e" + std::to_string(i);
    const double a = semi(rng);
    e.footprint = Ellipse{{pos(rng), pos(rng)}, a, a * ratio(rng), ang(rng)};
    sc.obstacles.ellipses.push_back(e);
  }
  // Both free, and the straight line between them blocked (else every planner
  // finds the trivial optimum and the scenario measures nothing).
  const ObstacleField field(sc.obstacles, kMargin);
  for (int attempt = 0; attempt < 100000; ++attempt) {
    do sc.start = {0.0, edge(rng)};
    while (!field.is_free(sc.start));
    do sc.goal = {sc.side, edge(rng)};
    while (!field.is_free(sc.goal));
    if (!field.segment_free(sc.start, sc.goal)) break;
  }
  return sc;
}

// Random free start/goal pairs anywhere in the square (for the prebuilt-graph queries).
std::vector<PlanningProblem> random_queries(const Scenario& sc, int count, unsigned seed) {
  const ObstacleField field(sc.obstacles, kMargin);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(0.0, sc.side);
  auto free_point = [&] {
    Vec2 p;
    do p = {pos(rng), pos(rng)};
    while (!field.is_free(p));
    return p;
  };
  std::vector<PlanningProblem> out;
  while (static_cast<int>(out.size()) < count) {
    PlanningProblem q{free_point(), free_point()};
    if ((q.start - q.goal).norm() > 1.0) out.push_back(q);
  }
  return out;
}

// ---------------------------------------------------------------- statistics

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}
double quantile(std::vector<double> v, double q) {  // nearest rank
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::clamp<std::size_t>(k, 1, v.size()) - 1];
}
double max_of(const std::vector<double>& v) { return v.empty() ? std::nan("") : *std::max_element(v.begin(), v.end()); }

std::string fmt(const char* f, double v) {
  if (std::isnan(v)) return "–";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string ms(double v) {  // milliseconds with about three significant digits
  if (std::isnan(v)) return "–";
  if (v < 1.0) return fmt("%.3f", v);
  if (v < 10.0) return fmt("%.2f", v);
  if (v < 1000.0) return fmt("%.1f", v);
  return fmt("%.0f", v);
}

// ---------------------------------------------------------------- graph cases

enum class Status : int { ok = 0, refused = 1, failed = 2, timeout = 3, skipped = 4 };

struct CaseResult {  // plain data: crosses the pipe from the child
  Status status = Status::skipped;
  double ctor_ms = 0, build_ms = 0, query_ms = 0, solve_ms = 0;
  double cpu_ms = 0;  // ctor + solve, CPU time
  double vertices = 0, edges = 0;
  bool found = false, safe = false;
  double route_m = 0, exact_m = 0, min_clearance_m = 0;
  // plan_single_query on the same scenario (graph over the obstacles within the ellipse bound)
  bool single_ok = false, single_found = false, single_safe = false;
  double single_ms = 0, single_cpu_ms = 0, single_route_m = 0, single_exact_m = 0;
  double single_rounds = 0, single_used = 0, single_vertices = 0;
  char message[256] = {};
};

void set_message(CaseResult& r, const std::string& m) { std::snprintf(r.message, sizeof r.message, "%s", m.c_str()); }

CaseResult measure(const Scenario& sc, GraphKind kind, double tolerance) {
  CaseResult r;
  try {
    const double c0 = cpu_ms();
    const auto t0 = Clock::now();
    Planner planner(sc.obstacles, PlannerOptions{.margin = kMargin, .tolerance = tolerance, .graph = kind});
    r.ctor_ms = ms_since(t0);
    const auto t1 = Clock::now();
    const PlanOutcome out = planner.solve(PlanningProblem{sc.start, sc.goal});
    r.solve_ms = ms_since(t1);
    r.cpu_ms = cpu_ms() - c0;
    r.build_ms = out.result.stats.build_ms;
    r.query_ms = out.result.stats.query_ms;
    r.vertices = static_cast<double>(out.result.stats.graph_vertices);
    r.edges = static_cast<double>(out.result.stats.graph_edges);
    r.found = out.result.found;
    r.route_m = out.result.found ? out.result.route.length() : 0.0;
    r.exact_m = out.result.exact_length_m;
    r.safe = out.check.safe;
    r.min_clearance_m = out.check.min_clearance_m;
    r.status = Status::ok;
    if (!r.found) set_message(r, out.result.message);
  } catch (const InputError& e) {
    r.status = Status::refused;
    set_message(r, e.what());
  } catch (const std::exception& e) {
    r.status = Status::failed;
    set_message(r, e.what());
  }
  try {
    const double c0 = cpu_ms();
    const auto t0 = Clock::now();
    const SingleQueryPlan one =
        plan_single_query(sc.obstacles, PlanningProblem{sc.start, sc.goal},
                          PlannerOptions{.margin = kMargin, .tolerance = tolerance, .graph = kind});
    r.single_ms = ms_since(t0);
    r.single_cpu_ms = cpu_ms() - c0;
    r.single_ok = true;
    r.single_found = one.outcome.result.found;
    r.single_safe = one.outcome.check.safe;
    r.single_route_m = r.single_found ? one.outcome.result.route.length() : 0.0;
    r.single_exact_m = one.outcome.result.exact_length_m;
    r.single_rounds = one.rounds;
    r.single_used = static_cast<double>(one.obstacles_used);
    r.single_vertices = static_cast<double>(one.outcome.result.stats.graph_vertices);
  } catch (const std::exception& e) {
    if (r.status == Status::ok) set_message(r, std::string("single query: ") + e.what());
  }
  return r;
}

CaseResult run_case(const Scenario& sc, GraphKind kind, double tolerance = kTolerance) {
  std::fflush(stdout);
  std::fflush(stderr);
  int fds[2];
  if (pipe(fds) != 0) {
    std::perror("pipe");
    std::exit(1);
  }
  const pid_t pid = fork();
  if (pid < 0) {
    std::perror("fork");
    std::exit(1);
  }
  if (pid == 0) {
    close(fds[0]);
    const CaseResult r = measure(sc, kind, tolerance);
    const ssize_t w = write(fds[1], &r, sizeof r);
    _exit(w == static_cast<ssize_t>(sizeof r) ? 0 : 1);
  }
  close(fds[1]);
  CaseResult r;
  pollfd p{fds[0], POLLIN, 0};
  const int ready = poll(&p, 1, static_cast<int>(kCaseTimeoutS * 1000));
  if (ready <= 0) {
    kill(pid, SIGKILL);
    r.status = Status::timeout;
    set_message(r, "over " + fmt("%.0f", kCaseTimeoutS) + " s, stopped");
  } else {
    std::size_t got = 0;
    auto* bytes = reinterpret_cast<char*>(&r);
    while (got < sizeof r) {
      const ssize_t k = read(fds[0], bytes + got, sizeof r - got);
      if (k <= 0) break;
      got += static_cast<std::size_t>(k);
    }
    if (got != sizeof r) {
      r = CaseResult{};
      r.status = Status::failed;
      set_message(r, "the measuring process died");
    }
  }
  close(fds[0]);
  int wstatus = 0;
  waitpid(pid, &wstatus, 0);
  return r;
}

std::string kind_name(const GraphKind& k) { return k == GraphKind::visibility ? "visibility (reduced)" : k.name; }

struct Options {
  std::vector<int> sizes{10, 50, 200, 1000};
  int scenarios = 5;
  int queries = 100;
  bool peer = true;
  std::vector<int> peer_sizes{10, 50, 200};
  int peer_scenarios = 5;
  std::vector<double> budgets{0.01, 0.1, 1.0};
};

Options parse(int argc, char** argv) {
  Options o;
  bool quick = false;
  CLI::App app{"bench_planning: planning time, graph sizes and route lengths as markdown tables"};
  app.add_flag("--quick", quick, "N = 10, 50, 200; 2 scenarios; peer: N = 10, 50, 2 scenarios, 0.01 and 0.1 s");
  app.add_option("--scenarios", o.scenarios, "Scenarios per obstacle count")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--queries", o.queries, "Random queries on the prebuilt 200-obstacle graph")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_flag("!--no-peer", o.peer, "Skip the OMPL peer");
  app.add_option("--peer-scenarios", o.peer_scenarios, "Scenarios per obstacle count for the OMPL peer")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  deepguide::bench::parse_or_exit(app, argc, argv);
  if (quick) {
    o.sizes = {10, 50, 200};
    o.scenarios = 2;
    o.peer_sizes = {10, 50};
    o.peer_scenarios = 2;
    o.budgets = {0.01, 0.1};
  }
  o.peer_scenarios = std::min(o.peer_scenarios, o.scenarios);
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options opt = parse(argc, argv);
  const auto run_t0 = Clock::now();
  const std::vector<GraphKind> kinds{GraphKind::visibility_full, GraphKind::visibility, GraphKind::tangent,
                                     GraphKind{"navmesh"}};

  std::printf("# bench_planning\n\n");
  std::printf("Load average at start: %s (1, 5, 15 min).\n\n", loadavg().c_str());
  std::printf(
      "Scenarios: N random ellipses (semi-major 5..40 m, b/a 0.2..1, any orientation), centres in a "
      "square of side 150 m * sqrt(N); margin %.0f m, polygon tolerance %.1f m; start on the west edge, "
      "goal on the east edge, both free, the straight line between them blocked; %d scenarios per N "
      "(fixed seeds); A*. Times are wall-clock ms on one core.\n\n",
      kMargin, kTolerance, opt.scenarios);

  std::map<int, std::vector<Scenario>> scenarios;
  for (int n : opt.sizes) {
    for (int k = 0; k < opt.scenarios; ++k) scenarios[n].push_back(make_scenario(n, k));
  }

  // Warm-up (page in the library code) before anything is timed.
  for (GraphKind kind : kinds) (void)measure(make_scenario(10, 99), kind, kTolerance);

  // ------------------------------------------------------------ graph table
  std::map<int, std::map<GraphKind, std::vector<CaseResult>>> res;  // [n][kind] per scenario (ok or not)
  std::map<GraphKind, std::string> blocked;                         // why larger N are skipped
  for (int n : opt.sizes) {
    for (GraphKind kind : kinds) {
      auto& cases = res[n][kind];
      if (!blocked[kind].empty()) {
        CaseResult r;
        r.status = Status::skipped;
        set_message(r, blocked[kind]);
        cases.push_back(r);
        continue;
      }
      for (const Scenario& sc : scenarios[n]) {
        std::fprintf(stderr, "[%6.1f s] N=%d %s scenario %d ...\n", ms_since(run_t0) / 1000.0, n,
                     kind_name(kind).c_str(), sc.index);
        const CaseResult r = run_case(sc, kind);
        cases.push_back(r);
        if (r.status == Status::refused || r.status == Status::timeout) break;  // the others would do the same
        if (r.status == Status::ok && (r.ctor_ms + r.solve_ms) / 1000.0 > kSlowS) break;
      }
      std::vector<double> totals;
      for (const auto& r : cases) {
        if (r.status == Status::ok) totals.push_back((r.ctor_ms + r.solve_ms) / 1000.0);
        if (r.status == Status::timeout) totals.push_back(kCaseTimeoutS);
      }
      const double t = median(totals);
      if (!std::isnan(t) && t > kSlowS) {
        blocked[kind] =
            "skipped: N=" + std::to_string(n) + " took " + fmt("%.0f", t) + " s (> " + fmt("%.0f", kSlowS) + " s)";
      }
    }
  }

  auto oks = [](const std::vector<CaseResult>& cs) {
    std::vector<const CaseResult*> out;
    for (const auto& r : cs)
      if (r.status == Status::ok) out.push_back(&r);
    return out;
  };
  // Exact optimum of scenario k: the tangent graph's exact length (0 if unknown).
  auto optimum = [&](int n, std::size_t k) {
    const auto& t = res[n][GraphKind::tangent];
    return k < t.size() && t[k].status == Status::ok && t[k].found ? t[k].exact_m : 0.0;
  };

  std::printf("## Build and first query (median over scenarios)\n\n");
  std::printf(
      "`ctor` is the Planner constructor (obstacle field + zones + graph), `build` the graph part of it "
      "(stats.build_ms); `query` is stats.query_ms (attach start and goal, A*), `solve` the whole "
      "Planner::solve call (start/goal checks, query, independent route check). `route / opt` is the "
      "route polyline's length over the exact optimum (the tangent graph's exact length); for the "
      "tangent graph the exact length itself is 1 and the polyline (arcs replaced by outside tangents) "
      "is shown.\n\n");
  std::printf(
      "| N | side m | graph | n | ctor ms | build ms | query ms | solve ms | ctor+solve ms (max) | "
      "ctor+solve CPU ms | vertices | edges | found | safe | route / opt |\n");
  std::printf("|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int n : opt.sizes) {
    for (GraphKind kind : kinds) {
      const auto& cs = res[n][kind];
      const auto ok = oks(cs);
      const double side = scenarios[n][0].side;
      if (ok.empty()) {
        std::printf("| %d | %.0f | %s | 0 | %s | | | | | | | | | | |\n", n, side, kind_name(kind).c_str(),
                    cs.empty() ? "not run" : cs.front().message);
        continue;
      }
      std::vector<double> ctor, build, query, solve, total, cpu, verts, edges, ratio;
      int found = 0, safe = 0;
      for (std::size_t k = 0; k < cs.size(); ++k) {
        const CaseResult& r = cs[k];
        if (r.status != Status::ok) continue;
        ctor.push_back(r.ctor_ms);
        build.push_back(r.build_ms);
        query.push_back(r.query_ms);
        solve.push_back(r.solve_ms);
        total.push_back(r.ctor_ms + r.solve_ms);
        cpu.push_back(r.cpu_ms);
        verts.push_back(r.vertices);
        edges.push_back(r.edges);
        found += r.found;
        safe += r.found && r.safe;
        const double o = optimum(n, k);
        if (r.found && o > 0) ratio.push_back(r.route_m / o);
      }
      std::string note;
      if (ok.size() < cs.size()) {
        note = " (" + std::string(cs.back().message) + ")";
      } else if (cs.size() < scenarios[n].size()) {
        note = " (first took > " + fmt("%.0f", kSlowS) + " s; rest not run)";
      }
      std::printf("| %d | %.0f | %s | %zu%s | %s | %s | %s | %s | %s (%s) | %s | %.0f | %.0f | %d/%zu | %d/%d | %s |\n",
                  n, side, kind_name(kind).c_str(), ok.size(), note.c_str(), ms(median(ctor)).c_str(),
                  ms(median(build)).c_str(), ms(median(query)).c_str(), ms(median(solve)).c_str(),
                  ms(median(total)).c_str(), ms(max_of(total)).c_str(), ms(median(cpu)).c_str(), median(verts),
                  median(edges), found, ok.size(), safe, found, fmt("%.5f", median(ratio)).c_str());
    }
  }

  std::printf("\n## One query: plan_single_query (what `deepguide plan` runs)\n\n");
  std::printf(
      "The graph is built only over the obstacles whose zone meets the ellipse |x-s| + |x-g| <= U, U "
      "growing from 1.01 x the straight line until the route fits, each round's graph focused on the query "
      "(only edges a path within U can use; src: lib/deepguide/planning/single_query.hpp, query_focus.hpp). "
      "`time` = the whole call (rounds of build + query + the final check against all "
      "obstacles). `route / planner` = its route length over the Planner's route on all obstacles (1 = the "
      "same optimum).\n\n");
  std::printf(
      "| N | graph | n | time median ms | time max ms | CPU median ms | rounds median (max) | obstacles "
      "used median | vertices median | found | safe | route / planner (max deviation) |\n");
  std::printf("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int n : opt.sizes) {
    for (GraphKind kind : kinds) {
      std::vector<double> t, c, rounds, used, verts, dev;
      int found = 0, safe = 0, count = 0;
      for (const CaseResult& r : res[n][kind]) {
        if (!r.single_ok) continue;
        ++count;
        t.push_back(r.single_ms);
        c.push_back(r.single_cpu_ms);
        rounds.push_back(r.single_rounds);
        used.push_back(r.single_used);
        verts.push_back(r.single_vertices);
        found += r.single_found;
        safe += r.single_found && r.single_safe;
        if (r.status == Status::ok && r.found && r.single_found) dev.push_back(r.single_route_m / r.route_m - 1.0);
      }
      if (count == 0) {
        std::printf("| %d | %s | 0 | | | | | | | | | |\n", n, kind_name(kind).c_str());
        continue;
      }
      double worst = 0.0;
      for (double d : dev) worst = std::max(worst, std::abs(d));
      std::printf("| %d | %s | %d | %s | %s | %s | %.0f (%.0f) | %.0f | %.0f | %d/%d | %d/%d | %s |\n", n,
                  kind_name(kind).c_str(), count, ms(median(t)).c_str(), ms(max_of(t)).c_str(), ms(median(c)).c_str(),
                  median(rounds), max_of(rounds), median(used), median(verts), found, count, safe, found,
                  dev.empty() ? "–" : fmt("%.1e", worst).c_str());
    }
  }

  std::printf("\n## Full versus reduced visibility graph (median of per-scenario ratios full / reduced)\n\n");
  std::printf(
      "Where the full graph refuses the default tolerance (more than 4000 corners), a second row compares "
      "both graphs at tolerance %.0f m, where it may still fit.\n\n",
      kCoarseTolerance);
  std::printf(
      "| N | tolerance m | n | full ctor+solve ms | reduced ctor+solve ms | build speed-up | query speed-up | "
      "ctor+solve speed-up | edges full / reduced | reduced route / full route |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  auto compare_row = [&](int n, double tol, const std::vector<CaseResult>& f, const std::vector<CaseResult>& r) {
    std::vector<double> b, q, t, e, len, ft, rt;
    for (std::size_t k = 0; k < std::min(f.size(), r.size()); ++k) {
      if (f[k].status != Status::ok || r[k].status != Status::ok) continue;
      ft.push_back(f[k].ctor_ms + f[k].solve_ms);
      rt.push_back(r[k].ctor_ms + r[k].solve_ms);
      b.push_back(f[k].build_ms / r[k].build_ms);
      q.push_back(f[k].query_ms / r[k].query_ms);
      t.push_back(ft.back() / rt.back());
      e.push_back(f[k].edges / r[k].edges);
      if (f[k].found && r[k].found) len.push_back(r[k].route_m / f[k].route_m);
    }
    if (b.empty()) {
      const char* why = f.empty() ? "not run" : f.front().message;
      std::printf("| %d | %g | 0 | full graph: %s | | | | | | |\n", n, tol, why);
      return false;
    }
    std::printf("| %d | %g | %zu | %s | %s | %sx | %sx | %sx | %sx | %s |\n", n, tol, b.size(), ms(median(ft)).c_str(),
                ms(median(rt)).c_str(), fmt("%.1f", median(b)).c_str(), fmt("%.1f", median(q)).c_str(),
                fmt("%.1f", median(t)).c_str(), fmt("%.1f", median(e)).c_str(), fmt("%.6f", median(len)).c_str());
    return true;
  };
  for (int n : opt.sizes) {
    if (compare_row(n, kTolerance, res[n][GraphKind::visibility_full], res[n][GraphKind::visibility])) continue;
    if (res[n][GraphKind::visibility_full].empty() ||
        res[n][GraphKind::visibility_full].front().status != Status::refused) {
      continue;  // skipped or timed out: a coarser tolerance would not help within the time limits
    }
    std::vector<CaseResult> f, r;
    for (const Scenario& sc : scenarios[n]) {
      std::fprintf(stderr, "[%6.1f s] N=%d tolerance %g m: full and reduced, scenario %d ...\n",
                   ms_since(run_t0) / 1000.0, n, kCoarseTolerance, sc.index);
      f.push_back(run_case(sc, GraphKind::visibility_full, kCoarseTolerance));
      if (f.back().status != Status::ok) break;
      r.push_back(run_case(sc, GraphKind::visibility, kCoarseTolerance));
      if ((f.back().ctor_ms + f.back().solve_ms) / 1000.0 > kSlowS) break;
    }
    compare_row(n, kCoarseTolerance, f, r);
  }

  // ------------------------------------------------------------ prebuilt graph queries
  const int qn = std::count(opt.sizes.begin(), opt.sizes.end(), 200) ? 200 : opt.sizes.back();
  std::printf("\n## Queries on a prebuilt %d-obstacle graph (%d random start/goal pairs, scenario 0)\n\n", qn,
              opt.queries);
  std::printf(
      "Start and goal uniform over the square, both outside every zone. `query` = stats.query_ms, "
      "`solve` = the whole Planner::solve call including the route check.\n\n");
  std::printf(
      "| graph | build ms | found | query median ms | query p90 ms | query max ms | solve median ms | "
      "solve p90 ms | solve max ms | solve CPU median ms |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::map<GraphKind, double> prebuilt_solve_median;
  {
    const Scenario& sc = scenarios[qn][0];
    const auto queries = random_queries(sc, opt.queries, 4242u);
    for (GraphKind kind : kinds) {
      const auto& c0 = res[qn][kind];
      if (c0.empty() || c0.front().status != Status::ok) {
        std::printf("| %s | %s | | | | | | | | |\n", kind_name(kind).c_str(),
                    c0.empty() ? "not run" : c0.front().message);
        continue;
      }
      std::fprintf(stderr, "[%6.1f s] prebuilt N=%d %s: %d queries ...\n", ms_since(run_t0) / 1000.0, qn,
                   kind_name(kind).c_str(), opt.queries);
      Planner planner(sc.obstacles, PlannerOptions{.margin = kMargin, .tolerance = kTolerance, .graph = kind});
      std::vector<double> q, s, c;
      int found = 0;
      double build = 0;
      for (const auto& pq : queries) {
        const double c0 = cpu_ms();
        const auto t0 = Clock::now();
        const PlanOutcome out = planner.solve(pq);
        s.push_back(ms_since(t0));
        c.push_back(cpu_ms() - c0);
        q.push_back(out.result.stats.query_ms);
        build = out.result.stats.build_ms;
        found += out.result.found;
      }
      prebuilt_solve_median[kind] = median(s);
      std::printf("| %s | %s | %d/%zu | %s | %s | %s | %s | %s | %s | %s |\n", kind_name(kind).c_str(),
                  ms(build).c_str(), found, queries.size(), ms(median(q)).c_str(), ms(quantile(q, 0.9)).c_str(),
                  ms(max_of(q)).c_str(), ms(median(s)).c_str(), ms(quantile(s, 0.9)).c_str(), ms(max_of(s)).c_str(),
                  ms(median(c)).c_str());
    }
  }

  // ------------------------------------------------------------ targets
  std::printf("\n## Targets (200 obstacles)\n\n");
  std::printf(
      "Built and queried, two ways: `single query` = plan_single_query, what `deepguide plan` runs (the "
      "graph over the obstacles the query can meet); `ctor+solve` = a reusable Planner over all obstacles "
      "plus its first query. Prebuilt: Planner::solve on the reusable graph.\n\n");
  std::printf(
      "| graph | single query median ms | single query max ms | < 50 ms (max) | ctor+solve median ms | "
      "ctor+solve max ms | < 50 ms (max) | prebuilt solve median ms | < 1 ms |\n");
  std::printf("|---|---:|---:|---|---:|---:|---|---:|---|\n");
  for (GraphKind kind : kinds) {
    if (!res.count(200)) break;
    std::vector<double> total, single;
    for (const auto& r : res[200][kind]) {
      if (r.single_ok) single.push_back(r.single_ms);
      if (r.status != Status::ok) continue;
      total.push_back(r.ctor_ms + r.solve_ms);
    }
    const double pm = prebuilt_solve_median.count(kind) ? prebuilt_solve_median[kind] : std::nan("");
    auto verdict = [](double v, double limit) { return std::isnan(v) ? "–" : v < limit ? "yes" : "**no**"; };
    std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", kind_name(kind).c_str(), ms(median(single)).c_str(),
                ms(max_of(single)).c_str(), verdict(max_of(single), 50.0), ms(median(total)).c_str(),
                ms(max_of(total)).c_str(), verdict(max_of(total), 50.0), ms(pm).c_str(), verdict(pm, 1.0));
  }

  // ------------------------------------------------------------ visibility versus quadtree
  // The seed's choice (its Fig. 7 against Fig. 6): the same scenarios, one
  // query each as `deepguide plan` runs it, and the quadtree's route with and
  // without smoothing against the visibility route.
  {
    constexpr double kCell = 2.0;
    std::printf("\n## Visibility versus quadtree graph (one query each, the same scenarios)\n\n");
    std::printf(
        "plan_single_query; quadtree with %.0f m minimum cells over the start-goal box widened by half their "
        "distance. Medians over scenarios; length ratios against the visibility route (median / max).\n\n",
        kCell);
    std::printf(
        "| N | graph | vertices | build ms | query ms | route / visibility | smoothed route / visibility | "
        "smoothed query ms |\n|---|---|---:|---:|---:|---|---|---:|\n");
    for (int n : opt.sizes) {
      if (n > 200) continue;  // the quadtree over N = 1000's 4.7 km box at 2 m: seconds per scenario
      std::vector<double> vis_v, vis_b, vis_q, qt_v, qt_b, qt_q, ratio, smooth_ratio, smooth_q;
      for (const Scenario& sc : scenarios[n]) {
        const PlanningProblem problem{sc.start, sc.goal};
        const SingleQueryPlan vis = plan_single_query(sc.obstacles, problem, PlannerOptions{.margin = kMargin});
        PlannerOptions q{.margin = kMargin, .graph = GraphKind::quadtree};
        q.quadtree.min_cell_m = kCell;
        const SingleQueryPlan raw = plan_single_query(sc.obstacles, problem, q);
        q.quadtree.smooth = true;
        const SingleQueryPlan smooth = plan_single_query(sc.obstacles, problem, q);
        if (!vis.outcome.result.found || !raw.outcome.result.found || !smooth.outcome.result.found) continue;
        const double best = vis.outcome.result.route.length();
        vis_v.push_back(static_cast<double>(vis.outcome.result.stats.graph_vertices));
        vis_b.push_back(vis.build_ms);
        vis_q.push_back(vis.query_ms);
        qt_v.push_back(static_cast<double>(raw.outcome.result.stats.graph_vertices));
        qt_b.push_back(raw.build_ms);
        qt_q.push_back(raw.query_ms);
        ratio.push_back(raw.outcome.result.route.length() / best);
        smooth_ratio.push_back(smooth.outcome.result.route.length() / best);
        smooth_q.push_back(smooth.query_ms);
      }
      if (ratio.empty()) continue;
      std::printf("| %d | visibility | %.0f | %s | %s | 1 | 1 | — |\n", n, median(vis_v), ms(median(vis_b)).c_str(),
                  ms(median(vis_q)).c_str());
      std::printf("| %d | quadtree | %.0f | %s | %s | %.3f / %.3f | %.4f / %.4f | %s |\n", n, median(qt_v),
                  ms(median(qt_b)).c_str(), ms(median(qt_q)).c_str(), median(ratio), max_of(ratio),
                  median(smooth_ratio), max_of(smooth_ratio), ms(median(smooth_q)).c_str());
    }
  }

  // ------------------------------------------------------------ OMPL peer
#ifdef DEEPGUIDE_BENCH_OMPL
  if (opt.peer) {
    using deepguide_bench::ompl_peer_solve;
    deepguide_bench::ompl_peer_init(20261122u);
    const std::vector<std::string> planners{"RRT*", "Informed RRT*", "BIT*", "PRM*"};
    std::printf("\n## OMPL %s peer (same scenarios, same exact validity test)\n\n",
                deepguide_bench::ompl_peer_version().c_str());
    std::printf(
        "2-D RealVectorStateSpace bounded to the square plus 60 m on each side (every zone fits), "
        "ObstacleField::is_free as state validity checker, a MotionValidator calling "
        "ObstacleField::segment_free (exact, no discretisation), PathLengthOptimizationObjective, default "
        "planner parameters, no path simplification; one run per scenario, planner and budget. `length / "
        "opt` = OMPL path length over the exact optimum (our tangent graph's exact length) over solved "
        "runs; `time ratio` = OMPL wall time (set-up + solve) over our tangent single-query time "
        "(plan_single_query), over all runs. `unsafe` counts OMPL paths our route checker rejects.\n\n");
    struct Cell {
      int runs = 0, solved = 0, unsafe = 0;
      std::vector<double> ratio, time_ratio;
    };
    std::map<int, std::map<std::string, std::map<double, Cell>>> cells;
    struct GoalRow {
      int scenarios = 0, shorter = 0, faster = 0, both = 0;
      std::vector<double> best_ratio, ours_ms;
    };
    std::map<int, GoalRow> goal;
    for (int n : opt.peer_sizes) {
      if (!scenarios.count(n)) continue;
      for (int k = 0; k < opt.peer_scenarios; ++k) {
        const Scenario& sc = scenarios[n][static_cast<std::size_t>(k)];
        const auto& tres = res[n][GraphKind::tangent];
        if (static_cast<std::size_t>(k) >= tres.size() || tres[k].status != Status::ok || !tres[k].found) continue;
        const double opt_len = tres[k].exact_m;
        // Ours: the one-shot answer, as OMPL's is (plan_single_query, the tangent graph).
        const double ours_ms = tres[k].single_ok ? tres[k].single_ms : tres[k].ctor_ms + tres[k].solve_ms;
        const ObstacleField field(sc.obstacles, kMargin);
        const Vec2 lo(-60.0, -60.0), hi(sc.side + 60.0, sc.side + 60.0);
        double best_1s = std::numeric_limits<double>::infinity(), best_1s_time = 0;
        for (const auto& p : planners) {
          for (double budget : opt.budgets) {
            std::fprintf(stderr, "[%6.1f s] OMPL N=%d scenario %d %s %.2f s ...\n", ms_since(run_t0) / 1000.0, n, k,
                         p.c_str(), budget);
            std::vector<Vec2> path;
            double elapsed = 0;
            const bool ok = ompl_peer_solve(field, lo, hi, sc.start, sc.goal, p, budget, path, elapsed);
            Cell& c = cells[n][p][budget];
            ++c.runs;
            c.time_ratio.push_back(elapsed * 1000.0 / ours_ms);
            if (!ok) continue;
            ++c.solved;
            const double len = Route{path}.length();
            c.ratio.push_back(len / opt_len);
            if (!check_route(path, field).safe) ++c.unsafe;
            if (budget == opt.budgets.back() && len < best_1s) {
              best_1s = len;
              best_1s_time = elapsed * 1000.0;
            }
          }
        }
        GoalRow& g = goal[n];
        ++g.scenarios;
        g.ours_ms.push_back(ours_ms);
        if (std::isfinite(best_1s)) g.best_ratio.push_back(best_1s / opt_len);
        const bool shorter = opt_len < best_1s;  // true as well when no OMPL planner solved it
        const bool faster = 100.0 * ours_ms < (std::isfinite(best_1s) ? best_1s_time : opt.budgets.back() * 1000.0);
        g.shorter += shorter;
        g.faster += faster;
        g.both += shorter && faster;
      }
    }
    for (const auto& [n, by_planner] : cells) {
      std::printf("### N = %d (side %.0f m)\n\n", n, scenarios[n][0].side);
      std::printf(
          "| planner | budget s | solved | length / opt median | length / opt best | time ratio median | "
          "unsafe |\n");
      std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
      for (const auto& p : planners) {
        for (double budget : opt.budgets) {
          const Cell& c = by_planner.at(p).at(budget);
          std::vector<double> r = c.ratio;
          std::printf("| %s | %g | %d/%d | %s | %s | %s | %d |\n", p.c_str(), budget, c.solved, c.runs,
                      fmt("%.4f", median(r)).c_str(),
                      fmt("%.4f", r.empty() ? std::nan("") : *std::min_element(r.begin(), r.end())).c_str(),
                      fmt("%.3g", median(c.time_ratio)).c_str(), c.unsafe);
        }
      }
      std::printf("\n");
    }
    std::printf("### Goal: tangent route shorter than the best OMPL planner at %g s, in under 1/100 of its time\n\n",
                opt.budgets.back());
    std::printf(
        "Per scenario: best = the shortest path of the four planners at %g s. \"faster\": our tangent "
        "single-query time x 100 < that planner's wall time.\n\n",
        opt.budgets.back());
    std::printf(
        "| N | scenarios | ours single query median ms (max) | best OMPL length / opt median (min) | shorter | "
        "faster | both |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const auto& [n, g] : goal) {
      const auto& b = g.best_ratio;
      std::printf("| %d | %d | %s (%s) | %s (%s) | %d/%d | %d/%d | %d/%d |\n", n, g.scenarios,
                  ms(median(g.ours_ms)).c_str(), ms(max_of(g.ours_ms)).c_str(), fmt("%.4f", median(b)).c_str(),
                  fmt("%.4f", b.empty() ? std::nan("") : *std::min_element(b.begin(), b.end())).c_str(), g.shorter,
                  g.scenarios, g.faster, g.scenarios, g.both, g.scenarios);
    }
  } else {
    std::printf("\nOMPL peer skipped (--no-peer).\n");
  }
#else
  std::printf(
      "\nOMPL peer not built: OMPL was not found when CMake configured the benchmarks "
      "(Debian: apt-get install libompl-dev, or run scripts/bench.sh).\n");
#endif

  std::printf("\nTotal run time: %.0f s; load average at the end: %s.\n", ms_since(run_t0) / 1000.0, loadavg().c_str());
  return 0;
}
