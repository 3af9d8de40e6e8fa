#pragma once
// A planned route in the local frame, and what every planner reports with it.

#include <cstddef>
#include <string>
#include <vector>

#include "deepguide/geometry/ellipse.hpp"

namespace deepguide {

struct Route {
  std::vector<Vec2> points;  ///< waypoints from start to goal, local frame (m)
  double length() const;
};

/// What a planner measured while solving; every planner fills what applies.
struct PlanStats {
  std::size_t graph_vertices = 0;
  std::size_t graph_edges = 0;
  std::size_t expanded = 0;   ///< vertices the search examined
  double build_ms = 0.0;      ///< building the environment's graph (once per environment)
  double query_ms = 0.0;      ///< attaching start and goal plus the search
};

/// One planning request in the local frame.
struct PlanningProblem {
  Vec2 start;
  Vec2 goal;
};

/// The common result of every planner's solve(problem).
struct PlanResult {
  bool found = false;
  Route route;
  PlanStats stats;
  std::string message;  ///< why no route was found, one line
};

}  // namespace deepguide
