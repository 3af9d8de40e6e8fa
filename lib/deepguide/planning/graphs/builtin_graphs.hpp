#pragma once
// The graphs the library comes with, in the order `--graph`'s help lists
// them: the registry (graph_registry.hpp) starts with these entries.

#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/graph_registry.hpp"

namespace DEEPGUIDE_API deepguide {

/// visibility, visibility-full, tangent, navmesh, quadtree, octree.
std::vector<GraphEntry> builtin_graph_entries();

}  // namespace deepguide
