#include "deepguide/vehicle/vehicle_params.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/input_files.hpp"
#include "deepguide/core/yaml_mapping.hpp"

namespace deepguide {
namespace {

// One numeric key of the file. Values are checked in SI against (lo, hi];
// messages quote the value in the file's unit.
enum class Unit { si, deg, kn };

// File unit <-> SI, written as the defaults are (deg_to_rad(25.0), 4.0 * knot)
// so that a file repeating a default gives the default to the last bit.
double to_si(Unit u, double v) {
  return u == Unit::deg ? deg_to_rad(v) : u == Unit::kn ? v * kMetresPerSecondPerKnot : v;
}
double from_si(Unit u, double v) {
  return u == Unit::deg ? rad_to_deg(v) : u == Unit::kn ? v / kMetresPerSecondPerKnot : v;
}

struct Field {
  const char* key;  // in the file, with its unit
  Unit scale;       // the file's unit
  double& (*ref)(VehicleParams&);
  double lo;         // exclusive
  double hi;         // inclusive
  const char* what;  // "a speed", ...
};

constexpr Unit kSI = Unit::si, kDeg = Unit::deg, kKn = Unit::kn;

// Section "" = top level, "autopilot" = the nested mapping. Two keys may fill
// one field (knots or m/s); giving both is an error.
const Field kFields[] = {
    {"length_m", kSI, [](VehicleParams& p) -> double& { return p.length_m; }, 0.0, 1000.0, "a length in metres"},
    {"mass_kg", kSI, [](VehicleParams& p) -> double& { return p.mass_kg; }, 0.0, 1e7, "a mass in kg"},
    {"cruise_speed_mps", kSI, [](VehicleParams& p) -> double& { return p.cruise_speed_mps; }, 0.0, 20.0,
     "a speed in m/s"},
    {"cruise_speed_kn", kKn, [](VehicleParams& p) -> double& { return p.cruise_speed_mps; }, 0.0, 20.0,
     "a speed in knots"},
    {"max_speed_mps", kSI, [](VehicleParams& p) -> double& { return p.max_speed_mps; }, 0.0, 20.0, "a speed in m/s"},
    {"max_speed_kn", kKn, [](VehicleParams& p) -> double& { return p.max_speed_mps; }, 0.0, 20.0, "a speed in knots"},
    {"min_speed_mps", kSI, [](VehicleParams& p) -> double& { return p.min_speed_mps; }, 0.0, 20.0, "a speed in m/s"},
    {"min_speed_kn", kKn, [](VehicleParams& p) -> double& { return p.min_speed_mps; }, 0.0, 20.0, "a speed in knots"},
    {"hotel_power_w", kSI, [](VehicleParams& p) -> double& { return p.energy.hotel_power_w; }, 0.0, 1e7,
     "a power in W"},
    {"propulsion_k_w_per_mps3", kSI, [](VehicleParams& p) -> double& { return p.energy.propulsion_k_w_per_mps3; }, 0.0,
     1e7, "a coefficient in W/(m/s)^3"},
    {"speed_time_constant_s", kSI, [](VehicleParams& p) -> double& { return p.speed_time_constant_s; }, 0.0, 3600.0,
     "a time constant in seconds"},
    {"nomoto_gain_per_s", kSI, [](VehicleParams& p) -> double& { return p.nomoto_gain_per_s; }, 0.0, 10.0,
     "a Nomoto gain K in 1/s"},
    {"nomoto_time_constant_s", kSI, [](VehicleParams& p) -> double& { return p.nomoto_time_constant_s; }, 0.0, 3600.0,
     "a time constant in seconds"},
    {"max_rudder_deg", kDeg, [](VehicleParams& p) -> double& { return p.max_rudder; }, 0.0, deg_to_rad(90.0),
     "a rudder angle in degrees"},
    {"max_rudder_rate_deg_s", kDeg, [](VehicleParams& p) -> double& { return p.max_rudder_rate; }, 0.0,
     deg_to_rad(1000.0), "a rudder rate in deg/s"},
    {"rudder_time_constant_s", kSI, [](VehicleParams& p) -> double& { return p.rudder_time_constant_s; }, 0.0, 60.0,
     "a time constant in seconds"},
    {"max_turn_rate_deg_s", kDeg, [](VehicleParams& p) -> double& { return p.max_turn_rate; }, 0.0, deg_to_rad(180.0),
     "a turning rate in deg/s"},
    {"max_vertical_speed_mps", kSI, [](VehicleParams& p) -> double& { return p.max_vertical_speed_mps; }, 0.0, 20.0,
     "a vertical speed in m/s"},
    {"depth_time_constant_s", kSI, [](VehicleParams& p) -> double& { return p.depth_time_constant_s; }, 0.0, 3600.0,
     "a time constant in seconds"},
    {"max_depth_m", kSI, [](VehicleParams& p) -> double& { return p.max_depth_m; }, 0.0, 11000.0, "a depth in metres"},
    {"step_s", kSI, [](VehicleParams& p) -> double& { return p.step_s; }, 0.0, 1.0, "a time step in seconds"},
};
const Field kAutopilotFields[] = {
    {"natural_frequency_rad_s", kSI, [](VehicleParams& p) -> double& { return p.autopilot.natural_frequency_rad_s; },
     0.0, 10.0, "a natural frequency in rad/s"},
    {"damping_ratio", kSI, [](VehicleParams& p) -> double& { return p.autopilot.damping_ratio; }, 0.0, 10.0,
     "a damping ratio"},
    {"reference_natural_frequency_rad_s", kSI,
     [](VehicleParams& p) -> double& { return p.autopilot.reference_natural_frequency_rad_s; }, 0.0, 10.0,
     "a natural frequency in rad/s"},
    {"max_reference_turn_rate_deg_s", kDeg,
     [](VehicleParams& p) -> double& { return p.autopilot.max_reference_turn_rate; }, 0.0, deg_to_rad(180.0),
     "a turning rate in deg/s"},
};

constexpr double kMinStep_s = 1e-3;

std::string range_text(const Field& f) {
  return f.what + std::string(" > 0 and <= ") + general(from_si(f.scale, f.hi), 10);
}

// Where a key sits: "line N" from the file, or empty for a default value.
using KeyLines = std::map<std::string, std::string>;

std::string line_of(const YAML::Mark& mark) {
  return mark.line >= 0 ? "line " + std::to_string(mark.line + 1) : std::string();
}

// Checks every field against its range and the pairs against each other. `key_of`
// gives the key the user wrote for a field (so the message quotes it).
void check(VehicleParams p, const std::string& source, const KeyLines& lines,
           const std::function<const Field*(const char*)>& key_of) {
  auto where = [&](const std::string& key) {
    const auto it = lines.find(key);
    return InputLocation{source, it == lines.end() ? std::string() : it->second, key};
  };
  auto check_fields = [&](const auto& fields, const std::string& prefix) {
    for (const Field& f : fields) {
      const Field* used = key_of(f.key);
      if (used != &f) continue;  // another key fills this field (or this is the alternative)
      const double v = f.ref(p);
      if (!std::isfinite(v) || v <= f.lo || v > f.hi) {
        throw input_error(where(prefix + f.key), range_text(f), general(from_si(f.scale, v), 10));
      }
    }
  };
  check_fields(kFields, "");
  check_fields(kAutopilotFields, "autopilot.");

  const Field* cruise = key_of("cruise_speed_mps");
  const Field* max = key_of("max_speed_mps");
  if (p.cruise_speed_mps > p.max_speed_mps) {
    throw input_error(
        where(cruise->key),
        std::string("cruise speed <= ") + max->key + " (" + general(from_si(max->scale, p.max_speed_mps), 10) + ")",
        general(from_si(cruise->scale, p.cruise_speed_mps), 10));
  }
  const Field* min = key_of("min_speed_mps");
  if (p.min_speed_mps > p.cruise_speed_mps) {
    throw input_error(where(min->key),
                      std::string("a minimum speed <= ") + cruise->key + " (" +
                          general(from_si(cruise->scale, p.cruise_speed_mps), 10) + ")",
                      general(from_si(min->scale, p.min_speed_mps), 10));
  }
  // RK4 on a first-order lag is accurate to about (h/T)^4 / 120; half the smallest
  // time constant keeps that under 1e-3 and far inside the stability bound 2.78 T.
  const double smallest =
      std::min({p.nomoto_time_constant_s, p.rudder_time_constant_s, p.speed_time_constant_s, p.depth_time_constant_s});
  // Below a millisecond a step buys no accuracy (the time constants are
  // seconds) and only multiplies the work: 1e-9 s made one run take minutes
  // per simulated second and gigabytes of samples.
  if (p.step_s < kMinStep_s) {
    throw input_error(where("step_s"), "a step >= " + general(kMinStep_s, 10) + " s", general(p.step_s, 10));
  }
  if (p.step_s > 0.5 * smallest) {
    throw input_error(where("step_s"),
                      "a step <= half the smallest time constant (" + general(0.5 * smallest, 10) + " s)",
                      general(p.step_s, 10));
  }
  const double capability = std::min(p.max_turn_rate, p.nomoto_gain_per_s * p.max_rudder);
  if (p.autopilot.max_reference_turn_rate > capability) {
    throw input_error(where("autopilot.max_reference_turn_rate_deg_s"),
                      "a reference turning rate <= what the vehicle can turn, min(max_turn_rate_deg_s, K x "
                      "max_rudder_deg) = " +
                          general(rad_to_deg(capability), 10) + " deg/s",
                      general(rad_to_deg(p.autopilot.max_reference_turn_rate), 10));
  }
}

const Field* field_named(const char* key) {
  for (const Field& f : kFields)
    if (std::string(f.key) == key) return &f;
  for (const Field& f : kAutopilotFields)
    if (std::string(f.key) == key) return &f;
  return nullptr;
}

// The keys of a table of fields, for the known-key reader (core/yaml_mapping.hpp).
template <std::size_t N>
std::vector<std::string> keys_of(const Field (&fields)[N], std::initializer_list<const char*> extra) {
  std::vector<std::string> keys;
  for (const Field& f : fields) keys.emplace_back(f.key);
  keys.insert(keys.end(), extra.begin(), extra.end());
  return keys;
}

// Reads a mapping's numeric keys into `p` (SI), noting each key's line and
// which key filled a field (two keys, knots and m/s, may fill one; not both).
template <std::size_t N>
void read_fields(const Mapping& m, const Field (&fields)[N], VehicleParams& p, KeyLines& lines,
                 std::map<double*, const Field*>& filled_by) {
  for (const Field& f : fields) {
    if (!m.has(f.key)) continue;
    lines[m.full(f.key)] = m.where(f.key).feature;
    double& slot = f.ref(p);
    if (const auto other = filled_by.find(&slot); other != filled_by.end()) {
      throw input_error(m.where(f.key), "one unit only, not both", "also " + m.full(other->second->key));
    }
    filled_by[&slot] = &f;
    slot = to_si(f.scale, m.finite_number(f.key, f.what));
  }
}

}  // namespace

void validate(const VehicleParams& params, const std::string& source) {
  check(params, source, {}, [](const char* key) { return field_named(key); });
}

VehicleParams parse_vehicle_yaml(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = load_one_document(text, source);
  } catch (const YAML::Exception& e) {
    throw input_error({source, line_of(e.mark), ""}, "a YAML vehicle file", printable(e.msg, 100));
  }

