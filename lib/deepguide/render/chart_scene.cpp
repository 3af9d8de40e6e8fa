#include "deepguide/render/chart_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <set>

#include "deepguide/charts/bathymetry.hpp"
#include "deepguide/charts/chart_info.hpp"
#include "deepguide/charts/chart_obstacles.hpp"
#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/charts/no_go.hpp"
#include "deepguide/charts/prepared_chart.hpp"
#include "deepguide/charts/raster_depths.hpp"
#include "deepguide/charts/s57_chart.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/render/enc_layer.hpp"
#include "deepguide/render/map_furniture.hpp"
#include "deepguide/render/plot_furniture.hpp"  // draw_figure_title
#include "deepguide/render/route_scene.hpp"     // kMinImageWidth, kMaxImageWidth
#include "deepguide/world/frame_scale.hpp"

namespace deepguide {
namespace {

constexpr double kPi = std::numbers::pi;

// Design units (at 1200 px wide), as in the route chart.
constexpr double kSide = 24.0;
constexpr double kTitleBand = 52.0;
constexpr double kFooter = 110.0;
constexpr double kScaleBarMax = 250.0;
constexpr double kLegendX = 330.0;
constexpr int kTargetBands = 7;

std::uint32_t pack(const Rgba& c) {
  auto byte = [](double v) { return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
  return 0xff000000u | byte(c.r) << 16 | byte(c.g) << 8 | byte(c.b);
}

// The overlay's legend entries: a 22-unit line, its label, and a gap.
double legend_entry_width(const std::string& label, double u) {
  return 28.0 * u + measure_text_width(label, 13.0 * u) + 18.0 * u;
}

// Where each row of the overlay's legend starts (indices into `lines`): as
// many entries a row as fit between the legend's left edge and the side.
std::vector<std::size_t> overlay_legend_rows(const std::vector<ChartRenderOptions::LegendLine>& lines, int width_px,
                                             double u) {
  std::vector<std::size_t> rows;
  const double room = width_px - (kLegendX + kSide) * u;
  double used = room;  // a first entry always starts a row
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const double w = legend_entry_width(lines[k].label, u);
    if (used + w - 18.0 * u > room) {
      rows.push_back(k);
      used = 0.0;
    }
    used += w;
  }
  return rows;
}

// Round band step (1, 2, 2.5 or 5 x 10^k) giving about kTargetBands bands over [lo, hi].
std::vector<double> band_edges(double lo, double hi) {
  if (!(hi > lo)) hi = lo + 1.0;
  const double raw = (hi - lo) / kTargetBands;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10.0 * decade;
  for (const double f : {1.0, 2.0, 2.5, 5.0}) {
    if (f * decade >= raw * (1.0 - 1e-12)) {
      step = f * decade;
      break;
    }
  }
  const double first = std::floor(lo / step) * step;
  std::vector<double> edges{first};
  while (edges.back() < hi - 1e-9) edges.push_back(edges.back() + step);
  if (edges.size() < 2) edges.push_back(first + step);
  return edges;
}

struct RasterSource {
  std::string path;
  BathymetryInfo info;
  BathymetryOptions read;  ///< the assumed CRS of a raster without one
};

// Box in the local frame around a raster.
WorldBox raster_box(const RasterSource& r, const LocalFrame& frame) {
  WorldBox box;
  for (const Vec2& p : raster_outline(r.path, r.read, r.info, frame)) box.extend(p);
  return box;
}

struct Shading {
  std::vector<double> edges;
  std::vector<std::uint32_t> colors;
  std::uint32_t land = 0, nodata = 0;

