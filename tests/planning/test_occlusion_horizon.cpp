// The occlusion horizon (what a point may see among polygons) and the reduced
// visibility graph built with it, against independent references: bearings
// against atan2, a hand-placed square, the exact segment test on every corner
// a horizon hides, and a brute-force all-pairs graph on random fields (with
// holes, overlaps merged, and enough corners for the threaded build).
#include <gtest/gtest.h>

#include <boost/geometry.hpp>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "deepguide/planning/graphs/visibility/occlusion_horizon.hpp"
#include "deepguide/planning/graphs/visibility/visibility_graph.hpp"
#include "deepguide/planning/polygon_visibility.hpp"
#include "deepguide/planning/zone_polygons.hpp"
#include "test_support.hpp"

using namespace deepguide;
namespace bg = boost::geometry;

namespace {

constexpr double kPi = 3.14159265358979323846;

BgPolygon square(double x0, double y0, double x1, double y1) {
  BgPolygon p;
  p.outer() = {to_bg({x0, y0}), to_bg({x0, y1}), to_bg({x1, y1}), to_bg({x1, y0}), to_bg({x0, y0})};
  bg::correct(p);
  return p;
}

// Random ellipses in a w x h field, zones merged at margin 5 m; every fourth
// field also holds a harbour: a wide square ring with obstacles in its basin.
BgMultiPolygon random_zones(std::mt19937& rng, int count, double w, double h, double tolerance, bool harbour) {
  std::uniform_real_distribution<double> x(-w / 2, w / 2), y(-h / 2, h / 2), a(5.0, 40.0), ratio(0.2, 1.0),
      theta(0.0, kPi);
  ObstacleSet set;
  for (int i = 0; i < count; ++i) {
    EllipticCylinder c;
    c.id = "e" + std::to_string(i);
    const double semi = a(rng);
    c.footprint = Ellipse{{x(rng), y(rng)}, semi, semi * ratio(rng), theta(rng)};
    set.ellipses.push_back(c);
  }
  if (harbour) {
    PolygonObstacle ring;
    ring.id = "harbour";
    ring.footprint = square(-w / 2 - 400, -h / 2 - 400, -w / 2 - 100, h / 2 + 100);
    BgPolygon basin = square(-w / 2 - 330, -h / 2 - 330, -w / 2 - 170, h / 2 + 30);
    bg::reverse(basin.outer());  // a hole runs anticlockwise
    ring.footprint.inners().push_back(basin.outer());
    bg::correct(ring.footprint);
    set.polygons.push_back(ring);
    for (double yy : {-h / 2 - 250, -h / 2, 0.0}) {
      EllipticCylinder c;
      c.id = "basin" + std::to_string(set.ellipses.size());
      c.footprint = Ellipse{{-w / 2 - 250, yy}, 20, 8, 0.4};
      set.ellipses.push_back(c);
    }
  }
  return merged_zone_polygons(set, {5.0, tolerance});
}

struct Corner {
  Vec2 p, prev, next;
};

std::vector<Corner> convex_corners(const BgMultiPolygon& zones) {
  std::vector<Corner> out;
  auto ring_corners = [&](const auto& ring) {
    const std::size_t n = ring.size() - 1;
    for (std::size_t i = 0; i < n; ++i) {
      Corner c{to_eigen(ring[i]), to_eigen(ring[(i + n - 1) % n]), to_eigen(ring[(i + 1) % n])};
      // Boost rings keep the obstacle on the right: convex corners turn right.
      if (cross(c.p - c.prev, c.next - c.p) < 0.0) out.push_back(c);
    }
  };
  for (const BgPolygon& poly : zones) {
    ring_corners(poly.outer());
    for (const auto& inner : poly.inners()) ring_corners(inner);
  }
  return out;
}

// Both polygon neighbours of c on one closed side of the line through c and
// q, up to eps in distance: the definition the reduced graph keeps.
bool supporting(const Corner& c, const Vec2& q, double eps) {
  const Vec2 d = (q - c.p).normalized();
  const double s1 = cross(d, c.prev - c.p), s2 = cross(d, c.next - c.p);
  return (s1 >= -eps && s2 >= -eps) || (s1 <= eps && s2 <= eps);
}

using Key = std::pair<long long, long long>;
Key key(const Vec2& p) { return {std::llround(p.x() * 1e4), std::llround(p.y() * 1e4)}; }

}  // namespace

