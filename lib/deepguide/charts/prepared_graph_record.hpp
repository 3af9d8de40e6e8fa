#pragma once
// A planning graph built once over a prepared chart's obstacles and kept in
// the chart's GeoPackage (`chart prepare --graphs`, the "deepguide_graphs"
// table). The charts module only stores and returns the bytes; the planning
// module makes them and says when they fit a query (prepared_graphs.hpp).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct PreparedGraphRecord {
  std::string graph;  ///< the graph's registry name ("navmesh")
  /// What it was built from (prepared_graph_key): taken only when a query's
  /// obstacles and options give the same key.
  std::string key;
  std::string about;  ///< a line for people: its size, how long it took
  std::vector<std::uint8_t> data;
  std::string source;  ///< the file it was read from (messages); empty when made here
};

/// Makes the records for a chart's obstacles as a planner will read them back.
using PreparedGraphsMaker = std::function<std::vector<PreparedGraphRecord>(const ObstacleSet& as_read)>;

}  // namespace deepguide