  std::uint32_t color(double depth) const {
    if (depth <= 0.0 || colors.empty()) return land;
    const auto it = std::upper_bound(edges.begin(), edges.end(), depth);
    const std::size_t band = it == edges.begin() ? 0 : static_cast<std::size_t>(it - edges.begin()) - 1;
    return colors[std::min(band, colors.size() - 1)];
  }
};

// Paints one raster into the map image (width x height pixels over `map`),
// the depth under each pixel's centre.
void shade_raster(std::vector<std::uint32_t>& image, std::vector<std::uint32_t>& land, int width, int height,
                  const PixelRect& map, const ViewTransform& view, const LocalFrame& frame, const RasterSource& source,
                  const Shading& shading) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<Vec2> points(n);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      points[static_cast<std::size_t>(j) * width + i] =
          view.to_world({map.x + (i + 0.5) * map.width / width, map.y + (j + 0.5) * map.height / height});
    }
  }
  const RasterDepths d = sample_raster_depths(source.path, source.read, frame, points, width, height);
  for (std::size_t k = 0; k < n; ++k) {
    if (d.state[k] == RasterDepths::State::outside) continue;
    const bool no_data = d.state[k] == RasterDepths::State::no_data;
    image[k] = no_data ? shading.nodata : shading.color(d.depth_m[k]);
    land[k] = no_data || d.depth_m[k] <= 0.0 ? image[k] : 0u;
  }
}

struct Scene {
  explicit Scene(const ChartRenderOptions& o) : options(o) {}
  const ChartRenderOptions& options;
  const ChartStyle& style = options.style;
  std::vector<RasterSource> rasters;
  std::vector<std::string> hazard_files;
  std::vector<std::string> enc_charts;  // S-57 cells, folders of cells, a prepared chart
  std::optional<EncLayer> enc;
  ObstacleSet hazards;
  ObstacleSet obstacles;
  std::set<std::string> blocking;  // ids of hazards and obstacles the vehicle cannot pass over
  std::vector<PolygonObstacle> no_go;
  bool has_depth = false;
};

struct Painter {
  Canvas& canvas;
  const Scene& scene;
  const ChartLayout& layout;
  const LocalFrame& frame;
  const ChartStyle& style = scene.style;
  double u = layout.unit;

  Vec2 px(const Vec2& w) const { return layout.view.to_pixel(w); }

  // The depth band's tint of a charted depth d >= 0 (the shallowest band at 0).
  Rgba band_color(double d) const {
    if (layout.band_colors.empty()) return style.shallow;
    const auto it = std::upper_bound(layout.band_edges.begin(), layout.band_edges.end(), d);
    const std::size_t band =
        it == layout.band_edges.begin() ? 0 : static_cast<std::size_t>(it - layout.band_edges.begin()) - 1;
    return layout.band_colors[std::min(band, layout.band_colors.size() - 1)];
  }

  std::vector<std::vector<Vec2>> polygon_px(const BgPolygon& p) const {
    std::vector<std::vector<Vec2>> rings;
    auto ring = [&](const auto& r) {
      std::vector<Vec2> out;
      for (const BgPoint& q : r) out.push_back(px(to_eigen(q)));
      rings.push_back(std::move(out));
    };
    ring(p.outer());
    for (const auto& inner : p.inners()) ring(inner);
    return rings;
  }

  std::vector<Vec2> ellipse_px(const Ellipse& e) const {
    const double perimeter_px = 2.0 * kPi * e.a * layout.view.scale();
    const int n = std::clamp(static_cast<int>(std::ceil(perimeter_px / 3.0)), 36, 2048);
    std::vector<Vec2> out;
    for (int i = 0; i < n; ++i) out.push_back(px(e.point_at(2.0 * kPi * i / n)));
    return out;
  }

  Stroke danger_line(const std::string& id) const {
    const bool blocks = !scene.has_depth || scene.blocking.count(id) > 0;
    return {blocks && scene.has_depth ? style.no_go
            : blocks                  ? style.text
                                      : style.passable,
            1.3 * u,
            {2.0 * u, 2.5 * u}};
  }

  // The water image, and land and no-data cells alone (transparent elsewhere)
  // to paint again over the no-go fill: land needs no red to say it is no-go.
  int image_w() const { return std::max(1, static_cast<int>(std::lround(layout.map.width))); }
  int image_h() const { return std::max(1, static_cast<int>(std::lround(layout.map.height))); }

