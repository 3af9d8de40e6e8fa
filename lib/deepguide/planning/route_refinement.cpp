#include "deepguide/planning/route_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <boost/math/tools/minima.hpp>

#include "deepguide/core/error.hpp"

namespace deepguide {

bool refinement_applies(const CostModel& model) {
  return model.kind != CostKind::length && static_cast<bool>(model.current) && !model.uniform;
}

namespace {

double route_length(const std::vector<Vec2>& points) {
  double l = 0.0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) l += (points[i + 1] - points[i]).norm();
  return l;
}

// Every leg longer than h cut into equal pieces; the cost stays as it was.
std::vector<Vec2> divided(const std::vector<Vec2>& points, double h) {
  std::vector<Vec2> out{points.front()};
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Vec2 a = points[i], b = points[i + 1];
    const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil((b - a).norm() / h)));
    for (std::size_t k = 1; k < n; ++k) out.push_back(a + (b - a) * (static_cast<double>(k) / static_cast<double>(n)));
    out.push_back(b);
  }
  return out;
}

struct Refiner {
  const CostModel& model;
  const LegIsFree& free;
  const RefinementOptions& options;

  // What the two legs through p cost, leaving p_prev at `depart`; +inf when
  // either is infeasible.
  double local(const Vec2& prev, const Vec2& p, const Vec2& next, double depart) const {
    const LegCost first = price_leg(model, prev, p, depart);
    if (!first.feasible) return std::numeric_limits<double>::infinity();
    const LegCost second = price_leg(model, p, next, model.steady ? depart : depart + first.time_s);
    if (!second.feasible) return std::numeric_limits<double>::infinity();
    return edge_weight(model, first) + edge_weight(model, second);
  }

  // One Gauss-Seidel sweep; the departures follow the moved vertices.
  void sweep(std::vector<Vec2>& p) const {
    double depart = model.depart_s;
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
      const Vec2 prev = p[i - 1], next = p[i + 1];
      const Vec2 chord = next - prev;
      const double reach = 0.5 * std::min((p[i] - prev).norm(), (next - p[i]).norm());
      if (chord.norm() > 0.0 && reach > 0.0) {
        const Vec2 along = chord.normalized();
        for (const Vec2& dir : {Vec2(-along.y(), along.x()), along}) {
          const Vec2 from = p[i];
          const double here = local(prev, from, next, depart);
          if (!std::isfinite(here)) break;
          // Brent wants finite values: an infeasible trial costs more than any feasible one there.
          const double penalty = 4.0 * here + 1.0;
          const auto f = [&](double s) {
            const double c = local(prev, from + s * dir, next, depart);
            return std::isfinite(c) ? c : penalty;
          };
          const auto best = boost::math::tools::brent_find_minima(f, -reach, reach, 30);
          // Too close to a zone: half the step, a few times, while it still gains.
          for (int k = 0; k < 6; ++k) {
            const Vec2 q = from + std::ldexp(best.first, -k) * dir;
            const double c = local(prev, q, next, depart);
            if (!(c < here)) break;
            if (free(prev, q) && free(q, next)) {
              p[i] = q;
              break;
            }
          }
        }
      }
      depart = departure_after_leg(p[i - 1], p[i], depart);
    }
  }

  double departure_after_leg(const Vec2& a, const Vec2& b, double depart) const {
    if (model.steady) return depart;
    const LegCost leg = price_leg(model, a, b, depart);
    return leg.feasible ? depart + leg.time_s : depart;
  }

  double cost(const std::vector<Vec2>& p) const {
    const RoutePricing priced = price_route(model, p);
    return priced.feasible ? priced.cost : std::numeric_limits<double>::infinity();
  }

  // Drops vertices, the cheapest removal first (Visvalingam-Whyatt with the
  // route's cost in place of an area), while all removals together cost at
  // most `budget` and every leg stays free: the vertices left are spread
  // where the current bends the route, none where it runs straight. In a
  // field that changes in time each leg leaves at the time it did before
  // pruning (the caller prices the result again).
  void prune(std::vector<Vec2>& p, double budget) const {
    const std::size_t n = p.size();
    if (n < 3) return;
    const RoutePricing priced = price_route(model, p);
    std::vector<double> depart(n, model.depart_s);
    for (std::size_t i = 0; i + 1 < n; ++i) depart[i] = priced.legs[i].depart_s;
    std::vector<std::size_t> prev(n), next(n);
    for (std::size_t i = 0; i < n; ++i) prev[i] = i == 0 ? 0 : i - 1, next[i] = i + 1;
    const auto extra = [&](std::size_t i) {
      const std::size_t a = prev[i], b = next[i];
      const LegCost without = price_leg(model, p[a], p[b], depart[a]);
      if (!without.feasible || !free(p[a], p[b])) return std::numeric_limits<double>::infinity();
      return edge_weight(model, without) - local(p[a], p[i], p[b], depart[a]);
    };
    std::set<std::pair<double, std::size_t>> cheapest;
    std::vector<double> key(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) cheapest.insert({key[i] = extra(i), i});
    std::vector<bool> gone(n, false);
    while (!cheapest.empty() && cheapest.begin()->first <= budget) {
      const auto [cost, i] = *cheapest.begin();
      cheapest.erase(cheapest.begin());
      budget -= std::max(cost, 0.0);
      gone[i] = true;
      next[prev[i]] = next[i];
      prev[next[i]] = prev[i];
      for (const std::size_t j : {prev[i], next[i]}) {
        if (j == 0 || j + 1 == n) continue;
        cheapest.erase({key[j], j});
        cheapest.insert({key[j] = extra(j), j});
      }
    }
    std::vector<Vec2> kept;
    for (std::size_t i = 0; i < n; ++i) {
      if (!gone[i]) kept.push_back(p[i]);
    }
    p = std::move(kept);
  }
};

}  // namespace

