#include "deepguide/simulation/scenario.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include "deepguide/core/error.hpp"
#include "deepguide/core/input_files.hpp"
#include "deepguide/core/yaml_mapping.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/currents/current_sampling.hpp"
#include "deepguide/currents/current_summary.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/identification/offset_path.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/world/frame_scale.hpp"

namespace deepguide {
namespace {

namespace fs = std::filesystem;

constexpr Range kCoordinate{-1e8, 1e8, true, "a coordinate in metres"};
constexpr Range kLon{-180.0, 180.0, true, "a longitude in degrees"};
constexpr Range kLat{-90.0, 90.0, true, "a latitude in degrees"};
constexpr Range kAngle{-360.0, 360.0, true, "an angle in degrees"};
constexpr Range kAxis{0.0, 1e6, false, "a semi-axis in metres"};
constexpr Range kSigma{0.0, 1e4, true, "a standard deviation"};
constexpr Range kDuration{0.0, kMaxSimulationTime_s, false, "a time in seconds"};

bool node_uses_lonlat(const YAML::Node& node) {
  return node.IsMap() && (node["lon"].IsDefined() || node["lat"].IsDefined());
}

// True for {lon, lat}, false for {x, y}; both kinds at once is an error.
bool is_lonlat(const Mapping& m) {
  const bool lonlat = m.has("lon") || m.has("lat");
  if (lonlat && (m.has("x") || m.has("y"))) {
    throw input_error(m.where(m.has("x") ? "x" : "y"), "either x, y or lon, lat", "both");
  }
  return lonlat;
}

// {x, y} or {lon, lat}; lon/lat need the frame.
// With a frame, the frame keeps metres metres there (frame_scale.hpp).
Vec2 read_position(const Mapping& m, const std::optional<LocalFrame>& frame) {
  if (!is_lonlat(m)) {
    const Vec2 xy(m.number("x", kCoordinate), m.number("y", kCoordinate));
    if (frame) require_true_scale(*frame, std::vector<Vec2>{frame->to_lonlat(xy)}, m.where("x").describe());
    return xy;
  }
  if (!frame) throw input_error(m.where("lon"), "x, y (lon, lat need a geographic frame)");
  const double lon = m.number("lon", kLon), lat = m.number("lat", kLat);
  const Vec2 xy = frame->from_lonlat(lon, lat);
  if (!xy.allFinite()) throw input_error(m.where("lon"), "a position inside the frame " + frame->id());
  require_true_scale(*frame, std::vector<Vec2>{Vec2(lon, lat)}, m.where("lon").describe());
  return xy;
}

Vec2 read_point(const Mapping& root, const char* key, const std::optional<LocalFrame>& frame) {
  if (!root.has(key)) {
    throw input_error(root.where(key), "a position {x: M, y: M} or {lon: DEG, lat: DEG}", "nothing");
  }
  const Mapping m(root.value(key), root.source(), root.full(key) + ".", {"x", "y", "lon", "lat"},
                  "a position {x: M, y: M} or {lon: DEG, lat: DEG}");
  return read_position(m, frame);
}

// Nautical degrees at a point -> math rad: from true north when the frame has a CRS.
double to_math(double heading_deg, const Vec2& at, const std::optional<LocalFrame>& frame) {
  return frame ? wrap_pi(frame->heading_to_local(heading_deg, at)) : heading_deg_to_math_rad(heading_deg);
}

void read_obstacles(const Mapping& root, const std::optional<LocalFrame>& frame, Scenario& sc) {
  const YAML::Node list = root.value("obstacles");
  if (!list.IsSequence()) {
    throw input_error(root.where("obstacles"), "a list of obstacles {x, y, semi_major_m, ...}",
                      list.IsNull() ? "nothing" : "a scalar or mapping");
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string prefix = "obstacles[" + std::to_string(i) + "].";
    const Mapping m(list[i], sc.source, prefix,
                    {"id", "x", "y", "lon", "lat", "semi_major_m", "semi_minor_m", "orientation_deg"},
                    "an obstacle mapping {x, y, semi_major_m, semi_minor_m, orientation_deg}");
    EllipticCylinder c;
    c.id = m.has("id") ? m.text("id", "an obstacle id (text)") : "obstacle " + std::to_string(i + 1);
    c.footprint.centre = read_position(m, frame);
    c.footprint.a = m.number("semi_major_m", kAxis);
    c.footprint.b = m.number_or("semi_minor_m", kAxis, c.footprint.a);
    if (c.footprint.b > c.footprint.a) {
      throw input_error(m.where("semi_minor_m"), "semi_minor_m <= semi_major_m (" + yaml_number(c.footprint.a) + ")",
                        yaml_number(c.footprint.b));
    }
    if (frame) {  // true metres into frame metres, as obstacle files are (frame_scale.hpp)
      const double scale = std::max(1.0, frame->scale_at(frame->to_lonlat(c.footprint.centre)).greatest);
      if (std::isfinite(scale)) c.footprint.a *= scale, c.footprint.b *= scale;
    }
    c.footprint.theta = to_math(m.number_or("orientation_deg", kAngle, 0.0), c.footprint.centre, frame);
    sc.obstacles.push_back(std::move(c));
  }
}

void read_sonar(const Mapping& root, Scenario& sc) {
  if (!root.has("sonar")) return;
  const Mapping m(root.value("sonar"), sc.source, "sonar.",
                  {"range_m", "field_of_view_deg", "update_rate_hz", "position_sigma_m", "position_sigma_per_m",
                   "size_sigma_m", "size_sigma_per_m"},
                  "a mapping of sonar keys");
  SonarParams& s = sc.sonar;
  s.range_m = m.number_or("range_m", {0.0, 1e5, true, "a range in metres (0 = no sonar)"}, s.range_m);
  s.field_of_view = deg_to_rad(
      m.number_or("field_of_view_deg", {0.0, 360.0, false, "a field of view in degrees"}, rad_to_deg(s.field_of_view)));
  s.update_rate_hz = m.number_or("update_rate_hz", {0.0, 1e3, false, "a rate in Hz"}, s.update_rate_hz);
  s.position_sigma_m = m.number_or("position_sigma_m", kSigma, s.position_sigma_m);
  s.position_sigma_per_m = m.number_or("position_sigma_per_m", kSigma, s.position_sigma_per_m);
  s.size_sigma_m = m.number_or("size_sigma_m", kSigma, s.size_sigma_m);
  s.size_sigma_per_m = m.number_or("size_sigma_per_m", kSigma, s.size_sigma_per_m);
}

void read_reactive(const Mapping& root, Scenario& sc) {
  sc.reactive.speed_mps = sc.vehicle.cruise_speed_mps;
  if (!root.has("reactive")) return;
  // The keys every method shares, then each registered method's own.
  const std::vector<ReactiveTuning> tunings = reactive_tunings();
  std::vector<std::string> known{"margin_m", "arrival_radius_m", "influence_m", "speed_mps", "exit_blend_fraction"};
  for (const ReactiveTuning& t : tunings) known.push_back(t.key);
  const Mapping m(root.value("reactive"), sc.source, "reactive.", known, "a mapping of reactive keys");
  ReactiveParams& r = sc.reactive;
  r.margin_m = m.number_or("margin_m", {0.0, 1e4, true, "a margin in metres"}, r.margin_m);
  r.arrival_radius_m = m.number_or("arrival_radius_m", {0.0, 1e4, false, "a radius in metres"}, r.arrival_radius_m);
  r.influence_m = m.number_or("influence_m", {0.0, 1e5, false, "a distance in metres"}, r.influence_m);
  r.speed_mps = m.number_or(
      "speed_mps", {0.0, sc.vehicle.max_speed_mps, false, "a speed in m/s up to the vehicle's max_speed"}, r.speed_mps);
  r.exit_blend_fraction = m.number_or("exit_blend_fraction", {0.0, 1.0, false, "a fraction"}, r.exit_blend_fraction);
  for (const ReactiveTuning& t : tunings) {
    if (!m.has(t.key.c_str())) continue;
    const double v = m.finite_number(t.key.c_str(), t.what.c_str());
    if (!t.holds(v)) throw input_error(m.where(t.key.c_str()), t.expected(), yaml_number(v));
    r.tuning[t.key] = v;
  }
}

void read_run_rules(const Mapping& root, Scenario& sc) {
  if (root.has("contacts")) {
    const Mapping m(root.value("contacts"), sc.source, "contacts.", {"gate_m", "memory_s"},
                    "a mapping of contact keys (gate_m, memory_s)");
    sc.contacts.gate_m = m.number_or("gate_m", {0.0, 1e4, true, "a gate in metres"}, sc.contacts.gate_m);
    sc.contacts.memory_s = m.number_or("memory_s", kDuration, sc.contacts.memory_s);
  }
  if (root.has("energy")) {
    const Mapping m(root.value("energy"), sc.source, "energy.", {"hotel_power_w", "propulsion_k_w_per_mps3"},
                    "a mapping of energy keys (hotel_power_w, propulsion_k_w_per_mps3)");
    sc.energy.hotel_power_w = m.number_or("hotel_power_w", {0.0, 1e7, true, "a power in W"}, sc.energy.hotel_power_w);
    sc.energy.propulsion_k_w_per_mps3 = m.number_or(
        "propulsion_k_w_per_mps3", {0.0, 1e7, true, "a coefficient in W/(m/s)^3"}, sc.energy.propulsion_k_w_per_mps3);
  }
  if (root.has("max_time_s")) sc.max_time_s = root.number("max_time_s", kDuration);
  sc.stall_time_s = root.number_or("stall_time_s", kDuration, sc.stall_time_s);
  sc.no_progress_s = root.number_or("no_progress_s", kDuration, sc.no_progress_s);
  sc.reversal_dead_band = deg_to_rad(root.number_or(
      "reversal_dead_band_deg_s", {0.0, 180.0, true, "a turning rate in deg/s"}, rad_to_deg(sc.reversal_dead_band)));
  if (root.has("seed")) {
    const YAML::Node v = root.value("seed");
    const std::string text = v.IsScalar() ? v.Scalar() : std::string();
    std::uint64_t seed = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), seed);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) {
      throw input_error(root.where("seed"), "an unsigned integer seed (0 .. 18446744073709551615)",
                        v.IsScalar() ? "'" + printable(text) + "'" : "a list or mapping");
    }
    sc.sonar.seed = seed;
  }
}

