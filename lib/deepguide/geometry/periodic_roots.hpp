#pragma once
// Roots of smooth 2-pi-periodic functions that have exactly two simple roots
// (tangency conditions written with support functions: common tangents of two
// convex sets, tangents from a point). Any angle where the function is
// negative and any where it is positive split the circle into two arcs with
// one root each, so sampling for both signs and bracketing solves it; TOMS 748
// (Boost.Math) then converges to full precision.

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cstdint>
#include <numbers>

namespace deepguide {

namespace periodic_detail {
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Coarse sampling finds both signs for all but nearly touching or very
// elongated pairs; only those pay for the dense pass and the polish.
inline constexpr int kCoarseSamples = 48;
inline constexpr int kDenseSamples = 720;

struct Extremes {
  double phi_neg, g_neg, phi_pos, g_pos, step;
};

template <class G>
Extremes sample_extremes(const G& g, int samples) {
  Extremes x{0.0, g(0.0), 0.0, 0.0, kTwoPi / samples};
  x.g_pos = x.g_neg;
  for (int k = 1; k < samples; ++k) {
    const double phi = x.step * k;
    const double v = g(phi);
    if (v < x.g_neg) x.g_neg = v, x.phi_neg = phi;
    if (v > x.g_pos) x.g_pos = v, x.phi_pos = phi;
  }
  return x;
}

}  // namespace periodic_detail

/// Finds the two roots (root_a, root_b in radians, not wrapped) of g, or
/// returns false when g has no negative or no positive value (then the roots
/// do not exist or coincide). `hint`: an angle where g is likely of one sign
/// and of the other half a turn away (e.g. the direction between the two
/// sets' centres); when it is, the sampling is skipped.
template <class G>
bool periodic_two_roots(const G& g, double& root_a, double& root_b, double hint = 0.0) {
  using namespace periodic_detail;
  const double g0 = g(hint), g1 = g(hint + std::numbers::pi);
  Extremes x{hint, g0, hint + std::numbers::pi, g1, std::numbers::pi};
  if (g0 > g1) x = Extremes{hint + std::numbers::pi, g1, hint, g0, std::numbers::pi};
  if (!(x.g_neg < 0.0 && x.g_pos > 0.0)) x = sample_extremes(g, kCoarseSamples);
  if (!(x.g_neg < 0.0 && x.g_pos > 0.0)) x = sample_extremes(g, kDenseSamples);
  double phi_neg = x.phi_neg, gmin = x.g_neg, phi_pos = x.phi_pos, gmax = x.g_pos;
  const double step = x.step;
  // A narrow sign window can fall between samples (nearly touching ellipses):
  // polish the extremum before giving up.
  if (gmin >= 0.0) {
    auto r = boost::math::tools::brent_find_minima(g, phi_neg - step, phi_neg + step, 52);
    phi_neg = r.first, gmin = r.second;
  }
  if (gmax <= 0.0) {
    auto neg = [&](double t) { return -g(t); };
    auto r = boost::math::tools::brent_find_minima(neg, phi_pos - step, phi_pos + step, 52);
    phi_pos = r.first, gmax = -r.second;
  }
  if (!(gmin < 0.0 && gmax > 0.0)) return false;
  // Each arc between the negative and the positive point holds exactly one root.
  const double lo1 = phi_neg;
  const double hi1 = phi_pos > phi_neg ? phi_pos : phi_pos + kTwoPi;
  const double lo2 = hi1;
  const double hi2 = phi_neg + kTwoPi;
  auto tol = boost::math::tools::eps_tolerance<double>(50);
  std::uintmax_t iters = 200;
  auto r1 = boost::math::tools::toms748_solve(g, lo1, hi1, tol, iters);
  iters = 200;
  auto r2 = boost::math::tools::toms748_solve(g, lo2, hi2, tol, iters);
  root_a = 0.5 * (r1.first + r1.second);
  root_b = 0.5 * (r2.first + r2.second);
  return true;
}

}  // namespace deepguide