  void map(const Shading& sh) {
    canvas.fill_rect(layout.map, style.sea);
    canvas.clip(layout.map);
    const int w = image_w(), h = image_h();
    std::vector<std::uint32_t> water, land;
    if (!scene.rasters.empty()) {
      water.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), pack(style.sea));
      land.assign(water.size(), 0u);
      for (const RasterSource& r : scene.rasters) {
        shade_raster(water, land, w, h, layout.map, layout.view, frame, r, sh);
      }
      canvas.image(layout.map, w, h, water);
    }
    for (const PolygonObstacle& p : scene.no_go) {
      canvas.fill_rings(polygon_px(p.footprint), {style.no_go.r, style.no_go.g, style.no_go.b, 0.28});
    }
    if (!land.empty()) canvas.image(layout.map, w, h, land);
    if (scene.enc) {
      LabelPlacer placer;
      draw_enc_layer(
          canvas, layout.view, *scene.enc, EncStyle{}, u, [&](double d) { return band_color(d); }, placer);
    }
    for (const PolygonObstacle& p : scene.no_go) {
      for (const auto& ring : polygon_px(p.footprint)) {
        canvas.stroke_polyline(ring, Stroke{style.no_go, 1.2 * u, {}}, true);
      }
    }
    auto draw = [&](const ObstacleSet& set, const Rgba& fill) {
      for (const PolygonObstacle& p : set.polygons) {
        const auto rings = polygon_px(p.footprint);
        canvas.fill_rings(rings, {fill.r, fill.g, fill.b, 0.15});
        for (const auto& ring : rings) canvas.stroke_polyline(ring, danger_line(p.id), true);
      }
      for (const EllipticCylinder& c : set.ellipses) {
        const Vec2 centre = px(c.footprint.centre);
        // Small hazards would vanish: a danger circle a few pixels out marks them.
        const double r = std::max(c.footprint.a * layout.view.scale() + 4.0 * u, 7.0 * u);
        canvas.circle(centre, r, Rgba{1.0, 1.0, 1.0, 0.25}, danger_line(c.id));
        canvas.fill_rings({ellipse_px(c.footprint)}, fill);
        canvas.circle(centre, 1.6 * u, fill, std::nullopt);
      }
    };
    draw(scene.hazards, style.hazard);
    draw(scene.obstacles, style.obstacle);
    labels(scene.hazards, style.hazard);
    labels(scene.obstacles, style.obstacle);
    if (scene.options.overlay) scene.options.overlay(canvas, layout.view, u);
    canvas.unclip();
    canvas.stroke_rect(layout.map, Stroke{style.frame, 1.0 * u, {}});
  }

  void labels(const ObstacleSet& set, const Rgba& color) {
    const Rgba halo{1.0, 1.0, 1.0, 0.85};
    for (const EllipticCylinder& c : set.ellipses) {
      const double r = std::max(c.footprint.a * layout.view.scale() + 4.0 * u, 7.0 * u);
      canvas.text_with_halo(px(c.footprint.centre) + Vec2(r + 3.0 * u, 4.0 * u), c.id, 11.5 * u, color, halo, 2.5 * u);
    }
    for (const PolygonObstacle& p : set.polygons) {
      WorldBox box;
      for (const BgPoint& q : p.footprint.outer()) box.extend(to_eigen(q));
      canvas.text_with_halo(px(box.centre()) + Vec2(0.0, 4.0 * u), p.id, 11.5 * u, color, halo, 2.5 * u,
                            TextAlign::centre);
    }
  }

  void title(const std::string& text) { draw_figure_title(canvas, text, layout.width, u, style.text, 22.0, 35.0); }

  FurnitureColors furniture() const { return {style.text, style.background, style.frame}; }

  void legend(const Shading& sh) {
    double x = kLegendX * u;
    const double size = 13.0 * u;
    if (!sh.edges.empty()) {
      const double y = layout.footer.y + 22.0 * u;
      canvas.text({x, y + 12.0 * u}, "depth m", size, style.text);
      x += canvas.text_width("depth m", size) + 10.0 * u;
      const double bw = std::min(38.0 * u, 300.0 * u / static_cast<double>(sh.colors.size()));
      for (std::size_t i = 0; i < layout.band_colors.size(); ++i) {
        canvas.fill_rect({x + bw * i, y, bw, 16.0 * u}, layout.band_colors[i]);
      }
      canvas.stroke_rect({x, y, bw * layout.band_colors.size(), 16.0 * u}, Stroke{style.frame, 1.0 * u, {}});
      for (std::size_t i = 0; i < sh.edges.size(); ++i) {
        canvas.text({x + bw * i, y + 30.0 * u}, general(sh.edges[i]), 11.5 * u, style.text, TextAlign::centre);
      }
    }
    struct Entry {
      Rgba fill;
      std::optional<Stroke> outline;
      std::string label;
    };
    std::vector<Entry> entries;
    if (!scene.rasters.empty()) {
      entries.push_back({style.land, Stroke{style.frame, 1.0 * u, {}}, "land"});
      entries.push_back({style.nodata, Stroke{style.frame, 1.0 * u, {}}, "no data"});
    }
    if (scene.has_depth && !scene.rasters.empty()) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "no-go at %g m (+%g m)", options_depth(), scene.options.clearance_m);
      entries.push_back({{style.no_go.r, style.no_go.g, style.no_go.b, 0.30}, Stroke{style.no_go, 1.2 * u, {}}, buf});
    }
    if (scene.enc) {
      const EncStyle es;
      entries.push_back({es.drying, Stroke{style.frame, 1.0 * u, {}}, "drying"});
      entries.push_back({es.land, Stroke{es.land_edge, 1.0 * u, {}}, "land"});
      if (scene.enc->no_go) {
        char buf[120];
        std::snprintf(buf, sizeof buf, "no-go and its edge at %g m (+%g m, zones of confidence)", options_depth(),
                      scene.options.clearance_m);
        entries.push_back({{es.no_go.r, es.no_go.g, es.no_go.b, 0.25}, Stroke{es.no_go, 1.6 * u, {}}, buf});
      }
    }
    if (!scene.hazards.empty()) entries.push_back({style.hazard, std::nullopt, "hazard"});
    if (!scene.obstacles.empty()) entries.push_back({style.obstacle, std::nullopt, "obstacle"});
    double ex = kLegendX * u;
    const double ey = layout.footer.y + 74.0 * u;
    for (const Entry& e : entries) {
      canvas.shape({{ex, ey}, {ex + 22.0 * u, ey}, {ex + 22.0 * u, ey + 14.0 * u}, {ex, ey + 14.0 * u}}, e.fill,
                   e.outline);
      canvas.text({ex + 28.0 * u, ey + 12.0 * u}, e.label, size, style.text);
      ex += 28.0 * u + canvas.text_width(e.label, size) + 18.0 * u;
    }
    const std::vector<ChartRenderOptions::LegendLine>& lines = scene.options.overlay_legend;
    const std::vector<std::size_t> rows = overlay_legend_rows(lines, layout.width, u);
    for (std::size_t row = 0; row < rows.size(); ++row) {
      double lx = kLegendX * u;
      const double ly = ey + 24.0 * u * static_cast<double>(row + 1);
      const std::size_t end = row + 1 < rows.size() ? rows[row + 1] : lines.size();
      for (std::size_t k = rows[row]; k < end; ++k) {
        Stroke stroke{lines[k].color, lines[k].width_px * u, {}};
        if (lines[k].dashed) stroke.dash = {6.0 * u, 4.0 * u};
        canvas.stroke_polyline({{lx, ly + 7.0 * u}, {lx + 22.0 * u, ly + 7.0 * u}}, stroke);
        canvas.text({lx + 28.0 * u, ly + 12.0 * u}, lines[k].label, size, style.text);
        lx += legend_entry_width(lines[k].label, u);
      }
    }
  }

  double options_depth() const { return scene.options.depth_m; }

  void north_arrow() {
    const double t = layout.true_north_deg;
    char buf[80];
    std::snprintf(buf, sizeof buf, "true north (%.1f\u00b0 %s of grid)", std::abs(t), t < 0.0 ? "W" : "E");
    draw_north_arrow(canvas, layout.width - kSide * u - 60.0 * u, layout.footer.y + 24.0 * u, u, t, buf,
                     layout.width - kSide * u, furniture());
  }
};

