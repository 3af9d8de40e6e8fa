#pragma once
// What every map figure carries besides its content, shared by the route
// chart and the sea chart: a scale bar and a north arrow, and how lengths are
// written on them. Sizes are in design units (at 1200 px wide) times `unit`.

#include <optional>
#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/render/canvas.hpp"

namespace DEEPGUIDE_API deepguide {

struct FurnitureColors {
  Rgba text;        ///< bar, arrow and labels
  Rgba background;  ///< the bar's empty parts, the arrow's light half
  Rgba muted;       ///< the notes under them
};

/// "500 m", "1.5 km".
std::string format_length(double metres);

/// The largest round length (1, 2 or 5 x 10^k m) not above max_length_m (> 0).
double nice_scale_length(double max_length_m);

/// A checkered scale bar with its left end at x, its top at y: the largest
/// round length (nice_scale_length) not longer than max_px, labelled
/// 0 / half / whole, and "scale 1 px = ... m" below.
void draw_scale_bar(Canvas& canvas, double px_per_m, double x, double y, double max_px, double unit,
                    const FurnitureColors& colors);

/// A north arrow whose tip is at (cx, top), turned clockwise by rotate_deg
/// from the image's up (0 = grid north on a north-up map), and a note
/// right-aligned at note_right_x below it.
void draw_north_arrow(Canvas& canvas, double cx, double top, double unit, double rotate_deg, const std::string& note,
                      double note_right_x, const FurnitureColors& colors);

}  // namespace deepguide
