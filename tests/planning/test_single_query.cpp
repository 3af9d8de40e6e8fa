// plan_single_query: the graph over only the obstacles within the ellipse
// bound gives the same route as the planner over all of them, in as many
// rounds as the detour needs.
#include <gtest/gtest.h>

#include <boost/geometry.hpp>
#include <cmath>
#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/query_focus.hpp"
#include "deepguide/planning/single_query.hpp"
#include "planning/obstacle_builders.hpp"

using namespace deepguide;

namespace {

using deepguide::test::box;
using deepguide::test::disc;

}  // namespace

class SingleQuery : public ::testing::TestWithParam<GraphKind> {};
INSTANTIATE_TEST_SUITE_P(AllGraphs, SingleQuery,
                         ::testing::Values(GraphKind::visibility, GraphKind::visibility_full, GraphKind::tangent),
                         [](const auto& info) {
                           return info.param == GraphKind::visibility_full ? std::string("full")
                                                                           : to_string(info.param);
                         });

TEST_P(SingleQuery, LongDetourTakesSeveralRoundsAndMatchesThePlanner) {
  // A wall 1000 m long across the straight line from (0, 0) to (400, 0),
  // capped in the north by a disc (so the way round is the south end, with no
  // tie), a disc beside the southern detour that only a grown bound takes in,
  // and discs far away that no bound reaches.
  ObstacleSet set;
  set.polygons.push_back(box(195, -500, 205, 500, "wall"));
  set.ellipses.push_back(disc(200, 505, 10, "north-cap"));
  set.ellipses.push_back(disc(300, -530, 10, "south-side"));
  set.ellipses.push_back(disc(5000, 5000, 10, "far-away"));
  set.ellipses.push_back(disc(-3000, 0, 10, "behind"));
  const PlannerOptions options{5.0, 0.5, GetParam(), SearchAlgorithm::astar};
  const PlanningProblem problem{{0, 0}, {400, 0}};
  const SingleQueryPlan one = plan_single_query(set, problem, options);
  ASSERT_TRUE(one.outcome.result.found);
  EXPECT_TRUE(one.outcome.check.safe) << one.outcome.check.describe();
  EXPECT_GE(one.rounds, 2);  // the straight line's 1.01 bound cannot hold a 1000 m detour
  EXPECT_EQ(one.obstacles_total, 5u);
  EXPECT_EQ(one.obstacles_used, 3u);  // never the far ones
  EXPECT_GE(one.bound_m, one.outcome.result.route.length());
  Planner all(set, options);
  const PlanOutcome ref = all.solve(problem);
  ASSERT_TRUE(ref.result.found);
  // The tangent graph's exact length (its polyline depends on which tangent
  // points split the arcs, and the full graph has more of them).
  const bool exact = GetParam() == GraphKind::tangent;
  const double got = exact ? one.outcome.result.exact_length_m : one.outcome.result.route.length();
  const double want = exact ? ref.result.exact_length_m : ref.result.route.length();
  EXPECT_NEAR(got, want, 1e-9 * want);
  // Around the south end of the wall: (0, 0) -> corner zone near (200, -505) -> (400, 0).
  EXPECT_GT(one.outcome.result.route.length(), 2.0 * std::hypot(195.0, 505.0));
  for (const Vec2& p : one.outcome.result.route.points) EXPECT_LT(p.y(), 1.0);
}

TEST_P(SingleQuery, NoRouteAmongFewerObstaclesMeansNoRoute) {
  ObstacleSet set;
  set.polygons = {box(-20, -20, 20, -15, "s"), box(-20, 15, 20, 20, "n"), box(-20, -20, -15, 20, "w"),
                  box(15, -20, 20, 20, "e")};
  set.ellipses.push_back(disc(9000, 9000, 5, "far"));
  const SingleQueryPlan one =
      plan_single_query(set, {{-100, 0}, {0, 0}}, {1.0, 0.5, GetParam(), SearchAlgorithm::astar});
  EXPECT_FALSE(one.outcome.result.found);
  EXPECT_FALSE(one.outcome.result.message.empty());
}

TEST_P(SingleQuery, StartInAZoneIsReportedOrEscaped) {
  ObstacleSet set;
  set.ellipses.push_back(disc(0, 0, 10, "buoy"));
  set.ellipses.push_back(disc(100, 0, 10, "mid"));
  const PlannerOptions options{5.0, 0.5, GetParam(), SearchAlgorithm::astar};
  try {
    (void)plan_single_query(set, {{12, 0}, {300, 0}}, options);
    ADD_FAILURE() << "a start 2 m from the buoy must be refused";
  } catch (const NoRouteError& e) {
    EXPECT_NE(std::string(e.what()).find("buoy"), std::string::npos) << e.what();
  }
  const SingleQueryPlan one = plan_single_query(set, {{12, 0}, {300, 0}, true}, options);
  ASSERT_TRUE(one.outcome.result.found);
  EXPECT_EQ(one.outcome.escaped_from, "buoy");
  EXPECT_TRUE(one.outcome.check.safe) << one.outcome.check.describe();
  // From inside the buoy itself, with an obstacle far off the focus leaves
  // out (so the route is checked again against all): the escape leg, 7 m to
  // the footprint and 5 m of margin, is the way out, not a failed check.
  set.ellipses.push_back(disc(2000, 2000, 10, "far"));
  const SingleQueryPlan inside = plan_single_query(set, {{3, 0}, {300, 0}, true}, options);
  ASSERT_TRUE(inside.outcome.result.found);
  EXPECT_LT(inside.obstacles_used, inside.obstacles_total);
  EXPECT_EQ(inside.outcome.escaped_from, "buoy");
  EXPECT_TRUE(inside.outcome.check.safe) << inside.outcome.check.describe();
  const auto& pts = inside.outcome.result.route.points;
  ASSERT_GE(pts.size(), 2u);
  EXPECT_NEAR((pts[1] - pts[0]).norm(), 12.0, 1e-5);
}

