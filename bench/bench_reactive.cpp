// Reactive-level benchmark: a plain program printing markdown tables for
// docs/PERFORMANCE.md.
//  1. Monte Carlo (evaluation/monte_carlo.hpp): every method on N seeded
//     random scenarios with inexact sonar detections and currents up to
//     0.5 m/s: collisions, clearance, turning rates, how runs ended.
//  2. Throughput: simulated time over wall-clock time for a 1-hour run at
//     the vehicle's 10 Hz step among 100 obstacles, each method.
// Usage: bench_reactive [--scenarios N] [--seed S] [--no-throughput]

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "bench_options.hpp"
#include "deepguide/core/angles.hpp"
#include "deepguide/evaluation/monte_carlo.hpp"

using namespace deepguide;

namespace {

constexpr ReactiveMethod kMethods[] = {ReactiveMethod::dipole, ReactiveMethod::geometric, ReactiveMethod::potential};

double deg_s(double rad_s) { return rad_s * 180.0 / std::numbers::pi; }

void progress(int done, int total) {
  if (done % 50 == 0 || done == total) std::fprintf(stderr, "monte carlo: %d / %d scenarios\n", done, total);
}

const MethodSummary* find(const MonteCarloResult& r, ReactiveMethod m) {
  for (const MethodSummary& s : r.summaries) {
    if (s.method == m) return &s;
  }
  return nullptr;
}

void print_monte_carlo(const MonteCarloResult& r) {
  const MonteCarloParams& p = r.params;
  std::printf("## Monte Carlo: %d scenarios (seed %llu)\n\n", p.scenarios, static_cast<unsigned long long>(p.seed));
  std::printf(
      "Each scenario (lib/deepguide/evaluation/monte_carlo.hpp): start and target 400..800 m apart, 1..%d "
      "ellipses (semi-major 5..30 m, b/a 0.3..1) scattered along the line (%.0f m across it, 1 sigma), "
      "overlaps allowed; a uniform current of 0..%.2f m/s in any direction; the DeepC-like vehicle at "
      "cruise; the default inexact forward-looking sonar (120 m, 120 deg, 2 Hz, position and size errors "
      "0.5 m + 1 %% of range, seeded per scenario); security margin 10 m. Every method runs every scenario. "
      "Turning rates: r_ref is the autopilot's reference turning rate (what the method asked, within the "
      "autopilot's 5 deg/s limit); r the vehicle's actual turning rate. Distributions over runs: median / 95th "
      "percentile / max.\n\n",
      p.max_obstacles, p.cross_track_sigma_m, p.max_current_mps);
  std::printf(
      "| method | runs | reached | collisions | stalled | no progress | time out | min clearance m: min / "
      "p5 / median | max abs r_ref deg/s | RMS r_ref deg/s | max abs r deg/s | RMS r deg/s | heading reversals "
      "mean | path / straight (median) |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---|---|---|---|---|---:|---:|\n");
  for (const MethodSummary& s : r.summaries) {
    auto three = [](const Distribution& d, double k) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%.2f / %.2f / %.2f", k * d.median, k * d.p95, k * d.max);
      return std::string(buf);
    };
    const double to_deg = 180.0 / std::numbers::pi;
    std::printf("| %s | %d | %d | %d | %d | %d | %d | %.2f / %.2f / %.2f | %s | %s | %s | %s | %.2f | %.4f |\n",
                std::string(to_string(s.method)).c_str(), s.runs, s.reached, s.collisions, s.stalled + s.target_in_zone,
                s.no_progress, s.time_out, s.min_clearance_m.min, s.min_clearance_m.p5, s.min_clearance_m.median,
                three(s.max_abs_rate_ref, to_deg).c_str(), three(s.rms_rate_ref, to_deg).c_str(),
                three(s.max_abs_rate, to_deg).c_str(), three(s.rms_rate, to_deg).c_str(), s.reversals.mean,
                s.path_ratio.median);
  }
  const MethodSummary* geo = find(r, ReactiveMethod::geometric);
  const MethodSummary* dip = find(r, ReactiveMethod::dipole);
  if (geo != nullptr && dip != nullptr) {
    // Per scenario: the geometric method's max |r| (and max |r_ref|) over the dipole's.
    auto compare = [&](const char* name, double SimulationStats::*stat, const Distribution& g, const Distribution& d) {
      std::vector<double> ratios;
      int lower = 0, both = 0;
      for (const MonteCarloRun& run : r.runs) {
        if (run.method != ReactiveMethod::geometric) continue;
        for (const MonteCarloRun& other : r.runs) {
          if (other.scenario != run.scenario || other.method != ReactiveMethod::dipole || !(other.stats.*stat > 0.0)) {
            continue;
          }
          ratios.push_back(run.stats.*stat / other.stats.*stat);
          ++both;
          lower += run.stats.*stat < other.stats.*stat;
        }
      }
      const Distribution q = distribution(ratios);
      std::printf(
          "- Geometric versus dipole, %s: median over runs %.2f vs %.2f deg/s (ratio %.3f); per scenario "
          "geometric / dipole: median %.3f, p95 %.3f, max %.3f; geometric lower in %d of %d scenarios.\n",
          name, deg_s(g.median), deg_s(d.median), g.median / std::max(d.median, 1e-12), q.median, q.p95, q.max, lower,
          both);
    };
    std::printf("\n");
    compare("max |r|", &SimulationStats::max_abs_rate, geo->max_abs_rate, dip->max_abs_rate);
    compare("max |r_ref|", &SimulationStats::max_abs_rate_ref, geo->max_abs_rate_ref, dip->max_abs_rate_ref);
    const MethodSummary* pot = find(r, ReactiveMethod::potential);
    std::printf("- Collisions: geometric %d, dipole %d, potential %d.\n", geo->collisions, dip->collisions,
                pot ? pot->collisions : -1);
  }
}

