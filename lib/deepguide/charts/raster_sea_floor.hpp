#pragma once
// The sea floor (world/sea_floor.hpp) sampled from a bathymetry raster.

#include <string>

#include "deepguide/charts/bathymetry.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/sea_floor.hpp"

namespace DEEPGUIDE_API deepguide {

/// Samples a bathymetry raster (bathymetry.hpp: any GDAL raster, its sign
/// convention) at nodes `spacing` apart over [area_min, area_max] in the
/// frame, never deeper than the chart: GDAL warps it into the frame's CRS
/// taking each node's shallowest cell value, and each node then takes the
/// shallowest of its 3 x 3 neighbours (so no bilinear patch dips below the
/// chart's shallowest point in it); no data is depth 0. A spacing of 0
/// takes the raster's own cell size.
/// Throws InputError as inspect_bathymetry does, and for an area the raster
/// does not reach at all.
SeaFloor raster_sea_floor(const std::string& path, const LocalFrame& frame, const Vec2& area_min, const Vec2& area_max,
                          double spacing, const BathymetryOptions& options = {});

}  // namespace deepguide
