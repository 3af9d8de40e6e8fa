// The exact tangent graph: arc lengths, closed-form optima, an independent
// exact solver for discs, and brackets for ellipses.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "deepguide/planning/graphs/tangent/tangent_graph.hpp"
#include "deepguide/planning/graphs/tangent/zone_pieces.hpp"
#include "deepguide/planning/graphs/visibility/visibility_graph.hpp"
#include "deepguide/planning/graphs/visibility/zone_visibility_graph.hpp"
#include "deepguide/planning/planner.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

constexpr double kPi = 3.14159265358979323846;

EllipticCylinder ellipse(double x, double y, double a, double b, double theta) {
  EllipticCylinder c;
  c.footprint = Ellipse{{x, y}, a, b, theta};
  return c;
}

// Boundary length of the offset curve between normal angles, by brute force:
// 200000 chords between boundary points found from the normal directly.
double offset_arc_by_chords(const Ellipse& e, double d, double phi0, double phi1) {
  const int n = 200000;
  double sum = 0.0;
  Vec2 prev;
  for (int k = 0; k <= n; ++k) {
    const double phi = phi0 + (phi1 - phi0) * k / n;
    const Vec2 u(std::cos(phi), std::sin(phi));
    // Support point of the ellipse for u, from its definition.
    const Vec2 ul(u.dot(e.major_dir()), u.dot(e.minor_dir()));
    const double h = std::hypot(e.a * ul.x(), e.b * ul.y());
    const Vec2 q =
        e.centre + (e.a * e.a * ul.x() / h) * e.major_dir() + (e.b * e.b * ul.y() / h) * e.minor_dir() + d * u;
    if (k > 0) sum += (q - prev).norm();
    prev = q;
  }
  return sum;
}

// ---- An independent exact solver for disjoint discs (closed-form tangents,
// plain O(V^2) Dijkstra); it shares no code with the library's planners.
struct Disc {
  Vec2 c;
  double r;
};

double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

double exact_disc_optimum(const std::vector<Disc>& discs, const Vec2& s, const Vec2& g) {
  struct N {
    Vec2 p;
    int disc;
    double ang;
  };
  std::vector<N> nodes{{s, -1, 0}, {g, -1, 0}};
  std::vector<std::tuple<int, int, double>> edges;
  auto free_segment = [&](const Vec2& a, const Vec2& b) {
    for (const Disc& d : discs) {
      if (point_segment_distance(d.c, a, b) < d.r - 1e-7) return false;
    }
    return true;
  };
  auto add = [&](const Vec2& a, int da, const Vec2& b, int db, int ia = -1) {
    if (!free_segment(a, b)) return;
    int i = ia;
    if (i < 0) {
      nodes.push_back({a, da, std::atan2(a.y() - discs[da].c.y(), a.x() - discs[da].c.x())});
      i = static_cast<int>(nodes.size()) - 1;
    }
    nodes.push_back({b, db, std::atan2(b.y() - discs[db].c.y(), b.x() - discs[db].c.x())});
    edges.emplace_back(i, static_cast<int>(nodes.size()) - 1, (a - b).norm());
  };
  for (std::size_t i = 0; i < discs.size(); ++i) {
    for (std::size_t j = i + 1; j < discs.size(); ++j) {
      const Vec2 dc = discs[j].c - discs[i].c;
      const double dist = dc.norm(), alpha = std::atan2(dc.y(), dc.x());
      for (double sigma : {1.0, -1.0}) {  // outer, inner
        const double c = (discs[i].r - sigma * discs[j].r) / dist;
        for (double sgn : {1.0, -1.0}) {
          // Line n.x = k touching disc i (n.c_i + r_i = k) and disc j (n.c_j + sigma r_j = k):
          // n.(c_j - c_i) = r_i - sigma r_j, so cos(phi - alpha) = c.
          const double phi = alpha + sgn * std::acos(c);
          const Vec2 n(std::cos(phi), std::sin(phi));
          add(discs[i].c + discs[i].r * n, int(i), discs[j].c + sigma * discs[j].r * n, int(j));
        }
      }
    }
  }
  for (int end = 0; end < 2; ++end) {
    const Vec2 p = end == 0 ? s : g;
    for (std::size_t i = 0; i < discs.size(); ++i) {
      const Vec2 d = p - discs[i].c;
      const double beta = std::atan2(d.y(), d.x()), half = std::acos(discs[i].r / d.norm());
      for (double sgn : {1.0, -1.0}) {
        const Vec2 n(std::cos(beta + sgn * half), std::sin(beta + sgn * half));
        add(p, -1, discs[i].c + discs[i].r * n, int(i), end);
      }
    }
  }
  if (free_segment(s, g)) edges.emplace_back(0, 1, (g - s).norm());
  // Arcs between consecutive tangent points on each disc (both ways round).
  for (std::size_t i = 0; i < discs.size(); ++i) {
    std::vector<int> ids;
    for (std::size_t k = 2; k < nodes.size(); ++k)
      if (nodes[k].disc == int(i)) ids.push_back(int(k));
    std::sort(ids.begin(), ids.end(), [&](int a, int b) { return nodes[a].ang < nodes[b].ang; });
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const int a = ids[k], b = ids[(k + 1) % ids.size()];
      double da = nodes[b].ang - nodes[a].ang;
      if (da < 0) da += 2 * kPi;
      edges.emplace_back(a, b, discs[i].r * da);
    }
  }
  std::vector<double> dist(nodes.size(), std::numeric_limits<double>::infinity());
  std::vector<bool> done(nodes.size(), false);
  dist[0] = 0;
  for (;;) {
    int u = -1;
    for (std::size_t k = 0; k < nodes.size(); ++k)
      if (!done[k] && (u < 0 || dist[k] < dist[u])) u = int(k);
    if (u < 0 || !std::isfinite(dist[u])) break;
    done[u] = true;
    for (const auto& [a, b, w] : edges) {
      if (a == u && dist[u] + w < dist[b]) dist[b] = dist[u] + w;
      if (b == u && dist[u] + w < dist[a]) dist[a] = dist[u] + w;
    }
  }
  return dist[1];
}

}  // namespace

