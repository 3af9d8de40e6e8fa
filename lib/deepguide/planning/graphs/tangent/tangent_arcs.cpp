// Arcs on the tangent graph's zone pieces: whether one is free of the other
// zones, the tangents from a point to the pieces, and an arc as a polyline
// and as the route's exact legs.

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <functional>
#include <numbers>

#include "deepguide/geometry/periodic_roots.hpp"
#include "deepguide/planning/graphs/tangent/tangent_graph_impl.hpp"

namespace deepguide {

using tangent_detail::kTouchEps;
using tangent_detail::unit;

bool TangentGraph::Impl::arc_free(std::size_t piece, double phi0, double phi1) const {
  const ZonePiece& z = pieces[piece];
  // Conservative advancement: where the arc's point has clearance c from
  // every other zone, the next c metres of arc are clear too (an arc is no
  // shorter than its chord), and the boundary runs at most `radius` metres
  // per radian of normal. Where c is below `step` the arc is sampled `step`
  // apart; an arc that enters another zone does so over a stretch, which the
  // samples find unless the overlap is thinner than the step (then the route
  // checker, which every route passes, has the last word). Far from other
  // zones an arc takes a few distances instead of one point test per `step`
  // (up to 200,000 on a turning circle). No arc takes more than 200,000
  // steps: a longer one is sampled that many times over its whole length.
  // The candidates are the obstacles whose box comes within the margin of
  // the piece's disc.
  const double radius = std::max(z.max_curvature_radius(), 1e-9);
  const double step = std::max({0.5 * tolerance, 1e-3, (phi1 - phi0) * radius / 200000.0});
  const std::size_t own = own_ellipse(piece);
  const Vec2 reach = Vec2::Constant(z.bounding_radius());
  std::vector<std::size_t> near = field->near(z.inner_point() - reach, z.inner_point() + reach, margin);
  std::erase(near, own);
  double phi = phi0;
  while (!near.empty()) {
    const Vec2 q = z.point_at_normal(phi);
    double c = std::numeric_limits<double>::infinity();
    for (std::size_t i : near) c = std::min(c, field->distance_to(i, q) - margin);
    if (c < -kTouchEps && phi > phi0) return false;
    phi += std::max(c, step) / radius;
    if (!(phi < phi1)) break;
  }
  // Capsules: the flat sides crossed are segments of their own.
  for (double f : z.flat_normals()) {
    for (double g = f + kTwoPi * std::ceil((phi0 - f) / kTwoPi); g < phi1; g += kTwoPi) {
      if (g > phi0 && !segment_free(z.a + z.margin * unit(g), z.b + z.margin * unit(g))) return false;
    }
  }
  return true;
}

void TangentGraph::Impl::add_point_tangents(const Vec2& p, std::vector<Segment>& out, const std::vector<double>& low,
                                            double bound) const {
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (low[i] > bound) continue;
    const ZonePiece& z = pieces[i];
    auto f = [&](double phi) {
      const Vec2 u = unit(phi);
      const ZonePiece::Support sz = z.support_at(u);
      return ValueSlope{u.dot(p) - sz.h, (p - sz.p).dot(Vec2(-u.y(), u.x()))};
    };
    double r[2];
    const Vec2 out_dir = p - z.inner_point();  // f > 0 this way when p lies outside
    if (periodic_two_roots(f, r[0], r[1], std::atan2(out_dir.y(), out_dir.x()))) {
      for (double phi : r) {
        const Node t{i, wrap_two_pi(phi), z.point_at_normal(wrap_two_pi(phi))};
        if (turns_at(i, t.phi) && segment_free(p, t.p, kNoPiece, i)) out.push_back({Node{kNoPiece, 0.0, p}, t});
      }
      continue;
    }
    // No tangent: p is inside the piece, or on its boundary. On the boundary,
    // p itself joins the piece's arcs at its normal angle.
    auto neg = [&](double phi) { return -f(phi).value; };
    const Vec2 d = p - z.inner_point();
    const double guess = std::atan2(d.y(), d.x());
    auto best = boost::math::tools::brent_find_minima(neg, guess - std::numbers::pi, guess + std::numbers::pi, 52);
    if (std::abs(best.second) <= kTouchEps && turns_at(i, wrap_two_pi(best.first))) {
      const double phi = wrap_two_pi(best.first);
      out.push_back({Node{kNoPiece, 0.0, p}, Node{i, phi, p}});
    }
  }
}

