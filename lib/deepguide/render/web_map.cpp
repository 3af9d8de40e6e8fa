#include "deepguide/render/web_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/render/web_map_script.hpp"  // generated from web_map.js (lib/CMakeLists.txt)

namespace deepguide {

namespace {

std::string read_leaflet(const std::string& name) {
  const std::filesystem::path path = std::filesystem::path(leaflet_dir()) / name;
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  if (in) text << in.rdbuf();
  if (!in || text.str().empty()) {
    throw InputError(
        path.string() +
        ": expected Leaflet for the web map (apt-get install libjs-leaflet, or set DEEPGUIDE_LEAFLET_DIR)");
  }
  return text.str();
}

// Leaflet's stylesheet names images only for what the page does not use (a
// collapsed layer switcher, marker icons): none is fetched, so none is named.
std::string offline_css(std::string css) {
  for (std::size_t at = css.find("url(images/"); at != std::string::npos; at = css.find("url(images/", at)) {
    const std::size_t end = css.find(')', at);
    if (end == std::string::npos) break;
    css.replace(at, end - at + 1, "none");
  }
  return css;
}

// JSON inside <script>: "</" would end the element, so it is written "<\/".
std::string script_safe(std::string json) {
  for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at + 3))
    json.insert(at + 1, "\\");
  return json;
}

// `e` grown by every position in GeoJSON coordinates (nested arrays).
void extend(LonLatExtent& e, const nlohmann::ordered_json& c) {
  if (!c.is_array() || c.empty()) return;
  if (c[0].is_number()) {
    const double lon = c[0].get<double>(), lat = c[1].get<double>();
    e.west = std::isnan(e.west) ? lon : std::min(e.west, lon);
    e.east = std::isnan(e.east) ? lon : std::max(e.east, lon);
    e.south = std::isnan(e.south) ? lat : std::min(e.south, lat);
    e.north = std::isnan(e.north) ? lat : std::max(e.north, lat);
    return;
  }
  for (const auto& x : c) extend(e, x);
}

// A line's or a ring's positions as integers of 1e-7 degrees, the first
// absolute and each next as the step from the one before: a third of the
// text of decimal degrees, decoded exactly by the page (x / 1e7 is the double
// nearest the decimal, as parsing it is).
nlohmann::ordered_json steps(const nlohmann::ordered_json& positions) {
  nlohmann::ordered_json q = nlohmann::ordered_json::array();
  long long x = 0, y = 0;
  for (const auto& p : positions) {
    const long long px = std::llround(p[0].get<double>() * 1e7), py = std::llround(p[1].get<double>() * 1e7);
    q.push_back(px - x);
    q.push_back(py - y);
    x = px, y = py;
  }
  return q;
}

// The geometry with its coordinates as steps ("q"); points stay as they are.
nlohmann::ordered_json compact(const nlohmann::ordered_json& geometry) {
  const std::string type = geometry.value("type", "");
  const auto& c = geometry.contains("coordinates") ? geometry["coordinates"] : nlohmann::ordered_json();
  nlohmann::ordered_json q = nlohmann::ordered_json::array();
  if (type == "LineString") {
    q = steps(c);
  } else if (type == "Polygon") {
    for (const auto& ring : c) q.push_back(steps(ring));
  } else if (type == "MultiPolygon") {
    for (const auto& polygon : c) {
      nlohmann::ordered_json rings = nlohmann::ordered_json::array();
      for (const auto& ring : polygon) rings.push_back(steps(ring));
      q.push_back(std::move(rings));
    }
  } else {
    return geometry;
  }
  return {{"type", type}, {"q", std::move(q)}};
}

nlohmann::ordered_json compact_features(const nlohmann::ordered_json& features) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& f : features) {
    nlohmann::ordered_json g = f;
    if (f.contains("geometry") && f["geometry"].is_object()) g["geometry"] = compact(f["geometry"]);
    out.push_back(std::move(g));
  }
  return out;
}