// The identify section (scenario.hpp); after the obstacles and the reactive speed it defaults to.
void read_identify(const Mapping& root, Scenario& sc) {
  if (!root.has("identify")) return;
  const Mapping m(root.value("identify"), sc.source, "identify.",
                  {"object", "mode", "hold_time_s", "position_tolerance_m", "align", "around"},
                  "a mapping of identify keys (object, mode, hold_time_s, position_tolerance_m, align, around)");
  IdentifySpec spec;
  spec.object_id = m.text("object", "the id of the obstacle to identify");
  const auto it = std::find_if(sc.obstacles.begin(), sc.obstacles.end(),
                               [&](const EllipticCylinder& o) { return o.id == spec.object_id; });
  if (it == sc.obstacles.end()) {
    std::string ids;
    for (std::size_t i = 0; i < sc.obstacles.size() && i < 5; ++i)
      ids += (i ? ", " : "") + printable(sc.obstacles[i].id);
    if (sc.obstacles.size() > 5) ids += ", ...";
    throw input_error(m.where("object"),
                      sc.obstacles.empty() ? "the id of an obstacle, but the scenario has none"
                                           : "the id of one of the scenario's obstacles (" + ids + ")",
                      "'" + printable(spec.object_id) + "'");
  }
  spec.object = it->footprint;
  if (m.has("mode")) {
    const std::string name = m.text("mode", "align or around");
    const auto mode = parse_identify_mode(name);
    if (!mode) throw input_error(m.where("mode"), "align or around", "'" + printable(name) + "'");
    spec.mode = *mode;
  }
  spec.hold_time_s = m.number_or("hold_time_s", kDuration, spec.hold_time_s);
  spec.position_tolerance_m =
      m.number_or("position_tolerance_m", {0.0, 1e4, false, "a distance in metres"}, spec.position_tolerance_m);
  const Range distance{0.0, 1e4, false, "a distance in metres"};
  const Range speed{0.0, sc.vehicle.max_speed_mps, false, "a speed in m/s up to the vehicle's max_speed"};
  AlignParams& a = spec.align;
  a.speed_mps = sc.reactive.speed_mps;
  a.max_speed_mps = sc.vehicle.max_speed_mps;
  if (m.has("align")) {
    const Mapping al(m.value("align"), sc.source, "identify.align.",
                     {"standoff_m", "hold_buffer_m", "approach_m", "approach_radius_m", "position_gain_per_s",
                      "max_approach_mps", "lookahead_m", "still_mps", "speed_mps", "slack_fraction"},
                     "a mapping of aligning keys");
    a.standoff_m = al.number_or("standoff_m", distance, a.standoff_m);
    a.hold_buffer_m = al.number_or("hold_buffer_m", {0.0, 1e4, true, "a distance in metres"}, a.hold_buffer_m);
    a.approach_m = al.number_or("approach_m", distance, a.approach_m);
    a.approach_radius_m = al.number_or("approach_radius_m", distance, a.approach_radius_m);
    a.position_gain_per_s =
        al.number_or("position_gain_per_s", {0.0, 10.0, false, "a gain in 1/s"}, a.position_gain_per_s);
    a.max_approach_mps = al.number_or("max_approach_mps", speed, a.max_approach_mps);
    a.lookahead_m = al.number_or("lookahead_m", distance, a.lookahead_m);
    a.still_mps = al.number_or("still_mps", {0.0, 20.0, true, "a speed in m/s"}, a.still_mps);
    a.speed_mps = al.number_or("speed_mps", speed, a.speed_mps);
    a.slack_fraction = al.number_or("slack_fraction", {0.0, 0.99, true, "a fraction"}, a.slack_fraction);
  }
  AroundParams& r = spec.around;
  r.speed_mps = sc.reactive.speed_mps;
  if (m.has("around")) {
    const Mapping ar(m.value("around"), sc.source, "identify.around.",
                     {"distance_m", "side", "laps", "lookahead_m", "switch_m", "speed_mps"},
                     "a mapping of going-around keys");
    r.distance_m = ar.number_or("distance_m", distance, r.distance_m);
    if (ar.has("side")) {
      const std::string side = ar.text("side", "port or starboard (the side the object is on)");
      if (side != "port" && side != "starboard") {
        throw input_error(ar.where("side"), "port or starboard (the side the object is on)",
                          "'" + printable(side) + "'");
      }
      r.direction = side == "port" ? 1 : -1;  // object to port: anticlockwise
    }
    r.laps = ar.number_or("laps", {0.0, 1000.0, false, "a number of laps"}, r.laps);
    r.lookahead_m = ar.number_or("lookahead_m", distance, r.lookahead_m);
    r.switch_m = ar.number_or("switch_m", distance, r.switch_m);
    r.speed_mps = ar.number_or("speed_mps", speed, r.speed_mps);
  }
  sc.identify = std::move(spec);
}

