#pragma once
// Replanning on new detections (the seed names D*): a vehicle follows its
// quadtree route; whenever the sonar reports an obstacle nobody knew, the
// edges it blocks become impassable and D* Lite (dstar_lite.hpp) repairs the
// route from where the vehicle is, instead of planning it again.
//
// Replay: detections are taken in the order of `along_m`, the distance the
// vehicle has sailed along its route when the report comes. The vehicle
// moves vertex by vertex (cell centre to cell centre) along the current
// route; a report that comes during a leg is acted on at the leg's end, the
// next decision point. Routes are weighed by length. The graph keeps the
// blocked edges afterwards (it is the map as the vehicle knows it then).
//
// On the navigation mesh (`--graph navmesh`) the vehicle sails the exact
// route and acts where the report reaches it: the obstacles' zones are cut
// out of the mesh round them (NavMeshGraph::insert) and Polyanya finds the
// shortest route again from there. The mesh keeps them afterwards.

#include <functional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh_graph.hpp"
#include "deepguide/planning/graphs/quadtree/quadtree_graph.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

/// A sonar report along the route (replan_events.csv): the obstacles it
/// reveals and how far the vehicle has sailed when it comes (vehicle/sonar.hpp
/// has the sonar's own Detection).
struct ReplanEvent {
  double along_m = 0.0;   ///< distance sailed when the sonar reports it (m)
  ObstacleSet obstacles;  ///< what it reports (usually one obstacle)
};

struct Repair {
  double along_m = 0.0;            ///< distance sailed when the route was repaired (at a vertex)
  Vec2 vehicle{0.0, 0.0};          ///< where the vehicle was
  std::size_t blocked_edges = 0;   ///< quadtree: directed edges the detection blocked (not blocked before)
  std::size_t remeshed_faces = 0;  ///< navmesh: faces taken out and triangulated anew
  bool found = false;
  std::vector<Vec2> route;   ///< from the vehicle to the goal
  double cost = 0.0;         ///< its length (+inf when none)
  std::size_t expanded = 0;  ///< vertices D* Lite processed (navmesh: Polyanya's nodes) for this repair
  double repair_ms = 0.0;    ///< blocking the edges and repairing (navmesh: inserting and searching)
};

struct Replay {
  std::vector<Vec2> initial_route;  ///< D* Lite's first route: the one the vehicle sails until a report
  double initial_cost = 0.0;
  std::vector<Repair> repairs;              ///< one per detection, in order
  std::vector<Vec2> track;                  ///< every vertex the vehicle reached, start first
  std::vector<GraphVertex> track_vertices;  ///< quadtree only
  bool reached_goal = false;
  bool remeshed = false;  ///< repaired on the navigation mesh (Repair::remeshed_faces), not by D* Lite
};

/// Reads detections from an obstacle file (any format load_obstacles reads,
/// docs/FORMATS.md) whose features also carry `detected_at_m`, the distance
/// sailed when the sonar reports them; one detection per feature, in the
/// local frame `frame`. Throws InputError naming the file, the feature and
/// the field for a missing, non-numeric or negative value.
std::vector<ReplanEvent> load_detections(const std::string& path, const LocalFrame& frame,
                                         const std::string& source_crs = "");

/// Plans from start to goal on `graph`, then replays the detections (with
/// the given safety margin around each). Throws NoRouteError when start or
/// goal lies outside the area or no first route exists, InputError for a
/// detection with a negative or non-finite along_m.
/// `after_repair(repair, vehicle_vertex)`, when given, runs after each repair
/// while start and goal are still attached (graph.goal_vertex()): tests and
/// benchmarks compare with a search from scratch on the changed graph there.
Replay replay_detections(QuadtreeGraph& graph, const PlanningProblem& problem, std::vector<ReplanEvent> detections,
                         double margin, const std::function<void(const Repair&, GraphVertex)>& after_repair = {});

/// The same replay on the navigation mesh (see above); the detections'
/// zones are made at the margin the graph was built with. Throws as the
/// quadtree's replay.
Replay replay_detections(NavMeshGraph& graph, const PlanningProblem& problem, std::vector<ReplanEvent> detections);

}  // namespace deepguide
