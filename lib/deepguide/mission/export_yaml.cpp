// Our own plan file: the basic manoeuvres themselves, in the mission's CRS,
// written by yaml-cpp and read back by read_plan_yaml.
//   name: ..., crs: EPSG:32632, length_m: ...
//   basic_manoeuvres:
//     - {kind: line, from: {x, y}, to: {x, y}, from_depth_m, depth_m, speed_mps, role, manoeuvre}
//     - {kind: arc, ..., centre: {x, y}, radius_m, turn: left|right}
//     - {kind: point, ..., hold_s}
// Coordinates have 4 decimals (0.1 mm), depths and speeds 4.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/input_files.hpp"
#include "deepguide/core/yaml_mapping.hpp"
#include "deepguide/mission/export_writers.hpp"

namespace deepguide {
namespace {

const char* kind_name(BasicManoeuvre::Kind kind) {
  switch (kind) {
    case BasicManoeuvre::Kind::arc: return "arc";
    case BasicManoeuvre::Kind::point: return "point";
    case BasicManoeuvre::Kind::line: break;
  }
  return "line";
}

void emit_xy(YAML::Emitter& e, const char* key, const Vec2& p) {
  e << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "x" << YAML::Value
    << fixed(p.x(), 4) << YAML::Key << "y" << YAML::Value << fixed(p.y(), 4) << YAML::EndMap;
}

constexpr Range kAny{-1e12, 1e12, true, "a number"};

Vec2 read_xy(const Mapping& m, const char* key, const std::string& source) {
  const Mapping p(m.value(key), source, m.full(key) + ".", {"x", "y"}, "a position {x: M, y: M}");
  return {p.number("x", kAny), p.number("y", kAny)};
}

}  // namespace

namespace detail {

void write_plan_yaml(const std::string& path, const std::string& destination, const Mission& mission,
                     const MissionPlan& plan) {
  YAML::Emitter e;
  e << YAML::Comment(
      "deepguide plan of basic manoeuvres (docs/MISSIONS.md, \"Export\"); x, y in crs, depths positive down");
  e << YAML::BeginMap;
  e << YAML::Key << "name" << YAML::Value << mission.name;
  e << YAML::Key << "crs" << YAML::Value << mission.frame.id();
  e << YAML::Key << "length_m" << YAML::Value << fixed(plan.length_m, 4);
  e << YAML::Key << "basic_manoeuvres" << YAML::Value << YAML::BeginSeq;
  for (const BasicManoeuvre& b : plan.basics) {
    e << YAML::Flow << YAML::BeginMap;
    e << YAML::Key << "kind" << YAML::Value << kind_name(b.kind);
    emit_xy(e, "from", b.from);
    emit_xy(e, "to", b.to);
    if (b.kind == BasicManoeuvre::Kind::arc) {
      emit_xy(e, "centre", b.centre);
      e << YAML::Key << "radius_m" << YAML::Value << fixed(b.radius_m, 4);
      e << YAML::Key << "turn" << YAML::Value << (b.turn > 0 ? "left" : "right");
      e << YAML::Key << "length_m" << YAML::Value << fixed(b.length_m, 4);  // a sweep near 0 or 2 pi is not recomputed
    }
    e << YAML::Key << "from_depth_m" << YAML::Value << fixed(b.from_depth_m, 4);
    e << YAML::Key << "depth_m" << YAML::Value << fixed(b.depth_m, 4);
    e << YAML::Key << "speed_mps" << YAML::Value << fixed(b.speed_mps, 4);
    if (b.kind == BasicManoeuvre::Kind::point) e << YAML::Key << "hold_s" << YAML::Value << fixed(b.hold_s, 4);
    e << YAML::Key << "role" << YAML::Value << role_name(b.role);
    if (b.source < mission.manoeuvres.size()) {
      e << YAML::Key << "manoeuvre" << YAML::Value << mission.manoeuvres[b.source].name;
    }
    e << YAML::EndMap;
  }
  e << YAML::EndSeq << YAML::EndMap;
  if (!e.good()) throw InputError(destination + ": could not write the plan (" + e.GetLastError() + ")");
  std::ofstream out(path, std::ios::binary);
  out << e.c_str() << "\n";
  out.close();
  if (!out) throw InputError(destination + ": could not write the plan file");
}

}  // namespace detail

MissionPlan read_plan_yaml(const std::string& path) {
  std::error_code ec;
  refuse_special_file(path);
  if (!std::filesystem::is_regular_file(path, ec)) throw input_error({path, "", ""}, "an existing plan file");
  YAML::Node doc;
  try {
    std::ifstream in(path, std::ios::binary);
    doc = load_one_document(std::string(std::istreambuf_iterator<char>(in), {}), path);
  } catch (const YAML::Exception& e) {
    const std::string at =
        e.mark.line >= 0 ? "line " + std::to_string(e.mark.line + 1) + ", column " + std::to_string(e.mark.column + 1)
                         : std::string();
    throw input_error({path, at, ""}, "a YAML plan file", printable(e.msg, 100));
  }
  const Mapping root(doc, path, "", {"name", "crs", "length_m", "basic_manoeuvres"},
                     "a deepguide plan (name, crs, length_m, basic_manoeuvres)");
  const YAML::Node list = root.value("basic_manoeuvres");
  if (!list.IsSequence() || list.size() == 0)
    throw input_error(root.where("basic_manoeuvres"), "a list of basic manoeuvres");
  MissionPlan plan;
  std::string manoeuvre;  // consecutive basics of one complex manoeuvre share its index
  std::size_t source = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string prefix = "basic_manoeuvres[" + std::to_string(i) + "].";
    const Mapping m(list[i], path, prefix,
                    {"kind", "from", "to", "centre", "radius_m", "turn", "length_m", "from_depth_m", "depth_m",
                     "speed_mps", "hold_s", "role", "manoeuvre"},
                    "a basic manoeuvre mapping");
    BasicManoeuvre b;
    const std::string kind = m.text("kind", "line, arc or point");
    if (kind == "line")
      b.kind = BasicManoeuvre::Kind::line;
    else if (kind == "arc")
      b.kind = BasicManoeuvre::Kind::arc;
    else if (kind == "point")
      b.kind = BasicManoeuvre::Kind::point;
    else
      throw input_error(m.where("kind"), "line, arc or point", "'" + printable(kind) + "'");
    b.from = read_xy(m, "from", path);
    b.to = read_xy(m, "to", path);
    b.from_depth_m = m.number("from_depth_m", {0.0, 11000.0, true, "a depth in metres"});
    b.depth_m = m.number("depth_m", {0.0, 11000.0, true, "a depth in metres"});
    b.speed_mps = m.number("speed_mps", {0.0, 100.0, true, "a speed in m/s"});
    if (b.kind == BasicManoeuvre::Kind::arc) {
      b.centre = read_xy(m, "centre", path);
      b.radius_m = m.number("radius_m", {0.0, 1e6, false, "a radius in metres"});
      const std::string turn = m.text("turn", "left or right");
      if (turn != "left" && turn != "right")
        throw input_error(m.where("turn"), "left or right", "'" + printable(turn) + "'");
      b.turn = turn == "left" ? 1 : -1;
      b.length_m = m.number("length_m", {0.0, 2.0 * M_PI * b.radius_m + 1e-3, true, "the arc's length in metres"});
      for (const Vec2& end : {b.from, b.to}) {
        if (std::abs((end - b.centre).norm() - b.radius_m) > 1e-3) {
          throw input_error(m.where("radius_m"), "the distance from centre to from and to (within 1 mm)",
                            yaml_number(b.radius_m));
        }
      }
    } else if (b.kind == BasicManoeuvre::Kind::line) {
      b.length_m = (b.to - b.from).norm();
    } else {
      b.hold_s = m.number_or("hold_s", {0.0, 1e7, true, "a time in seconds"}, 0.0);
    }
    if (m.has("role")) {
      const std::string role = m.text("role", "mission, evasion or identification");
      if (role == "evasion")
        b.role = BasicManoeuvre::Role::evasion;
      else if (role == "identification")
        b.role = BasicManoeuvre::Role::identification;
      else if (role != "mission")
        throw input_error(m.where("role"), "mission, evasion or identification", "'" + printable(role) + "'");
    }
    const std::string name = m.has("manoeuvre") ? m.text("manoeuvre", "a manoeuvre name") : std::string();
    if (i > 0 && name != manoeuvre) ++source;
    manoeuvre = name;
    b.source = source;
    b.start_m = plan.length_m;
    plan.length_m += b.length_m;
    plan.basics.push_back(b);
  }
  return plan;
}

}  // namespace deepguide
