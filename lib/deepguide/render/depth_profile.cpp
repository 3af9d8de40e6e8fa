#include "deepguide/render/depth_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>

#include "deepguide/core/error.hpp"
#include "deepguide/render/plot_furniture.hpp"

namespace deepguide {
namespace {

constexpr double kTitleBand = 52.0;
constexpr double kAxisTitle = 22.0;
constexpr double kPlot = 420.0;
constexpr double kLeft = 80.0;
constexpr double kRight = 24.0;
constexpr double kNumbers = 52.0;
constexpr double kBottom = 10.0;
constexpr int kLegendColumns = 3;
constexpr std::size_t kLegendEntries = 6;

const Rgba kText = rgb_hex(0x212529);
const Rgba kFrame = rgb_hex(0x5c636a);
const Rgba kFloor = rgb_hex(0x8d6e4f);
const Rgba kObstacle = rgb_hex(0xc92a2a);
const Rgba kRoute = rgb_hex(0x1c3d8f);
const Rgba kBand = rgb_hex(0x2b8a3e);
constexpr std::uint32_t kFreeCell = 0xffeef4fau, kFreeEdge = 0xffc3d3e3u;
constexpr std::uint32_t kOccupiedCell = 0xffd5d9deu, kOccupiedEdge = 0xffb3b9c0u, kOutside = 0xffffffffu;

Stroke route_stroke(double u) { return {kRoute, 2.6 * u, {}}; }
Stroke clearance_stroke(const Rgba& c, double u) { return {c, 1.2 * u, {5.0 * u, 3.0 * u}}; }

// The cells the section cuts, one pixel at a time: the leaf under each
// pixel, its edges where the leaf changes from the pixel above or left.
std::vector<std::uint32_t> section_pixels(const CellTree<3>& tree, const std::vector<Vec2>& column_points,
                                          const DepthProfileLayout& l, int rows) {
  const int cols = static_cast<int>(column_points.size());
  std::vector<std::uint32_t> pixels(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows), kOutside);
  std::vector<std::size_t> above(static_cast<std::size_t>(cols), std::numeric_limits<std::size_t>::max());
  for (int r = 0; r < rows; ++r) {
    const double depth = l.depth_top_m + (l.depth_bottom_m - l.depth_top_m) * (r + 0.5) / rows;
    std::size_t left = std::numeric_limits<std::size_t>::max();
    for (int c = 0; c < cols; ++c) {
      const Vec2& p = column_points[static_cast<std::size_t>(c)];
      const std::optional<std::size_t> leaf = tree.locate(Vec3(p.x(), p.y(), depth));
      const std::size_t id = leaf ? *leaf : std::numeric_limits<std::size_t>::max();
      if (leaf) {
        const bool free = tree.leaves()[*leaf].state == CellState::free;
        const bool edge = id != left || id != above[static_cast<std::size_t>(c)];
        pixels[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c)] =
            free ? (edge ? kFreeEdge : kFreeCell) : (edge ? kOccupiedEdge : kOccupiedCell);
      }
      left = id;
      above[static_cast<std::size_t>(c)] = id;
    }
  }
  return pixels;
}

// Obstacles whose zone the track crosses: where, along the track (as column
// runs), the track is within the margin of the footprint.
std::map<std::size_t, std::vector<std::pair<int, int>>> crossed_runs(const ObstacleField& field,
                                                                     const std::vector<Vec2>& column_points) {
  const int cols = static_cast<int>(column_points.size());
  std::map<std::size_t, std::vector<std::pair<int, int>>> crossed;  // obstacle -> column runs
  for (int c = 0; c < cols; ++c) {
    const Vec2& p = column_points[static_cast<std::size_t>(c)];
    for (std::size_t i : field.near(p, p, field.margin())) {
      if (field.distance_to(i, p) >= field.margin()) continue;
      auto& runs = crossed[i];
      if (!runs.empty() && runs.back().second == c - 1)
        runs.back().second = c;
      else
        runs.emplace_back(c, c);
    }
  }
  return crossed;
}

