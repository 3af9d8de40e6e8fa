#pragma once
// Charts as planning input: every chart file a planner is given becomes
// obstacles in one local frame, whatever its kind (chart_info.hpp decides the
// kind from what GDAL opens):
//  - a bathymetry raster: its no-go polygons at the operating depth
//    (no_go.hpp: too shallow for depth + clearance, land, and no data);
//  - an S-57 cell: its hazards and land (s57_chart.hpp), less the hazards
//    deep enough to pass over;
//  - a vector file (a hazard layer, an obstacle store): its obstacles, less
//    those whose top lies deeper than depth + clearance.
// A raster needs the operating depth: without it no cell can be judged, and
// the caller is told so instead of getting an empty chart.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace deepguide {

struct ChartObstacleOptions {
  /// Operating depth (m, positive down); NaN = none (then rasters are refused).
  double depth_m = std::numeric_limits<double>::quiet_NaN();
  /// Water kept above the sea floor and above hazards (m).
  double clearance_m = 2.0;
  /// How far a raster's simplified no-go boundary may lie outside the cells (m).
  double simplify_tolerance_m = 5.0;
  /// CRS of vector files that carry none (empty: lon/lat).
  std::string source_crs;
};

struct ChartFileObstacles {
  std::string path;
  std::string kind;  ///< to_string(ChartKind): "bathymetry raster", "S-57 cell", "hazard file"
  std::size_t obstacles = 0;    ///< obstacles taken from the file
  std::size_t passed_over = 0;  ///< hazards left out because the vehicle passes over them
};

struct ChartObstacles {
  ObstacleSet obstacles;
  std::vector<ChartFileObstacles> files;
};

/// Reads every chart into `frame`. Throws InputError (one line naming the
/// file, or the option) for an unreadable chart, or a raster without depth_m.
ChartObstacles chart_obstacles(const std::vector<std::string>& paths, const LocalFrame& frame,
                               const ChartObstacleOptions& options);

}  // namespace deepguide
