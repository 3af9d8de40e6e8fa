#include "deepguide/simulation/trajectory_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {
namespace {

// The columns every trajectory has (trajectory_io.hpp), without a line end.
constexpr const char* kVehicleHeader =
    "time_s,x_m,y_m,heading_deg,course_cmd_deg,rate_cmd_deg_s,rate_ref_deg_s,rate_deg_s,speed_mps,clearance_m";

// Nautical turning rate: clockwise positive, deg/s.
double nautical_rate(double r) { return -rad_to_deg(r) + 0.0; }

void append_row(std::string& out, const char* format, auto... values) {
  char row[320];
  const int n = std::snprintf(row, sizeof row, format, values...);
  out.append(row, static_cast<std::size_t>(std::clamp<int>(n, 0, static_cast<int>(sizeof row) - 1)));
}

void append_vehicle_columns(std::string& out, const TrajectorySample& sample) {
  const VehicleColumns x = vehicle_columns(sample);
  append_row(out, "%.3f,%.3f,%.3f,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f,", x.time_s, x.x_m, x.y_m, x.heading_deg,
             x.course_cmd_deg, x.rate_cmd_deg_s, x.rate_ref_deg_s, x.rate_deg_s, x.speed_mps);
  if (std::isinf(x.clearance_m) && x.clearance_m > 0) {
    out += "inf";
  } else {
    append_row(out, "%.3f", x.clearance_m);
  }
}

}  // namespace

VehicleColumns vehicle_columns(const TrajectorySample& x) {
  return {x.time_s,
          x.position.x(),
          x.position.y(),
          math_rad_to_heading_deg(x.heading),
          math_rad_to_heading_deg(x.course_cmd),
          nautical_rate(x.rate_cmd),
          nautical_rate(x.rate_ref),
          nautical_rate(x.rate),
          x.speed_mps,
          x.clearance_m};
}

std::string trajectory_csv(std::span<const TrajectorySample> trajectory) {
  std::string out = std::string(kVehicleHeader) + ",sector,status,course_unreachable\n";
  out.reserve(out.size() + trajectory.size() * 120);
  for (const TrajectorySample& x : trajectory) {
    append_vehicle_columns(out, x);
    const std::string_view status = to_string(x.status);
    append_row(out, ",%d,%.*s,%d\n", x.sector, static_cast<int>(status.size()), status.data(),
               x.course_unreachable ? 1 : 0);
  }
  return out;
}

void write_trajectory_csv(const std::string& path, std::span<const TrajectorySample> trajectory) {
  write_text_file(path, trajectory_csv(trajectory), "trajectory");
}

std::string identification_csv(std::span<const IdentifySample> trajectory) {
  std::string out = std::string(kVehicleHeader) +
                    ",mode,object_distance_m,distance_error_m,cross_track_m,goal_error_m,laps,"
                    "course_unreachable\n";
  out.reserve(out.size() + trajectory.size() * 150);
  for (const IdentifySample& x : trajectory) {
    append_vehicle_columns(out, x.vehicle);
    const std::string_view mode = to_string(x.phase);
    append_row(out, ",%.*s,%.3f,%.3f,%.3f,%.3f,%.4f,%d\n", static_cast<int>(mode.size()), mode.data(),
               x.object_distance_m, x.distance_error_m, x.cross_track_m, x.goal_error_m, x.laps,
               x.vehicle.course_unreachable ? 1 : 0);
  }
  return out;
}

void write_identification_csv(const std::string& path, std::span<const IdentifySample> trajectory) {
  write_text_file(path, identification_csv(trajectory), "trajectory");
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
  if (result.collision) {
    j["collision"] = result.collision->unavoidable ? "unavoidable" : "avoidable";
    j["collision_cause"] = result.collision->reason;
  }
  return j;
}

namespace {

nlohmann::ordered_json error_json(const ErrorStats& e) { return {{"rms", e.rms}, {"max", e.max_abs}}; }

nlohmann::ordered_json position_json(const Vec2& p) { return {{"x_m", p.x()}, {"y_m", p.y()}}; }

}  // namespace

