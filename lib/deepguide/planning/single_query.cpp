#include "deepguide/planning/single_query.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/informed_bound.hpp"

namespace deepguide {
namespace bg = boost::geometry;

namespace {

struct Disc {
  Vec2 centre;
  double radius;
};

// A disc holding the obstacle's footprint (before the margin).
Disc footprint_disc(const EllipticCylinder& c) { return {c.footprint.centre, c.footprint.a}; }
Disc footprint_disc(const PolygonObstacle& p) {
  BgBox box;
  bg::envelope(p.footprint, box);
  const Vec2 c = 0.5 * (to_eigen(box.min_corner()) + to_eigen(box.max_corner()));
  double r = 0.0;
  for (const BgPoint& pt : p.footprint.outer()) r = std::max(r, (to_eigen(pt) - c).norm());
  return {c, r};
}

// The first bound: a little longer than the straight line. Routes through
// random fields run 0.1 .. 1 % over it (docs/PERFORMANCE.md), and the graph
// over the band grows with its width (the band's half-width is
// D sqrt(k^2 - 1) / 2: 0.07 D at k = 1.01, 0.16 D at 1.05), so a tight first
// bound with an occasional second round beats a loose one.
constexpr double kFirstStretch = 1.01;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The bound after a focused round at `bound` found a route of reach `reach`
// past it (d: the straight line). That route lies in E(bound), where every
// obstacle was in the graph, so it is safe among all of them and the optimum
// reaches no farther: a round at its reach is final. Short of that, the
// ellipse's half-width sqrt(U^2 - d^2) / 2 doubles: a round's graph grows
// with the ellipse, so the rounds together cost about twice the last, where
// going straight to the reach of a poor first route costs what that route's
// ellipse holds (a 116 km transit across the Kachemak set: a first route of
// 169 km, and 30,000 corners in a round at 1.02 times it, where the optimum
// of 121.5 km needs a round at 121.5 km).
double widened(double bound, double reach, double d) {
  const double half_width = 2.0 * (std::sqrt(std::max(bound * bound - d * d, 0.0)) / 2.0);  // doubled
  const double doubled = std::sqrt(d * d + 4.0 * half_width * half_width);
  // The route's own reach, with room for round-off in its length, is final.
  return std::min(doubled, reach * (1.0 + 1e-9) + 1e-9);
}

}  // namespace

SingleQueryPlan plan_single_query(const ObstacleSet& obstacles, const PlanningProblem& problem,
                                  const PlannerOptions& options) {
  if (!problem.start.allFinite() || !problem.goal.allFinite()) {
    throw InputError("start and goal: expected finite coordinates");
  }
  const Vec2 s = problem.start, g = problem.goal;
  // Reach of an obstacle's zone polygon beyond its footprint, with room for rounding.
  const double reach = std::max(options.margin, 0.0) + std::max(options.tolerance, 0.0) + 1e-6;
  std::vector<double> low;  // lower bound of |x - s| + |x - g| over each obstacle's reach
  std::vector<Disc> discs;
  for (const auto& c : obstacles.ellipses) discs.push_back(footprint_disc(c));
  for (const auto& p : obstacles.polygons) discs.push_back(footprint_disc(p));
  // Beyond `farthest` every obstacle is in and the focus would prune next to
  // nothing: the last round is the plain graph over all obstacles.
  double farthest = 0.0;
  for (const Disc& d : discs) {
    const double centre = (d.centre - s).norm() + (d.centre - g).norm();
    low.push_back(centre - 2.0 * (d.radius + reach));
    farthest = std::max(farthest, centre + 2.0 * (d.radius + reach));
  }

  const bool weighed = options.cost != nullptr && options.cost->kind != CostKind::length;
  if (weighed) validate(*options.cost);
  const double per_metre = weighed ? cost_per_metre_lower_bound(*options.cost) : 1.0;

  SingleQueryPlan plan;
  plan.obstacles_total = obstacles.size();
  if (graph_entry(options.graph).can.covers_area) {
    plan.rounds = 1;
    plan.obstacles_used = obstacles.size();
    plan.bound_m = std::numeric_limits<double>::infinity();
    plan.planner = std::make_unique<Planner>(obstacles, options, QueryFocus{s, g, kFirstStretch * (g - s).norm()});
    plan.outcome = plan.planner->solve(problem);
    plan.build_ms = plan.outcome.result.stats.build_ms;
    plan.query_ms = plan.outcome.result.stats.query_ms;
    return plan;
  }
  double bound = kFirstStretch * (g - s).norm();
  bool focus = true;  // off for one round after a focused graph found nothing
  for (;;) {
    const bool last = !std::isfinite(bound);
    ObstacleSet subset;
    const std::size_t ne = obstacles.ellipses.size();
    for (std::size_t i = 0; i < ne; ++i) {
      if (low[i] <= bound) subset.ellipses.push_back(obstacles.ellipses[i]);
    }
    for (std::size_t i = 0; i < obstacles.polygons.size(); ++i) {
      if (low[ne + i] <= bound) subset.polygons.push_back(obstacles.polygons[i]);
    }
    ++plan.rounds;
    plan.obstacles_used = subset.size();
    plan.bound_m = bound;
    const bool focused = focus && !last;
    plan.planner =
        std::make_unique<Planner>(std::move(subset), options, focused ? QueryFocus{s, g, bound} : QueryFocus{});
    plan.outcome = plan.planner->solve(problem);
    plan.build_ms += plan.outcome.result.stats.build_ms;
    plan.query_ms += plan.outcome.result.stats.query_ms;
    // A route within the bound is the optimum over all obstacles (the
    // polyline is no shorter than the graph's path, so this errs on the side
    // of another round).
    const bool found = plan.outcome.result.found;
    // The longest route that can cost what this one does (its length when
    // weighed by length): a cheaper route is no longer, so it lies in E(bound).
    double reach = found ? plan.outcome.result.route.length() : 0.0;
    if (found && weighed) reach = price_route(*options.cost, plan.outcome.result.route.points).cost / per_metre;
    // Out of budget: nothing is proven, and the next round would run out too.
    if (plan.outcome.result.stats.stopped != SearchStop::none) break;
    // No route in the whole graph over some of the obstacles: none among all.
    if (!found && !focused) break;
    // No route in a focused graph proves nothing (the focus dropped edges):
    // the same obstacles once more, whole graph.
    if (!found) {
      focus = false;
      continue;
    }
    // A focused round at a bound past every obstacle is not final (the focus
    // may have dropped a shorter way): only the last, unfocused round is.
    const NextBound next = next_bound(bound, kInf, found, reach);
    if (next.final) break;
    // An unfocused round's route may pass obstacles left out of its graph: only a focused round's
    // route is known safe (widened()); after an unfocused one, a little past its reach.
    const double wider = focused ? widened(bound, reach, (g - s).norm()) : 1.02 * reach;
    focus = true;
    bound = wider >= farthest ? kInf : wider;
  }
  if (plan.obstacles_used < plan.obstacles_total) {
    // The route lies in E(bound), so the check against all obstacles agrees;
    // it is run anyway: every route a planner returns is checked against the
    // obstacles the user gave.
    // The escape leg (from a start inside a zone, out of it) is the way out,
    // not part of the checked route, as in Planner::solve.
    const ObstacleField all(obstacles, options.margin);
    const std::vector<Vec2>& points = plan.outcome.result.route.points;
    const bool escaped = !plan.outcome.escaped_from.empty() && points.size() > 2;
    plan.outcome.check = check_route(!plan.outcome.result.found ? std::vector<Vec2>{problem.start}
                                     : escaped                  ? std::vector<Vec2>(points.begin() + 1, points.end())
                                                                : points,
                                     all);
  }
  return plan;
}

}  // namespace deepguide