TEST(ZonePieces, EllipseArcLengthMatchesChords) {
  const Ellipse e{{3, -2}, 10, 2, 0.4};
  const ZonePiece z = zone_pieces(ObstacleSet{{ellipse(3, -2, 10, 2, 0.4)}, {}}, 5.0)[0];
  for (const auto& [p0, p1] : {std::pair{0.1, 0.7}, std::pair{2.0, 5.5}, std::pair{-1.0, 4.0},
                               std::pair{0.3, 0.3 + 2 * kPi}, std::pair{1.0, 1.0 + 3 * kPi}}) {
    EXPECT_NEAR(z.arc_length(p0, p1), offset_arc_by_chords(e, 5.0, p0, p1), 1e-6) << p0 << " " << p1;
  }
  // Full turn of the ellipse itself (d = 0): the perimeter 42.0200890794 (a = 10, b = 2).
  const ZonePiece bare = zone_pieces(ObstacleSet{{ellipse(0, 0, 10, 2, 0.4)}, {}}, 0.0)[0];
  EXPECT_NEAR(bare.arc_length(0.2, 0.2 + 2 * kPi), 42.020089079378, 1e-9);
}

TEST(ZonePieces, CapsuleArcLengthCountsFlatSides) {
  ObstacleSet set;
  PolygonObstacle p;
  p.footprint.outer() = {to_bg({0, 0}), to_bg({0, 10}), to_bg({10, 10}), to_bg({10, 0}), to_bg({0, 0})};
  set.polygons.push_back(p);
  const auto pieces = zone_pieces(set, 2.0);
  ASSERT_EQ(pieces.size(), 4u);
  // A full turn around one capsule: two flat sides of 10 m plus a circle of 2 m.
  EXPECT_NEAR(pieces[0].arc_length(0.1, 0.1 + 2 * kPi), 20.0 + 2 * kPi * 2.0, 1e-12);
}

namespace {
ZonePiece disc(double x, double y, double r) {
  ZonePiece z;
  z.kind = ZonePiece::Kind::capsule;
  z.a = z.b = {x, y};
  z.margin = r;
  return z;
}
}  // namespace

