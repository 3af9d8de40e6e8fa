#include "deepguide/render/obstacle_web_layers.hpp"

#include <cmath>
#include <utility>

#include "deepguide/core/format.hpp"
#include "deepguide/planning/zone_polygons.hpp"
#include "deepguide/render/reactive_map.hpp"  // ellipse_outline

namespace deepguide {

WebMapLayer web_map_layer(std::string id, std::string name, std::string stroke, std::string fill, double fill_opacity,
                          double weight) {
  WebMapLayer l;
  l.id = std::move(id);
  l.name = std::move(name);
  l.stroke = std::move(stroke);
  l.fill = std::move(fill);
  l.fill_opacity = fill_opacity;
  l.weight = weight;
  return l;
}

WebMapLayer obstacle_web_layer(const ObstacleSet& obstacles, const WebMapGeometry& to, std::string name,
                               const std::string& colour) {
  WebMapLayer layer = web_map_layer("obstacles", std::move(name), colour, colour, 0.3, 1.0);
  layer.explained = true;
  const auto top = [](nlohmann::ordered_json& props, const std::optional<double>& top_depth_m) {
    if (top_depth_m) props["top depth (m)"] = std::round(*top_depth_m * 100.0) / 100.0;
  };
  for (const EllipticCylinder& e : obstacles.ellipses) {
    nlohmann::ordered_json props{{"obstacle", e.id}, {"shape", "ellipse"}};
    props["semi-axes (m)"] = fixed(e.footprint.a, 2) + " x " + fixed(e.footprint.b, 2);
    top(props, e.top_depth_m);
    layer.features.push_back(web_map_feature(to.outline(ellipse_outline(e.footprint, 72)), std::move(props)));
  }
  for (const PolygonObstacle& p : obstacles.polygons) {
    nlohmann::ordered_json props{{"obstacle", p.id}, {"shape", "polygon"}};
    top(props, p.top_depth_m);
    layer.features.push_back(web_map_feature(to.polygon(p.footprint), std::move(props)));
  }
  return layer;
}

WebMapLayer zone_web_layer(const ObstacleSet& obstacles, const WebMapGeometry& to, double margin_m,
                           double tolerance_m) {
  WebMapLayer layer =
      web_map_layer("zones", "Safety zones (margin " + general(margin_m) + " m)", "#e8590c", "#e8590c", 0.04, 1.0);
  layer.dash = "5 4";
  const BgMultiPolygon zones = merged_zone_polygons(obstacles, {margin_m, tolerance_m});
  for (std::size_t i = 0; i < zones.size(); ++i) {
    layer.features.push_back(web_map_feature(to.polygon(zones[i]), {{"safety zone", i + 1}}));
  }
  return layer;
}

}  // namespace deepguide
