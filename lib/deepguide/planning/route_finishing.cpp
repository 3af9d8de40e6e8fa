#include "deepguide/planning/route_finishing.hpp"

#include <chrono>
#include <cstddef>
#include <utility>
#include <vector>

#include "deepguide/core/format.hpp"
#include "deepguide/planning/corner_fillets.hpp"
#include "deepguide/planning/route_refinement.hpp"

namespace deepguide {

// The message for a route whose corners cannot be rounded on the radius.
std::string unrounded_message(const PlannerOptions& options, const Vec2& at, const std::string& why) {
  return "the " + to_string(options.graph) + " route cannot turn at " + general(options.turn_radius_m) + " m at " +
         point_text(at, 1) + ": " + why + " (try `graph` tangent)";
}

// A polygon graph's route with its corners rounded on the turning radius.
// Close corners that wrap one zone are joined first. A corner that still
// turns too tightly for its fillet (an S-bend through a gap the turning
// polygons narrow) is cut when the straight line past it keeps the margin
// from the exact zones, or merged with its neighbour across a short leg.
// Not found when none of that helps; solve() then checks what was rounded.
bool round_corners(PlanResult& result, const ObstacleField& field, const PlannerOptions& options) {
  const double radius = options.turn_radius_m;
  const auto keeps_margin = [&](const Vec2& a, const Vec2& b) {
    return field.segment_clearance(a, b).distance >= field.margin();
  };
  const auto too_close = [&](const Vec2& at) {
    result.found = false;
    result.message = unrounded_message(options, at, "its corners there are too close to round");
    return false;
  };
  std::vector<Vec2> points = result.route.points;
  FilletedRoute rounded;
  for (std::size_t cuts = 0;; ++cuts) {
    points = join_tight_corners(points, radius);
    rounded = fillet_corners(points, radius);
    if (!rounded.too_tight) break;
    const std::size_t k = *rounded.too_tight;
    if (k == 0 || k + 1 >= points.size() || cuts >= result.route.points.size()) return too_close(points[k]);
    if (keeps_margin(points[k - 1], points[k + 1])) {
      points.erase(points.begin() + static_cast<std::ptrdiff_t>(k));
      continue;
    }
    // An S-bend over a short leg: its two corners become one at the leg's middle.
    bool merged = false;
    for (const std::size_t j : {k, k - 1}) {
      if (j == 0 || j + 2 >= points.size()) continue;
      const Vec2 mid = 0.5 * (points[j] + points[j + 1]);
      if (keeps_margin(points[j - 1], mid) && keeps_margin(mid, points[j + 2])) {
        points[j] = mid;
        points.erase(points.begin() + static_cast<std::ptrdiff_t>(j) + 1);
        merged = true;
        break;
      }
    }
    if (!merged) return too_close(points[k]);
  }
  result.route.points = points;
  result.legs = rounded.legs;
  result.exact_length_m = 0.0;
  for (const RouteLeg& leg : result.legs) result.exact_length_m += leg.length_m;
  return true;
}

// A polygon graph's route made what is returned: a time or energy route in
// a current that changes from place to place taken from the graph's
// vertices to the continuous optimum near it (every leg keeps the margin
// from the exact zones), then, within a turning radius, its corners rounded.
// The graph's route stays when the refined one cannot be rounded. False when
// no route can be rounded (round_corners says why).
bool refine_and_round(PlanResult& result, const ObstacleField& field, const PlannerOptions& options) {
  if (!result.found) return true;
  const bool rounding = options.turn_radius_m > 0.0;
  if (options.refine && options.cost && refinement_applies(*options.cost)) {
    const auto started = std::chrono::steady_clock::now();
    const RefinedRoute refined = refine_route(*options.cost, result.route.points,
                                              [&](const Vec2& a, const Vec2& b) { return field.segment_free(a, b); });
    result.stats.refine_sweeps = refined.sweeps;
    result.stats.refine_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    if (refined.cost_after < refined.cost_before) {
      PlanResult trial = result;
      trial.route.points = refined.points;
      trial.cost = refined.cost_after;
      trial.stats.refine_gain = 1.0 - refined.cost_after / refined.cost_before;
      if (!rounding || round_corners(trial, field, options)) {
        result = std::move(trial);
        return true;
      }
    }
  }
  return !rounding || round_corners(result, field, options);
}

}  // namespace deepguide