nlohmann::ordered_json identification_json(const Scenario& scenario, const IdentifyResult& result) {
  const IdentifyStats& s = result.stats;
  const SimulationStats& v = s.vehicle;
  const bool aligning = result.mode == IdentifyMode::align;
  nlohmann::ordered_json switches = nlohmann::ordered_json::array();
  for (const ModeSwitch& m : result.switches) {
    switches.push_back({{"time_s", m.time_s},
                        {"x_m", m.position.x()},
                        {"y_m", m.position.y()},
                        {"from", std::string(to_string(m.from))},
                        {"to", std::string(to_string(m.to))}});
  }
  nlohmann::ordered_json j = {
      {"scenario", scenario.name},
      {"object", scenario.identify ? scenario.identify->object_id : std::string()},
      {"mode", std::string(to_string(result.mode))},
      {"end", std::string(to_string(result.end))},
      {"failure", result.failure.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(result.failure)},
      {"in_position", s.in_position},
      {"time_to_position_s", s.in_position ? nlohmann::ordered_json(s.time_to_position_s) : nullptr},
      {"hold_s", s.hold_s},
      {"position_lost", s.position_lost},
      {"requested_distance_m", s.requested_distance_m},
      {"distance_error_m", error_json(s.distance_error_m)},
      {"cross_track_m", error_json(s.cross_track_m)},
      {"station_keeping_m", aligning ? error_json(s.station_keeping_m) : nlohmann::ordered_json(nullptr)},
      {"laps", aligning ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.laps)},
      {"goal", aligning ? position_json(result.goal) : nlohmann::ordered_json(nullptr)},
      {"min_clearance_m", std::isfinite(v.min_clearance_m) ? nlohmann::ordered_json(v.min_clearance_m) : nullptr},
      {"collided", v.collided},
      {"time_s", v.time_s},
      {"path_length_m", v.path_length_m},
      {"energy_j", v.energy_j},
      {"max_abs_rate_deg_s", rad_to_deg(v.max_abs_rate)},
      {"rms_rate_deg_s", rad_to_deg(v.rms_rate)},
      {"course_unreachable_s", v.course_unreachable_s},
      {"samples", result.samples},
      {"start_mode", std::string(to_string(result.start_phase))},
      {"mode_switches", switches},
  };
  return j;
}

namespace {

std::string error_text(const char* what, const ErrorStats& e) {
  return printf_text("  %-24s RMS %.3f m, max %.3f m\n", what, e.rms, e.max_abs);
}

}  // namespace

std::string simulation_text(const Scenario& scenario, const SimulationResult& result) {
  const nlohmann::ordered_json j = simulation_json(scenario, result);
  std::string t = "scenario " + scenario.name + ", method " + j.value("method", std::string()) + ", seed " +
                  std::to_string(scenario.sonar.seed) + "\n";
  for (const auto& [key, value] : j.items()) {
    if (key == "scenario" || key == "method" || key == "seed") continue;
    const std::string shown = value.is_number_float() ? printf_text("%.3f", value.get<double>())
                              : value.is_string()     ? value.get<std::string>()
                                                      : value.dump();
    t += printf_text("  %-24s %s\n", key.c_str(), shown.c_str());
  }
  return t;
}

std::string identification_text(const Scenario& sc, const IdentifyResult& r) {
  std::string t;
  const IdentifyStats& s = r.stats;
  const bool aligning = r.mode == IdentifyMode::align;
  t += printf_text("scenario %s, object %s, mode %s\n", printable(sc.name).c_str(),
                   printable(sc.identify->object_id).c_str(), std::string(to_string(r.mode)).c_str());
  t += printf_text("  %-24s %s\n", "end", std::string(to_string(r.end)).c_str());
  if (!s.in_position) {
    t += printf_text("  %-24s never\n", "in position");
  } else {
    t += printf_text("  %-24s %.1f s\n", "time to position", s.time_to_position_s);
    t += printf_text("  %-24s %.1f s\n", aligning ? "held" : "tracked", s.hold_s);
    if (s.position_lost > 0) t += printf_text("  %-24s %d times\n", "left position", s.position_lost);
    t += printf_text("  %-24s %.3f m from the object\n", "requested distance", s.requested_distance_m);
    t += error_text("distance error", s.distance_error_m);
    if (aligning) t += error_text("station-keeping error", s.station_keeping_m);
    t += error_text("cross-track error", s.cross_track_m);
  }
  if (!aligning) t += printf_text("  %-24s %.3f\n", "laps", s.laps);
  t += printf_text("  %-24s %.3f m%s\n", "min clearance", s.vehicle.min_clearance_m,
                   s.vehicle.collided ? " (COLLIDED)" : "");
  t += printf_text("  %-24s %.1f s, %.1f m, %.0f kJ\n", "time, path, energy", s.vehicle.time_s, s.vehicle.path_length_m,
                   s.vehicle.energy_j / 1e3);
  t += printf_text("  %-24s %.3f deg/s max, %.3f RMS\n", "turning rate", rad_to_deg(s.vehicle.max_abs_rate),
                   rad_to_deg(s.vehicle.rms_rate));
  t += printf_text("  mode switches (%zu; %s at the start)\n", r.switches.size(),
                   std::string(to_string(r.start_phase)).c_str());
  for (const ModeSwitch& m : r.switches) {
    t += printf_text("    %9.1f s  x %10.1f, y %10.1f m  %s -> %s\n", m.time_s, m.position.x(), m.position.y(),
                     std::string(to_string(m.from)).c_str(), std::string(to_string(m.to)).c_str());
  }
  return t;
}

}  // namespace deepguide
