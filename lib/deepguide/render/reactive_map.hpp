#pragma once
// The map that the reactive level's figures share (gradient lines,
// trajectories): the true obstacle footprints, their security zones, the start
// and the target, on axes in metres; a title band above and a legend below.
//
// Decisions:
// - Zones are drawn as the methods see them: security_ellipse(footprint,
//   margin) (reactive_method.hpp), the ellipse that contains the exact offset
//   zone, not the offset curve the route chart draws.
// - Axes with numbers in metres (x east, y north, equal scale) instead of a
//   scale bar: these are figures to read distances off (clearances, detours),
//   and the axis titles say where north is.
// - One colour per method, the same in every figure (Okabe-Ito: tell-apart
//   for the common colour blindnesses).
// Layout (design units at 1200 px wide, times unit = width / 1200):
//   title band 52 | y title 24 | plot (tick numbers left 80, right 24; the
//   content's aspect within [0.45, 1.1]) | x numbers and title 52 | the map's
//   legend row | the caller's legend rows | 10.
// Drawing: begin_reactive_map (title, sea, zones, obstacles; clips to the
// plot), the caller's content, end_reactive_map (start, target, axes, legends).

#include <cstddef>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/render/canvas.hpp"
#include "deepguide/render/plot_furniture.hpp"

namespace DEEPGUIDE_API deepguide {

struct Scenario;

struct ReactiveMapStyle {
  Rgba background = rgb_hex(0xffffff);
  Rgba sea = rgb_hex(0xf3f6f9);
  Rgba frame = rgb_hex(0x5c636a);
  Rgba grid = rgb_hex(0xdde3ea);
  Rgba obstacle = rgb_hex(0x3c3f44);
  Rgba zone = rgb_hex(0x868e96);  ///< dashed outline; fill at low alpha
  Rgba text = rgb_hex(0x212529);
};

/// The colour of a method's lines in every reactive figure.
Rgba method_color(const ReactiveMethod& method);

struct ReactiveMap {
  std::vector<Ellipse> objects;  ///< true footprints (local frame, m)
  double margin_m = 0.0;         ///< security margin: zones drawn when > 0
  Vec2 start{0.0, 0.0};
  Vec2 target{0.0, 0.0};
  std::string target_label = "target";  ///< the target marker's label and legend entry
  std::string title;
  ReactiveMapStyle style;
};

struct ReactiveMapLayout {
  int width = 0;
  int height = 0;
  double unit = 1.0;
  PixelRect plot;                  ///< the map area
  PixelRect legend;                ///< both legends
  WorldBox area;                   ///< the world box the plot shows (m)
  ViewTransform view;              ///< world -> pixels
  PlotAxis x, y;                   ///< the same mapping as view, per axis
  std::size_t legend_entries = 0;  ///< the caller's entries
  int legend_columns = 1;
};

/// A scenario's true obstacle footprints, margin, start and target, titled `title`.
ReactiveMap reactive_map_for(const Scenario& scenario, const std::string& title);

/// Where everything goes: the content is the zones, start, target and
/// `extra` (e.g. trajectories), padded. Throws InputError for a width outside
/// [kMinImageWidth, kMaxImageWidth] or non-finite content.
ReactiveMapLayout reactive_map_layout(const ReactiveMap& map, const WorldBox& extra, int width_px,
                                      std::size_t legend_entries, int legend_columns);

/// Title, the plot's sea, zones and obstacles; leaves the canvas clipped to the plot.
void begin_reactive_map(Canvas& canvas, const ReactiveMap& map, const ReactiveMapLayout& layout);
/// Start and target, then (unclipped) axes and the legends: the map's row and `entries`.
void end_reactive_map(Canvas& canvas, const ReactiveMap& map, const ReactiveMapLayout& layout,
                      const std::vector<LegendEntry>& entries);

/// The boundary of `e` as a closed polyline of n points.
std::vector<Vec2> ellipse_outline(const Ellipse& e, int n);

}  // namespace deepguide
