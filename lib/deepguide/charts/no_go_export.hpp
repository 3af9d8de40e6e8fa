#pragma once
// `chart nogo` as a library call: the no-go area of a bathymetry raster or of
// S-57 cells for an operating depth (no_go.hpp, enc_no_go.hpp), written as
// an obstacle file, with a report that prints itself as text or JSON.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "deepguide/charts/bathymetry.hpp"
#include "deepguide/charts/chart_options.hpp"
#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/no_go.hpp"
#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

struct NoGoExportRequest {
  /// One bathymetry raster, or S-57 cells (*.000 with their updates) and
  /// folders of cells.
  std::vector<std::string> charts;
  std::string output;                              ///< obstacle file (.geojson/.json, .gpkg, .csv)
  std::string crs;                                 ///< local frame ("": the UTM zone of the chart)
  std::string src_crs;                             ///< raster: the CRS of one that carries none
  VerticalSense sense = VerticalSense::automatic;  ///< raster values
  bool nodata_is_no_go = true;                     ///< raster: cells without data
  ChartOptions chart;                              ///< S-57: zones of confidence, restricted areas
  NoGoOptions nogo;                                ///< operating depth, vertical clearance, simplification tolerance
};

struct NoGoExportReport {
  NoGoExportRequest request;
  std::string local_crs, local_crs_name;
  double seconds = 0.0;  ///< computing the no-go area (reading included, writing not)
  bool from_cells = false;
  std::size_t polygons = 0;
  // S-57 cells (from_cells)
  std::vector<EncCellSummary> cells;
  double required_depth_m = 0.0;
  std::map<std::string, std::size_t> no_go_by_class, passable_by_class, zoc_areas;
  std::size_t discs = 0, vertices = 0;
  // a raster (!from_cells); its polygons are not kept
  NoGoArea area;

  nlohmann::json to_json() const;
  std::string to_text() const;  ///< lines "label   value", ending "wrote   OUTPUT\n"
};

/// Computes the no-go area and writes it (atomically) to request.output.
/// Throws InputError (one line) for unreadable charts, a bad output
/// extension (before any work) or out-of-range options.
NoGoExportReport export_no_go(const NoGoExportRequest& request);

}  // namespace deepguide
