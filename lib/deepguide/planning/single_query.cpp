#include "deepguide/planning/single_query.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <chrono>
#include <cmath>
#include <vector>

#include "deepguide/core/error.hpp"

namespace deepguide {
namespace bg = boost::geometry;

namespace {

struct Disc {
  Vec2 centre;
  double radius;
};

// A disc holding the obstacle's footprint (before the margin).
Disc footprint_disc(const EllipticCylinder& c) { return {c.footprint.center, c.footprint.a}; }
Disc footprint_disc(const PolygonObstacle& p) {
  BgBox box;
  bg::envelope(p.footprint, box);
  const Vec2 c = 0.5 * (to_eigen(box.min_corner()) + to_eigen(box.max_corner()));
  double r = 0.0;
  for (const BgPoint& pt : p.footprint.outer()) r = std::max(r, (to_eigen(pt) - c).norm());
  return {c, r};
}

// The first bound: a little longer than the straight line, so that a route
// with a modest detour is accepted in the first round.
constexpr double kFirstStretch = 1.05;
// Growth when a round's route is longer than its bound: past that route.
constexpr double kGrowth = 1.05;

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
  for (const Disc& d : discs) {
    low.push_back((d.centre - s).norm() + (d.centre - g).norm() - 2.0 * (d.radius + reach));
  }

  SingleQueryPlan plan;
  plan.obstacles_total = obstacles.size();
  double bound = kFirstStretch * (g - s).norm();
  std::size_t used = static_cast<std::size_t>(-1);
  for (;;) {
    ObstacleSet subset;
    const std::size_t ne = obstacles.ellipses.size();
    for (std::size_t i = 0; i < ne; ++i) {
      if (low[i] <= bound) subset.ellipses.push_back(obstacles.ellipses[i]);
    }
    for (std::size_t i = 0; i < obstacles.polygons.size(); ++i) {
      if (low[ne + i] <= bound) subset.polygons.push_back(obstacles.polygons[i]);
    }
    const bool all = subset.size() == obstacles.size();
    // The same obstacles as the last round (the subsets only grow): its route,
    // no longer than the new bound, stands.
    if (subset.size() == used) break;
    used = subset.size();
    ++plan.rounds;
    plan.obstacles_used = used;
    plan.bound_m = bound;
    plan.planner = std::make_unique<Planner>(std::move(subset), options);
    plan.outcome = plan.planner->solve(problem);
    plan.build_ms += plan.outcome.result.stats.build_ms;
    plan.query_ms += plan.outcome.result.stats.query_ms;
    if (!plan.outcome.result.found || all) break;
    const double length = plan.outcome.result.route.length();
    if (length <= bound) break;
    bound = kGrowth * length;
  }
  if (plan.obstacles_used < plan.obstacles_total) {
    // The route lies in E(bound), so the check against all obstacles agrees;
    // it is run anyway: every route a planner returns is checked against the
    // obstacles the user gave.
    const ObstacleField all(obstacles, options.margin);
    plan.outcome.check = check_route(
        plan.outcome.result.found ? plan.outcome.result.route.points : std::vector<Vec2>{problem.start}, all);
  }
  return plan;
}

}  // namespace deepguide
