#pragma once
// The route chart, after the seed paper's Fig. 6: obstacle footprints, their
// safety zones, optionally the planning graph, and the route from start to
// goal; with a title, a scale bar, a north arrow and a legend.
//
// Layout (pixels, everything scales with width_px / 1200):
//   title band | map (north up, equal scale, the content padded) | footer
//   with the scale bar, the legend and the north arrow.

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/render/canvas.hpp"
#include "deepguide/render/map_furniture.hpp"  // nice_scale_length
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

/// Colours of the route chart (tests read them back from the pixels).
struct RouteStyle {
  Rgba background = rgb_hex(0xffffff);    ///< title band and footer
  Rgba sea = rgb_hex(0xeef4f9);           ///< map area
  Rgba frame = rgb_hex(0x8a96a3);         ///< map border
  Rgba obstacle = rgb_hex(0x3c3f44);      ///< footprint fill
  Rgba safety_zone = rgb_hex(0xd9480f);   ///< exact zone outline (dashed)
  Rgba zone_polygon = rgb_hex(0x7b5ea7);  ///< the planner's enclosing polygons
  Rgba graph_edge = rgb_hex(0xb4c2d0);    ///< planning graph
  Rgba route = rgb_hex(0x1864d6);         ///< route line and waypoint outlines
  Rgba start = rgb_hex(0x2f9e44);
  Rgba goal = rgb_hex(0xc92a2a);
  Rgba text = rgb_hex(0x212529);
  Rgba current = rgb_hex(0x8fa3b8);        ///< current arrows
  Rgba cell = rgb_hex(0x9fb3c8);           ///< quadtree cell outlines
  Rgba occupied_cell = rgb_hex(0xe8c9b8);  ///< occupied cells' fill
  Rgba detected = rgb_hex(0xe67700);       ///< obstacles the sonar reported
  Rgba repaired = rgb_hex(0x7048e8);       ///< repaired routes
  Rgba track = rgb_hex(0x2b8a3e);          ///< the track sailed
};

struct RouteScene {
  const ObstacleSet* obstacles = nullptr;          ///< optional; local frame (m)
  double margin = 0.0;                             ///< safety margin (m); zones drawn when > 0
  const BgMultiPolygon* zone_polygons = nullptr;   ///< optional: the planner's zone polygons
  std::vector<std::pair<Vec2, Vec2>> graph_edges;  ///< optional: the planning graph
  /// Optional: quadtree cells as (min corner, max corner), free and occupied
  /// (the seed's Fig. 7): outlines, occupied ones shaded.
  std::vector<std::pair<Vec2, Vec2>> free_cells;
  std::vector<std::pair<Vec2, Vec2>> occupied_cells;
  std::vector<Vec2> route;  ///< waypoints, start to goal
  std::optional<Vec2> start;
  std::optional<Vec2> goal;
  std::string title;
  /// Optional: clockwise angle (deg) from grid north (the map's up) to true
  /// north, i.e. minus the meridian convergence; noted under the north arrow.
  std::optional<double> true_north_deg;
  bool label_obstacles = true;  ///< write each obstacle's id beside it
  /// Optional: the current (m/s, local frame) to draw as arrows under
  /// everything, on a lattice about 55 px apart, their length proportional to
  /// the speed (the fastest as long as the lattice spacing); nullopt = none there.
  std::function<std::optional<Vec2>(const Vec2&)> current;
  std::string current_label;  ///< its legend text, e.g. "current, max 1.8 m/s"
  /// Optional: one label per route leg (speed, time, energy), written beside
  /// the legs long enough on the map to carry it.
  std::vector<std::string> leg_labels;
  /// Optional, for replanning replays: obstacles the sonar reported (drawn in
  /// their own colour with their zones), each repaired route (dashed), and
  /// the track the vehicle sailed.
  const ObstacleSet* detected = nullptr;
  std::vector<std::vector<Vec2>> repaired_routes;
  std::vector<Vec2> track;
  RouteStyle style;
};

/// Where everything goes in an image of width_px.
struct RouteLayout {
  int width = 0;
  int height = 0;
  double unit = 1.0;   ///< pixels per design unit (width / 1200): line widths, fonts
  PixelRect map;       ///< the map area
  PixelRect footer;    ///< scale bar, legend, north arrow
  WorldBox extent;     ///< the world box shown (content, padded)
  ViewTransform view;  ///< world -> pixels
};

/// The smallest and largest image widths render_route accepts.
inline constexpr int kMinImageWidth = 300;
inline constexpr int kMaxImageWidth = 8000;

/// The layout for the scene. Throws InputError when there is nothing to draw,
/// a coordinate is not finite or width_px lies outside [kMinImageWidth, kMaxImageWidth].
RouteLayout route_layout(const RouteScene& scene, int width_px = 1200);

/// Draws the scene to `path` (.png or .svg). Atomic: a failure leaves no file.
/// Throws InputError naming the path on bad input or when writing fails.
void render_route(const RouteScene& scene, const std::string& path, int width_px = 1200);

/// The clockwise angle (deg) from grid north to true north at a local point
/// (RouteScene::true_north_deg).
double true_north_deg(const LocalFrame& frame, const Vec2& at);
/// A route chart's default title: "NAME: L m, N waypoints, margin M m  (CRS)".
std::string route_title(const std::string& name, const Route& route, double margin, const LocalFrame& frame);

}  // namespace deepguide
