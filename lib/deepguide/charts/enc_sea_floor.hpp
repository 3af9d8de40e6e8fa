#pragma once
// A sea floor never deeper than S-57 cells chart it, for what plans in depth
// (missions, `plan --graph octree`): the cells' features are judged as for
// the no-go (enc_no_go.hpp) with every depth too shallow, so each depth area,
// danger and sounding comes back with its least depth (charted depth less
// its zone of confidence's uncertainty), and is burned into a grid of nodes
// `spacing` apart, deepest first, so that each node keeps the shallowest
// depth touching its cell (GDAL's rasterizer, all touched). Land, unsurveyed
// areas, structures and dangers of unknown depth are land (depth -1); water
// no cell covers has no data (depth 0: no water to dive in). Point hazards
// burn a disc of their position accuracy. Each node then takes the shallowest
// of its 3 x 3 neighbours, as raster_sea_floor does, so no bilinear
// patch dips below the chart.

#include <string>
#include <vector>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/world/sea_floor.hpp"

namespace DEEPGUIDE_API deepguide {

/// The floor over [lo, hi] in `frame`. Throws what enc_no_go throws, and
/// InputError for a spacing that is not finite and > 0 or an empty box.
SeaFloor enc_sea_floor(const std::vector<std::string>& charts, const LocalFrame& frame, const Vec2& lo, const Vec2& hi,
                       double spacing, EncNoGoOptions options = {});

}  // namespace deepguide
