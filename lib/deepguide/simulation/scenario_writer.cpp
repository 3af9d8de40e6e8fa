#include "deepguide/simulation/scenario_writer.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/yaml_mapping.hpp"
#include "deepguide/reactive/reactive_registry.hpp"

namespace deepguide {

namespace {

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

std::string point(const Vec2& p) {
  return "{x: " + yaml_exact_number(p.x()) + ", y: " + yaml_exact_number(p.y()) + "}";
}

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
  if (sc.start_heading)
    o << "start_heading_deg: " << yaml_exact_number(math_rad_to_heading_deg(*sc.start_heading)) << "\n";
  o << "depth_m: " << yaml_exact_number(sc.depth_m) << "\n";
  o << "obstacles:" << (sc.obstacles.empty() ? " []" : "") << "\n";
  for (const EllipticCylinder& c : sc.obstacles) {
    const Ellipse& e = c.footprint;
    o << "  - {id: " << quoted(c.id) << ", x: " << yaml_exact_number(e.centre.x())
      << ", y: " << yaml_exact_number(e.centre.y()) << ", semi_major_m: " << yaml_exact_number(e.a)
      << ", semi_minor_m: " << yaml_exact_number(e.b)
      << ", orientation_deg: " << yaml_exact_number(math_rad_to_heading_deg(e.theta)) << "}\n";
  }
  if (sc.current.norm() > 0.0) {
    o << "current: \"" << yaml_exact_number(sc.current.norm()) << ","
      << yaml_exact_number(math_rad_to_heading_deg(std::atan2(sc.current.y(), sc.current.x()))) << "\"\n";
  }
  o << "seed: " << sc.sonar.seed << "\n";
  const SonarParams& s = sc.sonar;
  o << "sonar: {range_m: " << yaml_exact_number(s.range_m)
    << ", field_of_view_deg: " << yaml_exact_number(rad_to_deg(s.field_of_view))
    << ", update_rate_hz: " << yaml_exact_number(s.update_rate_hz)
    << ", position_sigma_m: " << yaml_exact_number(s.position_sigma_m)
    << ", position_sigma_per_m: " << yaml_exact_number(s.position_sigma_per_m)
    << ", size_sigma_m: " << yaml_exact_number(s.size_sigma_m)
    << ", size_sigma_per_m: " << yaml_exact_number(s.size_sigma_per_m) << "}\n";
  const ReactiveParams& r = sc.reactive;
  o << "reactive: {margin_m: " << yaml_exact_number(r.margin_m)
    << ", arrival_radius_m: " << yaml_exact_number(r.arrival_radius_m)
    << ", influence_m: " << yaml_exact_number(r.influence_m) << ", speed_mps: " << yaml_exact_number(r.speed_mps)
    << ", exit_blend_fraction: " << yaml_exact_number(r.exit_blend_fraction);
  // Every registered method's own parameters, the defaults too: the file says
  // what the run used.
  for (const ReactiveTuning& t : reactive_tunings())
    o << ", " << t.key << ": " << yaml_exact_number(tuning_value(r, t.key));
  o << "}\n";
  o << "contacts: {gate_m: " << yaml_exact_number(sc.contacts.gate_m);
  if (std::isfinite(sc.contacts.memory_s)) o << ", memory_s: " << yaml_exact_number(sc.contacts.memory_s);
  o << "}\n";
  o << "energy: {hotel_power_w: " << yaml_exact_number(sc.energy.hotel_power_w)
    << ", propulsion_k_w_per_mps3: " << yaml_exact_number(sc.energy.propulsion_k_w_per_mps3) << "}\n";
  if (!std::isnan(sc.max_time_s)) o << "max_time_s: " << yaml_exact_number(sc.max_time_s) << "\n";
  o << "stall_time_s: " << yaml_exact_number(sc.stall_time_s) << "\n";
  o << "no_progress_s: " << yaml_exact_number(sc.no_progress_s) << "\n";
  o << "reversal_dead_band_deg_s: " << yaml_exact_number(rad_to_deg(sc.reversal_dead_band)) << "\n";
  return o.str();
}

}  // namespace deepguide
