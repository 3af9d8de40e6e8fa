#pragma once
// Charts as planning input: every chart file a planner is given becomes
// obstacles in one local frame, whatever its kind (chart_info.hpp decides the
// kind from what GDAL opens):
//  - a bathymetry raster: its no-go polygons at the operating depth
//    (no_go.hpp: too shallow for depth + clearance, land, and no data);
//  - S-57 cells and folders of cells, read together: their no-go at the
//    operating depth (enc_no_go.hpp: depth areas, land, unsurveyed water,
//    structures, dangers and soundings, by the zones of confidence);
//  - a vector file (a hazard layer, an obstacle store): its obstacles, less
//    those whose top lies deeper than depth + clearance.
// A raster or an S-57 cell needs the operating depth: without it no cell can be judged, and
// the caller is told so instead of getting an empty chart.

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/prepared_graph_record.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct ChartObstacleOptions {
  /// Operating depth (m, positive down); NaN = none (then rasters are refused).
  double depth_m = std::numeric_limits<double>::quiet_NaN();
  /// Water kept above the sea floor and above hazards (m).
  double clearance_m = 2.0;
  /// How far a raster's simplified no-go boundary may lie outside the cells (m).
  double simplify_tolerance_m = 5.0;
  /// CRS of files that carry none: vector files (empty: lon/lat) and rasters
  /// such as an ESRI ASCII grid without .prj (empty: such a raster is an error).
  std::string source_crs;
  /// How S-57 cells are read (their depth and clearance are the two above).
  EncNoGoOptions enc = {};
};

struct ChartFileObstacles {
  std::string path;
  std::string kind;             ///< to_string(ChartKind): "bathymetry raster", "S-57 cell", "hazard file"
  std::size_t obstacles = 0;    ///< obstacles taken from the file
  std::size_t passed_over = 0;  ///< hazards left out because the vehicle passes over them
};

struct ChartObstacles {
  ObstacleSet obstacles;
  std::vector<ChartFileObstacles> files;
  /// The S-57 cells' no-go, feature by feature (null without cells): what names a crossing.
  std::shared_ptr<const EncNoGo> enc;
  /// The graphs a prepared chart keeps (prepared_graph_record.hpp; null when none).
  std::shared_ptr<const std::vector<PreparedGraphRecord>> prepared_graphs;
  /// The prepared chart's own obstacles, which its graphs were built over
  /// (PlannerOptions::prepared_obstacles; null when none).
  std::shared_ptr<const ObstacleSet> prepared_obstacles;
  /// Where the bathymetry rasters know the depth (their outlines, local frame;
  /// empty without rasters). A route must stay inside: route_leaves_coverage.
  BgMultiPolygon raster_coverage;
  std::vector<std::string> raster_paths;
};

/// Where a route first leaves the rasters' coverage: the leg (0-based) and
/// the point where it leaves (a waypoint, or where the leg crosses the
/// outline); nullopt when it stays inside (or there is no raster).
struct CoverageExit {
  std::size_t leg = 0;
  Vec2 at{0.0, 0.0};
};
std::optional<CoverageExit> route_leaves_coverage(const std::vector<Vec2>& route, const BgMultiPolygon& coverage);

/// True when `path` is read as S-57 (a cell, a folder of cells, an exchange
/// set's catalogue, or a prepared chart), not as a raster or a hazard file.
bool reads_as_enc(const std::string& path);

/// The frame charts are read into when the caller names none: `local_crs`
/// when given, else the first chart's own (a prepared chart's frame, the UTM
/// zone of an S-57 cell's or a raster's centre, a hazard file's frame;
/// `source_crs` for a raster that carries no CRS). Throws InputError naming
/// the file or the CRS.
LocalFrame charts_frame(const std::vector<std::string>& paths, const std::string& local_crs,
                        const std::string& source_crs);

/// Reads every chart into `frame`. Throws InputError (one line naming the
/// file, or the option) for an unreadable chart, or a raster without depth_m.
ChartObstacles chart_obstacles(const std::vector<std::string>& paths, const LocalFrame& frame,
                               const ChartObstacleOptions& options);

}  // namespace deepguide
