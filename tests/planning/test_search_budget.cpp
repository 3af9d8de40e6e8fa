// The search's budget and cancel hook (graph_search.hpp): a search stops
// after exactly its budget of vertices, or when cancelled, and every graph
// reports that as such, never as "no route".
#include <gtest/gtest.h>

#include <string>

#include "deepguide/planning/graph_search.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/single_query.hpp"
#include "planning/obstacle_builders.hpp"

using namespace deepguide;

namespace {

// A path graph 0 - 1 - ... - 99 with unit edges.
PlanningGraph chain(std::size_t n) {
  PlanningGraph g(n);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    boost::add_edge(i, i + 1, 1.0, g);
    boost::add_edge(i + 1, i, 1.0, g);
  }
  return g;
}

// A row of discs across the way, so every graph has some vertices to examine.
ObstacleSet wall() {
  ObstacleSet o;
  for (int k = -3; k <= 3; ++k) o.ellipses.push_back(test::disc(0.0, 30.0 * k, 12.0, "d" + std::to_string(k)));
  return o;
}

}  // namespace

TEST(SearchBudget, StopsAfterExactlyItsBudget) {
  const PlanningGraph g = chain(100);
  const auto h = [](GraphVertex v) { return 99.0 - static_cast<double>(v); };
  for (const SearchAlgorithm a : {SearchAlgorithm::astar, SearchAlgorithm::dijkstra}) {
    const SearchResult free = shortest_path(g, 0, 99, a, h);
    ASSERT_TRUE(free.found);
    EXPECT_EQ(free.cost, 99.0);
    EXPECT_EQ(free.stopped, SearchStop::none);
    EXPECT_EQ(free.expanded, 100u);  // every vertex of the chain, the target last
    const SearchResult limited = shortest_path(g, 0, 99, a, h, {}, {.max_expansions = 10});
    EXPECT_FALSE(limited.found);
    EXPECT_EQ(limited.stopped, SearchStop::budget);
    EXPECT_EQ(limited.expanded, 10u);
    // A budget the search does not need changes nothing.
    const SearchResult ample = shortest_path(g, 0, 99, a, h, {}, {.max_expansions = 100});
    EXPECT_TRUE(ample.found);
    EXPECT_EQ(ample.expanded, 100u);
  }
}

TEST(SearchBudget, ACancelEndsTheSearchAndIsSaidSo) {
  const PlanningGraph g = chain(2000);
  int asked = 0;
  const SearchBudget cancel{.cancelled = [&] { return ++asked == 3; }};
  const SearchResult r = shortest_path(
      g, 0, 1999, SearchAlgorithm::dijkstra, [](GraphVertex) { return 0.0; }, {}, cancel);
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.stopped, SearchStop::cancelled);
  EXPECT_EQ(r.expanded, 512u);  // asked at 0, 256 and 512 vertices
  EXPECT_EQ(search_stop_message(r.stopped, r.expanded), "the search was cancelled after 512 vertices");
}

TEST(SearchBudget, EveryGraphReportsItsBudgetNotNoRoute) {
  for (const GraphKind& kind :
       {GraphKind::visibility, GraphKind::visibility_full, GraphKind::tangent, GraphKind::quadtree}) {
    PlannerOptions options{.margin = 2.0, .graph = kind};
    const PlanningProblem problem{{-30.0, 5.0}, {30.0, -5.0}};  // inside the quadtree's area round the wall
    const PlanOutcome free = Planner(wall(), options).solve(problem);
    ASSERT_TRUE(free.result.found) << kind.name << ": " << free.result.message;
    ASSERT_GT(free.result.stats.expanded, 2u) << kind.name;
    options.budget.max_expansions = 2;
    const PlanOutcome out = Planner(wall(), options).solve(problem);
    EXPECT_FALSE(out.result.found) << kind.name;
    EXPECT_EQ(out.result.stats.stopped, SearchStop::budget) << kind.name;
    EXPECT_NE(out.result.message.find("its budget; no route is proven missing"), std::string::npos)
        << kind.name << ": " << out.result.message;
    // One query: the rounds stop at the first budget stop, which is the answer.
    const SingleQueryPlan one = plan_single_query(wall(), problem, options);
    EXPECT_EQ(one.rounds, 1) << kind.name;
    EXPECT_EQ(one.outcome.result.stats.stopped, SearchStop::budget) << kind.name;
  }
}
