#include "deepguide/planning/planner_options.hpp"

#include "deepguide/core/error.hpp"
#include "deepguide/planning/graph_registry.hpp"

namespace deepguide {

GraphKind parse_graph_kind(const std::string& text) { return GraphKind{graph_entry(GraphKind{text}).name}; }

SearchAlgorithm parse_search(const std::string& text) {
  if (text == "astar") return SearchAlgorithm::astar;
  if (text == "dijkstra") return SearchAlgorithm::dijkstra;
  throw InputError("`search`: expected astar or dijkstra, got '" + text + "'");
}

std::string to_string(const GraphKind& kind) { return kind.name; }
std::string to_string(SearchAlgorithm a) { return a == SearchAlgorithm::astar ? "astar" : "dijkstra"; }

}  // namespace deepguide
