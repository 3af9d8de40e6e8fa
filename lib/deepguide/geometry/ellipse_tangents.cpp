#include "deepguide/geometry/ellipse_tangents.hpp"

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace deepguide {

std::optional<PointTangents> tangent_points(const Ellipse& e, const Vec2& p) {
  const Vec2 q = e.to_unit(p);
  const double r = q.norm();
  if (!(r > 1.0)) return std::nullopt;
  const double base = std::atan2(q.y(), q.x());
  const double half = std::acos(1.0 / r);
  // Seen from q looking at the origin, the point at base - half lies to the left.
  const Vec2 left = e.from_unit(Vec2(std::cos(base - half), std::sin(base - half)));
  const Vec2 right = e.from_unit(Vec2(std::cos(base + half), std::sin(base + half)));
  return PointTangents{left, right};
}

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Coarse sampling finds both signs for all but nearly touching or very
// elongated pairs; only those pay for the dense pass and the polish.
constexpr int kCoarseSamples = 48;
constexpr int kDenseSamples = 720;

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

// Finds the two roots of a smooth 2-pi-periodic function known to have
// exactly two simple roots, or returns false when it has no negative or no
// positive value (then the roots do not exist or coincide).
template <class G>
bool two_roots(const G& g, double& root_a, double& root_b) {
  Extremes x = sample_extremes(g, kCoarseSamples);
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

Vec2 unit(double phi) { return {std::cos(phi), std::sin(phi)}; }

}  // namespace

std::vector<CommonTangent> common_tangents(const Ellipse& e1, const Ellipse& e2) {
  const Vec2 dc = e1.center - e2.center;
  // Centred support functions h_i(n) = sqrt(n^T A_i n), with the shape matrices
  // computed once (this runs ~150 times per pair).
  const Eigen::Matrix2d A1 = e1.shape_matrix();
  const Eigen::Matrix2d A2 = e2.shape_matrix();
  auto h = [](const Eigen::Matrix2d& A, const Vec2& n) { return std::sqrt(n.dot(A * n)); };
  auto g_outer = [&](double phi) {
    const Vec2 n = unit(phi);
    return n.dot(dc) + h(A1, n) - h(A2, n);
  };
  auto g_inner = [&](double phi) {
    const Vec2 n = unit(phi);
    return n.dot(dc) + h(A1, n) + h(A2, n);
  };
  double o1 = 0, o2 = 0, i1 = 0, i2 = 0;
  if (!two_roots(g_inner, i1, i2) || !two_roots(g_outer, o1, o2)) return {};
  std::vector<CommonTangent> out;
  for (double phi : {o1, o2}) {
    const Vec2 n = unit(phi);
    out.push_back({TangentKind::outer, e1.support_point(n), e2.support_point(n), n});
  }
  for (double phi : {i1, i2}) {
    const Vec2 n = unit(phi);
    out.push_back({TangentKind::inner, e1.support_point(n), e2.support_point(-n), n});
  }
  return out;
}

}  // namespace deepguide
