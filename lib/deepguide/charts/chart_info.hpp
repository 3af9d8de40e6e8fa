#pragma once
// What `deepguide chart info` reports about a chart file: its kind, layers,
// extent, CRS, depth range, hazards and, for an operating depth, its no-go area.
//
// Decisions:
// - The kind comes from what GDAL opens: the S57 driver -> an S-57 cell; a
//   dataset with raster bands -> bathymetry; else vector layers -> a hazard or
//   obstacle file. Anything else is an InputError naming the file.
// - Depth range (m, positive down): for a raster, its valid cells
//   (inspect_bathymetry: the file's sign convention); for an S-57 cell, the
//   depth areas (DEPARE DRVAL1..DRVAL2) joined with the soundings; for a
//   hazard file, the tops (top_depth_m) of its hazards. NaN when unknown.
// - Hazards: none for a raster (it only has depths); the OBSTRN, WRECKS and
//   UWTROC features for an S-57 cell (land is counted apart); every obstacle
//   for a vector file.
// - No-go at ChartInfoOptions::depth_m: for a raster, compute_no_go (too
//   shallow, land, NoData); for an S-57 cell, enc_no_go (depth areas,
//   soundings, dangers, land, zones of confidence: docs/CHARTS.md), inside
//   the cell's coverage; for a vector file, the union of the footprints of
//   the hazards that remain after the depth filter, ellipses as polygons
//   within 0.1 m. Areas in the local frame (m2):
//   the UTM zone of the chart's centre unless local_crs names one.

#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "deepguide/charts/chart_options.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/world/extent.hpp"

namespace DEEPGUIDE_API deepguide {

enum class ChartKind { raster, s57, vector };
const char* to_string(ChartKind kind);

struct ChartLayer {
  std::string name;          ///< raster: "band N"; S-57: object class; vector: layer name
  std::size_t features = 0;  ///< features (vector, S-57); cells (raster)
  std::string detail;        ///< raster: band description and type; vector: geometry type
};

struct NoGoSummary {
  double depth_m = 0;
  double clearance_m = 0;
  double area_m2 = 0;                ///< no-go area (m2, local frame)
  std::size_t polygons = 0;          ///< raster: no-go polygons; else hazards left (footprints unioned)
  std::size_t no_go_cells = 0;       ///< raster only
  std::size_t total_cells = 0;       ///< raster only
  std::size_t hazards_passable = 0;  ///< S-57 / vector: hazards the vehicle passes over
  /// S-57: no-go features per object class (SOUNDG: soundings), and the planners' polygon vertices.
  std::map<std::string, std::size_t> no_go_by_class;
  std::size_t vertices = 0;
};

/// One cell of a chart argument that names several (a folder, an exchange set).
struct ChartCell {
  std::string path, name;
  int usage_band = 0;
  long compilation_scale = 0;
  std::string edition;
  int update_number = 0;
  std::string catalogue;  ///< the CATALOG.031 that listed it ("" when found by a search)
};

struct ChartInfo {
  std::string path;
  ChartKind kind = ChartKind::raster;
  std::string driver;  ///< GDAL short name
  std::string crs;     ///< "EPSG:n" or the CRS's name
  std::vector<ChartLayer> layers;
  LonLatExtent extent;
  double width_m = 0, height_m = 0;  ///< extent in the local frame (east x north)
  std::string local_crs;             ///< the local frame's id
  double min_depth_m = std::numeric_limits<double>::quiet_NaN();
  double max_depth_m = std::numeric_limits<double>::quiet_NaN();
  std::size_t hazards = 0;
  std::size_t land_features = 0;                 ///< S-57: LNDARE features
  std::map<std::string, std::size_t> zoc_areas;  ///< S-57: M_QUAL areas per CATZOC letter
  /// S-57 folders and exchange sets: their cells, best scale first (the order
  /// overlaps are decided in); empty for a single cell.
  std::vector<ChartCell> cells;
  // Raster facts.
  int raster_width = 0, raster_height = 0;
  double cell_x_m = 0, cell_y_m = 0;  ///< in CRS units
  double valid_fraction = 0;
  bool has_nodata = false;
  double nodata = 0;
  std::string vertical_sense;  ///< "elevation" or "depth", with the reason
  std::optional<NoGoSummary> no_go;
};

struct ChartInfoOptions {
  /// Operating depth (m, positive down) for the no-go summary; NaN = none.
  double depth_m = std::numeric_limits<double>::quiet_NaN();
  /// Vertical clearance kept above the sea floor and hazards (m, >= 0).
  double clearance_m = 2.0;
  /// Local frame: empty = UTM zone of the chart's centre.
  std::string local_crs;
  /// CRS of a raster or vector file that carries none (e.g. "EPSG:4326" for
  /// an ESRI ASCII grid without .prj); empty = such a raster is an error.
  std::string source_crs;
  /// How S-57 cells are read for the no-go summary.
  ChartOptions chart;
};

/// The kind of chart at `path` (see the decisions above). Throws InputError
/// naming the file when it is missing, a folder, or nothing GDAL reads as a chart.
/// (chart_info itself takes folders of S-57 cells and exchange sets: their
/// cells are read together, as the planners read them.)
ChartKind chart_kind(const std::string& path);

/// Throws InputError (one line naming the file, or the option) for a missing
/// or unreadable file, a file that is no chart, or a bad depth or clearance.
ChartInfo chart_info(const std::string& path, const ChartInfoOptions& options = {});

nlohmann::json to_json(const ChartInfo& info);
/// What `chart info` prints for one file: a line per layer, extent, depths,
/// hazards, zones of confidence and the no-go area.
std::string to_text(const ChartInfo& info);

}  // namespace deepguide