TEST(OcclusionHorizon, PseudoBearingsOrderDirectionsAsAnglesDo) {
  EXPECT_DOUBLE_EQ(pseudo_bearing({1, 0}), 0.0);
  EXPECT_DOUBLE_EQ(pseudo_bearing({0, 3}), 1.0);
  EXPECT_DOUBLE_EQ(pseudo_bearing({-2, 0}), 2.0);
  EXPECT_DOUBLE_EQ(pseudo_bearing({0, -1}), 3.0);
  EXPECT_DOUBLE_EQ(pseudo_bearing({1, 1}), 0.5);
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  for (int k = 0; k < 2000; ++k) {
    const double a = angle(rng), b = angle(rng);
    const Vec2 va(std::cos(a), std::sin(a)), vb(std::cos(b), std::sin(b));
    const double pa = pseudo_bearing(va), pb = pseudo_bearing(vb);
    EXPECT_EQ(a < b, pa < pb) << a << " " << b;
    // A half turn is exactly 2, and the pseudo-angle never moves faster than the angle.
    EXPECT_NEAR(std::fmod(pseudo_bearing(-va) + 4.0 - pa, 4.0), 2.0, 1e-12);
    EXPECT_LE(std::abs(pb - pa), std::abs(b - a) + 1e-12);
  }
}

TEST(OcclusionHorizon, ArcsAcrossBearingZeroAreSplit) {
  BearingSet set;
  add_arc(set, 3.5, 4.25);
  ASSERT_EQ(set.size(), 2u);
  EXPECT_DOUBLE_EQ(set[0].first, 3.5);
  EXPECT_DOUBLE_EQ(set[0].second, 4.0);
  EXPECT_DOUBLE_EQ(set[1].first, 0.0);
  EXPECT_DOUBLE_EQ(set[1].second, 0.25);
  add_arc(set, -1.0, 5.0);  // more than a full turn: everything
  ASSERT_EQ(set.size(), 1u);
  EXPECT_DOUBLE_EQ(set[0].second - set[0].first, 4.0);
}

TEST(OcclusionHorizon, ASquareAheadHidesWhatIsBehindIt) {
  // Square [10, 20] x [-5, 5] seen from the origin: bearings within
  // atan(5 / 10) = 26.57 degrees of +x are hidden beyond its far corner,
  // sqrt(20^2 + 5^2) = 20.616 m away.
  BgMultiPolygon polys{square(10, -5, 20, 5)};
  const OcclusionHorizon occlusion(polys, 1e-9);
  const double ten_deg = pseudo_bearing({std::cos(0.1745), std::sin(0.1745)});
  BearingSet narrow;
  add_arc(narrow, -ten_deg, ten_deg);
  const Horizon h = occlusion.horizon({0, 0}, narrow, 64);
  EXPECT_TRUE(h.bounded());
  EXPECT_NEAR(h.reach_m, std::hypot(20.0, 5.0), 1e-12);
  EXPECT_FALSE(h.sees({30, 0}));
  EXPECT_FALSE(h.sees({25, 3}));
  EXPECT_TRUE(h.sees({20.5, 0}));  // within the reach: for the exact test to decide

  const double forty_deg = pseudo_bearing({std::cos(0.698), std::sin(0.698)});
  BearingSet wide;
  add_arc(wide, -forty_deg, forty_deg);
  const Horizon open = occlusion.horizon({0, 0}, wide, 64);
  EXPECT_FALSE(open.bounded());
  EXPECT_FALSE(open.sees({30, 0}));
  EXPECT_TRUE(open.sees({30, 24}));  // 38.7 degrees: past the square's side
  EXPECT_TRUE(open.sees({30, -24}));
  EXPECT_FALSE(open.sees({30, 14}));  // 25.0 degrees: behind it
  // The arc that stays open starts just past the square's tangent, 26.57 degrees.
  ASSERT_EQ(open.open.size(), 2u);
  EXPECT_NEAR(open.open[1].first, pseudo_bearing({10, 5}), 1e-5);
}