constexpr const char* kPageStyle = R"css(
html, body { margin: 0; height: 100%; font: 13px/1.4 system-ui, sans-serif; color: #212529; }
body { display: flex; flex-direction: column; }
header { padding: 6px 12px; border-bottom: 1px solid #dee2e6; }
header h1 { font-size: 16px; margin: 0; }
header p { margin: 0; color: #495057; }
main { flex: 1; display: flex; min-height: 0; }
#map { flex: 1; background: #eef4f9; }
#dg-table { width: 34%; max-width: 560px; overflow: auto; border-left: 1px solid #dee2e6; padding: 0 8px; }
#dg-table h2 { font-size: 14px; }
table.dg-rows { border-collapse: collapse; font-size: 12px; }
table.dg-rows th, table.dg-rows td { border-bottom: 1px solid #e9ecef; padding: 2px 6px; text-align: right; white-space: nowrap; }
table.dg-props th { text-align: left; padding-right: 8px; font-weight: 600; vertical-align: top; }
.dg-swatch { display: inline-block; width: 12px; height: 10px; border: 2px solid; margin-right: 5px; vertical-align: middle; }
.dg-count { color: #868e96; }
.dg-hits { max-height: 300px; overflow: auto; }
)css";

}  // namespace

std::string leaflet_dir() {
  if (const char* dir = std::getenv("DEEPGUIDE_LEAFLET_DIR"); dir != nullptr && *dir != '\0') return dir;
  return "/usr/share/javascript/leaflet";
}

nlohmann::ordered_json web_map_position(double lon, double lat) {
  return {std::round(lon * 1e7) / 1e7, std::round(lat * 1e7) / 1e7};
}

nlohmann::ordered_json web_map_feature(nlohmann::ordered_json geometry, nlohmann::ordered_json properties,
                                       nlohmann::ordered_json style) {
  nlohmann::ordered_json f{
      {"type", "Feature"}, {"geometry", std::move(geometry)}, {"properties", std::move(properties)}};
  if (!style.is_null()) f["style"] = std::move(style);
  return f;
}

namespace {

template <class Points>
nlohmann::ordered_json ring_of(const WebMapGeometry& g, const Points& points) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& p : points) out.push_back(g.position(Vec2(p.x(), p.y())));
  if (!out.empty() && out.front() != out.back()) out.push_back(out.front());  // GeoJSON rings are closed
  return out;
}

nlohmann::ordered_json rings_of(const WebMapGeometry& g, const BgPolygon& p) {
  nlohmann::ordered_json rings = nlohmann::ordered_json::array({ring_of(g, p.outer())});
  for (const auto& inner : p.inners()) rings.push_back(ring_of(g, inner));
  return rings;
}

}  // namespace

nlohmann::ordered_json WebMapGeometry::position(const Vec2& p) const {
  if (frame == nullptr) return web_map_position(p.x(), p.y());
  const Vec2 ll = frame->to_lonlat(p);
  return web_map_position(ll.x(), ll.y());
}

nlohmann::ordered_json WebMapGeometry::point(const Vec2& p) const {
  return {{"type", "Point"}, {"coordinates", position(p)}};
}

nlohmann::ordered_json WebMapGeometry::line(const std::vector<Vec2>& points) const {
  nlohmann::ordered_json coordinates = nlohmann::ordered_json::array();
  for (const Vec2& p : points) coordinates.push_back(position(p));
  return {{"type", "LineString"}, {"coordinates", std::move(coordinates)}};
}

nlohmann::ordered_json WebMapGeometry::outline(const std::vector<Vec2>& ring) const {
  return {{"type", "Polygon"}, {"coordinates", nlohmann::ordered_json::array({ring_of(*this, ring)})}};
}

nlohmann::ordered_json WebMapGeometry::polygon(const BgPolygon& p) const {
  return {{"type", "Polygon"}, {"coordinates", rings_of(*this, p)}};
}

nlohmann::ordered_json WebMapGeometry::multipolygon(const BgMultiPolygon& m) const {
  nlohmann::ordered_json polygons = nlohmann::ordered_json::array();
  for (const BgPolygon& p : m) polygons.push_back(rings_of(*this, p));
  return {{"type", "MultiPolygon"}, {"coordinates", std::move(polygons)}};
}

nlohmann::ordered_json WebMapGeometry::disc(const Vec2& centre, double radius_m) const {
  std::vector<Vec2> points;
  for (int k = 0; k < 48; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 48.0;
    points.push_back(centre + radius_m * Vec2(std::cos(a), std::sin(a)));
  }
  return outline(points);
}

WebMapLayer frame_grid_layer(const LocalFrame& frame, const Vec2& lo, const Vec2& hi) {
  const double span = std::max(hi.x() - lo.x(), hi.y() - lo.y());
  double step = 1.0;
  if (std::isfinite(span) && span > 0.0) {
    const double raw = span / 10.0, decade = std::pow(10.0, std::floor(std::log10(raw)));
    step = raw <= decade         ? decade
           : raw <= 2.0 * decade ? 2.0 * decade
           : raw <= 5.0 * decade ? 5.0 * decade
                                 : 10.0 * decade;
  }
  WebMapLayer layer;
  layer.id = "grid";
  layer.name = "Grid of " + frame.id() + " (every " + general(step) + " m)";
  layer.stroke = layer.fill = "#495057";
  layer.fill_opacity = 0.0;
  layer.weight = 0.8;
  layer.dash = "2 4";
  layer.shown = false;
  if (!(std::isfinite(span) && span > 0.0)) return layer;
  const WebMapGeometry to{&frame};
  // Straight in the frame, so a little curved on the map: 24 points a line.
  const auto line = [&](const Vec2& a, const Vec2& b) {
    std::vector<Vec2> points;
    for (int k = 0; k <= 24; ++k) points.push_back(a + (b - a) * (k / 24.0));
    return to.line(points);
  };
  const double x0 = std::floor(lo.x() / step) * step, y0 = std::floor(lo.y() / step) * step;
  const double x1 = std::ceil(hi.x() / step) * step, y1 = std::ceil(hi.y() / step) * step;
  for (double x = x0; x <= x1 + step / 2; x += step) {
    layer.features.push_back(web_map_feature(line({x, y0}, {x, y1}), {{"easting (m)", x}, {"frame", frame.id()}}));
  }
  for (double y = y0; y <= y1 + step / 2; y += step) {
    layer.features.push_back(web_map_feature(line({x0, y}, {x1, y}), {{"northing (m)", y}, {"frame", frame.id()}}));
  }
  return layer;
}

std::string web_map_html(const WebMap& map) {
  const std::string leaflet = read_leaflet("leaflet.min.js");
  const std::string css = offline_css(read_leaflet("leaflet.css"));
  nlohmann::ordered_json data;
  data["title"] = map.title;
  data["planar"] = map.planar;
  data["layers"] = nlohmann::ordered_json::array();
  for (const WebMapLayer& l : map.layers) {
    data["layers"].push_back({{"id", l.id},
                              {"name", l.name},
                              {"stroke", l.stroke},
                              {"fill", l.fill},
                              {"fill_opacity", l.fill_opacity},
                              {"weight", l.weight},
                              {"dash", l.dash},
                              {"point_radius_px", l.point_radius_px},
                              {"shown", l.shown},
                              {"explained", l.explained},
                              {"hatched", l.hatched},
                              {"min_zoom", l.min_zoom},
                              {"features", compact_features(l.features)}});
  }
  data["images"] = nlohmann::ordered_json::array();
  for (const WebMapImage& i : map.images) {
    data["images"].push_back({{"id", i.id},
                              {"name", i.name},
                              {"url", "data:image/png;base64," + i.png_base64},
                              {"south", i.bounds.south},
                              {"west", i.bounds.west},
                              {"north", i.bounds.north},
                              {"east", i.bounds.east},
                              {"opacity", i.opacity},
                              {"shown", i.shown}});
  }
  data["table"] = {{"title", map.table.title}, {"columns", map.table.columns}, {"rows", map.table.rows}};
  // The view: the focus, else every feature; worked out here, so the page
  // need not walk its features before it draws them.
  LonLatExtent view = map.focus;
  if (view.empty()) {
    for (const WebMapLayer& l : map.layers) {
      for (const auto& f : l.features) {
        if (f.contains("geometry") && f["geometry"].is_object() && f["geometry"].contains("coordinates")) {
          extend(view, f["geometry"]["coordinates"]);
        }
      }
    }
  }
  if (!view.empty()) {
    data["focus"] = {{"west", view.west}, {"east", view.east}, {"south", view.south}, {"north", view.north}};
  }
  std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                     html_text(map.title) + "</title>\n<style>\n" + css + "\n" + kPageStyle + "</style>\n<script>\n" +
                     leaflet + "\n</script>\n</head>\n<body>\n<header><h1>" + html_text(map.title) + "</h1>";
  if (!map.subtitle.empty()) page += "<p>" + html_text(map.subtitle) + "</p>";
  page += "</header>\n<main><div id=\"map\"></div><div id=\"dg-table\"></div></main>\n";
  // Invalid UTF-8 in a feature's text (a chart's attribute) is replaced, not a failure.
  page += "<script id=\"dg-data\" type=\"application/json\">" +
          script_safe(data.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace)) + "</script>\n";
  page += "<script>\n" + std::string(kWebMapScript) + "</script>\n</body>\n</html>\n";
  return page;
}

void check_web_map_path(const std::string& path, const std::string& option) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext != ".html" && ext != ".htm") {
    throw InputError(option + ": expected a web page file name ending in .html or .htm, got '" + printable(path) + "'");
  }
  // Before the work that fills it: a page that cannot be written is said at once.
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec)) {
    throw InputError(option + ": the folder '" + printable(folder.string()) + "' of '" + printable(path) +
                     "' does not exist");
  }
}

void write_web_map(const WebMap& map, const std::string& path) {
  check_web_map_path(path, path);
  write_text_file(path, web_map_html(map), "web map");
}

}  // namespace deepguide
