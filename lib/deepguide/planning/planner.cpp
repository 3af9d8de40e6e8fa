#include "deepguide/planning/planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/prepared_graphs.hpp"
#include "deepguide/planning/route_finishing.hpp"
#include "deepguide/planning/turn_rounding.hpp"

namespace deepguide {

namespace {

// The least margin the graphs plan with (PlannerOptions::margin): zero-width
// gaps between touching obstacles are closed. 1 um, or a ten-billionth of the
// largest coordinate where that is more: zones buffered by micrometres at UTM
// coordinates (6e6 m, where a double's step is 1e-9 m) came out within a few
// micrometres of where they belong, and two squares touching at a corner
// merged into a pinch the route went through (issue 39: "internal error: the
// planned route failed the independent check" at margins 1e-6 to 1e-5 m).
double min_graph_margin(const ObstacleSet& obstacles) {
  const auto [lo, hi] = footprint_box(obstacles);
  const bool any = (lo.array() <= hi.array()).all();
  const double largest = any ? std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff()) : 0.0;
  return std::max(1e-6, 1e-10 * largest);
}

double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

struct Planner::Impl {
  explicit Impl(ObstacleField f) : field(std::move(f)) {}
  ObstacleField field;  // before the graph, which may hold a reference to it
  GraphCapabilities can;
  std::unique_ptr<RouteGraph> graph;
  double build_ms = 0.0;
  double graph_margin = 0.0;  // GraphBuild::margin
  bool prepared = false;      // the graph was read from PlannerOptions::prepared
  // With a turning radius: the tangent graph without it, built when no route
  // is found, to say where the radius closes the way.
  std::unique_ptr<RouteGraph> plain;
};

namespace {

// A graph kept for the prepared chart's obstacles alone
// (PlannerOptions::prepared_obstacles), loaded and given the obstacles beyond
// them; null when none is kept for them at this margin, when they are not
// all among `all.obstacles`, or when the graph cannot take more.
std::unique_ptr<RouteGraph> extended_kept_graph(const GraphEntry& entry, const GraphBuild& all) {
  const PlannerOptions& options = all.options;
  if (!options.prepared || !options.prepared_obstacles || !entry.save || !entry.insert) return nullptr;
  const ObstacleSet& part = *options.prepared_obstacles;
  GraphBuild build{part, all.field, options, all.focus, std::max(options.margin, min_graph_margin(part))};
  if (build.margin != all.margin) return nullptr;  // the zones would be made at another margin
  const PreparedGraphRecord* record = find_prepared(*options.prepared, entry.name, prepared_graph_key(build));
  if (record == nullptr) return nullptr;
  const std::optional<ObstacleSet> beyond = obstacles_beyond(all.obstacles, part);
  if (!beyond) return nullptr;
  build.prepared = &record->data;
  std::unique_ptr<RouteGraph> graph;
  try {
    graph = entry.build(build);
  } catch (const InputError& e) {
    throw InputError(printable(record->source, 240) + ": table deepguide_graphs, graph '" + entry.name +
                     "': " + e.what());
  }
  if (graph) entry.insert(*graph, *beyond);
  return graph;
}

}  // namespace

Planner::Planner(ObstacleSet obstacles, const PlannerOptions& options, const QueryFocus& focus) : options_(options) {
  // 100 km is far beyond any safety margin, and keeps the zones' polygons
  // (corners ~ sqrt(margin / tolerance)) within what can be built.
  if (!std::isfinite(options.margin) || options.margin < 0.0 || options.margin > 1e5) {
    throw InputError("`margin`: expected a safety margin from 0 m to 100 km, got " + general(options.margin));
  }
  if (!std::isfinite(options.tolerance) || options.tolerance <= 0.0) {
    throw InputError("`tolerance`: expected a polygon tolerance > 0 m, got " + std::to_string(options.tolerance));
  }
  const GraphEntry& entry = graph_entry(options.graph);
  if (entry.can.in_depth || !entry.build) {
    throw InputError("`graph` " + entry.name +
                     ": plans in depth (depth_planning.hpp), not among obstacles in the plane");
  }
  const bool weighed = options.cost != nullptr && options.cost->kind != CostKind::length;
  if (weighed) validate(*options.cost);
  if (weighed && !entry.can.weighs_cost) {
    throw InputError("`cost` " + to_string(options.cost->kind) + ": expected `graph` " +
                     graph_names_text([](const GraphEntry& e) { return e.can.weighs_cost; }) + " (the " + entry.name +
                     " graph prices by length only)");
  }
  if (options.grid.active() && !entry.can.open_water_grid) {
    throw InputError("`waypoint_grid`: expected `graph` " +
                     graph_names_text([](const GraphEntry& e) { return e.can.open_water_grid; }) + " (the " +
                     entry.name + " graph has no open-water vertices)");
  }
  if (!std::isfinite(options.turn_radius_m) || options.turn_radius_m < 0.0) {
    throw InputError("turn radius: expected a radius > 0 m (or 0 for none), got " + general(options.turn_radius_m));
  }
  if (options.turn_radius_m > 0.0 && entry.can.steps && !options.quadtree.smooth) {
    // The graphs that keep the radius themselves first, then those the Planner rounds.
    const std::string itself = graph_names_text(
        [](const GraphEntry& e) { return e.can.turn_radius && !e.can.steps && !e.can.finished_by_planner; });
    const std::string rounded = graph_names_text(
        [](const GraphEntry& e) { return e.can.turn_radius && !e.can.steps && e.can.finished_by_planner; });
    throw InputError("turn radius: expected `graph` " + itself + (itself.empty() || rounded.empty() ? "" : ", ") +
                     rounded + ", or " + graph_names_text([](const GraphEntry& e) { return e.can.steps; }) +
                     " with `smooth` (the " + entry.name + " graph's cell-to-cell steps cannot be rounded)");
  }
  if (options.turn_radius_m > 0.0 && !entry.can.turn_radius) {
    throw InputError("turn radius: expected `graph` " +
                     graph_names_text([](const GraphEntry& e) { return e.can.turn_radius; }) + " (the " + entry.name +
                     " graph keeps no turning radius)");
  }
  impl_ = std::make_unique<Impl>(ObstacleField(obstacles, options.margin));
  impl_->can = entry.can;
  const auto started = std::chrono::steady_clock::now();
  // The field's own copy of the obstacles: a graph may keep a reference to it.
  const ObstacleSet& kept = impl_->field.obstacles();
  impl_->graph_margin = std::max(options.margin, min_graph_margin(kept));
  GraphBuild build{kept, impl_->field, options, focus, impl_->graph_margin};
  const PreparedGraphRecord* kept_graph = options.prepared && entry.save
                                              ? find_prepared(*options.prepared, entry.name, prepared_graph_key(build))
                                              : nullptr;
  if (kept_graph == nullptr) impl_->graph = extended_kept_graph(entry, build);
  if (impl_->graph) {
    impl_->prepared = true;
  } else if (kept_graph != nullptr) {
    build.prepared = &kept_graph->data;
    try {
      impl_->graph = entry.build(build);
    } catch (const InputError& e) {
      throw InputError(printable(kept_graph->source, 240) + ": table deepguide_graphs, graph '" + entry.name +
                       "': " + e.what());
    }
    impl_->prepared = true;
  } else {
    impl_->graph = entry.build(build);
  }
  if (!impl_->graph) throw InputError("graph '" + entry.name + "': its build function returned no graph");
  impl_->build_ms = elapsed_ms(started);
}

Planner::~Planner() = default;
Planner::Planner(Planner&&) noexcept = default;
Planner& Planner::operator=(Planner&&) noexcept = default;

const ObstacleField& Planner::field() const { return impl_->field; }

PreparedGraphRecord Planner::save_graph() const {
  const GraphEntry& entry = graph_entry(options_.graph);
  if (!entry.save) {
    throw InputError("graph '" + entry.name + "': cannot be prepared (expected " +
                     graph_names_text([](const GraphEntry& e) { return static_cast<bool>(e.save); }) + ")");
  }
  const GraphBuild build{impl_->field.obstacles(), impl_->field, options_, QueryFocus{}, impl_->graph_margin};
  return {entry.name, prepared_graph_key(build), "", entry.save(*impl_->graph), ""};
}
void Planner::insert(const ObstacleSet& found) {
  const GraphEntry& entry = graph_entry(options_.graph);
  if (!entry.insert) {
    throw InputError("graph '" + entry.name + "': cannot take obstacles after its build (expected " +
                     graph_names_text([](const GraphEntry& e) { return static_cast<bool>(e.insert); }) + ")");
  }
  if (found.empty()) return;
  ObstacleSet all = impl_->field.obstacles();
  all.ellipses.insert(all.ellipses.end(), found.ellipses.begin(), found.ellipses.end());
  all.polygons.insert(all.polygons.end(), found.polygons.begin(), found.polygons.end());
  ObstacleField field(std::move(all), options_.margin);  // checks them before the graph changes
  entry.insert(*impl_->graph, found);
  // Move-assigned: a graph holding a reference to the field sees the new one.
  impl_->field = std::move(field);
}

RouteGraph& Planner::graph() { return *impl_->graph; }
const RouteGraph& Planner::graph() const { return *impl_->graph; }

namespace {

void require_free(const ObstacleField& field, const Vec2& p, const char* which) {
  const ObstacleField::Nearest n = field.segment_clearance(p, p);
  // A point exactly on the zone boundary is free; rounding gets a micrometre.
  if (n.distance >= field.margin() - 1e-6) return;
  throw NoRouteError(std::string(which) + " lies " + fixed(n.distance, 2) + " m from obstacle '" +
                     printable(field.obstacle_name(n.obstacle)) + "', inside its " + fixed(field.margin(), 2) +
                     " m safety zone");
}

// Closest point of an obstacle's footprint boundary to p.
Vec2 closest_boundary_point(const ObstacleSet& set, std::size_t obstacle, const Vec2& p) {
  if (obstacle < set.ellipses.size()) return project_to_ellipse(set.ellipses[obstacle].footprint, p).point;
  const BgPolygon& poly = set.polygons.at(obstacle - set.ellipses.size()).footprint;
  Vec2 best = p;
  double best_d = std::numeric_limits<double>::infinity();
  auto ring = [&](const auto& r) {
    for (std::size_t i = 0; i + 1 < r.size(); ++i) {
      const Vec2 a = to_eigen(r[i]), d = to_eigen(r[i + 1]) - a;
      const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      const Vec2 q = a + t * d;
      if ((q - p).norm() < best_d) best_d = (q - p).norm(), best = q;
    }
  };
  ring(poly.outer());
  for (const auto& inner : poly.inners()) ring(inner);
  return best;
}

// The shortest way out of the zone that holds p: along the line from the
// nearest footprint point through p (away from the interior), to a point a
// micrometre beyond the margin.
Vec2 escape_point(const ObstacleField& field, const Vec2& p, std::string& obstacle_name) {
  const ObstacleField::Nearest n = field.segment_clearance(p, p);
  obstacle_name = field.obstacle_name(n.obstacle);
  const Vec2 q = closest_boundary_point(field.obstacles(), n.obstacle, p);
  Vec2 out = p - q;
  if (out.norm() == 0.0) {
    throw NoRouteError("the start lies on the boundary of obstacle '" + printable(obstacle_name) +
                       "' where no way out can be told; move it off the boundary");
  }
  out.normalize();
  if (n.distance < 0.0) out = -out;  // inside the footprint: leave through q
  const Vec2 e = q + (field.margin() + 1e-6) * out;
  if (!field.is_free(e)) {
    const ObstacleField::Nearest other = field.segment_clearance(e, e);
    throw NoRouteError("the shortest way out of obstacle '" + printable(obstacle_name) +
                       "''s safety zone ends in obstacle '" + printable(field.obstacle_name(other.obstacle)) +
                       "''s zone");
  }
  return e;
}

}  // namespace

// Where the turning radius closes the way: the first turn of the shortest
// route without it that is tighter than the radius.
std::string Planner::why_no_turning_route(const PlanningProblem& problem) {
  const std::string radius = general(options_.turn_radius_m) + " m";
  const std::string none =
      "no route keeps the " + general(options_.margin) + " m margin turning no tighter than " + radius;
  if (!impl_->plain) {
    PlannerOptions turning_freely = options_;
    turning_freely.graph = GraphKind::tangent;
    turning_freely.turn_radius_m = 0.0;
    turning_freely.cost = nullptr;
    turning_freely.grid = {};
    const ObstacleSet& obstacles = impl_->field.obstacles();
    impl_->plain = graph_entry(GraphKind::tangent)
                       .build(GraphBuild{obstacles, impl_->field, turning_freely, QueryFocus{},
                                         std::max(options_.margin, min_graph_margin(obstacles))});
  }
  PlanningProblem free_ends = problem;
  free_ends.start_heading.reset();
  free_ends.goal_heading.reset();
  const PlanResult plain = impl_->plain->solve(free_ends, options_.search, nullptr, SearchBudget{});
  if (!plain.found) return plain.message;
  for (const RouteLeg& leg : plain.legs) {
    if (min_turn_radius(leg) < options_.turn_radius_m) {
      return none + "; the shortest route without that limit turns round obstacle '" + printable(leg.obstacle) +
             "' at " + point_text(0.5 * (leg.from + leg.to), 1) + " on a " + fixed(min_turn_radius(leg), 1) +
             " m radius";
    }
  }
  if (problem.start_heading || problem.goal_heading) {
    return none + " leaving and arriving on the headings given (a route free to turn at its ends exists)";
  }
  return none;
}

PlanOutcome Planner::solve(const PlanningProblem& problem) {
  if (!problem.start.allFinite() || !problem.goal.allFinite()) {
    throw InputError("start and goal: expected finite coordinates");
  }
  if ((problem.start - problem.goal).norm() < 1e-9) {
    throw InputError("start and goal: expected two different points, got the same one");
  }
  if (problem.start_heading || problem.goal_heading) {
    // Dubins ends are circles of the tangent graph (tangent_graph.hpp); the
    // polygon graphs would need them as polygons and fillets of their own.
    const char* which = problem.start_heading ? "a start heading" : "a goal heading";
    if (!impl_->can.dubins_ends) {
      throw InputError(std::string(which) + ": expected the " +
                       graph_names_text([](const GraphEntry& e) { return e.can.dubins_ends; }) +
                       " graph (the graph that plans Dubins ends), got " + to_string(options_.graph));
    }
    if (!(options_.turn_radius_m > 0.0)) throw InputError(std::string(which) + ": expected a turning radius > 0");
    if (problem.escape && problem.start_heading && !impl_->field.is_free(problem.start)) {
      throw InputError(
          "a start heading: expected a start outside every safety zone (an escape leaves the zone "
          "along its normal, whatever the heading)");
    }
  }
  std::string escaped_from;
  PlanningProblem inner = problem;
  if (problem.escape && !impl_->field.is_free(problem.start)) {
    inner.start = escape_point(impl_->field, problem.start, escaped_from);
    inner.escape = false;
    PlanOutcome out = solve(inner);
    if (out.result.found) {
      out.result.route.points.insert(out.result.route.points.begin(), problem.start);
      // The escape is sailed too: where the graph gives lines and arcs, it is
      // the first line, and the exact length holds it (it left it out).
      if (!out.result.legs.empty()) {
        RouteLeg escape;
        escape.from = problem.start;
        escape.to = inner.start;
        escape.length_m = (inner.start - problem.start).norm();
        out.result.legs.insert(out.result.legs.begin(), escape);
        out.result.exact_length_m += escape.length_m;
      }
    }
    out.escaped_from = escaped_from;
    return out;
  }
  require_free(impl_->field, problem.start, "the start");
  require_free(impl_->field, problem.goal, "the goal");

  PlanOutcome out;
  const auto started = std::chrono::steady_clock::now();
  out.result = impl_->graph->solve(problem, options_.search, options_.cost.get(), options_.budget);
  out.result.stats.build_ms = impl_->build_ms;
  out.result.stats.prepared = impl_->prepared;
  out.result.stats.query_ms = elapsed_ms(started);
  bool rounding_failed = impl_->can.finished_by_planner && !refine_and_round(out.result, impl_->field, options_);
  out.check = check_route(out.result.found ? out.result.route.points : std::vector<Vec2>{problem.start}, impl_->field);
  if (out.result.found && !out.result.legs.empty()) out.legs_check = check_route_legs(out.result.legs, impl_->field);
  // A rounded polygon route whose joined corners or fillets come near another
  // zone is refused, saying where, rather than returned to fail the check.
  const bool rounded = out.result.found && options_.turn_radius_m > 0.0 && impl_->can.finished_by_planner;
  if (rounded && (!out.check.safe || !out.legs_check->safe)) {
    const RouteCheck& bad = out.check.safe ? *out.legs_check : out.check;
    out.result.found = false;
    out.result.message =
        unrounded_message(options_, bad.worst_point, "rounding its corners comes within the margin of another zone");
    rounding_failed = true;
  }
  if (out.result.stats.stopped != SearchStop::none) {
    // However the graph put it: out of budget, nothing is proven.
    out.result.found = false;
    out.result.message = search_stop_message(out.result.stats.stopped, out.result.stats.expanded);
  } else if (!out.result.found && !rounding_failed && options_.turn_radius_m > options_.margin) {
    out.result.message = why_no_turning_route(problem);
  }
  return out;
}

}  // namespace deepguide