TEST(OcclusionHorizon, EveryCornerAHorizonHidesIsHiddenByTheExactTest) {
  std::mt19937 rng(20261127);
  int hidden = 0, bounded = 0, open = 0;
  const int fields = deepguide::test::cases(10);
  for (int field = 0; field < fields; ++field) {
    const BgMultiPolygon zones = random_zones(rng, 120, 1200, 800, 0.5, field % 4 == 0);
    const double eps = 1e-9 * 1000.0;
    const PolygonVisibility visibility(zones, eps);
    const OcclusionHorizon occlusion(zones, eps);
    std::vector<Vec2> targets;
    for (const Corner& c : convex_corners(zones)) targets.push_back(c.p);
    std::uniform_real_distribution<double> x(-700, 700), y(-500, 500), b(0.0, 4.0), width(0.05, 1.5);
    for (int k = 0; k < 40; ++k) {
      Vec2 p(x(rng), y(rng));
      if (k % 2 == 0) p = targets[static_cast<std::size_t>(rng() % targets.size())];  // from a corner
      if (visibility.strictly_inside(p)) continue;
      BearingSet wanted;
      const double from = b(rng);
      add_arc(wanted, from, from + width(rng));
      const Horizon h = occlusion.horizon(p, wanted, k % 3 == 0 ? 16 : 256);
      (h.bounded() ? bounded : open) += 1;
      for (const Vec2& q : targets) {
        if ((q - p).norm() < 1e-6) continue;
        bool in_wanted = false;
        for (const auto& [lo, hi] : wanted)
          in_wanted = in_wanted || (lo <= pseudo_bearing(q - p) && pseudo_bearing(q - p) <= hi);
        if (!in_wanted || h.sees(q - p)) continue;
        ++hidden;
        ASSERT_FALSE(visibility.segment_visible(p, q))
            << "field " << field << " from (" << p.x() << ", " << p.y() << ") to (" << q.x() << ", " << q.y() << ")";
      }
    }
  }
  // The horizon did prune, and both outcomes were exercised (per field, over
  // the ten: about 9600 hidden pairs, 12 bounded and 25 open horizons).
  EXPECT_GT(hidden, 1000 * fields) << bounded << " bounded, " << open << " open";
  EXPECT_GT(bounded, 3 * fields) << hidden << " hidden, " << open << " open";
  EXPECT_GT(open, 3 * fields) << hidden << " hidden, " << bounded << " bounded";
}

TEST(OcclusionHorizon, ReducedGraphEqualsTheAllPairsGraph) {
  std::mt19937 rng(7);
  struct Field {
    int count;
    double w, h;
    bool harbour;
  };
  // The last field has more than 4000 usable corners: the build runs threaded.
  std::vector<Field> fields{{30, 500, 500, false},
                            {80, 1000, 400, true},
                            {150, 1500, 600, false},
                            {60, 400, 400, true},
                            {400, 3000, 1200, false}};
  if (deepguide::test::kCaseDivisor > 1) fields.pop_back();
  for (const Field& f : fields) {
    const BgMultiPolygon zones = random_zones(rng, f.count, f.w, f.h, 0.5, f.harbour);
    // Each way of pairing the corners, whatever the field's size chooses.
    for (const CornerPairs pairs : {CornerPairs::horizons, CornerPairs::all_pairs, CornerPairs::automatic}) {
      const VisibilityGraph graph(zones, VisibilityVariant::reduced, {}, {}, pairs);
      // Reference: every pair of convex corners, supporting at both ends and
      // visible by the exact test. The graph works around the box's centre, so
      // its eps is 1e-9 of the largest local coordinate.
      BgBox box;
      bg::envelope(zones, box);
      const double extent = std::max({1.0, 0.5 * (box.max_corner().x() - box.min_corner().x()),
                                      0.5 * (box.max_corner().y() - box.min_corner().y())});
      const double eps = 1e-9 * extent;
      const PolygonVisibility visibility(zones, eps);
      const std::vector<Corner> corners = convex_corners(zones);
      std::set<std::pair<Key, Key>> expected;
      for (std::size_t i = 0; i < corners.size(); ++i) {
        for (std::size_t j = i + 1; j < corners.size(); ++j) {
          const Corner& a = corners[i];
          const Corner& b = corners[j];
          if (!supporting(a, b.p, eps) || !supporting(b, a.p, eps)) continue;
          if (!visibility.segment_visible(a.p, b.p)) continue;
          expected.insert(std::minmax(key(a.p), key(b.p)));
        }
      }
      std::set<std::pair<Key, Key>> built;
      for (const auto& [a, b] : graph.edges()) built.insert(std::minmax(key(a), key(b)));
      std::vector<std::pair<Key, Key>> missing, extra;
      std::set_difference(expected.begin(), expected.end(), built.begin(), built.end(), std::back_inserter(missing));
      std::set_difference(built.begin(), built.end(), expected.begin(), expected.end(), std::back_inserter(extra));
      EXPECT_TRUE(missing.empty() && extra.empty())
          << f.count << " obstacles, pairs " << static_cast<int>(pairs) << ", " << corners.size()
          << " convex corners: " << expected.size() << " edges expected, " << missing.size() << " missing, "
          << extra.size() << " extra";
      EXPECT_GT(expected.size(), corners.size());
      if (f.count == 400) {
        EXPECT_GT(corners.size(), 4000u);
      }
    }
  }
}
