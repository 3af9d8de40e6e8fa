#include "deepguide/simulation/trajectory_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"

namespace deepguide {
namespace {

constexpr const char* kHeader =
    "time_s,x_m,y_m,heading_deg,course_cmd_deg,rate_cmd_deg_s,rate_ref_deg_s,rate_deg_s,speed_mps,"
    "clearance_m,sector,status,course_unreachable\n";

// Nautical turning rate: clockwise positive, deg/s.
double nautical_rate(double r) { return -rad_to_deg(r) + 0.0; }

}  // namespace

std::string trajectory_csv(std::span<const TrajectorySample> trajectory) {
  std::string out = kHeader;
  out.reserve(out.size() + trajectory.size() * 120);
  char row[320];
  for (const TrajectorySample& x : trajectory) {
    char clearance[32];
    if (std::isinf(x.clearance_m) && x.clearance_m > 0) {
      std::snprintf(clearance, sizeof clearance, "inf");
    } else {
      std::snprintf(clearance, sizeof clearance, "%.3f", x.clearance_m);
    }
    const std::string_view status = to_string(x.status);
    const int n =
        std::snprintf(row, sizeof row, "%.3f,%.3f,%.3f,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f,%s,%d,%.*s,%d\n", x.time_s,
                      x.position.x(), x.position.y(), math_rad_to_heading_deg(x.heading),
                      math_rad_to_heading_deg(x.course_cmd), nautical_rate(x.rate_cmd), nautical_rate(x.rate_ref),
                      nautical_rate(x.rate), x.speed_mps, clearance, x.sector, static_cast<int>(status.size()),
                      status.data(), x.course_unreachable ? 1 : 0);
    out.append(row, static_cast<std::size_t>(std::min<int>(n, static_cast<int>(sizeof row) - 1)));
  }
  return out;
}

void write_trajectory_csv(const std::string& path, std::span<const TrajectorySample> trajectory) {
  AtomicOutput out(path);
  {
    std::ofstream file(out.temp_path(), std::ios::binary);
    const std::string text = trajectory_csv(trajectory);
    file.write(text.data(), static_cast<std::streamsize>(text.size()));
    file.flush();
    if (!file) throw InputError(path + ": could not write the trajectory");
  }
  out.commit();
}

nlohmann::ordered_json simulation_json(const Scenario& scenario, const SimulationResult& result) {
  const SimulationStats& s = result.stats;
  nlohmann::ordered_json j = {
      {"scenario", scenario.name},
      {"method", std::string(to_string(result.method))},
      {"seed", scenario.sonar.seed},
      {"end", std::string(to_string(result.end))},
      {"reached", s.reached},
      {"collided", s.collided},
      {"time_s", s.time_s},
      {"path_length_m", s.path_length_m},
      {"straight_distance_m", (scenario.target - scenario.start).norm()},
      {"energy_j", s.energy_j},
      {"min_clearance_m", nullptr},
      {"max_abs_rate_ref_deg_s", rad_to_deg(s.max_abs_rate_ref)},
      {"rms_rate_ref_deg_s", rad_to_deg(s.rms_rate_ref)},
      {"max_abs_rate_deg_s", rad_to_deg(s.max_abs_rate)},
      {"rms_rate_deg_s", rad_to_deg(s.rms_rate)},
      {"heading_reversals", s.heading_reversals},
      {"course_unreachable_s", s.course_unreachable_s},
      {"samples", result.samples},
      {"contacts", result.contacts},
  };
  if (std::isfinite(s.min_clearance_m)) j["min_clearance_m"] = s.min_clearance_m;
  return j;
}

}  // namespace deepguide
