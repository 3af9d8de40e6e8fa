// Test-side independent reference geometry for ellipses.
//
// Everything here is computed from an ellipse's (centre, a, b, theta) only. It
// deliberately shares no code with the library's geometry (no Ellipse member
// functions, nothing from ellipse_distance / ellipse_tangents / safety_zone), so
// that the geometry tests can use it as an independent check of the library.
// Only the plain data of deepguide::Ellipse and the Vec2 type are used.
//
//  * Frame: the ellipse frame. The boundary is
//    x(t) = c + R(theta) diag(a, b) (cos t, sin t) = c + a cos t u + b sin t v,
//    u the major and v the minor axis direction.
//  * reference_distance: point-to-boundary distance by dense sampling. x(t) is
//    sampled at kDistanceSamples = 20000 parameters, every discrete local minimum of
//    |p - x(t)|^2 (the best few) is refined by golden-section search on the
//    bracketing sample interval and polished with safeguarded Newton steps on
//    d/dt |p - x(t)|^2 = 0, and the smallest refined distance wins.
//    test_ellipse_distance.cpp checks this reference on hand-derived cases.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "deepguide/geometry/ellipse.hpp"

namespace deepguide::test_ref {

// The ellipse frame, from (c, a, b, theta) only.
struct Frame {
  Vec2 c;
  double a, b;
  Vec2 u;  // major axis
  Vec2 v;  // minor axis

  explicit Frame(const Ellipse& e)
      : c(e.centre),
        a(e.a),
        b(e.b),
        u(std::cos(e.theta), std::sin(e.theta)),
        v(-std::sin(e.theta), std::cos(e.theta)) {}

  // Boundary point x(t) and its first and second derivatives.
  Vec2 point(double t) const { return c + a * std::cos(t) * u + b * std::sin(t) * v; }
  Vec2 d1(double t) const { return -a * std::sin(t) * u + b * std::cos(t) * v; }
  Vec2 d2(double t) const { return -a * std::cos(t) * u - b * std::sin(t) * v; }

  // Outward unit normal at x(t): the implicit gradient R (cos t / a, sin t / b), normalised.
  Vec2 normal(double t) const { return (std::cos(t) / a * u + std::sin(t) / b * v).normalized(); }
  // Outward unit normal at (or near) a boundary point p: the implicit gradient at p.
  Vec2 normal(const Vec2& p) const {
    const Vec2 d = p - c;
    return (d.dot(u) / (a * a) * u + d.dot(v) / (b * b) * v).normalized();
  }
  // Offset-curve point x(t) + d n(t).
  Vec2 offset_point(double t, double d) const { return point(t) + d * normal(t); }

  // (local x / a)^2 + (local y / b)^2: < 1 inside, 1 on the boundary, > 1 outside.
  double implicit(const Vec2& p) const {
    const Vec2 d = p - c;
    const double x = d.dot(u) / a;
    const double y = d.dot(v) / b;
    return x * x + y * y;
  }

  // Local (x along u, y along v) to world.
  Vec2 local_to_world(double x, double y) const { return c + x * u + y * v; }
  // Unit-circle frame (the ellipse is the unit circle) to world.
  Vec2 from_unit(double x, double y) const { return c + a * x * u + b * y * v; }

  // max over the ellipse of n.(x - c), for a unit n.
  double support_centered(const Vec2& n) const { return std::hypot(a * n.dot(u), b * n.dot(v)); }
  // Support value of the safety zone (ellipse grown by d) along a unit n.
  double zone_support(const Vec2& n, double d) const { return n.dot(c) + support_centered(n) + d; }
};

// ---- Dense-sampling distance reference --------------------------------------

struct RefResult {
  double distance;
  double t;  // boundary parameter of the closest point
};

inline constexpr int kDistanceSamples = 20000;

inline const std::vector<std::array<double, 2>>& cos_sin_table() {
  static const std::vector<std::array<double, 2>> table = [] {
    std::vector<std::array<double, 2>> tab(kDistanceSamples);
    for (int k = 0; k < kDistanceSamples; ++k) {
      const double t = 2.0 * std::numbers::pi * k / kDistanceSamples;
      tab[k] = {std::cos(t), std::sin(t)};
    }
    return tab;
  }();
  return table;
}

// Minimises f(t) = |p - x(t)|^2 on [lo, hi] (golden section, then Newton polish).
inline double refine_min(const Frame& f, const Vec2& p, double lo, double hi) {
  auto fx = [&](double t) { return (f.point(t) - p).squaredNorm(); };
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = hi - g * (hi - lo);
  double x2 = lo + g * (hi - lo);
  double f1 = fx(x1);
  double f2 = fx(x2);
  for (int i = 0; i < 200 && hi - lo > 1e-15 * (1.0 + std::abs(lo)); ++i) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - g * (hi - lo), f1 = fx(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + g * (hi - lo), f2 = fx(x2);
    }
  }
  double t = f1 <= f2 ? x1 : x2;
  double ft = std::min(f1, f2);
  // Newton on f'(t) = 2 (x - p).x' = 0; keep a step only if it does not increase f.
  for (int i = 0; i < 8; ++i) {
    const Vec2 r = f.point(t) - p;
    const double g1 = r.dot(f.d1(t));
    const double g2 = f.d1(t).squaredNorm() + r.dot(f.d2(t));
    if (!(g2 > 0.0)) break;
    const double tn = t - g1 / g2;
    if (!(std::abs(tn - t) < 1e-6)) break;
    const double fn = fx(tn);
    if (!(fn <= ft)) break;
    t = tn, ft = fn;
  }
  return t;
}

// Distance from p to the boundary of the ellipse with frame f, and the parameter t
// of the closest boundary point.
inline RefResult reference_distance(const Frame& f, const Vec2& p) {
  constexpr int n = kDistanceSamples;
  constexpr double pi = std::numbers::pi;
  const auto& cs = cos_sin_table();
  std::vector<double> d2(n);
  for (int k = 0; k < n; ++k) {
    const Vec2 x = f.c + f.a * cs[k][0] * f.u + f.b * cs[k][1] * f.v;
    d2[k] = (x - p).squaredNorm();
  }
  // Discrete local minima (cyclic), best few first.
  std::vector<int> minima;
  for (int k = 0; k < n; ++k) {
    const double prev = d2[(k + n - 1) % n];
    const double next = d2[(k + 1) % n];
    if (d2[k] <= prev && d2[k] <= next) minima.push_back(k);
  }
  std::sort(minima.begin(), minima.end(), [&](int i, int j) { return d2[i] < d2[j]; });
  if (minima.size() > 6) minima.resize(6);
  RefResult best{std::sqrt(d2[minima.front()]), 2.0 * pi * minima.front() / n};
  const double h = 2.0 * pi / n;
  for (int k : minima) {
    const double tk = 2.0 * pi * k / n;
    const double t = refine_min(f, p, tk - h, tk + h);
    const double d = (f.point(t) - p).norm();
    if (d < best.distance) best = {d, t};
  }
  return best;
}

inline RefResult reference_distance(const Ellipse& e, const Vec2& p) { return reference_distance(Frame(e), p); }

}  // namespace deepguide::test_ref
