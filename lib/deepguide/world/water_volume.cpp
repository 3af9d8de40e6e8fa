#include "deepguide/world/water_volume.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {
namespace {

// Depths within a nanometre of a limit count as on it: the ends of an
// obstacle's zone along a leg are found to about 1e-16 of its length, and
// legs between cell centres meet the limits exactly.
constexpr double kRounding = 1e-9;

// Parameters t of the line a + t d where it is closer than r to the segment
// [e0, e1]: the capsule around the segment is convex, so one interval (the
// union of the two end discs' and the rectangle's); none if it misses.
std::optional<std::pair<double, double>> capsule_interval(const Vec2& a, const Vec2& d, const Vec2& e0, const Vec2& e1,
                                                          double r) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const auto take = [&](double t0, double t1) {
    if (t0 < t1) {
      lo = std::min(lo, t0);
      hi = std::max(hi, t1);
    }
  };
  const double dd = d.squaredNorm();
  for (const Vec2& c : {e0, e1}) {  // |a + t d - c| < r
    const Vec2 w = a - c;
    const double B = w.dot(d), C = w.squaredNorm() - r * r;
    const double disc = B * B - dd * C;
    if (disc > 0.0) take((-B - std::sqrt(disc)) / dd, (-B + std::sqrt(disc)) / dd);
  }
  const Vec2 edge = e1 - e0;
  const double len = edge.norm();
  if (len > 0.0) {  // 0 <= along <= len and |across| < r, clipped like Liang-Barsky
    const Vec2 u = edge / len, n(-u.y(), u.x());
    double t0 = -std::numeric_limits<double>::infinity(), t1 = -t0;
    bool empty = false;
    const auto slab = [&](double p0, double dp, double lo_v, double hi_v) {
      if (dp == 0.0) {
        // Running along the capsule's flat side at exactly r is outside it (open).
        if (p0 < lo_v || p0 > hi_v || (hi_v == r && std::abs(p0) == r)) empty = true;
        return;
      }
      double ta = (lo_v - p0) / dp, tb = (hi_v - p0) / dp;
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
    };
    slab((a - e0).dot(u), d.dot(u), 0.0, len);
    slab((a - e0).dot(n), d.dot(n), -r, r);
    if (!empty) take(t0, t1);
  }
  if (!(lo < hi)) return std::nullopt;
  return std::pair{lo, hi};
}

}  // namespace

WaterVolume::WaterVolume(const ObstacleField& field, const SeaFloor* floor, const VolumeOptions& options)
    : field_(&field), floor_(floor), options_(options) {
  const double top = options.min_depth_m, bottom = options.max_depth_m;
  if (!(bottom > 0.0) || !(top >= 0.0) || std::isnan(bottom) || !std::isfinite(top)) {
    throw InputError(
        "depth band: expected a band below the surface (top >= 0 m, bottom > 0 m, depths positive "
        "down), got " +
        general(top) + " .. " + general(bottom) + " m");
  }
  if (!(top < bottom)) {
    throw InputError("depth band: expected its top (" + general(top) + " m) above its bottom (" + general(bottom) +
                     " m)");
  }
  const double c = options.vertical_clearance_m;
  if (!(c >= 0.0) || !std::isfinite(c)) {
    throw InputError("vertical clearance: expected a finite value >= 0 m, got " + general(c));
  }
  const ObstacleSet& set = field.obstacles();
  const auto resolve = [&](const std::optional<double>& top_depth, const std::optional<double>& height,
                           std::pair<Vec2, Vec2> box) {
    if ((top_depth && !std::isfinite(*top_depth)) || (height && !std::isfinite(*height))) {
      throw InputError("obstacle '" + field.obstacle_name(zone_top_.size()) +
                       "': expected a finite top_depth_m or height_m");
    }
    if (top_depth) return *top_depth - c;
    if (height && floor != nullptr) return floor->depth_range(box.first, box.second).first - *height - c;
    return -std::numeric_limits<double>::infinity();  // the whole water column
  };
  for (const EllipticCylinder& e : set.ellipses) {
    const double r = e.footprint.a;
    zone_top_.push_back(resolve(e.top_depth_m, e.height_m,
                                {e.footprint.centre - Vec2::Constant(r), e.footprint.centre + Vec2::Constant(r)}));
  }
  for (const PolygonObstacle& p : set.polygons) {
    ObstacleSet one;
    one.polygons.push_back(p);
    zone_top_.push_back(resolve(p.top_depth_m, p.height_m, footprint_box(one)));
  }
}

WaterVolume::Verdict WaterVolume::check_point(const Vec3& p) const { return check_segment(p, p); }

std::vector<std::pair<double, double>> WaterVolume::capsule_intervals(std::size_t i, const Vec2& a2,
                                                                      const Vec2& b2) const {
  const BgPolygon& poly = field_->obstacles().polygons[i - field_->obstacles().ellipses.size()].footprint;
  // A zero margin leaves the capsules without inside (the zone is the
  // polygon itself): a micrometre keeps them, erring on the safe side.
  const double radius = std::max(field_->margin(), 1e-6);
  std::vector<std::pair<double, double>> out;
  const auto ring = [&](const auto& points) {
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      if (const auto iv = capsule_interval(a2, b2 - a2, to_eigen(points[k]), to_eigen(points[k + 1]), radius)) {
        if (iv->second <= 0.0 || iv->first >= 1.0) continue;
        out.push_back(*iv);
      }
    }
  };
  ring(poly.outer());
  for (const auto& inner : poly.inners()) ring(inner);
  return out;
}

