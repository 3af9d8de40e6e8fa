#pragma once
// Graphs built once and kept (a prepared chart's "deepguide_graphs" table,
// prepared_graph_record.hpp), and when a kept one may stand in for a build.
//
// Its key names what the build reads: the obstacles' footprints (their
// fingerprint, bit for bit), the graph margin, the polygon tolerance and the
// turning radius (the zone polygons are made of exactly these,
// graph_zones.hpp). A Planner takes a kept graph only under the same key;
// another margin, an obstacle more, another frame, and the graph is built as
// if none were kept, never silently used for what it was not built for. A
// graph whose build reads more than these must not offer `save` until the
// key names it too.

#include <string>
#include <vector>

#include "deepguide/charts/prepared_graph_record.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/planner_options.hpp"

namespace DEEPGUIDE_API deepguide {

/// The key of the graph built from `in`.
std::string prepared_graph_key(const GraphBuild& in);

/// The record of `graph` under `key` among `kept`; null when there is none.
const PreparedGraphRecord* find_prepared(const std::vector<PreparedGraphRecord>& kept, const std::string& graph,
                                         const std::string& key);

/// What `chart prepare --graphs` gives prepare_chart (prepared_chart.hpp):
/// each of `graphs` built over the obstacles as read back, with `options`'
/// margin, tolerance and turning radius, and saved. InputError for a graph
/// whose entry cannot save, before anything is built.
PreparedGraphsMaker graph_preparer(const std::vector<GraphKind>& graphs, const PlannerOptions& options);

}  // namespace deepguide