// The box the vehicle works in: start and target, and round the object to identify.
std::pair<Vec2, Vec2> work_box(const Scenario& sc) {
  Vec2 lo = sc.start.cwiseMin(sc.target), hi = sc.start.cwiseMax(sc.target);
  if (sc.identify) {
    const IdentifySpec& id = *sc.identify;
    const double reach = id.object.a + std::max(id.align.standoff_m + id.align.hold_buffer_m + id.align.approach_m +
                                                    id.align.approach_radius_m,
                                                id.around.distance_m + 2.0 * id.around.switch_m);
    lo = lo.cwiseMin(id.object.centre - Vec2(reach, reach));
    hi = hi.cwiseMax(id.object.centre + Vec2(reach, reach));
  }
  return {lo, hi};
}

// The current: a constant (rotated to the frame at the start) or a field sampled as the vehicle goes.
void read_current(const Mapping& root, const std::string& base_dir, Scenario& sc) {
  if (root.has("current") && root.has("current_file")) {
    throw input_error(root.where("current_file"), "either current or current_file", "both");
  }
  if (root.has("current")) {
    const InputLocation at = root.where("current");
    const CurrentField f = parse_constant_current(root.text("current", "a current SPEED_MPS,DIR_DEG"), at.describe());
    if (f.constant_velocity.norm() > 20.0)
      throw input_error(at, "a current of at most 20 m/s", yaml_number(f.constant_velocity.norm()));
    if (!sc.frame) {
      sc.current = f.constant_velocity;  // true north is +y
    } else {
      const auto c = CurrentSampler(std::make_shared<CurrentField>(f), *sc.frame).sample(sc.start, 0.0);
      if (!c) throw input_error(at, "a start where the frame " + sc.frame->id() + " knows true north");
      sc.current = *c;
    }
    return;
  }
  if (!root.has("current_file")) return;
  if (!sc.frame) {
    throw input_error(
        root.where("current_file"),
        "a scenario with a geographic frame (crs, an obstacles_file or lon/lat positions) to place the field");
  }
  CurrentOptions options;
  options.depth_m = sc.depth_m;
  options.assumed_crs = sc.frame->id();
  auto field = std::make_shared<const CurrentField>(load_current_field(root.path("current_file", base_dir), options));
  sc.current_time_offset_s = field->times_s.empty() ? 0.0 : field->times_s.front();
  const auto [lo, hi] = work_box(sc);
  check_current_coverage(*field, *sc.frame, lo, hi, sc.current_time_offset_s, sc.current_time_offset_s);
  sc.current_field = std::make_shared<const CurrentSampler>(field, *sc.frame, lo, hi);
}