  const char* expected = "a YAML mapping of vehicle keys (see data/vehicles/deepc.yaml)";
  if (root.IsNull()) throw input_error({source, line_of(root.Mark()), ""}, expected, "an empty document");
  const Mapping top(root, source, "", keys_of(kFields, {"name", "autopilot"}), expected);
  VehicleParams p;
  KeyLines lines;
  std::map<double*, const Field*> filled_by;
  read_fields(top, kFields, p, lines, filled_by);
  if (top.has("name")) p.name = top.text("name", "a vehicle name (text)");
  if (top.has("autopilot")) {
    const Mapping autopilot(top.value("autopilot"), source, "autopilot.", keys_of(kAutopilotFields, {}),
                            "a mapping of autopilot keys");
    read_fields(autopilot, kAutopilotFields, p, lines, filled_by);
  }
  // Messages name the key as written (knots or m/s) and its line.
  check(p, source, lines, [&](const char* key) -> const Field* {
    const Field* canonical = field_named(key);
    const auto it = filled_by.find(&canonical->ref(p));
    return it == filled_by.end() ? canonical : it->second;
  });
  return p;
}

VehicleParams read_vehicle_file(const std::string& path) {
  std::error_code ec;
  refuse_special_file(path);
  if (!std::filesystem::is_regular_file(path, ec)) throw input_error({path, "", ""}, "an existing vehicle file");
  // A vehicle file is a page of text; refuse anything that cannot be one.
  constexpr std::uintmax_t kMaxBytes = 1 << 20;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxBytes)
    throw input_error({path, "", ""}, "a vehicle file under 1 MiB", std::to_string(size) + " bytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw input_error({path, "", ""}, "a readable vehicle file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_vehicle_yaml(text.str(), path);
}

std::string vehicle_yaml(const VehicleParams& params) {
  YAML::Emitter out;
  VehicleParams p = params;
  out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name;
  // Shortest text that reads back to the same double (5.8, not 5.7999999999999998).
  auto emit = [&](const Field& f) {
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, from_si(f.scale, f.ref(p))).ptr;
    out << YAML::Key << f.key << YAML::Value << std::string(buf, end);
  };
  for (const Field& f : kFields) {
    if (std::string(f.key).ends_with("_kn")) continue;  // speeds go out in m/s
    emit(f);
  }
  out << YAML::Key << "autopilot" << YAML::Value << YAML::BeginMap;
  for (const Field& f : kAutopilotFields) emit(f);
  out << YAML::EndMap << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

double turn_radius(const VehicleParams& vehicle, double speed_mps) {
  return speed_mps / vehicle.autopilot.max_reference_turn_rate;
}

double route_turn_radius(const VehicleParams& vehicle, double speed_mps, double current_mps) {
  constexpr double kHeadroom = 1.15;
  return kHeadroom * turn_radius(vehicle, speed_mps + std::max(current_mps, 0.0));
}

}  // namespace deepguide
