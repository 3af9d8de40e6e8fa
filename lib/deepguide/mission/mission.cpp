#include "deepguide/mission/mission.hpp"

#include <boost/geometry.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "deepguide/core/error.hpp"
#include "deepguide/core/input_files.hpp"
#include "deepguide/core/yaml_mapping.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/world/frame_scale.hpp"

namespace deepguide {
namespace {

namespace fs = std::filesystem;
namespace bg = boost::geometry;

constexpr Range kCoordinate{-1e8, 1e8, true, "a coordinate in metres"};
constexpr Range kLon{-180.0, 180.0, true, "a longitude in degrees"};
constexpr Range kLat{-90.0, 90.0, true, "a latitude in degrees"};
constexpr Range kDepth{0.0, 11000.0, true, "a depth in metres (positive down)"};
constexpr Range kDistance{0.0, 1e6, false, "a distance in metres"};
constexpr Range kHeading{-360.0, 360.0, true, "a heading in degrees"};
constexpr Range kHold{0.0, 86400.0, true, "a time in seconds"};

const char* const kTypes = "track, survey, gps_update, identify or goto";

// What the reader knows while it reads: the frame, once known.
struct Reader {
  std::string source, base_dir;
  std::optional<LocalFrame> frame;

  // {lon, lat} or {x, y} from a mapping that may hold other keys too.
  Vec2 position_of(const Mapping& m) const {
    const bool lonlat = m.has("lon") || m.has("lat");
    if (lonlat && (m.has("x") || m.has("y"))) throw input_error(m.where("x"), "either x, y or lon, lat", "both");
    if (!lonlat) {
      const Vec2 xy(m.number("x", kCoordinate), m.number("y", kCoordinate));
      require_true_scale(*frame, std::vector<Vec2>{frame->to_lonlat(xy)}, m.where("x").describe());
      return xy;
    }
    const Vec2 ll(m.number("lon", kLon), m.number("lat", kLat));
    const Vec2 xy = frame->from_lonlat(ll);
    if (!xy.allFinite()) throw input_error(m.where("lon"), "a position inside the frame " + frame->id());
    require_true_scale(*frame, std::vector<Vec2>{ll}, m.where("lon").describe());
    return xy;
  }
  Vec2 position(const YAML::Node& node, const std::string& key) const {
    return position_of(
        Mapping(node, source, key + ".", {"x", "y", "lon", "lat"}, "a position {lon: DEG, lat: DEG} or {x: M, y: M}"));
  }

  std::vector<Vec2> positions(const Mapping& m, const char* key, std::size_t at_least) const {
    const YAML::Node list = m.value(key);
    if (!list.IsSequence() || list.size() < at_least) {
      throw input_error(m.where(key), "a list of at least " + std::to_string(at_least) + " positions",
                        list.IsSequence() ? std::to_string(list.size()) + " position(s)"
                        : list.IsMap()    ? "a mapping"
                        : list.IsScalar() ? "'" + printable(list.Scalar()) + "'"
                                          : "nothing");
    }
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < list.size(); ++i)
      out.push_back(position(list[i], m.full(key) + "[" + std::to_string(i) + "]"));
    return out;
  }