std::vector<LegendEntry> legend_entries(const DepthPlan& plan, double u) {
  const double top_cell = plan.min_cell.z(), width_cell = plan.min_cell.x();
  char cells[96];
  std::snprintf(cells, sizeof cells, "octree cells cut (smallest %.2f m high, %.2f m wide)", top_cell, width_cell);
  return {
      {"route, steepest leg " + std::to_string(static_cast<int>(std::lround(plan.check.steepest_deg))) + "\u00b0",
       [u](Canvas& c, const Vec2& m) {
         c.stroke_polyline({m - Vec2(15 * u, 0), m + Vec2(15 * u, 0)}, route_stroke(u));
       }},
      {"sea floor, and its clearance",
       [u](Canvas& c, const Vec2& m) {
         c.fill_rect({m.x() - 15 * u, m.y() - 2 * u, 30 * u, 8 * u}, kFloor);
         c.stroke_polyline({m - Vec2(15 * u, 5 * u), m + Vec2(15 * u, -5 * u)}, clearance_stroke(kFloor, u));
       }},
      {"obstacle, and its top less the clearance",
       [u](Canvas& c, const Vec2& m) {
         c.fill_rect({m.x() - 15 * u, m.y() - 3 * u, 30 * u, 10 * u},
                     Rgba{kObstacle.r, kObstacle.g, kObstacle.b, 0.45});
         c.stroke_polyline({m - Vec2(15 * u, 5 * u), m + Vec2(15 * u, -5 * u)}, clearance_stroke(kObstacle, u));
       }},
      {"depth band",
       [u](Canvas& c, const Vec2& m) {
         c.stroke_polyline({m - Vec2(15 * u, 0), m + Vec2(15 * u, 0)}, clearance_stroke(kBand, u));
       }},
      {cells,
       [u](Canvas& c, const Vec2& m) {
         c.fill_rect({m.x() - 15 * u, m.y() - 7 * u, 30 * u, 14 * u}, rgb_hex(0xeef4fa));
         c.stroke_rect({m.x() - 15 * u, m.y() - 7 * u, 30 * u, 14 * u}, Stroke{rgb_hex(0xc3d3e3), 1.0 * u, {}});
       }},
      {"occupied cells",
       [u](Canvas& c, const Vec2& m) {
         c.fill_rect({m.x() - 15 * u, m.y() - 7 * u, 30 * u, 14 * u}, rgb_hex(0xd5d9de));
       }},
  };
}

}  // namespace

