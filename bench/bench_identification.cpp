// Identification benchmark: a plain program printing a markdown table for
// docs/PERFORMANCE.md. The two sample scenarios (data/scenarios/
// align_in_current.yaml, around_object.yaml) in uniform currents of 0, 0.5
// and 1.0 m/s from several directions (going around: both sides, at 30 m,
// where the path's tightest turn fits a 1 m/s current), each run through
// simulate_identification with the real vehicle model and autopilot: how it
// ended, the time to position, the errors over the hold, the minimum
// clearance, and the wall time per simulated time.
// Usage: bench_identification [DATA_DIR]   (default data/scenarios, from the repository root)

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "bench_options.hpp"
#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/simulation/identification_run.hpp"
#include "deepguide/simulation/scenario.hpp"

using namespace deepguide;

namespace {

struct Row {
  double speed, towards_deg;
};

constexpr Row kCurrents[] = {{0.0, 0.0},   {0.5, 100.0}, {0.5, 10.0},  {0.5, 200.0},
                             {1.0, 100.0}, {1.0, 250.0}, {1.0, 170.0}, {1.0, 45.0}};

int run(const std::string& dir) {
  const Scenario align = read_scenario_file(dir + "/align_in_current.yaml");
  const Scenario around = read_scenario_file(dir + "/around_object.yaml");
  std::printf(
      "| mode | current m/s towards deg | side | end | in position s | distance error RMS / max m | "
      "station keeping or cross-track RMS / max m | laps | min clearance m | x real time |\n");
  std::printf("|---|---|---|---|---:|---|---|---:|---:|---:|\n");
  int failures = 0;
  double worst_align = 0.0, worst_around = 0.0;
  for (int pass = 0; pass < 3; ++pass) {  // align; around to port; around to starboard
    for (const Row& c : kCurrents) {
      Scenario sc = pass == 0 ? align : around;
      sc.current = c.speed * unit_vector(heading_deg_to_math_rad(c.towards_deg));
      if (pass > 0) {
        sc.identify->around.distance_m = 30.0;
        sc.identify->around.direction = pass == 1 ? 1 : -1;
      }
      const auto t0 = std::chrono::steady_clock::now();
      const IdentifyResult r = simulate_identification(sc, {false});
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const IdentifyStats& s = r.stats;
      const ErrorStats& track = pass == 0 ? s.station_keeping_m : s.cross_track_m;
      std::printf("| %s | %.1f / %.0f | %s | %s | %.1f | %.2f / %.2f | %.2f / %.2f | %s | %.2f | %.0f |\n",
                  pass == 0 ? "align" : "around", c.speed, c.towards_deg,
                  pass == 0 ? "-" : (pass == 1 ? "port" : "starboard"), std::string(to_string(r.end)).c_str(),
                  s.time_to_position_s, s.distance_error_m.rms, s.distance_error_m.max_abs, track.rms, track.max_abs,
                  pass == 0 ? "-" : std::to_string(s.laps).substr(0, 4).c_str(), s.vehicle.min_clearance_m,
                  s.vehicle.time_s / wall);
      const bool ok = pass == 0 ? r.end == IdentifyEnd::held && s.distance_error_m.rms < 1.0 &&
                                      s.vehicle.min_clearance_m >= sc.identify->align.standoff_m
                                : r.end == IdentifyEnd::laps_done && s.cross_track_m.rms < 1.0;
      if (!ok) ++failures;
      (pass == 0 ? worst_align : worst_around) =
          std::max(pass == 0 ? worst_align : worst_around, pass == 0 ? s.distance_error_m.rms : s.cross_track_m.rms);
    }
  }
  std::printf(
      "\nWorst aligning distance-error RMS %.2f m, worst going-around cross-track RMS %.2f m; "
      "%d run(s) missed the goal (RMS < 1 m, held or laps done, aligning never inside the standoff).\n",
      worst_align, worst_around, failures);
  return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::string folder = "data/scenarios";
  CLI::App app{"bench_identification: aligning and going around in currents of 0..1 m/s"};
  app.add_option("folder", folder, "The scenario folder (its identify scenarios)")->capture_default_str();
  deepguide::bench::parse_or_exit(app, argc, argv);
  try {
    return run(folder);
  } catch (const InputError& e) {
    std::fprintf(stderr, "bench_identification: %s\n", e.what());
    return 1;
  }
}