RefinedRoute refine_route(const CostModel& model, std::vector<Vec2> points, const LegIsFree& leg_is_free,
                          const RefinementOptions& options) {
  if (points.size() < 2) throw InputError("route refinement: expected a route of at least two points");
  for (const Vec2& p : points) {
    if (!p.allFinite()) throw InputError("route refinement: expected finite route points");
  }
  const Refiner refiner{model, leg_is_free, options};
  RefinedRoute out;
  out.cost_before = out.cost_after = refiner.cost(points);
  out.points = points;
  if (!std::isfinite(out.cost_before)) return out;

  const double length = route_length(points);
  double finest = std::max(options.finest_leg_m, length / options.finest_division);
  finest = std::max(finest, length / static_cast<double>(std::max<std::size_t>(options.max_points, 2) - 1));
  double best = out.cost_before;
  for (double h = std::max(0.25 * length, finest);; h *= 0.5) {
    h = std::max(h, finest);
    std::vector<Vec2> p = divided(points, h);
    ++out.levels;
    for (std::size_t s = 0; s < options.max_sweeps_per_level; ++s) {
      std::vector<Vec2> trial = p;
      refiner.sweep(trial);
      ++out.sweeps;
      const double c = refiner.cost(trial);
      // A sweep that gains less than the tolerance is undone: the level is done.
      if (!(best - c >= options.relative_tolerance * best)) break;
      p = std::move(trial);
      best = c;
      points = p;
    }
    if (h <= finest) break;
  }
  // What pruning costs stays within its tolerance.
  std::vector<Vec2> pruned = points;
  refiner.prune(pruned, options.prune_tolerance * best);
  const double pruned_cost = refiner.cost(pruned);
  if (pruned_cost <= best * (1.0 + options.prune_tolerance)) {
    points = std::move(pruned);
    best = pruned_cost;
  }
  if (best < out.cost_before) {
    out.points = std::move(points);
    out.cost_after = best;
  }
  return out;
}

}  // namespace deepguide
