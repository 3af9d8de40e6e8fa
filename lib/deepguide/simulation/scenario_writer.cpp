#include "deepguide/simulation/scenario_writer.hpp"

#include <charconv>
#include <cstdio>
#include <cmath>
#include <sstream>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"

namespace deepguide {

namespace {

// The shortest text that reads back to the same double.
std::string num(double v) {
  if (std::isinf(v)) return v > 0 ? ".inf" : "-.inf";
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : std::string(".nan");
}

// YAML double-quoted scalar: ids and names may hold anything.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", static_cast<unsigned char>(c));
      out += hex;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string point(const Vec2& p) { return "{x: " + num(p.x()) + ", y: " + num(p.y()) + "}"; }

}  // namespace

std::string scenario_yaml(const Scenario& sc, const std::string& comment) {
  auto refuse = [&](const std::string& what) {
    throw InputError(sc.source + ": cannot write a scenario with " + what + " (only local-frame scenarios)");
  };
  if (sc.frame) refuse("a CRS");
  if (sc.current_field) refuse("a gridded current field");
  if (sc.identify) refuse("an identify section");

  std::ostringstream o;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) o << "# " << line << "\n";
  o << "name: " << quoted(sc.name) << "\n";
  o << "start: " << point(sc.start) << "\n";
  o << "target: " << point(sc.target) << "\n";
  if (sc.start_heading) o << "start_heading_deg: " << num(math_rad_to_heading_deg(*sc.start_heading)) << "\n";
  o << "depth_m: " << num(sc.depth_m) << "\n";
  o << "obstacles:" << (sc.obstacles.empty() ? " []" : "") << "\n";
  for (const EllipticCylinder& c : sc.obstacles) {
    const Ellipse& e = c.footprint;
    o << "  - {id: " << quoted(c.id) << ", x: " << num(e.center.x()) << ", y: " << num(e.center.y())
      << ", semi_major_m: " << num(e.a) << ", semi_minor_m: " << num(e.b)
      << ", orientation_deg: " << num(math_rad_to_heading_deg(e.theta)) << "}\n";
  }
  if (sc.current.norm() > 0.0) {
    o << "current: \"" << num(sc.current.norm()) << ","
      << num(math_rad_to_heading_deg(std::atan2(sc.current.y(), sc.current.x()))) << "\"\n";
  }
  o << "seed: " << sc.sonar.seed << "\n";
  const SonarParams& s = sc.sonar;
  o << "sonar: {range_m: " << num(s.range_m) << ", field_of_view_deg: " << num(rad_to_deg(s.field_of_view))
    << ", update_rate_hz: " << num(s.update_rate_hz) << ", position_sigma_m: " << num(s.position_sigma_m)
    << ", position_sigma_per_m: " << num(s.position_sigma_per_m) << ", size_sigma_m: " << num(s.size_sigma_m)
    << ", size_sigma_per_m: " << num(s.size_sigma_per_m) << "}\n";
  const ReactiveParams& r = sc.reactive;
  o << "reactive: {margin_m: " << num(r.margin_m) << ", arrival_radius_m: " << num(r.arrival_radius_m)
    << ", influence_m: " << num(r.influence_m) << ", potential_gain: " << num(r.potential_gain)
    << ", speed_mps: " << num(r.speed_mps) << ", exit_blend_fraction: " << num(r.exit_blend_fraction)
    << ", dipole_axis_band_m: " << num(r.dipole_axis_band_m) << ", dipole_blend_m: " << num(r.dipole_blend_m)
    << ", geometric_passage_m: " << num(r.geometric_passage_m)
    << ", potential_stall_fraction: " << num(r.potential_stall_fraction) << "}\n";
  o << "contacts: {gate_m: " << num(sc.contacts.gate_m);
  if (std::isfinite(sc.contacts.memory_s)) o << ", memory_s: " << num(sc.contacts.memory_s);
  o << "}\n";
  o << "energy: {hotel_power_w: " << num(sc.energy.hotel_power_w)
    << ", propulsion_k_w_per_mps3: " << num(sc.energy.propulsion_k_w_per_mps3) << "}\n";
  if (!std::isnan(sc.max_time_s)) o << "max_time_s: " << num(sc.max_time_s) << "\n";
  o << "stall_time_s: " << num(sc.stall_time_s) << "\n";
  o << "no_progress_s: " << num(sc.no_progress_s) << "\n";
  o << "reversal_dead_band_deg_s: " << num(rad_to_deg(sc.reversal_dead_band)) << "\n";
  return o.str();
}

}  // namespace deepguide
