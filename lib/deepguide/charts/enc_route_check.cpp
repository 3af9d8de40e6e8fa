#include "deepguide/charts/enc_route_check.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <stdexcept>

#include "deepguide/core/error.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

using BoxItem = std::pair<BgBox, std::size_t>;
using BgSegment = bg::model::segment<BgPoint>;
constexpr std::size_t kMaxSamples = 2000;
constexpr double kBisectTo = 0.01;

// Distance from p to the feature: 0 inside an area; a disc's distance from its edge.
double distance_to(const EncNoGoFeature& f, const Vec2& p) {
  if (f.point) return std::max(0.0, (p - *f.point).norm() - f.radius_m);
  return bg::distance(to_bg(p), f.area);
}

double distance_to(const EncNoGoFeature& f, const Vec2& a, const Vec2& b) {
  if (f.point) {
    const Vec2 d = b - a;
    const double len2 = d.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((*f.point - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return std::max(0.0, (a + t * d - *f.point).norm() - f.radius_m);
  }
  return bg::distance(BgSegment(to_bg(a), to_bg(b)), f.area);
}

BgBox feature_box(const EncNoGoFeature& f) {
  if (f.point) {
    const Vec2 r = Vec2::Constant(f.radius_m);
    return {to_bg(*f.point - r), to_bg(*f.point + r)};
  }
  return bg::return_envelope<BgBox>(f.area);
}

struct Index {
  bgi::rtree<BoxItem, bgi::rstar<16>> tree;
  explicit Index(const EncNoGo& no_go) {
    std::vector<BoxItem> items;
    for (std::size_t i = 0; i < no_go.features.size(); ++i) {
      const EncNoGoFeature& f = no_go.features[i];
      if (f.point || !f.area.empty()) items.emplace_back(feature_box(f), i);
    }
    tree = decltype(tree)(items.begin(), items.end());
  }
};

BgBox grown(const BgBox& b, double by) {
  return {BgPoint(b.min_corner().x() - by, b.min_corner().y() - by),
          BgPoint(b.max_corner().x() + by, b.max_corner().y() + by)};
}

// Parameter range [t0, t1] of a + t (b - a) inside box (Liang-Barsky); false if none.
bool clip_to_box(const Vec2& a, const Vec2& b, const BgBox& box, double& t0, double& t1) {
  t0 = 0.0, t1 = 1.0;
  const double lo[2] = {box.min_corner().x(), box.min_corner().y()};
  const double hi[2] = {box.max_corner().x(), box.max_corner().y()};
  for (int k = 0; k < 2; ++k) {
    const double d = b[k] - a[k];
    if (d == 0.0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    double ta = (lo[k] - a[k]) / d, tb = (hi[k] - a[k]) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}

// Where on a-b the distance to f first drops below margin (a parameter in [0, 1]).
double entry(const EncNoGoFeature& f, const Vec2& a, const Vec2& b, double margin) {
  double t0 = 0.0, t1 = 1.0;
  clip_to_box(a, b, grown(feature_box(f), margin), t0, t1);
  const double len = (b - a).norm();
  const double step = std::max(0.25 * margin, (t1 - t0) * len / static_cast<double>(kMaxSamples));
  const std::size_t n = len > 0.0 ? static_cast<std::size_t>(std::ceil((t1 - t0) * len / std::max(step, 1e-9))) : 0;
  double best_t = t0, best_d = std::numeric_limits<double>::infinity();
  double prev = t0;
  for (std::size_t i = 0; i <= n; ++i) {
    const double t = n == 0 ? t0 : t0 + (t1 - t0) * static_cast<double>(i) / static_cast<double>(n);
    const double d = distance_to(f, a + t * (b - a));
    if (d < margin) {
      if (i == 0) return t;
      double lo = prev, hi = t;  // lo outside, hi inside
      while ((hi - lo) * len > kBisectTo) {
        const double mid = 0.5 * (lo + hi);
        (distance_to(f, a + mid * (b - a)) < margin ? hi : lo) = mid;
      }
      return hi;
    }
    if (d < best_d) best_d = d, best_t = t;
    prev = t;
  }
  return best_t;  // a graze between two samples: its closest sample
}

// Whether distance d breaks the margin: closer than margin - tolerance, or in
// (or on) the feature whatever the margin.
bool breaks(double d, double margin, double tolerance) { return d <= 0.0 || d < margin - tolerance; }

std::string lonlat_text(const LocalFrame& frame, const Vec2& p) {
  const Vec2 ll = frame.to_lonlat(p);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f, %.6f", ll.x(), ll.y());
  return buf;
}

}  // namespace

ChartRouteCheck check_route_on_chart(const std::vector<Vec2>& route, const EncNoGo& no_go, double margin_m,
                                     double tolerance_m) {
  if (!std::isfinite(tolerance_m) || tolerance_m < 0.0) {
    throw std::invalid_argument("check_route_on_chart: tolerance must be finite and >= 0");
  }
  if (!std::isfinite(margin_m) || margin_m < 0.0) {
    throw InputError("`margin_m`: expected a safety margin >= 0 m, got " + std::to_string(margin_m));
  }
  if (route.size() < 2) throw InputError("route: expected at least two waypoints, got " + std::to_string(route.size()));
  const Index index(no_go);
  ChartRouteCheck out;
  out.margin_m = margin_m;
  std::set<std::size_t> crossed;
  double along = 0.0;
  for (std::size_t leg = 0; leg + 1 < route.size(); ++leg) {
    const Vec2 a = route[leg], b = route[leg + 1];
    BgBox box(to_bg(a.cwiseMin(b)), to_bg(a.cwiseMax(b)));
    std::vector<BoxItem> hits;
    index.tree.query(bgi::intersects(grown(box, margin_m)), std::back_inserter(hits));
    std::sort(hits.begin(), hits.end(), [](const BoxItem& x, const BoxItem& y) { return x.second < y.second; });
    for (const auto& h : hits) {
      const EncNoGoFeature& f = no_go.features[h.second];
      const double d = distance_to(f, a, b);
      if (!breaks(d, margin_m, tolerance_m)) continue;
      crossed.insert(h.second);
      const double t = entry(f, a, b, std::max(margin_m - tolerance_m, 1e-9));
      const double at_along = along + t * (b - a).norm();
      if (!out.first || at_along < out.first->along_m) {
        out.first = ChartCrossing{leg, at_along, a + t * (b - a), &f, d};
      }
    }
    along += (b - a).norm();
  }
  out.crossed_features = crossed.size();
  out.safe = crossed.empty();
  return out;
}

std::string ChartRouteCheck::describe(const LocalFrame& frame) const {
  if (safe) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "no leg comes within %g m of the charts' no-go", margin_m);
    return buf;
  }
  const ChartCrossing& c = *first;
  const EncNoGoFeature& f = *c.feature;
  char buf[160];
  std::snprintf(buf, sizeof buf, " at %s, %.1f m along the route (leg %zu)", lonlat_text(frame, c.at).c_str(),
                c.along_m, c.leg + 1);
  char how[64] = "crosses ";
  if (c.least_distance_m > 0.0) std::snprintf(how, sizeof how, "passes %.2f m from ", c.least_distance_m);
  char margin[48] = "";
  if (c.least_distance_m > 0.0) std::snprintf(margin, sizeof margin, "; margin %g m", margin_m);
  std::string s = how + printable(f.id) + (f.cell.empty() ? std::string() : " of " + printable(f.cell)) + " (" +
                  f.reason + margin + ")" + buf;
  if (crossed_features > 1) {
    s += "; " + std::to_string(crossed_features - 1) + " more no-go feature(s) within the margin";
  }
  return s;
}

const EncNoGoFeature* no_go_feature_at(const EncNoGo& no_go, const Vec2& p, double margin_m, double tolerance_m) {
  for (const EncNoGoFeature& f : no_go.features) {
    if (!f.point && f.area.empty()) continue;
    if (breaks(distance_to(f, p), margin_m, tolerance_m)) return &f;
  }
  return nullptr;
}

}  // namespace deepguide
