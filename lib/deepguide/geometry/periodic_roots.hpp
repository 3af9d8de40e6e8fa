#pragma once
// Roots of smooth 2-pi-periodic functions that have exactly two simple roots
// (tangency conditions written with support functions: common tangents of two
// convex sets, tangents from a point). Any angle where the function is
// negative and any where it is positive split the circle into two arcs with
// one root each, so sampling for both signs and bracketing solves it; TOMS 748
// (Boost.Math) then converges to full precision. A function that also gives
// its slope (returns ValueSlope) is solved by Newton's method inside the
// bracket instead: about half the evaluations, and the tangent graph spends
// most of its build here.

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <type_traits>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// A function's value and its derivative at one angle.
struct ValueSlope {
  double value;
  double slope;
};

namespace periodic_detail {
// Coarse sampling finds both signs for all but nearly touching or very
// elongated pairs; only those pay for the dense pass and the polish.
inline constexpr int kCoarseSamples = 48;
inline constexpr int kDenseSamples = 720;

inline double value_of(double v) { return v; }
inline double value_of(const ValueSlope& v) { return v.value; }

// Newton's method kept inside a sign bracket (rtsafe in Numerical Recipes): a
// step that leaves the bracket or does not halve the one before is replaced by
// bisection, so it always converges, quadratically near the root. Boost 1.74's
// newton_raphson_iterate instead throws near flat stretches and stops relative
// to |root|, which never triggers for roots near angle 0.
template <class G>
double bracketed_newton(const G& g, double x_neg, double g_neg, double x_pos, double g_pos) {
  // Rounding in g (differences of support values of hundreds of metres)
  // keeps the last steps from falling below ~1e-14 rad; a Newton step of
  // 1e-12 rad leaves an error of order its square.
  const double tiny = 1e-12 * std::max({1.0, std::abs(x_neg), std::abs(x_pos)});
  double x = x_neg - g_neg * (x_pos - x_neg) / (g_pos - g_neg);  // false position: a fair start
  double step_before = std::abs(x_pos - x_neg);
  for (int it = 0; it < 200; ++it) {
    const ValueSlope v = g(x);
    if (v.value == 0.0) return x;
    (v.value < 0.0 ? x_neg : x_pos) = x;
    const double step = v.value / v.slope;
    // Converged: tested before the bracket, as the last step may round to nothing.
    if (std::abs(step) <= tiny) return x - step;
    double next = x - step;
    const bool inside = std::isfinite(next) && (next - x_neg) * (next - x_pos) < 0.0;
    if (!inside || 2.0 * std::abs(step) > step_before) next = 0.5 * (x_neg + x_pos);
    step_before = std::abs(next - x);
    x = next;
    if (std::abs(x_pos - x_neg) <= tiny) break;
  }
  return x;
}

struct Extremes {
  double phi_neg, g_neg, phi_pos, g_pos, step;
};

template <class G>
Extremes sample_extremes(const G& g, int samples) {
  Extremes x{0.0, value_of(g(0.0)), 0.0, 0.0, kTwoPi / samples};
  x.g_pos = x.g_neg;
  for (int k = 1; k < samples; ++k) {
    const double phi = x.step * k;
    const double v = value_of(g(phi));
    if (v < x.g_neg) x.g_neg = v, x.phi_neg = phi;
    if (v > x.g_pos) x.g_pos = v, x.phi_pos = phi;
  }
  return x;
}

}  // namespace periodic_detail

/// Finds the two roots (root_a, root_b in radians, not wrapped) of g (which
/// returns a double, or a ValueSlope with its derivative), or
/// returns false when g has no negative or no positive value (then the roots
/// do not exist or coincide). `hint`: an angle where g is likely of one sign
/// and of the other half a turn away (e.g. the direction between the two
/// sets' centres); when it is, the sampling is skipped.
template <class G>
bool periodic_two_roots(const G& g, double& root_a, double& root_b, double hint = 0.0) {
  using namespace periodic_detail;
  auto value = [&g](double t) { return value_of(g(t)); };
  const double g0 = value(hint), g1 = value(hint + std::numbers::pi);
  Extremes x{hint, g0, hint + std::numbers::pi, g1, std::numbers::pi};
  if (g0 > g1) x = Extremes{hint + std::numbers::pi, g1, hint, g0, std::numbers::pi};
  if (!(x.g_neg < 0.0 && x.g_pos > 0.0)) x = sample_extremes(g, kCoarseSamples);
  if (!(x.g_neg < 0.0 && x.g_pos > 0.0)) x = sample_extremes(g, kDenseSamples);
  double phi_neg = x.phi_neg, gmin = x.g_neg, phi_pos = x.phi_pos, gmax = x.g_pos;
  const double step = x.step;
  // A narrow sign window can fall between samples (nearly touching ellipses):
  // polish the extremum before giving up.
  if (gmin >= 0.0) {
    auto r = boost::math::tools::brent_find_minima(value, phi_neg - step, phi_neg + step, 52);
    phi_neg = r.first, gmin = r.second;
  }
  if (gmax <= 0.0) {
    auto neg = [&](double t) { return -value(t); };
    auto r = boost::math::tools::brent_find_minima(neg, phi_pos - step, phi_pos + step, 52);
    phi_pos = r.first, gmax = -r.second;
  }
  if (!(gmin < 0.0 && gmax > 0.0)) return false;
  // Each arc between the negative and the positive point holds exactly one root.
  const double lo1 = phi_neg;
  const double hi1 = phi_pos > phi_neg ? phi_pos : phi_pos + kTwoPi;
  const double lo2 = hi1;
  const double hi2 = phi_neg + kTwoPi;
  if constexpr (std::is_same_v<std::invoke_result_t<const G&, double>, ValueSlope>) {
    root_a = bracketed_newton(g, lo1, gmin, hi1, gmax);
    root_b = bracketed_newton(g, hi2, gmin, lo2, gmax);
    return true;
  }
  auto tol = boost::math::tools::eps_tolerance<double>(50);
  std::uintmax_t iters = 200;
  auto r1 = boost::math::tools::toms748_solve(value, lo1, hi1, tol, iters);
  iters = 200;
  auto r2 = boost::math::tools::toms748_solve(value, lo2, hi2, tol, iters);
  root_a = 0.5 * (r1.first + r1.second);
  root_b = 0.5 * (r2.first + r2.second);
  return true;
}

}  // namespace deepguide
