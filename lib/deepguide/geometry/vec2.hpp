#pragma once
// The 2-D vector of the local frame: x = easting, y = northing (m).

#include <Eigen/Core>

namespace deepguide {
using Vec2 = Eigen::Vector2d;
}  // namespace deepguide