Scenario parse(const YAML::Node& doc, const std::string& source, const std::string& base_dir) {
  const Mapping root(doc, source, "",
                     {"name",           "vehicle",           "crs",           "start",
                      "target",         "start_heading_deg", "depth_m",       "obstacles",
                      "obstacles_file", "current",           "current_file",  "seed",
                      "sonar",          "reactive",          "contacts",      "energy",
                      "max_time_s",     "stall_time_s",      "no_progress_s", "reversal_dead_band_deg_s",
                      "identify"},
                     "a YAML mapping of scenario keys (see data/scenarios/one_obstacle.yaml)");
  Scenario sc;
  sc.source = source;
  sc.name = root.has("name") ? root.text("name", "a scenario name (text)") : fs::path(source).stem().string();
  if (root.has("vehicle")) sc.vehicle = read_vehicle_file(root.path("vehicle", base_dir));

  // The frame: crs, else the obstacle file's, else the start's UTM zone when lon/lat are used.
  if (root.has("crs")) {
    sc.frame = LocalFrame::from_user_crs(root.text("crs", "a projected CRS in metres such as EPSG:32632"),
                                         root.where("crs").describe());
  }
  ObstacleSet from_file;
  if (root.has("obstacles_file")) {
    LoadedObstacles loaded =
        load_obstacles({root.path("obstacles_file", base_dir)}, {sc.frame ? sc.frame->id() : std::string(), ""});
    if (!loaded.obstacles.polygons.empty()) {
      throw input_error(root.where("obstacles_file"),
                        "elliptic-cylinder (Point) obstacles only: the sonar reports no polygons",
                        std::to_string(loaded.obstacles.polygons.size()) + " polygon(s)");
    }
    sc.frame = loaded.frame;
    from_file = std::move(loaded.obstacles);
  }
  bool lonlat = node_uses_lonlat(root.value("start")) || node_uses_lonlat(root.value("target"));
  if (root.has("obstacles") && root.value("obstacles").IsSequence())
    for (const auto& o : root.value("obstacles")) lonlat = lonlat || node_uses_lonlat(o);
  if (!sc.frame && lonlat) {
    if (!node_uses_lonlat(root.value("start"))) {
      throw input_error(root.where("start"), "lon, lat like the other positions (or a crs to read x, y in)");
    }
    const Mapping m(root.value("start"), source, "start.", {"x", "y", "lon", "lat"}, "a position");
    is_lonlat(m);
    const double lon = m.number("lon", kLon), lat = m.number("lat", kLat);
    sc.frame = default_frame_for({lon, lon, lat, lat});
  }

  sc.start = read_point(root, "start", sc.frame);
  if (root.has("target") || !root.has("identify")) sc.target = read_point(root, "target", sc.frame);
  if (root.has("start_heading_deg"))
    sc.start_heading = to_math(root.number("start_heading_deg", kAngle), sc.start, sc.frame);
  sc.depth_m = root.number_or(
      "depth_m", {0.0, sc.vehicle.max_depth_m, true, "a depth in metres up to the vehicle's max_depth_m"}, 0.0);
  if (root.has("obstacles")) read_obstacles(root, sc.frame, sc);
  for (EllipticCylinder& c : from_file.ellipses) sc.obstacles.push_back(std::move(c));
  read_sonar(root, sc);
  read_reactive(root, sc);
  read_run_rules(root, sc);
  read_identify(root, sc);
  if (sc.identify && !root.has("target")) sc.target = sc.identify->object.centre;
  read_current(root, base_dir, sc);
  validate(sc);
  return sc;
}

}  // namespace

