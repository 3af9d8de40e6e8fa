#pragma once
// A prepared chart: S-57 cells' no-go at one depth, computed once and kept in
// a GeoPackage (`chart prepare`), so that `plan --chart area.gpkg` and
// `check route --chart area.gpkg` skip reading and judging the cells.
//
// Layers:
//  - "obstacles": what the planners take (EncNoGo::obstacles: the merged,
//    simplified no-go polygons and the discs outside them), in the obstacle
//    file format (obstacle_io.hpp, lon/lat), so any obstacle reader takes it too;
//  - "no_go_features": every no-go feature with its id, cell, class, RCID,
//    reason and charted depth (what names a crossing); discs as points with
//    radius_m. In the frame's CRS it was prepared in (format 3; lon/lat
//    before), so reading it in that frame reprojects nothing: on the Kachemak
//    set that was half of `plan --chart area.gpkg`;
//  - "cell_areas", "depth_areas", "zones": what a route's quality is
//    measured on, in the frame's CRS as well;
//  - "deepguide_chart": one row without geometry: the depth, clearance,
//    required depth, options and cells it was prepared for, and the format
//    version. A chart is used only at the depth and clearance it was
//    prepared for: anything else is an error naming both;
//  - "deepguide_graphs" (optional): planning graphs built over the
//    obstacles as read back from the file (prepared_graph_record.hpp), one
//    row each: graph, key, about, and the graph's bytes as a BLOB.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/charts/prepared_graph_record.hpp"
#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

struct PreparedChartInfo {
  double depth_m = 0;
  double vertical_clearance_m = 0;
  /// The chart options it was prepared with (a chart of format 1, before the
  /// policies, reads as strict or none).
  ChartOptions chart;
  double simplify_tolerance_m = 0;
  std::string cells;  ///< "NAME edition E update U; ..."
};

/// True when `path` is a GeoPackage holding a "deepguide_chart" layer.
bool is_prepared_chart(const std::string& path);

/// Writes the no-go atomically (a failed write leaves no file; an existing
/// file is replaced only with `replace`). With `graphs`, the obstacles are
/// read back from the written file as `plan --chart` reads them, and the
/// graphs it makes of them are stored too. Throws InputError naming the file.
void write_prepared_chart(const std::string& path, const EncNoGo& no_go, const EncNoGoOptions& options, bool replace,
                          const PreparedGraphsMaker& graphs = {});

/// The graphs kept in a prepared chart (none when it has no such table).
/// Throws InputError naming the file for a table that is not as written.
std::vector<PreparedGraphRecord> read_prepared_graphs(const std::string& path);

/// What `chart prepare` did: the cells judged, the no-go written and how
/// long both took.
struct ChartPreparation {
  std::string output;
  EncNoGo no_go;
  EncNoGoOptions options;
  std::vector<PreparedGraphRecord> graphs;  ///< their bytes dropped once written
  double seconds = 0.0;

  nlohmann::json to_json() const;
  std::string to_text() const;
  nlohmann::json graphs_json() const;
};

/// Judges `charts` (cells and folders of cells) at the options' depth, in
/// `local_crs` (empty: the first cell's UTM zone), and writes the prepared
/// chart to `output` (write_prepared_chart), with `graphs` when given.
ChartPreparation prepare_chart(const std::vector<std::string>& charts, const std::string& local_crs,
                               const EncNoGoOptions& options, const std::string& output, bool overwrite,
                               const PreparedGraphsMaker& graphs = {});

/// The frame a prepared chart was prepared in (its local_crs); throws
/// InputError naming the file when it is not a prepared chart.
LocalFrame prepared_chart_frame(const std::string& path);

/// Reads a prepared chart into `frame` (or the frame it was prepared in) for
/// `depth_m` and `vertical_clearance_m`; throws InputError naming the file
/// when it was prepared for others, or is not a prepared chart.
EncNoGo read_prepared_chart(const std::string& path, const std::optional<LocalFrame>& frame, double depth_m,
                            double vertical_clearance_m, PreparedChartInfo* info = nullptr);

/// The no-go of `charts`: S-57 cells and folders (enc_no_go), or one prepared
/// chart read at options' depth and clearance; a prepared chart whose chart
/// options differ from `options` is refused, naming the option.
EncNoGo chart_no_go(const std::vector<std::string>& charts, const std::optional<LocalFrame>& frame,
                    const EncNoGoOptions& options);

}  // namespace deepguide
