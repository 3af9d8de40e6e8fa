#include "deepguide/world/chart_obstacles.hpp"

#include <cmath>

#include "deepguide/core/error.hpp"
#include "deepguide/world/chart_info.hpp"
#include "deepguide/world/no_go.hpp"
#include "deepguide/world/obstacle_io.hpp"
#include "deepguide/world/s57_chart.hpp"

namespace deepguide {

namespace {

void append(ObstacleSet& to, ObstacleSet from) {
  to.ellipses.insert(to.ellipses.end(), std::make_move_iterator(from.ellipses.begin()),
                     std::make_move_iterator(from.ellipses.end()));
  to.polygons.insert(to.polygons.end(), std::make_move_iterator(from.polygons.begin()),
                     std::make_move_iterator(from.polygons.end()));
}

}  // namespace

ChartObstacles chart_obstacles(const std::vector<std::string>& paths, const LocalFrame& frame,
                               const ChartObstacleOptions& options) {
  const bool has_depth = !std::isnan(options.depth_m);
  ChartObstacles out;
  for (const std::string& path : paths) {
    const ChartKind kind = chart_kind(path);
    ChartFileObstacles file{path, to_string(kind)};
    ObstacleSet set;
    switch (kind) {
      case ChartKind::raster: {
        if (!has_depth) {
          throw input_error({path, "", "--depth"},
                            "the operating depth (m) to tell too-shallow water in a bathymetry raster");
        }
        NoGoOptions no_go;
        no_go.operating_depth_m = options.depth_m;
        no_go.vertical_clearance_m = options.clearance_m;
        no_go.simplify_tolerance_m = options.simplify_tolerance_m;
        set.polygons = compute_no_go(path, frame, no_go).polygons;
        break;
      }
      case ChartKind::s57: {
        S57Options s57;
        s57.operating_depth_m = options.depth_m;
        s57.vertical_clearance_m = options.clearance_m;
        S57Hazards hazards = s57_hazards(path, frame, s57);
        file.passed_over = hazards.removed_by_depth;
        set = std::move(hazards.obstacles);
        break;
      }
      case ChartKind::vector: {
        set = load_obstacles({path}, {frame.id(), options.source_crs}).obstacles;
        if (has_depth) file.passed_over = remove_passable(set, options.depth_m, options.clearance_m);
        break;
      }
    }
    file.obstacles = set.size();
    append(out.obstacles, std::move(set));
    out.files.push_back(file);
  }
  return out;
}

}  // namespace deepguide
