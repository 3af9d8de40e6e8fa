#pragma once
// A planner's graph as layers of a route figure (route_scene.hpp): its edges,
// the zone polygons of a visibility graph, a quadtree's free and occupied
// cells. Each graph's extras are reached by type (RouteGraph::as).

#include "deepguide/core/api.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/render/route_scene.hpp"

namespace DEEPGUIDE_API deepguide {

/// Adds the layers; the scene then points into `planner`, which must outlive it.
void add_graph_layers(const Planner& planner, RouteScene& scene);

}  // namespace deepguide
