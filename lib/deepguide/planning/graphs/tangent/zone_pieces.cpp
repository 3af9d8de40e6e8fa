#include "deepguide/planning/graphs/tangent/zone_pieces.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <numbers>

#include "deepguide/core/angles.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace deepguide {
namespace {

Vec2 unit(double phi) { return {std::cos(phi), std::sin(phi)}; }

// Ellipse parameter t of the boundary point whose normal has local angle phi_l:
// the normal at t is proportional to (cos t / a, sin t / b), so
// tan(phi_l) = (a / b) tan t, i.e. t = atan2(b sin phi_l, a cos phi_l).
double param_of_normal(const Ellipse& e, double phi_l) {
  return std::atan2(e.b * std::sin(phi_l), e.a * std::cos(phi_l));
}

}  // namespace

// The ellipse's support function and point as in Ellipse::support and
// support_point, with the cached axis instead of two sincos per call.
double ZonePiece::support(const Vec2& u) const {
  if (kind == Kind::ellipse) {
    const double ul = u.dot(axis), vl = axis.x() * u.y() - axis.y() * u.x();
    return u.dot(ellipse.centre) + std::sqrt(ellipse.a * ellipse.a * ul * ul + ellipse.b * ellipse.b * vl * vl) +
           margin;
  }
  return std::max(u.dot(a), u.dot(b)) + margin;
}

ZonePiece::Support ZonePiece::support_at(const Vec2& u) const {
  if (kind == Kind::ellipse) {
    const double ul = u.dot(axis), vl = axis.x() * u.y() - axis.y() * u.x();
    const double aa = ellipse.a * ellipse.a, bb = ellipse.b * ellipse.b;
    const double h = std::sqrt(aa * ul * ul + bb * vl * vl);
    const Vec2 minor(-axis.y(), axis.x());
    return {u.dot(ellipse.centre) + h + margin,
            ellipse.centre + (aa * ul / h) * axis + (bb * vl / h) * minor + margin * u};
  }
  const Vec2& end = u.dot(b) > u.dot(a) ? b : a;
  return {u.dot(end) + margin, end + margin * u};
}

Vec2 ZonePiece::point_at_normal(double phi) const { return support_at(unit(phi)).p; }

double ZonePiece::arc_length(double phi0, double phi1) const {
  if (!(phi1 > phi0)) return 0.0;
  const double dphi = phi1 - phi0;
  double length = margin * dphi;  // the disc's share: d per radian
  if (kind == Kind::capsule) {
    // Each flat side crossed adds the edge length.
    const double edge = (b - a).norm();
    if (edge > 0.0) {
      for (double f : flat_normals()) {
        // Count the k with phi0 < f + 2 pi k <= phi1.
        const double first = f + kTwoPi * std::ceil((phi0 - f) / kTwoPi);
        for (double g = first; g <= phi1; g += kTwoPi) {
          if (g > phi0) length += edge;
        }
      }
    }
    return length;
  }
  // Ellipse: integrate |x'(t)| = sqrt(a^2 sin^2 t + b^2 cos^2 t) over the
  // parameter interval that the normal angles span (t increases with phi).
  // t(phi) is increasing with t(phi + 2 pi) = t(phi) + 2 pi: split the span
  // into whole turns and a remainder r in [0, 2 pi).
  const double turns = std::floor(dphi / kTwoPi);
  const double r = dphi - kTwoPi * turns;
  const double t0 = param_of_normal(ellipse, phi0 - ellipse.theta);
  double dt = wrap_two_pi(param_of_normal(ellipse, phi0 + r - ellipse.theta) - t0);
  if (r < std::numbers::pi && dt > 1.5 * std::numbers::pi) dt = 0.0;  // rounding below zero wrapped round
  const double t1 = t0 + kTwoPi * turns + dt;
  const double a = ellipse.a, b = ellipse.b;
  auto speed = [a, b](double t) { return std::hypot(a * std::sin(t), b * std::cos(t)); };
  // Gauss-Kronrod per quarter turn: the integrand is smooth, 15 points are exact to ~1e-14.
  double sum = 0.0;
  const int pieces = std::max(1, static_cast<int>(std::ceil((t1 - t0) / (kTwoPi / 8))));
  const double h = (t1 - t0) / pieces;
  for (int k = 0; k < pieces; ++k) {
    sum += boost::math::quadrature::gauss_kronrod<double, 15>::integrate(speed, t0 + k * h, t0 + (k + 1) * h, 0, 0);
  }
  return length + sum;
}

std::vector<double> ZonePiece::flat_normals() const {
  if (kind != Kind::capsule || (b - a).norm() == 0.0) return {};
  const double along = std::atan2(b.y() - a.y(), b.x() - a.x());
  return {wrap_two_pi(along + std::numbers::pi / 2), wrap_two_pi(along - std::numbers::pi / 2)};
}

double ZonePiece::max_curvature_radius() const {
  if (kind == Kind::capsule) return margin;
  return ellipse.a * ellipse.a / ellipse.b + margin;
}

Vec2 ZonePiece::inner_point() const { return kind == Kind::ellipse ? ellipse.centre : 0.5 * (a + b); }

double ZonePiece::bounding_radius() const {
  return (kind == Kind::ellipse ? ellipse.a : 0.5 * (b - a).norm()) + margin;
}

double ZonePiece::core_distance(const Vec2& p) const {
  if (kind == Kind::capsule) return point_segment_distance(p, a, b);
  return std::max(0.0, signed_distance(ellipse, p));
}

bool zones_overlap(const ZonePiece& p, const ZonePiece& q) {
  // w in p's core with the disc of radius r round it in p's zone; the zones'
  // interiors meet when w lies closer than r + q.margin to q's core. The
  // nanometre per metre keeps a touch (one common point, tangents through
  // it) out of the verdict despite rounding.
  auto reaches = [](const ZonePiece& x, const ZonePiece& y) {
    auto within = [&](const Vec2& w, double r) {
      const double reach = r + y.margin;
      return y.core_distance(w) < reach - 1e-9 * (1.0 + reach);
    };
    if (x.kind == ZonePiece::Kind::ellipse) return within(x.ellipse.centre, x.ellipse.b + x.margin);
    return within(x.a, x.margin) || within(x.b, x.margin);
  };
  // Discs round the inner points that hold the pieces and do not meet rule it out at once.
  if ((p.inner_point() - q.inner_point()).norm() >= p.bounding_radius() + q.bounding_radius()) return false;
  return reaches(p, q) || reaches(q, p);
}

std::vector<ZonePiece> zone_pieces(const ObstacleSet& obstacles, double margin) {
  std::vector<ZonePiece> out;
  std::size_t index = 0;
  for (const EllipticCylinder& c : obstacles.ellipses) {
    ZonePiece p;
    p.kind = ZonePiece::Kind::ellipse;
    p.ellipse = c.footprint;
    p.axis = c.footprint.major_dir();
    p.margin = margin;
    p.obstacle = index++;
    out.push_back(p);
  }
  for (const PolygonObstacle& poly : obstacles.polygons) {
    auto add_ring = [&](const auto& ring) {
      for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
        ZonePiece p;
        p.kind = ZonePiece::Kind::capsule;
        p.a = to_eigen(ring[i]);
        p.b = to_eigen(ring[i + 1]);
        p.margin = margin;
        p.obstacle = index;
        out.push_back(p);
      }
    };
    add_ring(poly.footprint.outer());
    for (const auto& inner : poly.footprint.inners()) add_ring(inner);
    ++index;
  }
  return out;
}

}  // namespace deepguide