std::string default_title(const ChartRenderOptions& o, const std::string& frame_id) {
  std::string names;
  for (const std::string& f : o.charts)
    names += (names.empty() ? "" : ", ") + std::filesystem::path(f).filename().string();
  std::string t = names + "  (" + frame_id + ")";
  if (!std::isnan(o.depth_m)) t += ", no-go at " + general(o.depth_m) + " m";
  return t;
}

}  // namespace

Rgba depth_band_color(const ChartStyle& style, std::size_t i, std::size_t n) {
  const double f = n > 1 ? static_cast<double>(i) / static_cast<double>(n - 1) : 0.0;
  // Slightly faster darkening at first: the shallow bands, where it matters, stay apart.
  const double g = std::pow(f, 0.85);
  return {style.shallow.r + g * (style.deep.r - style.shallow.r),
          style.shallow.g + g * (style.deep.g - style.shallow.g),
          style.shallow.b + g * (style.deep.b - style.shallow.b), 1.0};
}

ChartLayout render_chart(const ChartRenderOptions& options, const std::string& path) {
  image_format_for(path);  // the cheapest mistake first
  if (options.width_px < kMinImageWidth || options.width_px > kMaxImageWidth) {
    throw InputError("`width_px`: expected " + std::to_string(kMinImageWidth) + " to " +
                     std::to_string(kMaxImageWidth) + " pixels, got " + std::to_string(options.width_px));
  }
  if (!std::isnan(options.depth_m) && (!std::isfinite(options.depth_m) || options.depth_m < 0.0)) {
    throw InputError("`depth_m`: expected an operating depth >= 0 m, got " + general(options.depth_m));
  }
  if (!std::isfinite(options.clearance_m) || options.clearance_m < 0.0) {
    throw InputError("`clearance_m`: expected a vertical clearance >= 0 m, got " + general(options.clearance_m));
  }
  if (options.charts.empty()) throw InputError("render chart: expected at least one chart file");

  Scene scene(options);
  scene.has_depth = !std::isnan(options.depth_m);
  for (const std::string& f : options.charts) {
    if (names_enc(f) || is_prepared_chart(f)) {
      scene.enc_charts.push_back(f);
      continue;
    }
    switch (chart_kind(f)) {
      case ChartKind::raster: {
        BathymetryOptions read;
        read.assumed_crs = options.source_crs;
        scene.rasters.push_back({f, inspect_bathymetry(f, read), read});
        break;
      }
      case ChartKind::s57: scene.enc_charts.push_back(f); break;
      case ChartKind::vector: scene.hazard_files.push_back(f); break;
    }
  }

  // One local frame for everything: the user's, else the first chart's UTM zone.
  const LocalFrame frame = charts_frame(options.charts, options.local_crs, options.source_crs);
  const ObstacleReadOptions read{frame.wkt(), ""};
  if (!scene.hazard_files.empty()) scene.hazards = load_obstacles(scene.hazard_files, read).obstacles;
  if (!scene.enc_charts.empty()) {
    scene.enc = read_enc_layer(scene.enc_charts, frame, options.depth_m, options.clearance_m, options.chart_options);
  }
  if (!options.obstacles.empty()) scene.obstacles = load_obstacles(options.obstacles, read).obstacles;
  if (scene.has_depth) {
    for (const ObstacleSet* set : {&scene.hazards, &scene.obstacles}) {
      ObstacleSet left = *set;
      remove_passable(left, options.depth_m, options.clearance_m);
      for (const auto& c : left.ellipses) scene.blocking.insert(c.id);
      for (const auto& p : left.polygons) scene.blocking.insert(p.id);
    }
    NoGoOptions n;
    n.operating_depth_m = options.depth_m;
    n.vertical_clearance_m = options.clearance_m;
    for (const RasterSource& r : scene.rasters) {
      n.bathymetry = r.read;
      NoGoArea a = compute_no_go(r.path, frame, n);
      for (auto& p : a.polygons) scene.no_go.push_back(std::move(p));
    }
  }

  // What the map shows: the rasters, the hazards and the obstacles.
  WorldBox content;
  for (const RasterSource& r : scene.rasters) content.extend(raster_box(r, frame));
  if (scene.enc) content.extend(scene.enc->box());
  for (const ObstacleSet* set : {&scene.hazards, &scene.obstacles}) {
    for (const auto& c : set->ellipses) {
      content.extend(c.footprint.centre - Vec2(c.footprint.a, c.footprint.a));
      content.extend(c.footprint.centre + Vec2(c.footprint.a, c.footprint.a));
    }
    for (const auto& p : set->polygons) {
      for (const BgPoint& q : p.footprint.outer()) content.extend(to_eigen(q));
    }
  }
  if (content.empty() || !(content.width() > 0.0 || content.height() > 0.0)) {
    throw InputError(options.charts.front() + ": expected something to draw, got an empty chart");
  }

  ChartLayout l;
  l.frame_id = frame.id();
  l.extent = !options.extent.empty()               ? options.extent
             : scene.rasters.empty() && !scene.enc ? content.padded(0.05 * std::max(content.width(), content.height()))
                                                   : content;
  l.width = options.width_px;
  l.unit = options.width_px / 1200.0;
  const double u = l.unit;
  l.map = {kSide * u, kTitleBand * u, options.width_px - 2.0 * kSide * u, 0.0};
  const double aspect = std::clamp(l.extent.height() / std::max(l.extent.width(), 1e-9), 0.45, 1.5);
  l.map.height = std::round(l.map.width * aspect);
  // A row of 24 for each row of the overlay's legend, and 2 under the last.
  const std::size_t rows = overlay_legend_rows(options.overlay_legend, options.width_px, u).size();
  const double footer = kFooter + (rows == 0 ? 0.0 : 2.0 + 24.0 * static_cast<double>(rows));
  l.footer = {0.0, l.map.y + l.map.height, static_cast<double>(options.width_px), footer * u};
  l.height = static_cast<int>(std::ceil(l.footer.y + l.footer.height));
  l.view = ViewTransform(l.extent, l.map);
  l.true_north_deg = 90.0 - frame.true_north_angle(l.extent.centre()) * 180.0 / kPi;
  l.no_go_polygons =
      scene.no_go.size() + (scene.enc && scene.enc->no_go ? scene.enc->no_go->obstacles.polygons.size() : 0);
  l.hazards = scene.hazards.size() + (scene.enc ? scene.enc->dangers.size() : 0);

  Shading sh;
  sh.land = pack(options.style.land);
  sh.nodata = pack(options.style.nodata);
  if (scene.enc && scene.rasters.empty() && scene.enc->max_depth_m > 0.0) {
    sh.edges = band_edges(0.0, scene.enc->max_depth_m);
    for (std::size_t i = 0; i + 1 < sh.edges.size(); ++i) {
      l.band_colors.push_back(depth_band_color(options.style, i, sh.edges.size() - 1));
      sh.colors.push_back(pack(l.band_colors.back()));
    }
    l.band_edges = sh.edges;
  }
  if (!scene.rasters.empty()) {
    double lo = INFINITY, hi = -INFINITY;
    for (const RasterSource& r : scene.rasters) {
      if (std::isnan(r.info.min_depth_m)) continue;
      lo = std::min(lo, std::max(0.0, r.info.min_depth_m));
      hi = std::max(hi, r.info.max_depth_m);
    }
    if (hi > 0.0) {
      sh.edges = band_edges(lo, hi);
      for (std::size_t i = 0; i + 1 < sh.edges.size(); ++i) {
        l.band_colors.push_back(depth_band_color(options.style, i, sh.edges.size() - 1));
        sh.colors.push_back(pack(l.band_colors.back()));
      }
      l.band_edges = sh.edges;
    }
  }

  Canvas canvas(path, l.width, l.height);
  canvas.fill_rect({0.0, 0.0, static_cast<double>(l.width), static_cast<double>(l.height)}, options.style.background);
  Painter painter{canvas, scene, l, frame, options.style, l.unit};
  painter.map(sh);
  painter.title(options.title.empty() ? default_title(options, l.frame_id) : options.title);
  draw_scale_bar(canvas, l.view.scale(), kSide * u, l.footer.y + 44.0 * u, kScaleBarMax * u, u, painter.furniture());
  painter.legend(sh);
  painter.north_arrow();
  canvas.finish();
  return l;
}

}  // namespace deepguide
