#include "deepguide/world/sea_floor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {
SeaFloor::SeaFloor(const Vec2& origin, double spacing, std::size_t nx, std::size_t ny, std::vector<double> depths)
    : origin_(origin), spacing_(spacing), nx_(nx), ny_(ny), depth_(std::move(depths)) {
  if (!(spacing > 0.0) || !std::isfinite(spacing)) {
    throw InputError("sea floor: expected a node spacing > 0 m, got " + general(spacing));
  }
  if (nx < 2 || ny < 2 || nx > depth_.size() / ny || depth_.size() != nx * ny || !origin.allFinite()) {
    throw InputError("sea floor: expected a grid of at least 2 x 2 nodes with one depth each, got " +
                     std::to_string(nx) + " x " + std::to_string(ny) + " nodes and " + std::to_string(depth_.size()) +
                     " depths");
  }
  for (double& d : depth_) {
    if (!std::isfinite(d)) d = 0.0;  // no data: not water to dive in
  }
  // The min/max pyramid: level 0 is the nodes, each next level halves both sides.
  min_.push_back(depth_);
  max_.push_back(depth_);
  width_.push_back(nx);
  std::size_t w = nx, h = ny;
  while (w > 1 || h > 1) {
    const std::size_t w2 = (w + 1) / 2, h2 = (h + 1) / 2;
    const auto& lo = min_.back();
    const auto& hi = max_.back();
    std::vector<double> mn(w2 * h2, std::numeric_limits<double>::infinity());
    std::vector<double> mx(w2 * h2, -std::numeric_limits<double>::infinity());
    for (std::size_t j = 0; j < h; ++j) {
      for (std::size_t i = 0; i < w; ++i) {
        const std::size_t to = (j / 2) * w2 + i / 2;
        mn[to] = std::min(mn[to], lo[j * w + i]);
        mx[to] = std::max(mx[to], hi[j * w + i]);
      }
    }
    min_.push_back(std::move(mn));
    max_.push_back(std::move(mx));
    width_.push_back(w2);
    w = w2;
    h = h2;
  }
  levels_ = min_.size();
}

double SeaFloor::node(std::ptrdiff_t i, std::ptrdiff_t j) const {
  if (i < 0 || j < 0 || i >= static_cast<std::ptrdiff_t>(nx_) || j >= static_cast<std::ptrdiff_t>(ny_)) return 0.0;
  return depth_[static_cast<std::size_t>(j) * nx_ + static_cast<std::size_t>(i)];
}

double SeaFloor::depth_at(const Vec2& p) const {
  const double u = (p.x() - origin_.x()) / spacing_, v = (p.y() - origin_.y()) / spacing_;
  if (!(u >= 0.0 && v >= 0.0 && u <= static_cast<double>(nx_ - 1) && v <= static_cast<double>(ny_ - 1))) return 0.0;
  const auto i = std::min(static_cast<std::ptrdiff_t>(u), static_cast<std::ptrdiff_t>(nx_) - 2);
  const auto j = std::min(static_cast<std::ptrdiff_t>(v), static_cast<std::ptrdiff_t>(ny_) - 2);
  const double fu = u - static_cast<double>(i), fv = v - static_cast<double>(j);
  return (1 - fv) * ((1 - fu) * node(i, j) + fu * node(i + 1, j)) +
         fv * ((1 - fu) * node(i, j + 1) + fu * node(i + 1, j + 1));
}

std::pair<double, double> SeaFloor::depth_range(const Vec2& lo, const Vec2& hi) const {
  const double u0 = std::floor((lo.x() - origin_.x()) / spacing_), u1 = std::ceil((hi.x() - origin_.x()) / spacing_);
  const double v0 = std::floor((lo.y() - origin_.y()) / spacing_), v1 = std::ceil((hi.y() - origin_.y()) / spacing_);
  const double last_i = static_cast<double>(nx_ - 1), last_j = static_cast<double>(ny_ - 1);
  // Reaching past the grid: the 0 m of unsounded water is part of the range.
  const bool outside = u0 < 0.0 || v0 < 0.0 || u1 > last_i || v1 > last_j;
  if (u1 < 0.0 || v1 < 0.0 || u0 > last_i || v0 > last_j) return {0.0, 0.0};
  auto i0 = static_cast<std::size_t>(std::max(u0, 0.0)), i1 = static_cast<std::size_t>(std::min(u1, last_i));
  auto j0 = static_cast<std::size_t>(std::max(v0, 0.0)), j1 = static_cast<std::size_t>(std::min(v1, last_j));
  std::size_t k = 0;
  while (k + 1 < levels_ && ((i1 >> k) - (i0 >> k) > 3 || (j1 >> k) - (j0 >> k) > 3)) ++k;
  double mn = outside ? 0.0 : std::numeric_limits<double>::infinity();
  double mx = outside ? 0.0 : -std::numeric_limits<double>::infinity();
  for (std::size_t J = j0 >> k; J <= j1 >> k; ++J) {
    for (std::size_t I = i0 >> k; I <= i1 >> k; ++I) {
      mn = std::min(mn, min_[k][J * width_[k] + I]);
      mx = std::max(mx, max_[k][J * width_[k] + I]);
    }
  }
  return {mn, mx};
}

