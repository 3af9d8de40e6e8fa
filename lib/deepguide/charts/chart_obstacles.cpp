#include "deepguide/charts/chart_obstacles.hpp"

#include <boost/geometry.hpp>
#include <cmath>

#include "deepguide/charts/bathymetry.hpp"
#include "deepguide/charts/chart_info.hpp"
#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/no_go.hpp"
#include "deepguide/charts/prepared_chart.hpp"
#include "deepguide/charts/s57_chart.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/world/frame_scale.hpp"

namespace deepguide {

namespace {

void append(ObstacleSet& to, ObstacleSet from) {
  to.ellipses.insert(to.ellipses.end(), std::make_move_iterator(from.ellipses.begin()),
                     std::make_move_iterator(from.ellipses.end()));
  to.polygons.insert(to.polygons.end(), std::make_move_iterator(from.polygons.begin()),
                     std::make_move_iterator(from.polygons.end()));
}

}  // namespace

bool reads_as_enc(const std::string& path) {
  return names_enc(path) || is_prepared_chart(path) || chart_kind(path) == ChartKind::s57;
}

LocalFrame charts_frame(const std::vector<std::string>& paths, const std::string& local_crs,
                        const std::string& source_crs) {
  if (!local_crs.empty()) return LocalFrame::from_user_crs(local_crs);
  if (paths.empty()) throw InputError("charts: expected at least one chart file");
  const std::string& first = paths.front();
  if (is_prepared_chart(first)) return prepared_chart_frame(first);
  if (names_enc(first)) return s57_local_frame(summarize_s57(find_enc_cells({first}).front().base));
  switch (chart_kind(first)) {
    case ChartKind::raster: {
      BathymetryOptions read;
      read.assumed_crs = source_crs;
      return default_frame_for(inspect_bathymetry(first, read).extent);
    }
    case ChartKind::s57: return s57_local_frame(summarize_s57(find_enc_cells({first}).front().base));
    case ChartKind::vector: break;
  }
  return load_obstacles({first}).frame;
}

ChartObstacles chart_obstacles(const std::vector<std::string>& paths, const LocalFrame& frame,
                               const ChartObstacleOptions& options) {
  const bool has_depth = !std::isnan(options.depth_m);
  ChartObstacles out;
  // S-57 cells (and folders of them) are read together: where they overlap the better scale wins.
  std::vector<std::string> enc;
  for (const std::string& path : paths) {
    if (reads_as_enc(path)) {
      enc.push_back(path);
      continue;
    }
    const ChartKind kind = chart_kind(path);
    ChartFileObstacles file{path, to_string(kind)};
    ObstacleSet set;
    if (kind == ChartKind::raster) {
      if (!has_depth) {
        throw input_error({path, "", ""},
                          "`depth_m`, the operating depth (m) to tell too-shallow water in a bathymetry raster");
      }
      NoGoOptions no_go;
      no_go.operating_depth_m = options.depth_m;
      no_go.vertical_clearance_m = options.clearance_m;
      no_go.simplify_tolerance_m = options.simplify_tolerance_m;
      no_go.bathymetry.assumed_crs = options.source_crs;
      set.polygons = compute_no_go(path, frame, no_go).polygons;
      BgMultiPolygon merged;
      boost::geometry::union_(out.raster_coverage, raster_coverage(path, frame, no_go.bathymetry), merged);
      out.raster_coverage = std::move(merged);
      out.raster_paths.push_back(path);
    } else {
      set = load_obstacles({path}, {frame.id(), options.source_crs}).obstacles;
      if (has_depth) file.passed_over = remove_passable(set, options.depth_m, options.clearance_m);
    }
    file.obstacles = set.size();
    append(out.obstacles, std::move(set));
    out.files.push_back(file);
  }
  if (!enc.empty()) {
    if (!has_depth) {
      throw input_error({enc.front(), "", ""},
                        "`depth_m`, the operating depth (m) to judge an S-57 chart's depth areas and dangers by");
    }
    EncNoGoOptions o = options.enc;
    o.operating_depth_m = options.depth_m;
    o.vertical_clearance_m = options.clearance_m;
    EncNoGo no_go = chart_no_go(enc, frame, o);
    if (no_go.cells.empty()) {  // one prepared chart (chart_no_go refuses more)
      auto graphs = read_prepared_graphs(enc.front());
      if (!graphs.empty()) {
        out.prepared_graphs = std::make_shared<const std::vector<PreparedGraphRecord>>(std::move(graphs));
        out.prepared_obstacles = std::make_shared<const ObstacleSet>(no_go.obstacles);
      }
    }
    // One row for the cells read together.
    ChartFileObstacles file{no_go.cells.empty()       ? enc.front()
                            : no_go.cells.size() == 1 ? no_go.cells.front().path
                                                      : std::to_string(no_go.cells.size()) + " cells",
                            no_go.cells.empty() ? "prepared chart" : to_string(ChartKind::s57)};
    for (const auto& [cls, n] : no_go.passable_by_class) file.passed_over += n;
    file.obstacles = no_go.obstacles.size();
    out.files.push_back(file);
    append(out.obstacles, std::move(no_go.obstacles));
    out.enc = std::make_shared<EncNoGo>(std::move(no_go));
  }
  return out;
}

std::optional<CoverageExit> route_leaves_coverage(const std::vector<Vec2>& route, const BgMultiPolygon& coverage) {
  namespace bg = boost::geometry;
  if (coverage.empty() || route.empty()) return std::nullopt;
  const auto inside = [&](const Vec2& p) { return bg::covered_by(BgPoint(p.x(), p.y()), coverage); };
  if (!inside(route.front())) return CoverageExit{0, route.front()};
  for (std::size_t i = 1; i < route.size(); ++i) {
    bg::model::linestring<BgPoint> leg{{route[i - 1].x(), route[i - 1].y()}, {route[i].x(), route[i].y()}};
    if (bg::covered_by(leg, coverage)) continue;
    // Where it leaves: the crossing of the outline nearest the leg's start.
    std::vector<BgPoint> crossings;
    for (const BgPolygon& p : coverage) bg::intersection(leg, p.outer(), crossings);
    Vec2 at = route[i];
    double best = INFINITY;
    for (const BgPoint& c : crossings) {
      const Vec2 q(c.x(), c.y());
      if (const double d = (q - route[i - 1]).norm(); d < best) best = d, at = q;
    }
    return CoverageExit{i - 1, at};
  }
  return std::nullopt;
}

}  // namespace deepguide