  // Speed: speed_kn or speed_mps, within the vehicle's; default its cruise speed.
  double speed(const Mapping& m, const VehicleParams& vehicle) const {
    if (m.has("speed_kn") && m.has("speed_mps"))
      throw input_error(m.where("speed_mps"), "speed_kn or speed_mps", "both");
    const double max_kn = vehicle.max_speed_mps / kMetresPerSecondPerKnot;
    if (m.has("speed_kn")) {
      return kMetresPerSecondPerKnot *
             m.number("speed_kn", {0.0, max_kn, false, "a speed in knots up to the vehicle's max_speed"});
    }
    return m.number_or("speed_mps", {0.0, vehicle.max_speed_mps, false, "a speed in m/s up to the vehicle's max_speed"},
                       vehicle.cruise_speed_mps);
  }
};

ComplexManoeuvre read_manoeuvre(const Reader& r, const YAML::Node& item, std::size_t index, double depth_before,
                                const VehicleParams& vehicle) {
  const std::string where = "manoeuvres[" + std::to_string(index) + "]";
  if (!item.IsMap() || item.size() != 1) {
    throw input_error({r.source, line_of(item), where},
                      "a mapping with one key, the manoeuvre's type (" + std::string(kTypes) + ")");
  }
  const auto kv = *item.begin();
  ComplexManoeuvre c;
  c.type = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
  c.line = line_of(kv.first);
  const std::string prefix = where + "." + c.type + ".";
  const auto common = [&](std::initializer_list<const char*> own) {
    std::vector<const char*> keys{"name", "depth_m", "speed_kn", "speed_mps"};
    keys.insert(keys.end(), own.begin(), own.end());
    return keys;
  };
  std::vector<const char*> keys;
  if (c.type == "track")
    keys = common({"waypoints", "route_file"});
  else if (c.type == "survey")
    keys = common({"area", "line_spacing_m", "heading_deg", "turn_radius_m"});
  else if (c.type == "gps_update")
    keys = common({"hold_s"});
  else if (c.type == "identify")
    keys = common({"object", "mode", "distance_m"});
  else if (c.type == "goto")
    keys = common({"position"});
  else
    throw input_error({r.source, c.line, where}, "a manoeuvre type (" + std::string(kTypes) + ")",
                      "'" + printable(c.type) + "'");

  // Mapping takes an initializer list; the key sets differ per type, so check them here.
  // A manoeuvre with nothing under it (`- gps_update:`) takes every default.
  const YAML::Node body = kv.second.IsNull() ? YAML::Node(YAML::NodeType::Map) : kv.second;
  if (!body.IsMap())
    throw input_error({r.source, line_of(body), where + "." + c.type}, "a mapping of " + c.type + " keys");
  for (const auto& field : body) {
    const std::string key = field.first.IsScalar() ? field.first.Scalar() : "?";
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      std::string list;
      for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
      throw input_error({r.source, line_of(field.first), printable(prefix + key)},
                        "one of the " + c.type + " keys (" + list + ")", "an unknown key");
    }
  }
  const Mapping m(body, r.source, prefix,
                  {"name", "depth_m", "speed_kn", "speed_mps", "waypoints", "route_file", "area", "line_spacing_m",
                   "heading_deg", "turn_radius_m", "hold_s", "object", "mode", "distance_m", "position"},
                  "a mapping of " + c.type + " keys");
  c.name = m.has("name") ? m.text("name", "a name (text)") : c.type + " " + std::to_string(index + 1);
  c.depth_m = m.number_or("depth_m", kDepth, depth_before);
  if (c.depth_m > vehicle.max_depth_m) {
    throw input_error(m.where("depth_m"),
                      "a depth within the vehicle's max_depth_m (" + yaml_number(vehicle.max_depth_m) + ")",
                      yaml_number(c.depth_m));
  }
  c.speed_mps = r.speed(m, vehicle);
  if (c.type == "track") {
    if (m.has("waypoints") == m.has("route_file")) {
      throw input_error(m.where("waypoints"), "waypoints or a route_file (one of them)",
                        m.has("waypoints") ? "both" : "neither");
    }
    if (m.has("route_file")) {
      // A route from an ECDIS (RTZ), OpenCPN (GPX) or any route file: its waypoints in order.
      TrackSpec t;
      const std::string file = m.path("route_file", r.base_dir);
      std::vector<RouteFileWaypoint> route;
      try {
        route = read_route_waypoints(file);
      } catch (const InputError& e) {
        throw input_error(m.where("route_file"), "a route file with its waypoints (RTZ, GPX, GeoJSON, KML)", e.what());
      }
      for (const RouteFileWaypoint& w : route) {
        const Vec2 xy = r.frame->from_lonlat(w.lonlat);
        if (!xy.allFinite()) throw input_error(m.where("route_file"), "waypoints inside the frame " + r.frame->id());
        t.waypoints.push_back(xy);
      }
      c.spec = std::move(t);
    } else {
      c.spec = TrackSpec{r.positions(m, "waypoints", 1)};
    }
  } else if (c.type == "goto") {
    if (!m.has("position"))
      throw input_error(m.where("position"), "a position {lon: DEG, lat: DEG} or {x: M, y: M}", "nothing");
    c.spec = GotoSpec{r.position(m.value("position"), m.full("position"))};
  } else if (c.type == "gps_update") {
    c.spec = GpsUpdateSpec{m.number_or("hold_s", kHold, 60.0)};
  } else if (c.type == "identify") {
    IdentifyTask t;
    t.object = m.text("object", "the id of the obstacle to identify");
    if (m.has("mode")) {
      const std::string mode = m.text("mode", "align or around");
      if (mode != "align" && mode != "around")
        throw input_error(m.where("mode"), "align or around", "'" + printable(mode) + "'");
      t.mode = mode == "align" ? IdentifyTask::Mode::align : IdentifyTask::Mode::around;
    }
    t.distance_m = m.number_or("distance_m", kDistance, t.distance_m);
    c.spec = t;
  } else {  // survey
    SurveySpec s;
    std::vector<Vec2> ring = r.positions(m, "area", 3);
    for (const Vec2& p : ring) s.area.outer().push_back(to_bg(p));
    if (!(ring.front() == ring.back())) s.area.outer().push_back(to_bg(ring.front()));
    bg::correct(s.area);
    std::string why;
    if (!bg::is_valid(s.area, why) || !(bg::area(s.area) > 0.0)) {
      throw input_error(m.where("area"), "a simple polygon (its sides must not cross)",
                        "an invalid one (" + printable(why, 80) + ")");
    }
    s.line_spacing_m = m.number("line_spacing_m", kDistance);
    s.heading_deg = m.number_or("heading_deg", kHeading, 0.0);
    s.turn_radius_m = m.number_or("turn_radius_m", {0.0, 1e6, true, "a radius in metres (0: the vehicle's)"}, 0.0);
    c.spec = s;
  }
  return c;
}

