#include "deepguide/render/gradient_lines.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"

namespace deepguide {
namespace {

bool inside(const WorldBox& box, const Vec2& p) {
  return p.x() >= box.min.x() && p.x() <= box.max.x() && p.y() >= box.min.y() && p.y() <= box.max.y();
}

/// The parameter range [t0, t1] of p + t d inside the box (slab method);
/// t0 > t1 when the line misses it.
std::pair<double, double> box_span(const WorldBox& box, const Vec2& p, const Vec2& d) {
  double t0 = -std::numeric_limits<double>::infinity();
  double t1 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 2; ++i) {
    if (d[i] == 0.0) {
      if (p[i] < box.min[i] || p[i] > box.max[i]) return {1.0, 0.0};
      continue;
    }
    double a = (box.min[i] - p[i]) / d[i];
    double b = (box.max[i] - p[i]) / d[i];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return {t0, t1};
}

// A unit field flips (dot -1) across the point where the true field vanishes;
// a sector border of the geometric method turns it by less than 90 degrees.
constexpr double kReversalDot = -0.5;

}  // namespace

std::vector<Vec2> upstream_seeds(const WorldBox& area, const Vec2& start, const Vec2& target, double spacing_m) {
  if (!(spacing_m > 0.0) || !std::isfinite(spacing_m)) {
    throw InputError("gradient lines: expected a positive seed spacing (m), got " + std::to_string(spacing_m));
  }
  if (area.empty() || !inside(area, start)) return {};
  const Vec2 along = target - start;
  if (along.norm() == 0.0) return {start};
  const Vec2 across = Vec2(-along.y(), along.x()) / along.norm();
  const auto [t0, t1] = box_span(area, start, across);
  std::vector<Vec2> seeds;
  for (double k = std::ceil(t0 / spacing_m); k * spacing_m <= t1; k += 1.0)
    seeds.push_back(start + k * spacing_m * across);
  return seeds;
}

GradientLine trace_gradient_line(const ReactiveMethod& method, const ReactiveParams& params, const Vec2& seed,
                                 const Vec2& target, std::span<const Ellipse> objects, const WorldBox& area,
                                 const GradientLineOptions& options) {
  const double h = options.step_m;
  if (!(h > 0.0) || !std::isfinite(h)) {
    throw InputError("gradient lines: expected a positive step (m), got " + std::to_string(h));
  }
  if (!inside(area, seed)) throw InputError("gradient lines: expected a seed inside the area drawn");
  auto field = [&](const Vec2& p) { return reactive_gradient(method, params, p, target, objects); };

  GradientLine line;
  line.points.push_back(seed);
  Vec2 p = seed;
  Vec2 last(0.0, 0.0);
  for (std::size_t step = 0; step < options.max_steps; ++step) {
    if ((p - target).norm() <= h) {
      if (p != target) line.points.push_back(target);
      line.end = LineEnd::target;
      return line;
    }
    const Vec2 k1 = field(p);
    if (k1.squaredNorm() == 0.0 || k1.dot(last) < kReversalDot) {
      line.end = LineEnd::stalled;
      return line;
    }
    const Vec2 mid = p + 0.5 * h * k1;
    const Vec2 k2 = inside(area, mid) ? field(mid) : k1;
    if (k2.squaredNorm() == 0.0 || k1.dot(k2) < kReversalDot) {
      line.end = LineEnd::stalled;
      return line;
    }
    const Vec2 next = p + h * k2;
    if (!inside(area, next)) {
      // Cut the last step at the boundary: the line visibly leaves the map.
      const double t_exit = box_span(area, p, next - p).second;
      line.points.push_back(p + std::clamp(t_exit, 0.0, 1.0) * (next - p));
      line.end = LineEnd::left_area;
      return line;
    }
    line.points.push_back(next);
    last = k2;
    p = next;
  }
  line.end = LineEnd::step_limit;
  return line;
}

std::vector<GradientLine> gradient_lines(const ReactiveMethod& method, const ReactiveParams& params,
                                         std::span<const Vec2> seeds, const Vec2& target,
                                         std::span<const Ellipse> objects, const WorldBox& area,
                                         const GradientLineOptions& options) {
  std::vector<GradientLine> lines;
  lines.reserve(seeds.size());
  for (const Vec2& s : seeds) lines.push_back(trace_gradient_line(method, params, s, target, objects, area, options));
  return lines;
}

std::vector<int> passing_sides(const GradientLine& line, const Vec2& target, std::span<const Ellipse> objects) {
  std::vector<int> sides;
  sides.reserve(objects.size());
  for (const Ellipse& o : objects) {
    const Vec2 c = o.centre;
    const auto nearest = std::min_element(line.points.begin(), line.points.end(), [&](const Vec2& a, const Vec2& b) {
      return (a - c).squaredNorm() < (b - c).squaredNorm();
    });
    const Vec2 axis = target - c;
    const Vec2 off = *nearest - c;
    sides.push_back(axis.x() * off.y() - axis.y() * off.x() > 0.0 ? 1 : -1);
  }
  return sides;
}

std::vector<GradientLine> dividing_lines(const ReactiveMethod& method, const ReactiveParams& params,
                                         std::span<const Vec2> seeds, std::span<const GradientLine> lines,
                                         const Vec2& target, std::span<const Ellipse> objects, const WorldBox& area,
                                         const GradientLineOptions& options) {
  constexpr double kTolerance_m = 1e-6;
  constexpr int kMaxBisections = 60;
  std::vector<GradientLine> out;
  for (std::size_t i = 0; i + 1 < seeds.size() && i + 1 < lines.size(); ++i) {
    // Seeds on either side of an object (the seed line crosses it) are not neighbours.
    if (std::any_of(objects.begin(), objects.end(),
                    [&](const Ellipse& o) { return segment_intersects(o, seeds[i], seeds[i + 1]); })) {
      continue;
    }
    const std::vector<int> side_lo = passing_sides(lines[i], target, objects);
    if (side_lo == passing_sides(lines[i + 1], target, objects)) continue;
    Vec2 lo = seeds[i], hi = seeds[i + 1];
    GradientLine divider = lines[i];
    for (int k = 0; k < kMaxBisections && (hi - lo).norm() > kTolerance_m; ++k) {
      const Vec2 mid = 0.5 * (lo + hi);
      divider = trace_gradient_line(method, params, mid, target, objects, area, options);
      if (divider.end == LineEnd::stalled) break;
      (passing_sides(divider, target, objects) == side_lo ? lo : hi) = mid;
    }
    out.push_back(std::move(divider));
  }
  return out;
}

}  // namespace deepguide
