#pragma once
// The quadtree graph's options (quadtree_graph.hpp), apart from the graph so
// that PlannerOptions can hold them without the graph's header.

#include <cstddef>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

struct QuadtreeOptions {
  double min_cell_m = 2.0;  ///< the smallest cell side (m), > 0
  Vec2 area_min{0.0, 0.0};  ///< the work area (local frame); the root is the square over it
  Vec2 area_max{0.0, 0.0};
  bool smooth = false;
  /// Refused above this many cells (InputError): a free cell costs about
  /// 1 KiB with its edges, so 2 million is about 2 GiB.
  std::size_t max_cells = 2'000'000;
};

}  // namespace deepguide
