#pragma once
// What an ECDIS's route check reports about a route on ENCs besides whether
// it is safe (docs/CHARTS.md, "Route quality"):
//  - the cells it crosses, in the order sailed, with their usage bands and
//    the length in each, a cell counting where it is the best scale (the
//    chart the planners used there; EncNoGo::cell_areas);
//  - the least charted depth under it: the least DRVAL1 of the depth and
//    dredged areas it crosses, with the feature, its cell and the zone of
//    confidence it lies in there;
//  - the length in each zone of confidence (A1 .. U, "none" for charted
//    water without M_QUAL, "uncharted" outside every cell): they sum to the
//    route's length;
//  - the nearest no-go feature (its zone's edge: a disc's, an area's) and
//    the distance to it.

#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

struct RouteQuality {
  double length_m = 0.0;
  struct CellPart {
    std::string cell;
    int usage_band = 0;
    long compilation_scale = 0;
    double length_m = 0.0;
  };
  std::vector<CellPart> cells;  ///< in the order first entered
  struct Depth {
    std::string feature_id, cell, zoc;
    double depth_m = std::numeric_limits<double>::quiet_NaN();  ///< DRVAL1
    Vec2 at{0.0, 0.0};                                          ///< where the route first meets it
    double along_m = 0.0;
  };
  std::optional<Depth> least_depth;
  std::map<std::string, double> length_by_zoc;  ///< "A1", ..., "U", "none", "uncharted"
  struct Nearest {
    std::string feature_id, cell, reason;
    double distance_m = 0.0;
    Vec2 at{0.0, 0.0};  ///< the route's point nearest the feature
    double along_m = 0.0;
  };
  std::optional<Nearest> nearest_no_go;

  nlohmann::json to_json(const LocalFrame& frame) const;
  /// Report lines ("cells", "least depth", "zones", "nearest no-go").
  std::string to_text(const LocalFrame& frame) const;
};

/// The quality of `route` (waypoints in no_go.frame, at least two) on the
/// charts the no-go was built from. A prepared chart of format 1 carries no
/// cell, depth or zone areas: those parts are then empty.
RouteQuality route_quality(const std::vector<Vec2>& route, const EncNoGo& no_go);

}  // namespace deepguide
