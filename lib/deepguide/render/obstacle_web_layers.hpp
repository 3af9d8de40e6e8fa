#pragma once
// The web map layers every page of obstacles shares (render/web_map.hpp):
// the obstacles' footprints, named by a click, and their safety zones at a
// margin, as the planner builds them (planning/zone_polygons.hpp).

#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/render/web_map.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

/// A layer of its id, name, colours, fill opacity and line width.
WebMapLayer web_map_layer(std::string id, std::string name, std::string stroke, std::string fill, double fill_opacity,
                          double weight);

/// The footprints (an ellipse as 72 points), each with its id, shape,
/// semi-axes and top depth; a click lists every one under it.
WebMapLayer obstacle_web_layer(const ObstacleSet& obstacles, const WebMapGeometry& to, std::string name,
                               const std::string& colour = "#862e9c");

/// The safety zones at `margin_m` (zone polygons within `tolerance_m`), overlapping ones merged.
WebMapLayer zone_web_layer(const ObstacleSet& obstacles, const WebMapGeometry& to, double margin_m, double tolerance_m);

}  // namespace deepguide
