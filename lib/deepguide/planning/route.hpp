#pragma once
// A planned route in the local frame, and what every planner reports with it.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"

namespace DEEPGUIDE_API deepguide {

struct Route {
  std::vector<Vec2> points;  ///< waypoints from start to goal, local frame (m)
  /// Routes in depth (the octree graph): each waypoint's depth (m, positive
  /// down); empty for routes at one operating depth.
  std::vector<double> depth_m = {};
  /// Along the legs: in 3-D when the route has depths.
  double length() const;
  /// The point `s` metres along the route's horizontal track (clamped to its ends).
  Vec2 point_at(double s) const;
};

/// A leg of a route made of the seed's basic manoeuvres: a straight line, or
/// an arc along a safety zone's boundary (a circle of radius `radius_m` for
/// discs and polygon corners; an offset-ellipse arc otherwise).
struct RouteLeg {
  enum class Kind { line, arc };
  Kind kind = Kind::line;
  Vec2 from, to;
  double length_m = 0.0;
  int turn = 0;           ///< arcs: +1 anticlockwise (turning left), -1 clockwise
  double radius_m = 0.0;  ///< arcs: largest radius of curvature along the arc
  std::string obstacle;   ///< arcs: the obstacle whose zone the arc follows
  /// Arcs: the curve itself, the boundary of core (+) disc(offset_m) from the
  /// point whose outward normal has angle phi_from to the one at phi_to
  /// (phi_to - phi_from has the sign of turn). A circle when core.a == core.b:
  /// centre core.centre, radius core.a + offset_m.
  Ellipse core{{0.0, 0.0}, 0.0, 0.0, 0.0};
  double offset_m = 0.0;
  double phi_from = 0.0, phi_to = 0.0;
};

/// The unit direction of travel where a leg begins (at_end = false) or ends.
Vec2 leg_direction(const RouteLeg& leg, bool at_end);
/// A line leg from a to b.
RouteLeg line_leg(const Vec2& from, const Vec2& to);
/// An arc leg on the circle of `radius` round `centre`, from the point at
/// normal angle phi_from, turning by `sweep` rad (anticlockwise > 0).
RouteLeg circle_leg(const Vec2& centre, double radius, double phi_from, double sweep);
/// An arc leg's point with outward normal angle phi (between phi_from and phi_to).
Vec2 arc_point(const RouteLeg& leg, double phi);
/// Radius of curvature of the boundary of ellipse (+) disc(offset) at the
/// point whose outward normal has angle phi: a^2 b^2 / h^3 + offset with
/// h = sqrt(a^2 cos^2 psi + b^2 sin^2 psi), psi = phi - theta (h = 0: offset).
double offset_ellipse_radius(const Ellipse& e, double offset, double phi);
/// Its least value over normal angles [lo, hi]: at an end or at a tip
/// (psi = 0 or pi) inside, as it grows monotonically from the tips to the sides.
double least_offset_ellipse_radius(const Ellipse& e, double offset, double lo, double hi);
/// An arc leg's least radius of curvature (m); +inf for a line.
double min_turn_radius(const RouteLeg& leg);

/// What a planner measured while solving; every planner fills what applies.
/// Limits on one search: at most `max_expansions` vertices examined (0: no
/// limit), and `cancelled()`, asked every 256 expansions, ends it early (a
/// replanning deadline on the vehicle, a user's interrupt).
struct SearchBudget {
  std::size_t max_expansions = 0;
  std::function<bool()> cancelled = {};
  bool limited() const { return max_expansions > 0 || static_cast<bool>(cancelled); }
};

/// Why a search ended before it examined its target: it did not (none), its
/// budget ran out, or it was cancelled.
enum class SearchStop { none, budget, cancelled };

struct PlanStats {
  std::size_t graph_vertices = 0;
  std::size_t graph_edges = 0;
  std::size_t open_water_vertices = 0;    ///< of graph_vertices, lattice points (--waypoint-grid)
  std::size_t expanded = 0;               ///< vertices the search examined
  SearchStop stopped = SearchStop::none;  ///< the search's budget ran out, or it was cancelled (PlannerOptions::budget)
  double build_ms = 0.0;                  ///< building the environment's graph (once per environment)
  bool prepared = false;                  ///< the graph was read from a prepared chart, not built
  double query_ms = 0.0;                  ///< attaching start and goal plus the search
  /// Continuous refinement of a time or energy route (route_refinement.hpp).
  std::size_t refine_sweeps = 0;
  double refine_gain = 0.0;  ///< the fraction of the graph route's cost it saved
  double refine_ms = 0.0;
};

/// One planning request in the local frame.
struct PlanningProblem {
  Vec2 start;
  Vec2 goal;
  /// A start inside a safety zone first leaves it the shortest way (straight
  /// out along the normal of the nearest obstacle) instead of being refused.
  bool escape = false;
  /// Dubins ends: the direction the vehicle has at the start and must have at
  /// the goal (math angles in the local frame, rad). They need a turning
  /// radius, and only the tangent graph plans them (Planner refuses others).
  std::optional<double> start_heading = std::nullopt;
  std::optional<double> goal_heading = std::nullopt;
};

/// The common result of every planner's solve(problem).
struct PlanResult {
  bool found = false;
  Route route;                  ///< a polyline; curved legs are approximated from outside
  std::vector<RouteLeg> legs;   ///< exact lines and arcs, where the planner knows them
  double exact_length_m = 0.0;  ///< length of the legs (0 when legs is empty)
  double cost = 0.0;  ///< the route's cost: metres, or the cost model's s or J (the search's, or the refined route's)
  PlanStats stats;
  std::string message;  ///< why no route was found, one line
};

}  // namespace deepguide