TEST(ZonePieces, OverlapByHand) {
  // Discs 10 m apart: radii 6 + 5 overlap, 4 + 5 do not, 5 + 5 only touch.
  EXPECT_TRUE(zones_overlap(disc(0, 0, 6), disc(10, 0, 5)));
  EXPECT_FALSE(zones_overlap(disc(0, 0, 4), disc(10, 0, 5)));
  EXPECT_FALSE(zones_overlap(disc(0, 0, 5), disc(10, 0, 5)));
  // Ellipse a = 10, b = 2 along x with a 1 m zone (its tip at x = 11): a disc
  // at x = 12.5 is 2.5 m from the ellipse, so radius 1.6 reaches its zone
  // and 1.4 does not; the test is symmetric.
  const ZonePiece e = zone_pieces(ObstacleSet{{ellipse(0, 0, 10, 2, 0.0)}, {}}, 1.0)[0];
  EXPECT_TRUE(zones_overlap(e, disc(12.5, 0, 1.6)));
  EXPECT_TRUE(zones_overlap(disc(12.5, 0, 1.6), e));
  EXPECT_FALSE(zones_overlap(e, disc(12.5, 0, 1.4)));
  // Across the minor axis the ellipse's centre disc (b + d = 3) reaches a disc at y = 4.5 of radius 1.6.
  EXPECT_TRUE(zones_overlap(e, disc(0, 4.5, 1.6)));
  EXPECT_FALSE(zones_overlap(e, disc(0, 4.5, 1.4)));
}

TEST(ZonePieces, OverlappingZonesHaveNoInnerTangent) {
  // What the tangent graph relies on when it skips the inner tangents: for
  // every pair the test calls overlapping, h_p(u) + h_q(-u) stays positive
  // on a dense scan of u (it would be negative somewhere for disjoint zones).
  std::mt19937_64 rng(2027);
  std::uniform_real_distribution<double> pos(-30, 30), semi(1, 20), ratio(0.1, 1), angle(0, 2 * kPi), rad(0.5, 15);
  int overlapping = 0, separated = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const double a = semi(rng);
    const ZonePiece e =
        zone_pieces(ObstacleSet{{ellipse(pos(rng), pos(rng), a, a * ratio(rng), angle(rng))}, {}}, rad(rng) / 3)[0];
    const ZonePiece d = trial % 2
                            ? disc(pos(rng), pos(rng), rad(rng))
                            : zone_pieces(ObstacleSet{{ellipse(pos(rng), pos(rng), a, a * ratio(rng), angle(rng))}, {}},
                                          rad(rng) / 3)[0];
    double least = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 20000; ++k) {
      const Vec2 u(std::cos(2 * kPi * k / 20000), std::sin(2 * kPi * k / 20000));
      least = std::min(least, e.support(u) + d.support(-u));
    }
    if (zones_overlap(e, d)) {
      ++overlapping;
      EXPECT_GT(least, 0.0) << "trial " << trial;
    } else if (least < 0.0) {
      ++separated;
    }
  }
  // Both kinds occur, so the loop tests something.
  EXPECT_GT(overlapping, 300);
  EXPECT_GT(separated, 300);
}

TEST(TangentGraph, SingleDiscAndEllipseClosedForms) {
  ObstacleSet set{{ellipse(0, 0, 15, 15, 0.3)}, {}};
  Planner planner(set, {5.0, 0.05, GraphKind::tangent, SearchAlgorithm::astar});
  const PlanOutcome out = planner.solve({{-150, 0}, {150, 0}});
  ASSERT_TRUE(out.result.found);
  const double exact = 2.0 * std::sqrt(150.0 * 150.0 - 400.0) + 20.0 * (kPi - 2.0 * std::acos(20.0 / 150.0));
  EXPECT_NEAR(out.result.exact_length_m, exact, 1e-9 * exact);
  EXPECT_TRUE(out.check.safe) << out.check.describe();
  EXPECT_GE(out.result.route.length(), exact);
  EXPECT_LE(out.result.route.length(), exact + 0.05);
  ASSERT_EQ(out.result.legs.size(), 3u);
  EXPECT_EQ(out.result.legs[1].kind, RouteLeg::Kind::arc);
  EXPECT_NEAR(out.result.legs[1].radius_m, 20.0, 1e-12);
}

