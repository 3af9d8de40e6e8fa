#pragma once
// Obstacles on disk, through OGR: any vector source GDAL opens (GeoJSON,
// GeoPackage, Shapefile, CSV with X/Y or WKT columns, ...). Fields
// (DESIGN.md): a Point feature with `semi_major_m`, `semi_minor_m`,
// `orientation_deg` (major axis, clockwise from true north) and `height_m` or
// `top_depth_m` is an elliptical cylinder; a Polygon (or MultiPolygon) feature
// is a polygonal obstacle. Optional `id` or `name` names the obstacle.
//
// Decisions (docs/FORMATS.md): `semi_minor_m` defaults to `semi_major_m` (a
// circle) and `orientation_deg` to 0; a source without a CRS is read as
// lon/lat WGS 84 unless ReadOptions::source_crs says otherwise.

#include <string>
#include <vector>

#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace deepguide {

struct ObstacleReadOptions {
  /// Local planning frame: empty = UTM zone of the obstacles' centre, else e.g. "EPSG:32632".
  std::string local_crs;
  /// CRS for sources that carry none (CSV, bare GeoJSON). Empty = EPSG:4326.
  std::string source_crs;
};

struct ObstacleSourceInfo {
  std::string path;
  std::string driver;  ///< GDAL driver short name, e.g. "GeoJSON"
  std::string crs;     ///< e.g. "EPSG:4326"; "(none: read as ...)" when assumed
  std::size_t ellipses = 0;
  std::size_t polygons = 0;
};

struct LoadedObstacles {
  ObstacleSet obstacles;
  LocalFrame frame;
  std::vector<ObstacleSourceInfo> sources;
};

/// Reads every feature of every layer of each path into one set in one local
/// frame. Throws InputError (one line: file, feature, field, expectation).
LoadedObstacles load_obstacles(const std::vector<std::string>& paths,
                               const ObstacleReadOptions& options = {});

/// Output formats, chosen from the file extension.
enum class ObstacleFormat { geojson, geopackage, csv };
/// Throws InputError for an extension deepguide does not write.
ObstacleFormat obstacle_format_for(const std::string& path);

/// Writes the set as lon/lat WGS 84 (GeoJSON RFC 7946, GeoPackage layer
/// "obstacles", or CSV with a WKT column). Atomic: a failed write leaves no file.
void write_obstacles(const std::string& path, const ObstacleSet& obstacles, const LocalFrame& frame);

}  // namespace deepguide
