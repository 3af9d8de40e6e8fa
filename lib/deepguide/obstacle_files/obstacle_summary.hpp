#pragma once
// What `deepguide obstacles info` reports: counts, extent, sizes and frames,
// as a struct for programs and as JSON for `--json`.

#include <nlohmann/json.hpp>

#include "deepguide/core/api.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"

namespace DEEPGUIDE_API deepguide {

struct RangeStats {
  std::size_t n = 0;
  double min = 0.0;
  double mean = 0.0;
  double max = 0.0;
  void add(double v);  ///< running min / mean / max
};

struct ObstacleSummary {
  std::size_t count = 0;
  std::size_t ellipses = 0;
  std::size_t polygons = 0;
  bool has_extent = false;
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;         ///< footprints' box, local metres
  double west = 0, south = 0, east = 0, north = 0;           ///< the same box's corners in lon/lat
  RangeStats semi_major_m, semi_minor_m, footprint_area_m2;  ///< ellipses; area over all obstacles
  std::size_t with_height = 0, with_top_depth = 0, full_column = 0;
  std::string local_crs_id, local_crs_name;
  std::vector<ObstacleSourceInfo> sources;
};

ObstacleSummary summarize(const LoadedObstacles& loaded);
nlohmann::json to_json(const ObstacleSummary& s);
/// What `obstacles info` prints: each source, the count, frame, extent, sizes
/// and how the obstacles stand in the water column.
std::string to_text(const ObstacleSummary& s);

}  // namespace deepguide