std::string_view to_string(IdentifyMode mode) { return mode == IdentifyMode::align ? "align" : "around"; }

std::optional<IdentifyMode> parse_identify_mode(std::string_view name) {
  if (name == "align") return IdentifyMode::align;
  if (name == "around") return IdentifyMode::around;
  return std::nullopt;
}

double default_max_time_s(const Scenario& sc) {
  const double straight = (sc.target - sc.start).norm() / sc.reactive.speed_mps;
  return std::min(3.0 * straight + 300.0, kMaxSimulationTime_s);
}

namespace {

// The identify section's rules (scenario.hpp).
template <class Fail, class Within>
void validate_identify(const Scenario& sc, const Fail& fail, const Within& within) {
  const IdentifySpec& id = *sc.identify;
  const Ellipse& e = id.object;
  const std::string object = "object '" + printable(id.object_id) + "'";
  if (!e.centre.allFinite() || !std::isfinite(e.theta) || !(e.b > 0.0 && e.b <= e.a && e.a <= 1e6))
    fail("identify.object", "a finite ellipse with 0 < semi-minor <= semi-major <= 1e6 m", object);
  // The object is one of the obstacles (it counts for the clearance), named by one id only.
  const auto named = std::count_if(sc.obstacles.begin(), sc.obstacles.end(),
                                   [&](const EllipticCylinder& o) { return o.id == id.object_id; });
  if (named != 1) {
    fail("identify.object", "the id of exactly one of the scenario's obstacles",
         "'" + printable(id.object_id) + "' naming " + std::to_string(named));
  }
  const auto it = std::find_if(sc.obstacles.begin(), sc.obstacles.end(),
                               [&](const EllipticCylinder& o) { return o.id == id.object_id; });
  const Ellipse& f = it->footprint;
  if (f.centre != e.centre || f.a != e.a || f.b != e.b || f.theta != e.theta)
    fail("identify.object", "the obstacle's own footprint", "a different ellipse");
  within([&] { validate(id.align); });
  within([&] { validate(id.around); });
  // At most half the longest run: the approach needs time too.
  if (!(id.hold_time_s > 0.0 && id.hold_time_s <= 0.5 * kMaxSimulationTime_s))
    fail("identify.hold_time_s", "a time > 0 and <= " + yaml_number(0.5 * kMaxSimulationTime_s) + " s",
         yaml_number(id.hold_time_s));
  if (id.mode == IdentifyMode::align && !std::isnan(sc.max_time_s) && !(sc.max_time_s > id.hold_time_s)) {
    fail("max_time_s", "a time longer than identify.hold_time_s (" + yaml_number(id.hold_time_s) + " s)",
         yaml_number(sc.max_time_s));
  }
  if (!(id.position_tolerance_m > 0.0) || !std::isfinite(id.position_tolerance_m))
    fail("identify.position_tolerance_m", "a distance > 0 m", yaml_number(id.position_tolerance_m));
  const double vmax = sc.vehicle.max_speed_mps;
  const auto speed_ok = [&](const char* field, double v) {
    if (!(v <= vmax)) fail(field, "a speed <= the vehicle's max speed " + yaml_number(vmax) + " m/s", yaml_number(v));
  };
  speed_ok("identify.align.speed_mps", id.align.speed_mps);
  speed_ok("identify.align.max_speed_mps", id.align.max_speed_mps);
  speed_ok("identify.around.speed_mps", id.around.speed_mps);
  if (security_ellipse(e, id.align.standoff_m).contains(sc.start) && id.mode == IdentifyMode::align) {
    fail("start",
         "a start outside the " + object + "'s safety ellipse (standoff " + yaml_number(id.align.standoff_m) + " m)",
         "inside it");
  }
  if (e.contains(sc.start)) fail("start", "a start outside the " + object, "inside it");
  if (id.mode == IdentifyMode::around) {
    // Over ground, downstream, the vehicle turns on a circle wider by the
    // current's speed (a field's fastest anywhere); the autopilot asks for at
    // most its reference rate.
    double current = sc.current.norm();
    if (sc.current_field) {
      const double fastest = summarize_current(sc.current_field->field()).max_speed_mps;
      current = std::isfinite(fastest) ? fastest : 0.0;
    }
    const double radius = (id.around.speed_mps + current) / sc.vehicle.autopilot.max_reference_turn_rate;
    try {
      check_offset_path_fits(e, id.around.distance_m, radius, printable(id.object_id));
    } catch (const InputError& error) {
      throw InputError(sc.source + ": field 'identify.around.distance_m': " + error.what());
    }
  }
}

}  // namespace