DepthProfileLayout render_depth_profile(const DepthPlan& plan, const std::string& title, const std::string& path,
                                        int width_px) {
  image_format_for(path);
  const Route& route = plan.result.route;
  if (!plan.result.found || route.points.size() < 2 || route.depth_m.size() != route.points.size() || !plan.graph ||
      !plan.volume) {
    throw InputError(path + ": depth profile: expected a route planned in depth");
  }
  try {
    check_figure_width(width_px);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  const WaterVolume& volume = *plan.volume;
  const VolumeOptions& band = volume.options();
  DepthProfileLayout l;
  l.width = width_px;
  l.unit = width_px / 1200.0;
  const double u = l.unit;
  Route track = route;
  track.depth_m.clear();
  l.along_m = track.length();
  // The depth axis: the band's top to below the deepest of the route and the floor under it.
  double deepest = *std::max_element(route.depth_m.begin(), route.depth_m.end());
  const int samples = 400;
  for (int k = 0; k <= samples; ++k) {
    if (volume.floor() != nullptr)
      deepest = std::max(deepest, volume.floor()->depth_at(track.point_at(l.along_m * k / samples)));
  }
  const double step = nice_tick_step(std::max(deepest, 1.0) * 1.05, 7);
  l.depth_top_m = 0.0;
  l.depth_bottom_m = std::ceil(deepest * 1.05 / step) * step;
  const PixelRect plot{kLeft * u, (kTitleBand + kAxisTitle) * u, width_px - (kLeft + kRight) * u, kPlot * u};
  const PlotAxis x{0.0, l.along_m, plot.x, plot.x + plot.width};
  const PlotAxis y{l.depth_top_m, l.depth_bottom_m, plot.y, plot.y + plot.height};
  l.exaggeration = (plot.height / (l.depth_bottom_m - l.depth_top_m)) / (plot.width / l.along_m);
  const PixelRect legend{plot.x, plot.y + plot.height + kNumbers * u, plot.width,
                         legend_height(kLegendEntries, kLegendColumns, u)};
  l.height = static_cast<int>(std::ceil(legend.y + legend.height + kBottom * u));

  Canvas canvas(path, l.width, l.height);
  canvas.fill_rect({0.0, 0.0, static_cast<double>(l.width), static_cast<double>(l.height)}, rgb_hex(0xffffff));
  char exaggeration[64];
  std::snprintf(exaggeration, sizeof exaggeration, ", vertical exaggeration \u00d7%.0f", l.exaggeration);
  draw_figure_title(canvas, (title.empty() ? std::string("Depth profile") : title) + exaggeration, l.width, u, kText);

  // The cells the section cuts, one column per pixel.
  const int cols = static_cast<int>(std::ceil(plot.width)), rows = static_cast<int>(std::ceil(plot.height));
  std::vector<Vec2> column_points;
  for (int c = 0; c < cols; ++c) column_points.push_back(track.point_at(l.along_m * (c + 0.5) / cols));
  const std::vector<std::uint32_t> pixels = section_pixels(plan.graph->tree(), column_points, l, rows);
  canvas.image({plot.x, plot.y, static_cast<double>(cols), static_cast<double>(rows)}, cols, rows, pixels);
  canvas.clip(plot);

  // Band limits.
  for (double z : {band.min_depth_m, band.max_depth_m}) {
    if (std::isfinite(z))
      canvas.stroke_polyline({{x.px_lo, y.to_px(z)}, {x.px_hi, y.to_px(z)}}, clearance_stroke(kBand, u));
  }
  // Obstacles whose zone the track crosses, drawn from the top down.
  const ObstacleField& field = volume.field();
  const std::map<std::size_t, std::vector<std::pair<int, int>>> crossed = crossed_runs(field, column_points);
  l.obstacles_crossed = crossed.size();
  const double c_m = band.vertical_clearance_m;
  for (const auto& [i, runs] : crossed) {
    const double zone_top = volume.zone_top(i);
    const double top = std::isfinite(zone_top) ? zone_top + c_m : l.depth_top_m;
    for (const auto& [c0, c1] : runs) {
      const double x0 = plot.x + c0, x1 = plot.x + c1 + 1.0;
      canvas.fill_rect({x0, y.to_px(top), x1 - x0, plot.y + plot.height - y.to_px(top)},
                       Rgba{kObstacle.r, kObstacle.g, kObstacle.b, 0.45});
      if (std::isfinite(zone_top))
        canvas.stroke_polyline({{x0, y.to_px(zone_top)}, {x1, y.to_px(zone_top)}}, clearance_stroke(kObstacle, u));
    }
    const auto& widest = *std::max_element(
        runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.second - a.first < b.second - b.first; });
    canvas.text_with_halo({plot.x + 0.5 * (widest.first + widest.second + 1), y.to_px(top) - 6.0 * u},
                          field.obstacle_name(i), 11.5 * u, kObstacle, rgb_hex(0xffffff), 2.5 * u, TextAlign::centre);
  }
  // The sea floor and its clearance line.
  if (const SeaFloor* floor = volume.floor()) {
    std::vector<Vec2> ground, clear;
    for (int c = 0; c <= cols; ++c) {
      const double s = l.along_m * c / cols;
      const double d = floor->depth_at(track.point_at(s));
      ground.emplace_back(x.to_px(s), y.to_px(d));
      clear.emplace_back(x.to_px(s), y.to_px(d - c_m));
    }
    std::vector<Vec2> shape = ground;
    shape.emplace_back(x.px_hi, plot.y + plot.height + 2.0);
    shape.emplace_back(x.px_lo, plot.y + plot.height + 2.0);
    canvas.shape(shape, kFloor, Stroke{rgb_hex(0x5d4631), 1.4 * u, {}});
    canvas.stroke_polyline(clear, clearance_stroke(kFloor, u));
  }
  // The route.
  std::vector<Vec2> line;
  double s = 0.0;
  for (std::size_t i = 0; i < route.points.size(); ++i) {
    if (i > 0) s += (route.points[i] - route.points[i - 1]).norm();
    line.emplace_back(x.to_px(s), y.to_px(route.depth_m[i]));
  }
  canvas.stroke_polyline(line, route_stroke(u));
  for (const Vec2& p : line) canvas.circle(p, 3.2 * u, rgb_hex(0xffffff), Stroke{kRoute, 1.6 * u, {}});
  canvas.unclip();
  draw_axes(canvas, plot, x, y, {"distance along the track (m)", "depth (m)", 10, 7, true}, u,
            {kText, kFrame, Rgba{0, 0, 0, 0}});

  draw_legend(canvas, legend_entries(plan, u), legend, kLegendColumns, u, kText);
  canvas.finish();
  return l;
}

}  // namespace deepguide
