#pragma once
// Any route checked against S-57 cells' no-go, feature by feature, with the
// first crossing named: what `check route --chart` prints. It reads the exact
// geometry of every no-go feature (enc_no_go.hpp: areas and line strips as
// charted, point hazards as discs) with Boost.Geometry distances, and shares
// nothing with the planners' zone polygons or obstacle field.
//
// A leg crosses a feature when it comes closer than the margin, less the
// tolerance, to it (inside an area counts as distance 0, and distance 0 is a
// crossing whatever the margin). The tolerance only absorbs rounding of a
// route planned to touch the margin (route files round positions: RTZ's nine
// decimals are 0.1 mm); it is not a second margin. The first crossing is the one whose entry
// point, where the distance first drops below the margin, lies least far
// along the route; it is found by sampling the leg inside the feature's
// envelope (grown by the margin) at a quarter of the margin (at most 2,000
// samples a feature) and bisecting to 1 cm.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

struct ChartCrossing {
  std::size_t leg = 0;  ///< 0-based: from waypoint leg to leg + 1
  double along_m = 0;   ///< from the route's start to the entry point
  Vec2 at{0.0, 0.0};    ///< the entry point, in the no-go's frame
  const EncNoGoFeature* feature = nullptr;
  double least_distance_m = 0;  ///< the leg's least distance to the feature (0: it enters or touches it)
};

struct ChartRouteCheck {
  bool safe = true;
  std::optional<ChartCrossing> first;
  std::size_t crossed_features = 0;  ///< distinct features some leg comes closer to than the margin
  double margin_m = 0;
  /// One line: "no leg comes within ..." or the first crossing with its
  /// feature, why it is no-go, and where (lon, lat and metres along the
  /// route): "crosses" when the leg enters the feature, "passes 3.20 m from"
  /// when it stays out of it but inside the margin.
  std::string describe(const LocalFrame& frame) const;
};

/// Checks `route` (waypoints in no_go.frame) against every feature. Throws
/// InputError for a negative or non-finite margin or fewer than two
/// waypoints, std::invalid_argument for a tolerance that is not finite and >= 0.
ChartRouteCheck check_route_on_chart(const std::vector<Vec2>& route, const EncNoGo& no_go, double margin_m,
                                     double tolerance_m = 1e-6);

/// The first no-go feature p lies in or closer than margin_m - tolerance_m to, or null.
const EncNoGoFeature* no_go_feature_at(const EncNoGo& no_go, const Vec2& p, double margin_m, double tolerance_m = 1e-6);

}  // namespace deepguide