std::optional<std::pair<double, double>> WaterVolume::zone_span(std::size_t i, const Vec2& a2, const Vec2& b2) const {
  const double margin = field_->margin();
  const Vec2 d = b2 - a2;
  const auto inside = [&](double t) { return field_->distance_to(i, a2 + t * d) < margin; };
  double first = 0.0, last = 1.0;
  const bool in_a = inside(0.0), in_b = inside(1.0);
  if (a2 == b2) {
    if (!in_a) return std::nullopt;
  } else if (i < field_->obstacles().ellipses.size()) {
    const SegmentDistance nearest = field_->segment_distance_to(i, a2, b2);
    if (nearest.distance >= margin) return std::nullopt;
    const double mid = std::clamp((nearest.point_on_segment - a2).dot(d) / d.squaredNorm(), 0.0, 1.0);
    // Bisection, keeping the bracket's outer end: the zone is never underestimated.
    const auto edge = [&](double in, double out) {
      for (int k = 0; k < 60; ++k) {
        const double m = 0.5 * (in + out);
        (inside(m) ? in : out) = m;
      }
      return out;
    };
    if (!in_a) first = edge(mid, 0.0);
    if (!in_b) last = edge(mid, 1.0);
  } else {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& [t0, t1] : capsule_intervals(i, a2, b2)) {
      lo = std::min(lo, t0);
      hi = std::max(hi, t1);
    }
    if (!in_a && !in_b && !(lo < hi)) return std::nullopt;
    first = in_a ? 0.0 : std::clamp(lo, 0.0, 1.0);
    last = in_b ? 1.0 : std::clamp(hi, 0.0, 1.0);
  }
  return std::pair{first, last};
}

std::optional<double> WaterVolume::first_in_zone(std::size_t obstacle, const Vec3& a, const Vec3& b) const {
  const double top = zone_top_[obstacle];
  if (std::max(a.z(), b.z()) <= top + kRounding) return std::nullopt;
  const std::optional<std::pair<double, double>> span = zone_span(obstacle, a.head<2>(), b.head<2>());
  if (!span) return std::nullopt;
  auto [first, last] = *span;
  // Where the leg is deeper than the zone's top: t > t_top when diving, t < t_top when climbing.
  if (a.z() != b.z() && !std::isinf(top)) {
    const double t_top = (top - a.z()) / (b.z() - a.z());
    if (b.z() < a.z()) {
      last = std::min(last, t_top);
    } else if (t_top > first) {
      // Diving into a polygon's zone: its span along the leg may have gaps (a
      // concave outline), so the first point below the top is t_top itself
      // when that lies in the zone, else the next capsule entry after it.
      first = t_top;
      if (obstacle >= field_->obstacles().ellipses.size() &&
          !(field_->distance_to(obstacle, a.head<2>() + t_top * (b - a).head<2>()) < field_->margin())) {
        first = std::numeric_limits<double>::infinity();
        for (const auto& [t0, t1] : capsule_intervals(obstacle, a.head<2>(), b.head<2>())) {
          if (t1 > t_top) first = std::min(first, std::max(t0, t_top));
        }
      }
    }
  }
  if (first > last) return std::nullopt;
  return first;
}

WaterVolume::Verdict WaterVolume::check_segment(const Vec3& a, const Vec3& b) const {
  if (!a.allFinite() || !b.allFinite()) return {true, "has a point that is not finite", a.allFinite() ? b : a};
  const double c = options_.vertical_clearance_m;
  // The band: z is linear, so the ends decide.
  for (const Vec3& p : {a, b}) {
    if (p.z() < options_.min_depth_m) {
      return {true, "rises above the depth band's top " + general(options_.min_depth_m) + " m", p};
    }
    if (p.z() > options_.max_depth_m) {
      return {true, "sinks below the depth band's bottom " + general(options_.max_depth_m) + " m", p};
    }
  }
  if (floor_ != nullptr) {
    const SeaFloor::Gap gap = floor_->lowest_gap(a, b);
    if (gap.gap_m < c - kRounding) {
      // The floor as the planner holds it: its spacing (the octree's cell
      // width) says why a point can be judged nearer than a finer chart shows.
      return {true,
              "comes within " + fixed(gap.gap_m, 2) + " m of the sea floor (clearance " + general(c) +
                  " m; the floor sampled every " + general(floor_->spacing(), 4) + " m)",
              gap.where};
    }
  }
  const double margin = field_->margin();
  const Vec2 a2 = a.head<2>(), b2 = b.head<2>();
  const double deepest_end = std::max(a.z(), b.z());
  for (std::size_t i : field_->near(a2.cwiseMin(b2), a2.cwiseMax(b2), margin)) {
    const double top = zone_top_[i];
    if (deepest_end <= top) continue;  // the whole leg passes over this obstacle's zone
    const std::optional<std::pair<double, double>> span = zone_span(i, a2, b2);
    if (!span) continue;
    const auto [first, last] = *span;
    // The deepest point of the leg within the zone.
    const double t = b.z() >= a.z() ? last : first;
    const Vec3 p = a + t * (b - a);
    if (p.z() > top + kRounding) {
      const std::string name = field_->obstacle_name(i);
      if (std::isinf(top)) return {true, "enters the safety zone of obstacle '" + name + "'", p};
      return {true,
              "passes over obstacle '" + name + "' " + fixed(p.z() - top, 2) + " m too deep (its top less " +
                  general(c) + " m clearance is at depth " + fixed(top, 2) + " m)",
              p};
    }
  }
  return {};
}

}  // namespace deepguide
