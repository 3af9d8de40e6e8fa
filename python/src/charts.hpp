#pragma once
// What Python holds of a chart and of a current field, read once and given
// to `plan` as many times as a script asks (charts.cpp reads them, plan.cpp
// plans on them).

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "deepguide/charts/chart_obstacles.hpp"
#include "deepguide/charts/chart_options.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace deepguide::python {

/// Charts (S-57 cells, folders, exchange sets, prepared charts, rasters,
/// hazard files) read into one frame at one depth, with the CLI's chart options.
struct Chart {
  std::vector<std::string> paths;
  LocalFrame frame;
  double depth_m = 0;  ///< NaN: read without an operating depth
  double clearance_m = 2.0;
  std::string src_crs;
  ChartOptions options;
  /// The no-go and hazards as planning obstacles; null when no depth was
  /// given and a raster or S-57 cell needs one (then `unread` says why).
  std::shared_ptr<const ChartObstacles> charted;
  std::string unread;

  /// The obstacles, or InputError(unread).
  const ChartObstacles& obstacles() const;
};

/// A current field read once (or a constant one).
struct Current {
  std::shared_ptr<const CurrentField> field;
};

/// The CLI's --zoc, --restricted and --unassessed-zoc as keywords; throws
/// InputError naming the keyword.
ChartOptions chart_options(const std::string& zoc, bool restricted_areas,
                           const std::optional<std::tuple<double, double, double>>& unassessed_zoc);

/// Footprints in lon/lat, per obstacle a list of (k, 2) rings, the outline
/// first (an ellipse as 72 points), for matplotlib.
pybind11::list lonlat_outlines(const ObstacleSet& obstacles, const LocalFrame& frame);

}  // namespace deepguide::python