// 100 obstacles along a 10 km line, alternately left and right of it, so the
// vehicle keeps evading for the whole hour (it covers about 7.4 km).
Scenario throughput_scenario() {
  Scenario sc;
  sc.name = "throughput";
  sc.source = sc.name;
  sc.start = Vec2::Zero();
  sc.target = Vec2(10000.0, 0.0);
  for (int i = 0; i < 100; ++i) {
    EllipticCylinder e;
    e.id = "t" + std::to_string(i);
    const double x = 150.0 + 75.0 * i;
    const double y = (i % 2 == 0 ? 1.0 : -1.0) * 8.0;
    e.footprint = Ellipse{{x, y}, 12.0, 8.0, 0.3 * i};
    sc.obstacles.push_back(e);
  }
  sc.current = Vec2(0.1, 0.2);
  sc.max_time_s = 3600.0;
  sc.no_progress_s = 3600.0;
  return sc;
}

void print_throughput() {
  const Scenario sc = throughput_scenario();
  std::printf("\n## Throughput: a 1-hour run at 10 Hz among 100 obstacles\n\n");
  std::printf(
      "100 ellipses (12 x 8 m) every 75 m along a 10 km line, alternately 8 m left and right of it; "
      "current 0.22 m/s; step %.2f s; the run stops at 3600 s simulated. Wall-clock time of simulate() "
      "(sonar, contacts, method, autopilot, vehicle, clearance to the true obstacles, trajectory kept), "
      "best of 3. Target: at least 10^4 x real time.\n\n",
      sc.vehicle.step_s);
  std::printf(
      "| method | simulated s | samples | wall ms (best of 3) | x real time | >= 1e4 | reached/ended | collided |\n");
  std::printf("|---|---:|---:|---:|---:|---|---|---|\n");
  for (const ReactiveMethod& m : kMethods) {
    double best = 1e300;
    SimulationResult keep;
    for (int rep = 0; rep < 3; ++rep) {
      const auto t0 = std::chrono::steady_clock::now();
      SimulationResult r = simulate(sc, m);
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      if (ms < best) best = ms;
      keep = std::move(r);
    }
    const double ratio = keep.stats.time_s / (best / 1000.0);
    std::printf("| %s | %.0f | %zu | %.1f | %.0f | %s | %s | %s |\n", std::string(to_string(m)).c_str(),
                keep.stats.time_s, keep.samples, best, ratio, ratio >= 1e4 ? "yes" : "no",
                std::string(to_string(keep.end)).c_str(), keep.stats.collided ? "yes" : "no");
  }
}

}  // namespace

int main(int argc, char** argv) {
  MonteCarloParams params;
  bool throughput = true;
  CLI::App app{"bench_reactive: Monte Carlo over seeded scenarios, then simulation throughput"};
  app.add_option("--scenarios", params.scenarios, "Scenarios")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--seed", params.seed, "The suite's seed")->capture_default_str();
  app.add_flag("!--no-throughput", throughput, "Skip the one-hour throughput run");
  deepguide::bench::parse_or_exit(app, argc, argv);
  try {
    std::printf("# bench_reactive\n\n");
    const auto t0 = std::chrono::steady_clock::now();
    const MonteCarloResult r = run_monte_carlo(params, kMethods, progress);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    print_monte_carlo(r);
    std::printf("\n(%zu runs in %.1f s wall.)\n", r.runs.size(), s);
    if (throughput) print_throughput();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_reactive: %s\n", e.what());
    return 1;
  }
  return 0;
}