std::vector<Vec2> TangentGraph::Impl::arc_polyline(std::size_t piece, double phi0, double phi1, int turn) const {
  const ZonePiece& z = pieces[piece];
  // The arc's tangent lines at normals spaced so each corner where two meet
  // lies within `tolerance` of the arc, plus every flat side crossed. Between
  // tangent points T_k, T_k+1 the polyline runs T_k -> corner -> T_k+1, which
  // stays outside this zone; where a corner would poke into a neighbouring
  // zone the interval is split further (the arc itself is clear of it).
  const double lo = std::min(phi0, phi1), hi = std::max(phi0, phi1);
  const double rho = std::max(z.max_curvature_radius(), 1e-12);
  const double delta = 2.0 * std::acos(1.0 / (1.0 + tolerance / rho));
  std::vector<double> normals;
  const int n = std::max(1, static_cast<int>(std::ceil((hi - lo) / delta)));
  for (int k = 0; k <= n; ++k) normals.push_back(lo + (hi - lo) * k / n);
  for (double f : z.flat_normals()) {
    for (double g = f + kTwoPi * std::ceil((lo - f) / kTwoPi); g < hi; g += kTwoPi) {
      if (g > lo) normals.push_back(g);
    }
  }
  std::sort(normals.begin(), normals.end());
  normals.erase(std::unique(normals.begin(), normals.end()), normals.end());
  if (turn < 0) std::reverse(normals.begin(), normals.end());

  std::vector<Vec2> out;
  // Two tangent lines meet at a point whose rounding error grows as 1 / (b - a):
  // below 1e-7 rad it could land metres off, while the chord is within
  // R (b - a)^2 / 8 (< 1e-12 m) of the arc: no corner then.
  auto corner = [&](double a, double b, Vec2& v) {
    if (std::abs(b - a) < 1e-7) return false;
    const Vec2 u1 = unit(a), u2 = unit(b);
    const double h1 = z.support(u1), h2 = z.support(u2);
    const double det = u1.x() * u2.y() - u1.y() * u2.x();
    if (std::abs(det) < 1e-15) return false;
    v = Vec2((h1 * u2.y() - h2 * u1.y()) / det, (u1.x() * h2 - u2.x() * h1) / det);
    return true;
  };
  std::function<void(double, double, int)> emit = [&](double a, double b, int depth) {
    const Vec2 ta = z.point_at_normal(wrap_two_pi(a)), tb = z.point_at_normal(wrap_two_pi(b));
    Vec2 v;
    if (!corner(a, b, v)) return;
    if (depth < 40 && (!segment_free(ta, v, piece) || !segment_free(v, tb, piece))) {
      const double mid = 0.5 * (a + b);
      emit(a, mid, depth + 1);
      out.push_back(z.point_at_normal(wrap_two_pi(mid)));
      emit(mid, b, depth + 1);
      return;
    }
    out.push_back(v);
  };
  for (std::size_t k = 0; k + 1 < normals.size(); ++k) {
    if (k > 0) out.push_back(z.point_at_normal(wrap_two_pi(normals[k])));
    emit(normals[k], normals[k + 1], 0);
  }
  return out;
}

std::vector<RouteLeg> TangentGraph::Impl::arc_legs(std::size_t piece, double phi0, double phi1, int turn,
                                                   const Vec2& from_p, const Vec2& to_p) const {
  const ZonePiece& z = pieces[piece];
  std::vector<RouteLeg> out;
  auto arc = [&](const Ellipse& core, double from, double to, double length, double radius) {
    if (!(length > 1e-12)) return;
    RouteLeg leg;
    leg.kind = RouteLeg::Kind::arc;
    leg.turn = turn;
    leg.core = core;
    leg.core.centre += origin;
    leg.offset_m = z.margin;
    leg.phi_from = from;
    leg.phi_to = to;
    // From the core, not the piece: at a flat side's normal the piece's point is either end.
    leg.from = arc_point(leg, from);
    leg.to = arc_point(leg, to);
    leg.length_m = length;
    leg.radius_m = radius;
    leg.obstacle = piece_names[piece];
    out.push_back(std::move(leg));
  };
  if (z.kind == ZonePiece::Kind::ellipse) {
    arc(z.ellipse, phi0, phi1, z.arc_length(std::min(phi0, phi1), std::max(phi0, phi1)), z.max_curvature_radius());
    return out;
  }
  // A capsule: the flat sides crossed split the span into turns round one
  // end each, with a line along each side. A side's normal within rounding of
  // either end of the span is no cut: the points say which end the route is at.
  const double lo = std::min(phi0, phi1), hi = std::max(phi0, phi1);
  std::vector<double> cuts;
  for (double f : z.flat_normals()) {
    for (double g = f + kTwoPi * std::ceil((lo - f) / kTwoPi); g < hi; g += kTwoPi) {
      if (g > lo + 1e-12 && g < hi - 1e-12) cuts.push_back(g);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  if (turn < 0) std::reverse(cuts.begin(), cuts.end());
  auto end_at = [&](const Vec2& p, double phi) {
    const Vec2 q = p - z.margin * unit(phi);
    return (q - z.a).norm() <= (q - z.b).norm() ? z.a : z.b;
  };
  auto side = [&](const Vec2& from_end, const Vec2& to_end, double normal) {
    RouteLeg line;
    line.from = from_end + z.margin * unit(normal) + origin;
    line.to = to_end + z.margin * unit(normal) + origin;
    line.length_m = (line.to - line.from).norm();
    out.push_back(std::move(line));
  };
  Vec2 end = end_at(from_p, phi0);
  double from = phi0;
  for (double g : cuts) {
    arc(Ellipse{end, 0.0, 0.0, 0.0}, from, g, z.margin * std::abs(g - from), z.margin);
    const Vec2 other = end == z.a ? z.b : z.a;
    side(end, other, g);
    end = other;
    from = g;
  }
  arc(Ellipse{end, 0.0, 0.0, 0.0}, from, phi1, z.margin * std::abs(phi1 - from), z.margin);
  if (const Vec2 last = end_at(to_p, phi1); last != end) side(end, last, phi1);
  return out;
}

}  // namespace deepguide
