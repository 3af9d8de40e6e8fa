#pragma once
// The side latch that keeps a vehicle from flipping left and right of an
// object it is passing: the memory of the dipole method, and part of the
// geometric method's. Set when an object is first engaged (the geometric
// method's sector 1 or 3, the dipole method's object blocking the line of
// sight), kept while that object stays engaged, cleared when none is. The
// object is recognised in later scans by its centre (engaged_centre), not by
// its index, since the sonar's list can change order. The side convention
// is reactive_method.hpp's.

#include <cstddef>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

struct SideLatch {
  /// +1 / -1: the side of the object passed, as the sign of cross(target - centre, position - centre); 0 none
  int side = 0;
  std::ptrdiff_t engaged_object = -1;  ///< the object the side was latched for
  Vec2 engaged_centre{0.0, 0.0};       ///< its centre then (objects are re-reported every scan)
};

}  // namespace deepguide
