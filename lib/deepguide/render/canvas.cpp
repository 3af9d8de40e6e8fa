#include "deepguide/render/canvas.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <numbers>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"

namespace deepguide {

ImageFormat image_format_for(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".png") return ImageFormat::png;
  if (ext == ".svg") return ImageFormat::svg;
  throw InputError(path + ": expected an image file name ending in .png or .svg, got " +
                   (ext.empty() ? std::string("no extension") : "'" + ext + "'"));
}

// ---------------------------------------------------------------- WorldBox

void WorldBox::extend(const Vec2& p) {
  if (empty()) {
    min = max = p;
    return;
  }
  min = min.cwiseMin(p);
  max = max.cwiseMax(p);
}

void WorldBox::extend(const WorldBox& other) {
  if (other.empty()) return;
  extend(other.min);
  extend(other.max);
}

WorldBox WorldBox::padded(double d) const {
  if (empty()) return *this;
  WorldBox out = *this;
  out.min -= Vec2(d, d);
  out.max += Vec2(d, d);
  return out;
}

// ---------------------------------------------------------------- ViewTransform

ViewTransform::ViewTransform(const WorldBox& world, const PixelRect& frame) {
  if (world.empty()) throw InputError("view: expected a non-empty world box to draw");
  const double w = world.width();
  const double h = world.height();
  if (!(w > 0.0 || h > 0.0) || !std::isfinite(w) || !std::isfinite(h)) {
    throw InputError("view: expected a world box with a finite, non-zero extent");
  }
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double sx = w > 0.0 ? frame.width / w : kInf;
  const double sy = h > 0.0 ? frame.height / h : kInf;
  scale_ = std::min(sx, sy);
  world_centre_ = world.centre();
  pixel_centre_ = Vec2(frame.x + 0.5 * frame.width, frame.y + 0.5 * frame.height);
}

Vec2 ViewTransform::to_pixel(const Vec2& world) const {
  const Vec2 d = world - world_centre_;
  return {pixel_centre_.x() + scale_ * d.x(), pixel_centre_.y() - scale_ * d.y()};
}

Vec2 ViewTransform::to_world(const Vec2& pixel) const {
  const Vec2 d = pixel - pixel_centre_;
  return {world_centre_.x() + d.x() / scale_, world_centre_.y() - d.y() / scale_};
}

Rgba rgb_hex(unsigned hex, double alpha) {
  return {((hex >> 16) & 0xff) / 255.0, ((hex >> 8) & 0xff) / 255.0, (hex & 0xff) / 255.0, alpha};
}

// ---------------------------------------------------------------- Canvas

struct Canvas::Impl {
  // Declared first so it is destroyed last: the surface (and its open file)
  // goes before the temporary file is removed.
  AtomicOutput output;
  ImageFormat format;
  int width;
  int height;
  cairo_surface_t* surface = nullptr;
  cairo_t* cr = nullptr;

  Impl(const std::string& path, ImageFormat f, int w, int h) : output(path), format(f), width(w), height(h) {}
  ~Impl() { release(); }

  void release() {
    if (cr != nullptr) cairo_destroy(cr);
    if (surface != nullptr) cairo_surface_destroy(surface);
    cr = nullptr;
    surface = nullptr;
  }

  [[noreturn]] void fail(cairo_status_t status) const {
    throw InputError(output.destination().string() +
                     ": could not write the image (cairo: " + cairo_status_to_string(status) + ")");
  }

  // Fills and text are always antialiased; apply() may turn it off for a stroke.
  void set_color(const Rgba& c) {
    cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_GOOD);
  }

  void apply(const Stroke& s) {
    set_color(s.color);
    cairo_set_line_width(cr, s.width);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, s.dash.empty() ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
    cairo_set_dash(cr, s.dash.empty() ? nullptr : s.dash.data(), static_cast<int>(s.dash.size()), 0.0);
    cairo_set_antialias(cr, s.antialias ? CAIRO_ANTIALIAS_GOOD : CAIRO_ANTIALIAS_NONE);
  }

  // Fills and/or outlines the current path, then clears it.
  void fill_and_outline(const std::optional<Rgba>& fill, const std::optional<Stroke>& outline) {
    if (fill) {
      set_color(*fill);
      cairo_fill_preserve(cr);
    }
    if (outline) {
      apply(*outline);
      cairo_stroke_preserve(cr);
    }
    cairo_new_path(cr);
  }

  void path(const std::vector<Vec2>& points, bool closed) {
    if (points.empty()) return;
    cairo_move_to(cr, points[0].x(), points[0].y());
    for (std::size_t i = 1; i < points.size(); ++i) cairo_line_to(cr, points[i].x(), points[i].y());
    if (closed) cairo_close_path(cr);
  }

  void font(double size, bool bold) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
  }
};

