#pragma once
// Depths no sea has. S-57 cells and uncompressed rasters carry no checksum,
// so a flipped byte in a depth is a different number; where that number
// cannot be true it is the only sign of the damage, and it must not become a
// chart. Bounds with a margin: the Challenger Deep is about 10 935 m deep,
// Everest 8849 m high (negative depths are drying heights and land).

#include <cmath>
#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace DEEPGUIDE_API deepguide {

inline constexpr double kDeepestSea_m = 11100.0;
inline constexpr double kHighestLand_m = 9000.0;

/// InputError "WHERE holds a depth of D m: expected ..." when `depth_m`
/// (positive down) is not finite or beyond the bounds.
inline void require_plausible_depth(double depth_m, const std::string& where) {
  if (std::isfinite(depth_m) && depth_m <= kDeepestSea_m && depth_m >= -kHighestLand_m) return;
  throw InputError(where + " holds a depth of " + fixed(depth_m, 1) + " m: expected one between " +
                   fixed(-kHighestLand_m, 0) + " and " + fixed(kDeepestSea_m, 0) +
                   " m (a damaged file, or a unit or sign the file does not state)");
}

}  // namespace deepguide