void validate(const Scenario& sc) {
  validate(sc.vehicle, sc.source);
  auto fail = [&](const std::string& field, const std::string& expected, const std::string& got) {
    throw input_error({sc.source, "", field}, expected, got);
  };
  // The sonar's and the methods' own checks name "sonar" and "reactive": prefix the scenario.
  auto within = [&](const auto& check) {
    try {
      check();
    } catch (const InputError& e) {
      throw InputError(sc.source + ": " + e.what());
    }
  };
  // Range 0 (no sonar) is the scenario's addition to the sonar's ranges.
  if (!(sc.sonar.range_m >= 0.0)) fail("sonar.range_m", "a range >= 0 m (0 = no sonar)", yaml_number(sc.sonar.range_m));
  SonarParams sonar = sc.sonar;
  if (sonar.range_m == 0.0) sonar.range_m = 1.0;
  within([&] { validate(sonar); });
  within([&] { validate(sc.reactive); });
  const ReactiveParams& r = sc.reactive;
  if (!(r.arrival_radius_m > 0.0)) fail("reactive.arrival_radius_m", "a radius > 0 m", yaml_number(r.arrival_radius_m));
  if (!(r.speed_mps <= sc.vehicle.max_speed_mps))
    fail("reactive.speed_mps", "a speed <= the vehicle's max speed " + yaml_number(sc.vehicle.max_speed_mps) + " m/s",
         yaml_number(r.speed_mps));
  if (!sc.start.allFinite()) fail("start", "a finite position", "NaN or infinity");
  if (!sc.target.allFinite()) fail("target", "a finite position", "NaN or infinity");
  if (sc.start_heading && !std::isfinite(*sc.start_heading)) fail("start_heading_deg", "a finite heading", "NaN");
  if (!(sc.depth_m >= 0.0 && sc.depth_m <= sc.vehicle.max_depth_m))
    fail("depth_m", "a depth >= 0 and <= the vehicle's max depth", yaml_number(sc.depth_m));
  if (!sc.current.allFinite() || sc.current.norm() > 20.0)
    fail("current", "a finite current of at most 20 m/s", yaml_number(sc.current.norm()));
  for (const EllipticCylinder& o : sc.obstacles) {
    const Ellipse& e = o.footprint;
    if (!e.centre.allFinite() || !std::isfinite(e.theta) || !(e.b > 0.0 && e.b <= e.a && e.a <= 1e6)) {
      fail("obstacle '" + printable(o.id) + "'", "a finite ellipse with 0 < semi-minor <= semi-major <= 1e6 m",
           "a = " + yaml_number(e.a) + ", b = " + yaml_number(e.b));
    }
  }
  for (const EllipticCylinder& o : sc.obstacles) {
    if (o.footprint.contains(sc.start))
      fail("start", "a start outside every obstacle", "inside obstacle '" + printable(o.id) + "'");
    if (!sc.identify && o.footprint.contains(sc.target))
      fail("target", "a target outside every obstacle (reaching it would be a collision)",
           "inside obstacle '" + printable(o.id) + "'");
  }
  if (!(sc.contacts.gate_m >= 0.0) || !std::isfinite(sc.contacts.gate_m))
    fail("contacts.gate_m", "a gate >= 0 m", yaml_number(sc.contacts.gate_m));
  if (!(sc.contacts.memory_s > 0.0)) fail("contacts.memory_s", "a time > 0 s", yaml_number(sc.contacts.memory_s));
  if (!(sc.energy.hotel_power_w >= 0.0) || !std::isfinite(sc.energy.hotel_power_w) ||
      !(sc.energy.propulsion_k_w_per_mps3 >= 0.0) || !std::isfinite(sc.energy.propulsion_k_w_per_mps3))
    fail("energy", "finite hotel_power_w and propulsion_k_w_per_mps3 >= 0", "a negative or non-finite value");
  if (!std::isnan(sc.max_time_s) && !(sc.max_time_s > 0.0 && sc.max_time_s <= kMaxSimulationTime_s))
    fail("max_time_s", "a time > 0 and <= " + yaml_number(kMaxSimulationTime_s) + " s", yaml_number(sc.max_time_s));
  if (!(sc.stall_time_s > 0.0) || !std::isfinite(sc.stall_time_s))
    fail("stall_time_s", "a time > 0 s", yaml_number(sc.stall_time_s));
  if (!(sc.no_progress_s > 0.0) || !std::isfinite(sc.no_progress_s))
    fail("no_progress_s", "a time > 0 s", yaml_number(sc.no_progress_s));
  if (!(sc.reversal_dead_band >= 0.0) || !std::isfinite(sc.reversal_dead_band))
    fail("reversal_dead_band_deg_s", "a turning rate >= 0", yaml_number(rad_to_deg(sc.reversal_dead_band)));
  if (sc.identify) validate_identify(sc, fail, within);
}

Scenario parse_scenario_yaml(const std::string& text, const std::string& source, const std::string& base_dir) {
  YAML::Node doc;
  try {
    doc = load_one_document(text, source);
  } catch (const YAML::Exception& e) {
    throw input_error({source, e.mark.line >= 0 ? "line " + std::to_string(e.mark.line + 1) : std::string(), ""},
                      "a YAML scenario file", printable(e.msg, 100));
  }
  if (doc.IsNull()) throw input_error({source, "", ""}, "a YAML mapping of scenario keys", "an empty document");
  return parse(doc, source, base_dir);
}

Scenario read_scenario_file(const std::string& path) {
  std::error_code ec;
  refuse_special_file(path);
  if (!fs::is_regular_file(path, ec)) throw input_error({path, "", ""}, "an existing scenario file");
  const auto size = fs::file_size(path, ec);
  if (ec || size > kMaxScenarioFileBytes) {
    throw input_error({path, "", ""}, "a scenario file under 4 MiB (large obstacle sets go in an obstacles_file)",
                      std::to_string(size) + " bytes");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw input_error({path, "", ""}, "a readable scenario file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scenario_yaml(text.str(), path, fs::path(path).parent_path().string());
}

}  // namespace deepguide
