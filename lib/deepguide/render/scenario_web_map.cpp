#include "deepguide/render/scenario_web_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "deepguide/core/format.hpp"
#include "deepguide/reactive/reactive_method.hpp"  // security_ellipse
#include "deepguide/render/reactive_map.hpp"       // ellipse_outline

namespace deepguide {

namespace {

using json = nlohmann::ordered_json;

// The methods' colours, in the order given (as the report's figures take them).
constexpr std::array<const char*, 8> kColours{"#1c7ed6", "#e8590c", "#2f9e44", "#ae3ec9",
                                              "#f59f00", "#0c8599", "#c2255c", "#5c940d"};

json metres(double v) { return std::isfinite(v) ? json(std::round(v * 100.0) / 100.0) : json("none"); }

}  // namespace

WebMap scenario_web_map(const Scenario& sc, const std::string& title, const std::vector<ScenarioTrack>& runs) {
  const WebMapGeometry to{sc.frame ? &*sc.frame : nullptr};
  WebMap map;
  map.title = title;
  map.planar = !sc.frame;
  map.subtitle = std::to_string(sc.obstacles.size()) + " obstacle(s), security margin " +
                 general(sc.reactive.margin_m) + " m" +
                 (sc.frame ? ", frame " + sc.frame->id() : ", a local frame in metres");

  WebMapLayer obstacles;
  obstacles.id = "obstacles";
  obstacles.name = "Obstacles (true footprints)";
  obstacles.stroke = obstacles.fill = "#862e9c";
  obstacles.fill_opacity = 0.35;
  obstacles.weight = 1.0;
  obstacles.explained = true;
  WebMapLayer zones;
  zones.id = "zones";
  zones.name = "Security zones (margin " + general(sc.reactive.margin_m) + " m)";
  zones.stroke = zones.fill = "#e8590c";
  zones.fill_opacity = 0.05;
  zones.weight = 1.0;
  zones.dash = "5 4";
  for (const EllipticCylinder& o : sc.obstacles) {
    json props{{"obstacle", o.id}, {"semi-axes (m)", fixed(o.footprint.a, 2) + " x " + fixed(o.footprint.b, 2)}};
    obstacles.features.push_back(web_map_feature(to.outline(ellipse_outline(o.footprint, 72)), std::move(props)));
    zones.features.push_back(web_map_feature(
        to.outline(ellipse_outline(security_ellipse(o.footprint, sc.reactive.margin_m), 72)), {{"zone of", o.id}}));
  }
  map.layers.push_back(std::move(obstacles));
  map.layers.push_back(std::move(zones));

  WebMapLayer ends;
  ends.id = "ends";
  ends.name = "Start and target";
  ends.stroke = "#212529";
  ends.fill = "#ffffff";
  ends.fill_opacity = 1.0;
  ends.point_radius_px = 6.0;
  ends.features.push_back(web_map_feature(to.point(sc.start), {{"start", sc.name}}));
  ends.features.push_back(web_map_feature(to.point(sc.target), {{"target", sc.name}}));
  map.layers.push_back(std::move(ends));

  map.table.title = "Methods";
  map.table.columns = {"method", "end", "least clearance (m)", "path (m)"};
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const ScenarioTrack& r = runs[i];
    const char* colour = kColours[i % kColours.size()];
    json props{{"method", r.method},
               {"end", r.end},
               {"least clearance (m)", metres(r.min_clearance_m)},
               {"path (m)", metres(r.path_length_m)},
               {"collided", r.collided ? "yes" : "no"}};
    if (!r.note.empty()) props["note"] = r.note;
    if (r.route.size() >= 2) {
      WebMapLayer route;
      route.id = "route:" + r.method;
      route.name = r.method + ": route planned";
      route.stroke = route.fill = colour;
      route.fill_opacity = 0.0;
      route.weight = 1.5;
      route.dash = "6 4";
      route.features.push_back(web_map_feature(to.line(r.route), props));
      map.layers.push_back(std::move(route));
    }
    WebMapLayer track;
    track.id = "track:" + r.method;
    track.name = r.method + ": track sailed (" + r.end + ")";
    track.stroke = track.fill = colour;
    track.fill_opacity = 0.0;
    track.weight = 3.0;
    if (r.track.size() >= 2) track.features.push_back(web_map_feature(to.line(r.track), props));
    map.layers.push_back(std::move(track));
    map.table.rows.push_back({r.method, r.end, metres(r.min_clearance_m), metres(r.path_length_m)});
  }
  return map;
}

}  // namespace deepguide
