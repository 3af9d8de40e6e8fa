#pragma once
// A small drawing layer on Cairo, for charts of the local frame.
//
// Two parts:
//  - ViewTransform maps the local metric frame (x east, y north, metres) to
//    image pixels (column right, row down): north up, one scale for both
//    axes, the world box centred in a pixel rectangle.
//  - Canvas is an image being drawn, in pixel coordinates: PNG or SVG, picked
//    from the output file's extension. It writes through AtomicOutput, so a
//    failed drawing never leaves a half-written file; finish() writes and
//    renames.
// Cairo stays inside the .cpp: this header is installed and consumers of the
// library need no Cairo headers.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

enum class ImageFormat { png, svg };

/// The format for an output path from its extension (.png or .svg, any case).
/// Throws InputError naming the path and the extensions deepguide writes.
ImageFormat image_format_for(const std::string& path);

/// An axis-aligned box in the local frame (m); starts empty.
struct WorldBox {
  Vec2 min{1.0, 1.0};
  Vec2 max{-1.0, -1.0};

  bool empty() const { return min.x() > max.x() || min.y() > max.y(); }
  void extend(const Vec2& p);
  void extend(const WorldBox& other);
  double width() const { return empty() ? 0.0 : max.x() - min.x(); }
  double height() const { return empty() ? 0.0 : max.y() - min.y(); }
  Vec2 centre() const { return 0.5 * (min + max); }
  bool contains(const Vec2& p) const {
    return p.x() >= min.x() && p.x() <= max.x() && p.y() >= min.y() && p.y() <= max.y();
  }
  /// Grows every side by d metres.
  WorldBox padded(double d) const;
};

/// A rectangle in pixels: left column x, top row y.
struct PixelRect {
  double x = 0.0;
  double y = 0.0;
  double width = 0.0;
  double height = 0.0;
};

/// World (local frame, m) -> pixels. North up, equal scale on both axes.
class ViewTransform {
 public:
  ViewTransform() = default;
  /// Fits `world` (non-empty; a zero-size side is allowed if the other is
  /// not) into `frame` as large as it goes, centred.
  ViewTransform(const WorldBox& world, const PixelRect& frame);

  /// Pixel position (column, row) of a world point; rows grow southwards.
  Vec2 to_pixel(const Vec2& world) const;
  /// World point of a pixel position.
  Vec2 to_world(const Vec2& pixel) const;
  /// Pixels per metre, the same along both axes.
  double scale() const { return scale_; }

 private:
  Vec2 world_centre_{0.0, 0.0};
  Vec2 pixel_centre_{0.0, 0.0};
  double scale_ = 1.0;
};

/// Colour with alpha, components in [0, 1].
struct Rgba {
  double r = 0.0;
  double g = 0.0;
  double b = 0.0;
  double a = 1.0;
};
/// Colour from 0xRRGGBB.
Rgba rgb_hex(unsigned hex, double alpha = 1.0);

struct Stroke {
  Rgba color;
  double width = 1.0;        ///< pixels
  std::vector<double> dash;  ///< on/off lengths in pixels; empty = solid
  /// Antialiased edges. Off suits dense hairlines (graphs) in PNGs: they
  /// compress several times better and look the same at a glance.
  bool antialias = true;
};

enum class TextAlign { left, centre, right };

/// Advance width in pixels of `text` in the canvases' sans-serif, without a
/// canvas: for layouts that must know how much room text takes before drawing.
double measure_text_width(const std::string& text, double size_px, bool bold = false);

class Canvas {
 public:
  /// Starts an image of the given size for `path`; the format comes from the
  /// extension. Throws InputError (naming the path) for an unknown extension,
  /// a missing folder, a bad size or when Cairo cannot create the surface.
  Canvas(const std::string& path, int width_px, int height_px);
  ~Canvas();  ///< without finish(), discards the image: no file appears
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  int width() const;
  int height() const;
  ImageFormat format() const;

  void fill_rect(const PixelRect& rect, const Rgba& color);
  void stroke_rect(const PixelRect& rect, const Stroke& stroke);
  /// Restricts drawing to the rectangle until unclip().
  void clip(const PixelRect& rect);
  void unclip();

  /// Fills closed rings with the even-odd rule, so inner rings are holes.
  void fill_rings(const std::vector<std::vector<Vec2>>& rings, const Rgba& color);
  /// Strokes a polyline (closed: back to the first point).
  void stroke_polyline(const std::vector<Vec2>& points, const Stroke& stroke, bool closed = false);
  /// Parallel diagonal lines `spacing_px` apart inside the rings (even-odd, holes left clear).
  void hatch_rings(const std::vector<std::vector<Vec2>>& rings, const Stroke& stroke, double spacing_px);
  /// Strokes many separate segments as one path.
  void stroke_segments(const std::vector<std::pair<Vec2, Vec2>>& segments, const Stroke& stroke);
  /// A closed polygon, filled and/or outlined.
  void shape(const std::vector<Vec2>& points, const std::optional<Rgba>& fill, const std::optional<Stroke>& outline);
  void circle(const Vec2& centre, double radius, const std::optional<Rgba>& fill, const std::optional<Stroke>& outline);

  /// Paints an image of width x height pixels (0xAARRGGBB, premultiplied
  /// alpha, row by row from the top) stretched over `rect`; pixels stay sharp.
  void image(const PixelRect& rect, int width, int height, const std::vector<std::uint32_t>& argb);

  /// Text at `anchor` (the baseline's left end, centre or right end); sans-serif.
  void text(const Vec2& anchor, const std::string& text, double size_px, const Rgba& color,
            TextAlign align = TextAlign::left, bool bold = false);
  /// The same with a halo: an outline of halo_px in halo_color behind the
  /// glyphs keeps labels readable where they cross lines.
  void text_with_halo(const Vec2& anchor, const std::string& text, double size_px, const Rgba& color,
                      const Rgba& halo_color, double halo_px, TextAlign align = TextAlign::left);
  /// Advance width of the text in pixels.
  double text_width(const std::string& text, double size_px, bool bold = false);

  /// Ends the drawing, writes the file and moves it into place. Throws
  /// InputError naming the path when Cairo reports an error.
  void finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace deepguide