Canvas::Canvas(const std::string& path, int width_px, int height_px) {
  const ImageFormat format = image_format_for(path);
  // Cairo's image surfaces stop at 32767 pixels a side.
  if (width_px < 1 || height_px < 1 || width_px > 32767 || height_px > 32767) {
    throw InputError(path + ": expected an image size of 1 to 32767 pixels a side, got " + std::to_string(width_px) +
                     " x " + std::to_string(height_px));
  }
  impl_ = std::make_unique<Impl>(path, format, width_px, height_px);
  const std::string temp = impl_->output.temp_path().string();
  impl_->surface = format == ImageFormat::png ? cairo_image_surface_create(CAIRO_FORMAT_RGB24, width_px, height_px)
                                              : cairo_svg_surface_create(temp.c_str(), width_px, height_px);
  if (const cairo_status_t s = cairo_surface_status(impl_->surface); s != CAIRO_STATUS_SUCCESS) impl_->fail(s);
  impl_->cr = cairo_create(impl_->surface);
  if (const cairo_status_t s = cairo_status(impl_->cr); s != CAIRO_STATUS_SUCCESS) impl_->fail(s);
  cairo_set_antialias(impl_->cr, CAIRO_ANTIALIAS_GOOD);
  // Text the same on every surface, whatever the process drew before: the
  // surfaces' own font options differ (an SVG surface asks for unhinted
  // metrics), and Cairo's shared font cache then let a PNG drawn after an SVG
  // differ from the same PNG drawn first. One set of options for all.
  cairo_font_options_t* text = cairo_font_options_create();
  cairo_font_options_set_antialias(text, CAIRO_ANTIALIAS_GRAY);
  cairo_font_options_set_hint_style(text, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(text, CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(impl_->cr, text);
  cairo_font_options_destroy(text);
  // An RGB24 surface starts black; every image starts white.
  fill_rect({0.0, 0.0, static_cast<double>(width_px), static_cast<double>(height_px)}, {1.0, 1.0, 1.0, 1.0});
}

Canvas::~Canvas() = default;

int Canvas::width() const { return impl_->width; }
int Canvas::height() const { return impl_->height; }
ImageFormat Canvas::format() const { return impl_->format; }

void Canvas::fill_rect(const PixelRect& r, const Rgba& color) {
  impl_->set_color(color);
  cairo_rectangle(impl_->cr, r.x, r.y, r.width, r.height);
  cairo_fill(impl_->cr);
}

void Canvas::stroke_rect(const PixelRect& r, const Stroke& stroke) {
  impl_->apply(stroke);
  cairo_rectangle(impl_->cr, r.x, r.y, r.width, r.height);
  cairo_stroke(impl_->cr);
}

void Canvas::clip(const PixelRect& r) {
  cairo_save(impl_->cr);
  cairo_rectangle(impl_->cr, r.x, r.y, r.width, r.height);
  cairo_clip(impl_->cr);
}

void Canvas::unclip() { cairo_restore(impl_->cr); }

void Canvas::fill_rings(const std::vector<std::vector<Vec2>>& rings, const Rgba& color) {
  for (const auto& ring : rings) impl_->path(ring, true);
  impl_->set_color(color);
  cairo_set_fill_rule(impl_->cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_fill(impl_->cr);
  cairo_set_fill_rule(impl_->cr, CAIRO_FILL_RULE_WINDING);
}

void Canvas::hatch_rings(const std::vector<std::vector<Vec2>>& rings, const Stroke& stroke, double spacing_px) {
  if (rings.empty() || !(spacing_px > 0.0)) return;
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const auto& ring : rings) {
    for (const Vec2& p : ring) {
      x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y()), x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
    }
  }
  if (!(x1 > x0) || !(y1 > y0)) return;
  cairo_save(impl_->cr);
  for (const auto& ring : rings) impl_->path(ring, true);
  cairo_set_fill_rule(impl_->cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_clip(impl_->cr);
  // Lines at 45 degrees (down-right), `spacing_px` apart, across the rings' box.
  const double span = (x1 - x0) + (y1 - y0);
  for (double c = std::floor((x0 - y1) / spacing_px) * spacing_px; c <= x1 - y0 + spacing_px; c += spacing_px) {
    cairo_move_to(impl_->cr, c + y0, y0);
    cairo_line_to(impl_->cr, c + y0 + span, y0 + span);
  }
  impl_->apply(stroke);
  cairo_stroke(impl_->cr);
  cairo_restore(impl_->cr);
}

void Canvas::stroke_polyline(const std::vector<Vec2>& points, const Stroke& stroke, bool closed) {
  if (points.size() < 2) return;
  impl_->path(points, closed);
  impl_->apply(stroke);
  cairo_stroke(impl_->cr);
}

void Canvas::stroke_segments(const std::vector<std::pair<Vec2, Vec2>>& segments, const Stroke& stroke) {
  if (segments.empty()) return;
  for (const auto& [a, b] : segments) {
    cairo_move_to(impl_->cr, a.x(), a.y());
    cairo_line_to(impl_->cr, b.x(), b.y());
  }
  impl_->apply(stroke);
  cairo_stroke(impl_->cr);
}

void Canvas::shape(const std::vector<Vec2>& points, const std::optional<Rgba>& fill,
                   const std::optional<Stroke>& outline) {
  if (points.size() < 3) return;
  impl_->path(points, true);
  impl_->fill_and_outline(fill, outline);
}

void Canvas::circle(const Vec2& c, double radius, const std::optional<Rgba>& fill,
                    const std::optional<Stroke>& outline) {
  cairo_new_sub_path(impl_->cr);
  cairo_arc(impl_->cr, c.x(), c.y(), radius, 0.0, 2.0 * std::numbers::pi);
  impl_->fill_and_outline(fill, outline);
}

void Canvas::image(const PixelRect& rect, int width, int height, const std::vector<std::uint32_t>& argb) {
  if (width < 1 || height < 1 || argb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw InputError("image: expected " + std::to_string(width) + " x " + std::to_string(height) + " pixels, got " +
                     std::to_string(argb.size()));
  }
  cairo_surface_t* src = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  if (const cairo_status_t s = cairo_surface_status(src); s != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(src);
    impl_->fail(s);
  }
  cairo_surface_flush(src);
  unsigned char* data = cairo_image_surface_get_data(src);
  const int stride = cairo_image_surface_get_stride(src);
  for (int y = 0; y < height; ++y) {
    std::memcpy(data + static_cast<std::ptrdiff_t>(y) * stride, argb.data() + static_cast<std::size_t>(y) * width,
                static_cast<std::size_t>(width) * 4);
  }
  cairo_surface_mark_dirty(src);
  cairo_t* cr = impl_->cr;
  cairo_save(cr);
  cairo_rectangle(cr, rect.x, rect.y, rect.width, rect.height);
  cairo_clip(cr);
  cairo_translate(cr, rect.x, rect.y);
  cairo_scale(cr, rect.width / width, rect.height / height);
  cairo_set_source_surface(cr, src, 0.0, 0.0);
  // Cells are data: no smoothing between them, and no bleeding at the edges.
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
  cairo_pattern_set_extend(cairo_get_source(cr), CAIRO_EXTEND_PAD);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(src);
}

void Canvas::text(const Vec2& anchor, const std::string& text, double size_px, const Rgba& color, TextAlign align,
                  bool bold) {
  if (text.empty()) return;
  impl_->font(size_px, bold);
  cairo_text_extents_t ext;
  cairo_text_extents(impl_->cr, text.c_str(), &ext);
  double x = anchor.x();
  if (align == TextAlign::centre) x -= 0.5 * ext.x_advance;
  if (align == TextAlign::right) x -= ext.x_advance;
  impl_->set_color(color);
  cairo_move_to(impl_->cr, x, anchor.y());
  cairo_show_text(impl_->cr, text.c_str());
  cairo_new_path(impl_->cr);
}

void Canvas::text_with_halo(const Vec2& anchor, const std::string& text, double size_px, const Rgba& color,
                            const Rgba& halo_color, double halo_px, TextAlign align) {
  if (text.empty()) return;
  impl_->font(size_px, false);
  cairo_text_extents_t ext;
  cairo_text_extents(impl_->cr, text.c_str(), &ext);
  double x = anchor.x();
  if (align == TextAlign::centre) x -= 0.5 * ext.x_advance;
  if (align == TextAlign::right) x -= ext.x_advance;
  cairo_move_to(impl_->cr, x, anchor.y());
  cairo_text_path(impl_->cr, text.c_str());
  impl_->apply(Stroke{halo_color, 2.0 * halo_px, {}});
  cairo_stroke_preserve(impl_->cr);
  impl_->set_color(color);
  cairo_fill(impl_->cr);
}

double measure_text_width(const std::string& text, double size_px, bool bold) {
  // A 1 x 1 surface measures as any other: text extents do not depend on it.
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
  cairo_t* cr = cairo_create(surface);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size_px);
  cairo_text_extents_t ext{};
  cairo_text_extents(cr, text.c_str(), &ext);
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  return ext.x_advance;
}

double Canvas::text_width(const std::string& text, double size_px, bool bold) {
  impl_->font(size_px, bold);
  cairo_text_extents_t ext;
  cairo_text_extents(impl_->cr, text.c_str(), &ext);
  return ext.x_advance;
}

void Canvas::finish() {
  Impl& im = *impl_;
  if (const cairo_status_t s = cairo_status(im.cr); s != CAIRO_STATUS_SUCCESS) im.fail(s);
  cairo_destroy(im.cr);
  im.cr = nullptr;
  if (im.format == ImageFormat::png) {
    cairo_surface_flush(im.surface);
    const std::string temp = im.output.temp_path().string();
    if (const cairo_status_t s = cairo_surface_write_to_png(im.surface, temp.c_str()); s != CAIRO_STATUS_SUCCESS) {
      im.fail(s);
    }
  } else {
    cairo_surface_finish(im.surface);  // writes the rest of the SVG and closes the file
  }
  if (const cairo_status_t s = cairo_surface_status(im.surface); s != CAIRO_STATUS_SUCCESS) im.fail(s);
  im.release();
  im.output.commit();
}

}  // namespace deepguide