TEST(TangentGraph, RandomDiscsMatchAnIndependentExactSolver) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> pos(-150.0, 150.0), rad(3.0, 30.0), u01(0.0, 1.0);
  int compared = 0;
  double worst = 0.0;
  for (int scenario = 0; scenario < 300; ++scenario) {
    // Disjoint zones that are discs of radius r: obstacles of radius r - margin.
    std::vector<Disc> discs;
    ObstacleSet set;
    const double margin = scenario % 3 == 0 ? 0.0 : 3.0 * u01(rng);
    for (int tries = 0; tries < 40 && discs.size() < 7; ++tries) {
      const Disc d{{pos(rng), pos(rng)}, margin + rad(rng)};
      bool ok = true;
      for (const Disc& o : discs) ok = ok && (d.c - o.c).norm() > d.r + o.r + 0.5;
      if (!ok) continue;
      discs.push_back(d);
      set.ellipses.push_back(ellipse(d.c.x(), d.c.y(), d.r - margin, d.r - margin, 2.0 * kPi * u01(rng)));
    }
    const Vec2 s(-220.0, pos(rng)), g(220.0, pos(rng));
    const double reference = exact_disc_optimum(discs, s, g);
    Planner planner(set, {margin, 0.1, GraphKind::tangent, SearchAlgorithm::astar});
    const PlanOutcome out = planner.solve({s, g});
    ASSERT_TRUE(out.result.found) << scenario;
    ASSERT_TRUE(out.check.safe) << scenario << ": " << out.check.describe();
    const double rel = std::abs(out.result.exact_length_m / reference - 1.0);
    worst = std::max(worst, rel);
    EXPECT_LT(rel, 1e-6) << "scenario " << scenario << ": " << out.result.exact_length_m << " vs " << reference;
    ++compared;
  }
  std::printf("[ tangent ] %d disc scenarios, worst relative difference to the independent solver %.3g\n", compared,
              worst);
}

TEST(TangentGraph, RandomEllipsesAreBracketedByPolygonGraphs) {
  // Lower bound: visibility graph over polygons inscribed in the zones (512
  // vertices on the offset curve). Upper bound: the polygon planner's route.
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> pos(-150.0, 150.0), ang(-kPi, kPi), u01(0.0, 1.0);
  int compared = 0;
  double worst_gap = 0.0;
  for (int scenario = 0; scenario < test::cases(120); ++scenario) {
    ObstacleSet set;
    const double margin = 8.0 * u01(rng);
    const int n = 1 + scenario % 5;
    for (int i = 0; i < n; ++i) {
      const double a = 5.0 + 30.0 * u01(rng);
      set.ellipses.push_back(ellipse(pos(rng), pos(rng), a, a * (0.15 + 0.85 * u01(rng)), ang(rng)));
    }
    const Vec2 s(-230.0, pos(rng)), g(230.0, pos(rng));
    Planner poly(set, {margin, 0.05, GraphKind::visibility, SearchAlgorithm::astar});
    if (poly.graph().as<ZoneVisibilityGraph>()->zones().size() != set.size())
      continue;  // zones overlap: no simple bracket
    Planner tangent(set, {margin, 0.05, GraphKind::tangent, SearchAlgorithm::astar});
    const PlanOutcome t = tangent.solve({s, g});
    const PlanOutcome p = poly.solve({s, g});
    ASSERT_TRUE(t.result.found && p.result.found) << scenario;
    ASSERT_TRUE(t.check.safe) << scenario << ": " << t.check.describe();
    BgMultiPolygon inscribed;
    for (const auto& c : set.ellipses) {
      BgPolygon ring;
      for (int k = 512; k >= 0; --k) {
        const double tt = 2.0 * kPi * k / 512;
        ring.outer().push_back(to_bg(c.footprint.point_at(tt) + margin * c.footprint.normal_at(tt)));
      }
      inscribed.push_back(ring);
    }
    VisibilityGraph lower(inscribed, VisibilityVariant::reduced);
    const double lb = lower.solve({s, g}, SearchAlgorithm::astar).route.length();
    const double exact = t.result.exact_length_m;
    EXPECT_GE(exact, lb * (1 - 1e-12)) << scenario;
    EXPECT_LE(exact, p.result.route.length() * (1 + 1e-12)) << scenario;
    worst_gap = std::max(worst_gap, exact / lb - 1.0);
    EXPECT_LE(exact / lb - 1.0, 2e-5) << scenario;
    ++compared;
  }
  std::printf("[ tangent ] %d ellipse scenarios, exact length at most %.3g above the inscribed lower bound\n", compared,
              worst_gap);
  EXPECT_GT(compared, test::cases(60));
}
