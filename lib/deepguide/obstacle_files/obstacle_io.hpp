#pragma once
// Obstacles on disk, through OGR: any vector source GDAL opens (GeoJSON,
// GeoPackage, Shapefile, CSV with X/Y or WKT columns, ...). Fields
// (docs/FORMATS.md, "Obstacle files"): a Point feature with `semi_major_m`, `semi_minor_m`,
// `orientation_deg` (major axis, clockwise from true north) and `height_m` or
// `top_depth_m` is an elliptical cylinder; a Polygon (or MultiPolygon) feature
// is a polygonal obstacle. Optional `id` or `name` names the obstacle.
//
// Decisions (docs/FORMATS.md): `semi_minor_m` defaults to `semi_major_m` (a
// circle) and `orientation_deg` to 0; a source without a CRS is read as
// lon/lat WGS 84 unless ReadOptions::source_crs says otherwise.
// Callers that need more of a feature than the obstacle model (the obstacle
// store: contact time, mission) name extra fields and get them back as text in
// LoadedObstacles::*_origins, with date/time fields as ISO 8601. In a source
// that also has layers with geometry, layers without any (a GeoPackage's
// attribute tables) are skipped; a lone geometry-less layer stays an error.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct ObstacleReadOptions {
  /// Local planning frame: empty = UTM zone of the obstacles' centre, else e.g. "EPSG:32632".
  std::string local_crs;
  /// CRS for sources that carry none (CSV, bare GeoJSON). Empty = EPSG:4326.
  std::string source_crs;
  /// Extra fields to return per feature as text (ObstacleOrigin::extra), e.g. "time".
  std::vector<std::string> extra_fields = {};
  /// Layers to read (empty: every layer with geometry), e.g. a prepared chart's "obstacles".
  std::vector<std::string> layers = {};
  /// Positions (lon, lat) besides the obstacles' that the frame serves, e.g. a
  /// route being checked: the default frame is chosen over both, and a named
  /// frame must keep true metres over both (frame_scale.hpp).
  std::vector<Eigen::Vector2d> work_area_lonlat = {};
  /// Without local_crs, when no file holds an obstacle and no work area is
  /// given: the lon, lat the frame is chosen at (a command's start). None: 0, 0.
  std::optional<Eigen::Vector2d> fallback_lonlat = std::nullopt;
  /// Repair a polygon that is not simple in the frame (GEOS, no_go_union.hpp)
  /// instead of refusing it: only for the library's own files, a prepared
  /// chart's polygons, valid where they were made, that the round trip through
  /// lon/lat into another frame's round-off can leave touching themselves
  /// (Kachemak at 7 m: two holes that touch at a vertex). A user's file is
  /// refused, as repairing it would choose the obstacle's shape for them.
  bool repair_polygons = false;
};

struct ObstacleSourceInfo {
  std::string path;
  std::string driver;  ///< GDAL driver short name, e.g. "GeoJSON"
  std::string crs;     ///< e.g. "EPSG:4326"; "(none: read as ...)" when assumed
  std::size_t ellipses = 0;
  std::size_t polygons = 0;
};

/// Where one obstacle came from, and what else its feature carried.
struct ObstacleOrigin {
  std::size_t source = 0;            ///< index into LoadedObstacles::sources
  std::int64_t fid = 0;              ///< OGR feature id in its layer
  InputLocation where;               ///< file and feature (field empty), for messages
  Eigen::Vector2d lonlat{0.0, 0.0};  ///< Points: the centre as read, lon/lat, before the local frame
  double heading_deg = 0.0;          ///< Points: orientation_deg as read (0 when absent)
  /// One per ObstacleReadOptions::extra_fields; nullopt when absent, null or empty.
  std::vector<std::optional<std::string>> extra = {};
};

struct LoadedObstacles {
  ObstacleSet obstacles;
  LocalFrame frame;
  std::vector<ObstacleSourceInfo> sources;
  std::vector<ObstacleOrigin> ellipse_origins = {};  ///< parallel to obstacles.ellipses
  std::vector<ObstacleOrigin> polygon_origins = {};  ///< parallel to obstacles.polygons
};

/// Reads every feature of every layer of each path into one set in one local
/// frame. Throws InputError (one line: file, feature, field, expectation).
LoadedObstacles load_obstacles(const std::vector<std::string>& paths, const ObstacleReadOptions& options = {});

/// An elliptic obstacle's footprint in `frame` from the fields a file gives
/// it: the centre (`centre` in the frame, `lonlat` the same point), the
/// semi-axes in true metres (made frame metres where the frame stretches
/// them, frame_scale.hpp) and orientation_deg, the major axis clockwise from
/// true north. What the readers and deepguide.plan's `ellipses` share.
Ellipse ellipse_from_fields(const LocalFrame& frame, const Eigen::Vector2d& centre, const Eigen::Vector2d& lonlat,
                            double semi_major_m, double semi_minor_m, double orientation_deg);

/// Adds a polygon obstacle read from somewhere (`where` names it in errors):
/// its rings oriented as the planners expect (outer clockwise), and either
/// refused when it is not simple (InputError) or, with `repair`, split into
/// GEOS's valid parts. What the readers and deepguide.plan's `polygons` share.
void add_polygon_obstacle(PolygonObstacle polygon, bool repair, const InputLocation& where, ObstacleSet& into);

/// The fields an obstacle file gives an ellipse in `frame`, back from its
/// footprint: ellipse_from_fields' inverse (axes in true metres, the major
/// axis clockwise from true north in [0, 180)).
struct EllipseFields {
  Eigen::Vector2d lonlat;
  double semi_major_m, semi_minor_m, orientation_deg;
};
EllipseFields ellipse_fields(const LocalFrame& frame, const Ellipse& footprint);

/// Output formats, chosen from the file extension.
enum class ObstacleFormat { geojson, geopackage, csv };
/// Throws InputError for an extension deepguide does not write.
ObstacleFormat obstacle_format_for(const std::string& path);

/// Writes the set as lon/lat WGS 84 (GeoJSON RFC 7946, GeoPackage layer
/// "obstacles", or CSV with a WKT column). Atomic: a failed write leaves no file.
void write_obstacles(const std::string& path, const ObstacleSet& obstacles, const LocalFrame& frame);

}  // namespace deepguide