TEST(QueryFocus, KeepsWhatAPathWithinTheBoundCanUse) {
  // s = (0, 0), g = (10, 0), U = 12: the ellipse's half-width at x = 5 is
  // sqrt(6^2 - 5^2) = 3.3166.
  const QueryFocus f{{0, 0}, {10, 0}, 12.0};
  EXPECT_TRUE(f.active());
  EXPECT_TRUE(f.keeps_point({5, 3.3}));
  EXPECT_FALSE(f.keeps_point({5, 3.4}));
  // (5, 3) -> (5, -3): 2 sqrt(34) + 6 = 17.66 either way.
  EXPECT_FALSE(f.keeps_segment({5, 3}, {5, -3}));
  EXPECT_TRUE((QueryFocus{{0, 0}, {10, 0}, 17.7}).keeps_segment({5, 3}, {5, -3}));
  // (8, 0) -> (2, 0) is useless as given (8 + 6 + 8 = 22) but a path runs it
  // the other way round (2 + 6 + 2 = 10).
  EXPECT_TRUE(f.keeps_segment({8, 0}, {2, 0}));
  // Discs of radius 1 at (3, 5) and (7, 5): (sqrt(34) - 1) + (4 - 2) + (sqrt(34) - 1) = 11.66.
  EXPECT_TRUE(f.keeps_disc_pair({3, 5}, 1.0, {7, 5}, 1.0));
  EXPECT_FALSE((QueryFocus{{0, 0}, {10, 0}, 11.6}).keeps_disc_pair({3, 5}, 1.0, {7, 5}, 1.0));
  // Overlapping discs and discs around s or g: gaps of zero, never negative.
  EXPECT_TRUE(f.keeps_disc_pair({0, 0}, 2.0, {10, 0}, 2.0));
  // The shifted frame judges the same points.
  const QueryFocus moved = f.shifted({100, -50});
  EXPECT_TRUE(moved.keeps_point(Vec2(5, 3.3) - Vec2(100, -50)));
  EXPECT_FALSE(moved.keeps_point(Vec2(5, 3.4) - Vec2(100, -50)));
  // No focus: everything is kept.
  const QueryFocus none;
  EXPECT_FALSE(none.active());
  EXPECT_TRUE(none.keeps_segment({1e9, 1e9}, {-1e9, 0}));
  EXPECT_TRUE(none.keeps_disc_pair({1e9, 1e9}, 1.0, {-1e9, 0}, 1.0));
}

TEST_P(SingleQuery, FocusedGraphWithoutARouteIsNotTheLastWord) {
  // A 400 m wall across the line, open at both ends: the 1.01 bound's focused
  // polygon graph keeps no corner of the wall's far ends, finds nothing, and
  // the round is repeated unfocused before the bound grows. (The tangent
  // graph joins start and goal to the wall's end caps at query time, finds
  // the detour in the first round and only grows the bound.)
  ObstacleSet set;
  set.polygons.push_back(box(45, -200, 55, 200, "wall"));
  const PlannerOptions options{2.0, 0.5, GetParam(), SearchAlgorithm::astar};
  const SingleQueryPlan one = plan_single_query(set, {{0, 0}, {100, 0}}, options);
  ASSERT_TRUE(one.outcome.result.found);
  EXPECT_TRUE(one.outcome.check.safe) << one.outcome.check.describe();
  EXPECT_GE(one.rounds, GetParam() == GraphKind::tangent ? 2 : 3);
  // Round an end of the wall: two legs of about hypot(45, 202) each at least.
  EXPECT_GT(one.outcome.result.route.length(), 2.0 * std::hypot(43.0, 202.0));
  Planner all(set, options);
  const PlanOutcome ref = all.solve({{0, 0}, {100, 0}});
  const bool exact = GetParam() == GraphKind::tangent;
  const double got = exact ? one.outcome.result.exact_length_m : one.outcome.result.route.length();
  const double want = exact ? ref.result.exact_length_m : ref.result.route.length();
  EXPECT_NEAR(got, want, 1e-9 * want);
}

TEST(SingleQueryInput, BadPointsAndOptionsAreBadInput) {
  ObstacleSet set;
  set.ellipses.push_back(disc(0, 0, 10, "buoy"));
  const PlannerOptions ok{5.0, 0.5, GraphKind::visibility, SearchAlgorithm::astar};
  EXPECT_THROW(plan_single_query(set, {{std::nan(""), 0}, {100, 0}}, ok), InputError);
  EXPECT_THROW(plan_single_query(set, {{-100, 0}, {-100, 0}}, ok), InputError);
  PlannerOptions bad = ok;
  bad.margin = -1;
  EXPECT_THROW(plan_single_query(set, {{-100, 0}, {100, 0}}, bad), InputError);
}
