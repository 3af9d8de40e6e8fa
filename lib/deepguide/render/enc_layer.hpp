#pragma once
// S-57 cells drawn as an ECDIS draws them, for the chart figure
// (chart_scene.hpp): depth areas tinted by DRVAL1 (drying areas green), land,
// structures, dangers as symbols by kind (rock: a cross, wreck: a hull,
// obstruction: a dotted circle), soundings as numbers; with an operating
// depth, the no-go hatched, its boundary drawn as the safety contour, and the
// dangers and soundings shallower than the required depth in the no-go
// colour. Labels (soundings, danger ids) are placed only where they collide
// with no label already placed, shallowest first, so a cell with hundreds of
// them stays legible; so are danger symbols, where hundreds fall on a few
// pixels of a regional chart's coast. Several cells are drawn as the
// planners read them (the best scale wins where they overlap), each cell's
// coverage outlined faintly with its name and usage band.

#include <optional>
#include <string>
#include <vector>

#include "deepguide/charts/chart_options.hpp"
#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/render/canvas.hpp"

namespace DEEPGUIDE_API deepguide {

struct EncLayer {
  struct DepthArea {
    BgMultiPolygon area;
    double drval1;  ///< NaN: unknown
  };
  struct Danger {
    std::string id, cls;
    std::vector<Vec2> points;
    BgMultiPolygon area;
    std::vector<std::vector<Vec2>> lines;
    double depth;  ///< VALSOU; NaN unknown
  };
  struct Sounding {
    Vec2 at;
    double depth;
  };
  std::vector<DepthArea> depth_areas;
  BgMultiPolygon land;
  BgMultiPolygon structure_areas;
  std::vector<std::vector<Vec2>> structure_lines;
  std::vector<Vec2> structure_points;
  std::vector<Danger> dangers;
  std::vector<Sounding> soundings;
  BgMultiPolygon coverage;
  /// Several cells: each one's coverage, best scale first (one cell: none).
  struct Cell {
    std::string name;
    int usage_band = 0;
    long compilation_scale = 0;
    BgMultiPolygon coverage;
  };
  std::vector<Cell> cells;
  std::optional<EncNoGo> no_go;  ///< with an operating depth
  double max_depth_m = 0;        ///< deepest DRVAL1 (for the depth bands)

  WorldBox box() const;  ///< the coverage's box in the frame
};

/// Reads the cells (files or folders) into `frame` for drawing; with a finite
/// depth_m also their no-go. Throws what enc_no_go throws.
EncLayer read_enc_layer(const std::vector<std::string>& cells, const LocalFrame& frame, double depth_m,
                        double clearance_m, const ChartOptions& chart = {});

struct EncStyle {
  Rgba drying = rgb_hex(0xb8d3a3);
  Rgba land = rgb_hex(0xf0e2bd);
  Rgba land_edge = rgb_hex(0x9c8a5a);
  Rgba structure = rgb_hex(0x5c5f66);
  Rgba danger = rgb_hex(0x2b2d31);
  Rgba no_go = rgb_hex(0xc2255c);  ///< hatching, the safety contour, dangers too shallow
  Rgba sounding = rgb_hex(0x5b6b7c);
  Rgba cell_edge = rgb_hex(0x7d8da0);  ///< the cells' coverage outlines and names, faint
};

/// Rectangles of labels already on the map; a label goes where none overlaps.
class LabelPlacer {
 public:
  explicit LabelPlacer(std::size_t max_labels = 400) : max_(max_labels) {}
  /// True (and the box kept) when `box` overlaps no placed box.
  bool place(const PixelRect& box);
  std::size_t placed() const { return boxes_.size(); }

 private:
  std::size_t max_;
  std::vector<PixelRect> boxes_;
};

/// Draws the layer; `depth_color(d)` tints a depth area of DRVAL1 d.
void draw_enc_layer(Canvas& canvas, const ViewTransform& view, const EncLayer& layer, const EncStyle& style,
                    double unit, const std::function<Rgba(double)>& depth_color, LabelPlacer& labels);

}  // namespace deepguide
