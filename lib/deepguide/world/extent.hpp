#pragma once
// Longitude/latitude bounds of data, and where their middle is: the frame a
// work area gets by default is chosen from it, so data on both sides of the
// antimeridian must give a middle near 180, not near 0.

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// Longitude/latitude bounds (degrees). An extent across the antimeridian has
/// east > 180 (e.g. west 179.5, east 180.5): east - west is always its width.
struct LonLatExtent {
  double west = std::numeric_limits<double>::quiet_NaN();
  double east = std::numeric_limits<double>::quiet_NaN();
  double south = std::numeric_limits<double>::quiet_NaN();
  double north = std::numeric_limits<double>::quiet_NaN();

  bool empty() const { return !(west <= east && south <= north); }
  /// The middle, longitude in [-180, 180).
  Eigen::Vector2d centre() const;
};

/// The narrowest extent holding every point (lon, lat in degrees): across the
/// antimeridian when that is narrower than the plain bounds. Empty for none.
LonLatExtent extent_of(const std::vector<Eigen::Vector2d>& lonlat);

}  // namespace deepguide
