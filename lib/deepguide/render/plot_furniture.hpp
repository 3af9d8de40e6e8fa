#pragma once
// What every plot carries besides its content: axes with round ticks and
// labelled numbers, and a legend. The plot counterpart of map_furniture.hpp;
// sizes are in design units (at 1200 px wide) times `unit`.
//
// Ticks: the step is the smallest 1, 2 or 5 x 10^k that puts at most
// max_ticks ticks on the range ("nice numbers", Heckbert, Graphics Gems 1990);
// the ticks are the step's multiples inside [lo, hi], written with as many
// decimals as the step needs (never "1e+06", never "0.6000000001").
// The y axis title sits above the axis, horizontally: Cairo's toy text API
// draws no rotated text, and a title read without turning the head is no loss.

#include <functional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/render/canvas.hpp"

namespace DEEPGUIDE_API deepguide {

/// Throws InputError unless width_px lies in [kMinImageWidth, kMaxImageWidth]
/// (route_scene.hpp), the widths every figure accepts.
void check_figure_width(int width_px);

/// Appends the three segments of an arrow of `length` px centred at the pixel
/// `c`, along the WORLD direction d (unit; y north, so rows flip).
void add_arrow(std::vector<std::pair<Vec2, Vec2>>& segments, const Vec2& c, const Vec2& d, double length);

/// The figure's title, bold, at the top left of an image width_px wide, its
/// baseline `baseline` design units down; `size` design units high, shrunk to
/// fit when long. Maps use a size and baseline one unit larger than plots.
void draw_figure_title(Canvas& canvas, const std::string& title, int width_px, double unit, const Rgba& color,
                       double size = 21.0, double baseline = 34.0);

/// A linear axis: the data range [lo, hi] drawn from pixel px_lo to px_hi
/// (px_hi < px_lo for a y axis, rows grow downwards).
struct PlotAxis {
  double lo = 0.0;
  double hi = 1.0;
  double px_lo = 0.0;
  double px_hi = 1.0;

  double to_px(double v) const { return px_lo + (v - lo) / (hi - lo) * (px_hi - px_lo); }
};

/// The tick step for `span` (> 0, finite): 1, 2 or 5 x 10^k, at most max_ticks (>= 2) ticks.
double nice_tick_step(double span, int max_ticks);
/// The ticks inside [lo, hi] (lo < hi) at nice_tick_step(hi - lo, max_ticks).
std::vector<double> nice_ticks(double lo, double hi, int max_ticks);
/// A tick value with the decimals that `step` needs ("-5", "0.25", "512300").
std::string format_tick(double value, double step);

struct AxesStyle {
  Rgba text;
  Rgba frame;
  Rgba grid;  ///< alpha 0: no grid lines
};

struct AxesOptions {
  std::string x_title;  ///< under the x tick labels, right-aligned
  std::string y_title;  ///< above the plot, left-aligned
  int max_x_ticks = 10;
  int max_y_ticks = 6;
  bool x_labels = true;  ///< false for the upper panels of a stack sharing one time axis
  bool x_ticks = true;   ///< false for a categorical x axis (box plots): no x grid, ticks or numbers
  /// The y tick labels (value, step); empty: format_tick. A log axis plots
  /// log10 of its values and labels 10^v.
  std::function<std::string(double value, double step)> y_label = {};
};

/// Grid lines, the frame, outward ticks with their numbers and the titles
/// around `plot`.
void draw_axes(Canvas& canvas, const PixelRect& plot, const PlotAxis& x, const PlotAxis& y, const AxesOptions& options,
               double unit, const AxesStyle& style);

/// One legend line: a swatch drawn centred at `mid` (about 30 x 16 design
/// units) and its label.
struct LegendEntry {
  std::string label;
  std::function<void(Canvas&, const Vec2& mid)> swatch;
};

/// Height (pixels) of a legend of `entries` in `columns` columns.
double legend_height(std::size_t entries, int columns, double unit);

/// The entries row by row in `columns` equal columns across `rect`; labels
/// that would run into the next column are shrunk to fit.
void draw_legend(Canvas& canvas, const std::vector<LegendEntry>& entries, const PixelRect& rect, int columns,
                 double unit, const Rgba& text);

}  // namespace deepguide