std::vector<double> SeaFloor::cuts(const Vec3& a, const Vec3& b) const {
  std::vector<double> out{0.0, 1.0};
  for (int axis = 0; axis < 2; ++axis) {
    const double o = origin_[axis], d = b[axis] - a[axis];
    if (d == 0.0) continue;
    const double g0 = (a[axis] - o) / spacing_, g1 = (b[axis] - o) / spacing_;
    for (double g = std::ceil(std::min(g0, g1)); g <= std::max(g0, g1); g += 1.0) {
      const double t = (o + g * spacing_ - a[axis]) / d;
      if (t > 0.0 && t < 1.0) out.push_back(t);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::optional<double> SeaFloor::first_below(const Vec3& a, const Vec3& b, double clearance) const {
  if (!a.allFinite() || !b.allFinite()) return 0.0;
  const auto excess = [&](double t) {
    const Vec3 p = a + t * (b - a);
    return depth_at(p.head<2>()) - p.z() - clearance;
  };
  if (excess(0.0) < 0.0) return 0.0;
  const std::vector<double> pieces = cuts(a, b);
  for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
    const double t0 = pieces[k], t1 = pieces[k + 1];
    if (!(t1 > t0)) continue;
    // The piece's least excess (a quadratic, as in lowest_gap); from t0 to it
    // the excess falls monotonically, so bisection finds the first crossing.
    const double e0 = excess(t0), em = excess(0.5 * (t0 + t1)), e1 = excess(t1);
    const double B = -3.0 * e0 + 4.0 * em - e1, C = 2.0 * e0 - 4.0 * em + 2.0 * e1;
    double low_t = t1, low = e1;
    if (C > 0.0) {
      const double sv = -B / (2.0 * C);
      if (sv > 0.0 && sv < 1.0 && excess(t0 + sv * (t1 - t0)) < low) {
        low_t = t0 + sv * (t1 - t0);
        low = excess(low_t);
      }
    }
    if (!(low < 0.0)) continue;
    double ok = t0, bad = low_t;
    for (int i = 0; i < 60; ++i) {
      const double m = 0.5 * (ok + bad);
      (excess(m) < 0.0 ? bad : ok) = m;
    }
    return bad;
  }
  return std::nullopt;
}

SeaFloor::Gap SeaFloor::lowest_gap(const Vec3& a, const Vec3& b) const {
  if (!a.allFinite() || !b.allFinite()) return {-std::numeric_limits<double>::infinity(), a.allFinite() ? b : a};
  // Pieces between the grid lines the segment crosses: inside one grid cell
  // the bilinear floor along the segment is a quadratic in t, and so is the gap.
  const std::vector<double> cuts = this->cuts(a, b);
  const auto gap = [&](double t) {
    const Vec3 p = a + t * (b - a);
    return depth_at(p.head<2>()) - p.z();
  };
  Gap best{gap(0.0), a};
  const auto consider = [&](double t) {
    const double g = gap(t);
    if (g < best.gap_m) best = {g, a + t * (b - a)};
  };
  consider(1.0);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double t0 = cuts[k], t1 = cuts[k + 1];
    if (t1 <= t0) continue;
    // g(s) = g0 + B s + C s^2 on s in [0, 1] through the piece's ends and middle.
    const double g0 = gap(t0), gm = gap(0.5 * (t0 + t1)), g1 = gap(t1);
    const double B = -3.0 * g0 + 4.0 * gm - g1, C = 2.0 * g0 - 4.0 * gm + 2.0 * g1;
    consider(t1);
    if (C > 0.0) {
      const double s = -B / (2.0 * C);
      if (s > 0.0 && s < 1.0) consider(t0 + s * (t1 - t0));
    }
  }
  return best;
}

}  // namespace deepguide