Mission parse(const YAML::Node& doc, const std::string& source, const std::string& base_dir) {
  const Mapping root(doc, source, "",
                     {"name", "vehicle", "crs", "environment", "safety", "control", "start", "manoeuvres"},
                     "a YAML mapping of mission keys (see data/missions/sample_mission.yaml)");
  Mission mission;
  mission.source = source;
  mission.name = root.has("name") ? root.text("name", "a mission name (text)") : fs::path(source).stem().string();
  if (root.has("vehicle")) {
    try {
      mission.vehicle = read_vehicle_file(root.path("vehicle", base_dir));
    } catch (const InputError& e) {
      throw InputError(root.where("vehicle").describe() + ": " + e.what());
    }
  }
  Reader r{source, base_dir, std::nullopt};

  // The frame: crs, else the one chosen at the start (its UTM zone; a stereographic
  // beyond UTM), which must then be lon/lat.
  if (root.has("crs")) {
    r.frame = LocalFrame::from_user_crs(root.text("crs", "a projected CRS in metres such as EPSG:32632"),
                                        root.where("crs").describe());
  }
  if (!root.has("start"))
    throw input_error(root.where("start"), "a start {lon, lat, depth_m} or {x, y, depth_m}", "nothing");
  {
    const Mapping s(root.value("start"), source, "start.", {"x", "y", "lon", "lat", "depth_m"},
                    "a start {lon: DEG, lat: DEG, depth_m: M} or {x: M, y: M, depth_m: M}");
    if (!r.frame) {
      if (!s.has("lon")) throw input_error(root.where("start"), "lon, lat for the start, or a crs for x, y");
      const double lon = s.number("lon", kLon), lat = s.number("lat", kLat);
      r.frame = default_frame_for({lon, lon, lat, lat});
    }
    mission.start = r.position_of(s);
    mission.start_depth_m = s.number_or("depth_m", kDepth, 0.0);
  }
  mission.frame = *r.frame;

  if (root.has("environment")) {
    const Mapping e(root.value("environment"), source, "environment.",
                    {"charts", "obstacles", "current", "current_file"},
                    "a mapping of environment keys (charts, obstacles, current, current_file)");
    const auto files = [&](const char* key) {
      std::vector<std::string> out;
      if (!e.has(key)) return out;
      const YAML::Node list = e.value(key);
      if (!list.IsSequence()) throw input_error(e.where(key), "a list of file paths");
      for (const auto& item : list) {
        if (!item.IsScalar() || item.Scalar().empty())
          throw input_error({source, line_of(item), e.full(key)}, "a file path");
        const fs::path p(item.Scalar());
        const std::string path = p.is_absolute() ? p.string() : (fs::path(base_dir) / p).string();
        std::error_code ec;
        if (!fs::exists(path, ec))
          throw input_error({source, line_of(item), e.full(key)}, "an existing file", "'" + printable(path) + "'");
        out.push_back(path);
      }
      return out;
    };
    mission.charts = files("charts");
    mission.obstacles = files("obstacles");
    if (e.has("current") && e.has("current_file"))
      throw input_error(e.where("current_file"), "either current or current_file", "both");
    if (e.has("current")) {
      mission.current = e.text("current", "a current SPEED_MPS,DIR_DEG");
      parse_constant_current(mission.current, e.where("current").describe());  // refused here, not later
    }
    if (e.has("current_file")) {
      mission.current_file = e.path("current_file", base_dir);
      std::error_code ec;
      if (!fs::is_regular_file(mission.current_file, ec)) {
        throw input_error(e.where("current_file"), "an existing file", "'" + printable(mission.current_file) + "'");
      }
    }
  }
  if (root.has("safety")) {
    const Mapping s(root.value("safety"), source, "safety.", {"margin_m", "vertical_clearance_m"},
                    "a mapping of safety keys (margin_m, vertical_clearance_m)");
    mission.margin_m = s.number_or("margin_m", {0.0, 1e4, true, "a margin in metres"}, mission.margin_m);
    mission.vertical_clearance_m =
        s.number_or("vertical_clearance_m", {0.0, 1e4, true, "a clearance in metres"}, mission.vertical_clearance_m);
  }
  if (root.has("control")) {
    const Mapping c(root.value("control"), source, "control.",
                    {"identify", "identify_distance_m", "unknown_objects", "evasion_graph"},
                    "a mapping of control keys (identify, identify_distance_m, unknown_objects, evasion_graph)");
    if (c.has("identify")) {
      const YAML::Node ids = c.value("identify");
      if (!ids.IsSequence()) throw input_error(c.where("identify"), "a list of obstacle ids");
      for (const auto& id : ids) {
        if (!id.IsScalar() || id.Scalar().empty())
          throw input_error({source, line_of(id), c.full("identify")}, "an obstacle id");
        mission.control.identify.push_back(id.Scalar());
      }
    }
    // The lap must stay out of the planner's zone (margin + half the vehicle's
    // width + 0.2 m, mission_control.hpp) with room for its chords' sag: 1.5 m past the margin.
    const double least = mission.margin_m + 1.5;
    mission.control.identify_distance_m =
        c.number_or("identify_distance_m", {least, 1e4, true, "a distance in metres of at least margin_m + 1.5"},
                    std::max(mission.control.identify_distance_m, least + 5.0));
    if (c.has("unknown_objects")) {
      const std::string what = c.text("unknown_objects", "evade or identify");
      if (what != "evade" && what != "identify")
        throw input_error(c.where("unknown_objects"), "evade or identify", "'" + printable(what) + "'");
      mission.control.unknown_objects =
          what == "evade" ? ControlRules::Reaction::evade : ControlRules::Reaction::identify;
    }
    if (c.has("evasion_graph")) {
      // Graphs whose routes are the shortest polylines among the zones: the evasion's lines.
      const char* kEvasionGraphs = "visibility, visibility-full or navmesh";
      const std::string what = c.text("evasion_graph", kEvasionGraphs);
      if (what != "visibility" && what != "visibility-full" && what != "navmesh")
        throw input_error(c.where("evasion_graph"), kEvasionGraphs, "'" + printable(what) + "'");
      mission.control.evasion_graph = GraphKind{what};
    }
  }
  const YAML::Node list = root.value("manoeuvres");
  if (!list.IsSequence() || list.size() == 0) {
    throw input_error(root.where("manoeuvres"), "a list of at least one manoeuvre (" + std::string(kTypes) + ")",
                      list.IsDefined() && !list.IsNull() ? "something else" : "nothing");
  }
  double depth = mission.start_depth_m;
  for (std::size_t i = 0; i < list.size(); ++i) {
    mission.manoeuvres.push_back(read_manoeuvre(r, list[i], i, depth, mission.vehicle));
    depth = mission.manoeuvres.back().depth_m;
  }
  return mission;
}

}  // namespace

Mission read_mission(const std::string& path) {
  std::error_code ec;
  refuse_special_file(path);
  if (!fs::is_regular_file(path, ec)) throw input_error({path, "", ""}, "an existing mission file");
  const auto size = fs::file_size(path, ec);
  if (ec || size > (4u << 20))
    throw input_error({path, "", ""}, "a mission file under 4 MiB", std::to_string(size) + " bytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw input_error({path, "", ""}, "a readable mission file");
  std::ostringstream text;
  text << in.rdbuf();
  YAML::Node doc;
  try {
    doc = load_one_document(text.str(), path);
  } catch (const YAML::Exception& e) {
    const std::string at =
        e.mark.line >= 0 ? "line " + std::to_string(e.mark.line + 1) + ", column " + std::to_string(e.mark.column + 1)
                         : std::string();
    throw input_error({path, at, ""}, "a YAML mission file", printable(e.msg, 100));
  }
  if (doc.IsNull()) throw input_error({path, "", ""}, "a YAML mapping of mission keys", "an empty document");
  return parse(doc, path, fs::path(path).parent_path().string());
}

}  // namespace deepguide
