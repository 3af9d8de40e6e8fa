// The quadtree's entry in the graph registry: how it is built from the
// Planner's obstacles and options, and its area for one query.
#include <algorithm>
#include <optional>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/graphs/quadtree/quadtree_graph.hpp"
#include "deepguide/planning/turn_rounding.hpp"

namespace deepguide {
namespace {

// The area when none is given. For one query (an active focus), the
// start-goal box widened by half their distance (at least ten cells): a cell
// graph covers a box, not the focus's ellipse. Else the zones' box, widened
// by a tenth (at least ten cells) on every side.
QuadtreeOptions quadtree_area(const ObstacleSet& obstacles, QuadtreeOptions q, double margin, const QueryFocus& focus) {
  if (focus.active()) {
    const Vec2 s = focus.start, g = focus.goal;
    // Cells wider than half the trip cannot tell the water between start and
    // goal apart: the route runs through centres far off (a 1.8 km trip at
    // --min-cell 1e5 became 314 km, every leg safe, the route absurd).
    const double widest = 0.5 * (g - s).norm();
    if (q.min_cell_m > widest && widest > 0.0) {
      throw InputError("`min_cell_m`: expected at most half the distance from start to goal (" + fixed(widest, 1) +
                       " m), got " + general(q.min_cell_m) + " m: larger cells cannot resolve the water between them");
    }
    if (!((q.area_max - q.area_min).minCoeff() > 0.0)) {
      const double pad = std::max(0.5 * (g - s).norm(), 10.0 * q.min_cell_m);
      q.area_min = s.cwiseMin(g) - Vec2::Constant(pad);
      q.area_max = s.cwiseMax(g) + Vec2::Constant(pad);
    }
    return q;
  }
  if ((q.area_max - q.area_min).minCoeff() > 0.0) return q;
  if (obstacles.empty()) throw InputError("quadtree: expected obstacles or a work area");
  const auto [lo, hi] = footprint_box(obstacles);
  const double pad = margin + std::max(0.1 * (hi - lo).maxCoeff(), 10.0 * q.min_cell_m);
  q.area_min = lo - Vec2::Constant(pad);
  q.area_max = hi + Vec2::Constant(pad);
  return q;
}

std::unique_ptr<RouteGraph> build_quadtree(const GraphBuild& in) {
  const PlannerOptions& o = in.options;
  const QuadtreeOptions area = quadtree_area(in.obstacles, o.quadtree, o.margin, in.focus);
  if (!(o.turn_radius_m > 0.0)) return std::make_unique<QuadtreeGraph>(in.field, area);
  // Within a turning radius the cells keep out of the turning circles too
  // (discs whose zones are the circles widened by the tolerance, as the
  // visibility graphs' 32-gons), and the tolerance beyond every zone: the
  // taut route then has room to lose the small zig-zags its corner cutting
  // leaves where it wraps a zone, which no fillet could round.
  ObstacleSet turning = in.obstacles;
  for (const TurningCircle& c : turning_circles(in.obstacles, o.margin, o.turn_radius_m)) {
    const double r = o.turn_radius_m - o.margin;
    turning.ellipses.push_back({"turning circle of " + in.field.obstacle_name(c.obstacle), Ellipse{c.centre, r, r, 0.0},
                                std::nullopt, std::nullopt});
  }
  return std::make_unique<QuadtreeGraph>(std::make_unique<const ObstacleField>(turning, o.margin + o.tolerance), area);
}

}  // namespace

GraphEntry quadtree_graph_entry() {
  GraphEntry e;
  e.name = GraphKind::quadtree.name;
  e.help = "free cells' centres, the seed's Fig. 7";
  e.can = {.weighs_cost = true,
           .turn_radius = true,
           .steps = true,
           .finished_by_planner = true,
           .repairs = true,
           .covers_area = true};
  e.build = build_quadtree;
  return e;
}

}  // namespace deepguide
