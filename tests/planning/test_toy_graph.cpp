// A graph kind added from outside the library, through its public interface
// only (planning/graph_registry.hpp): this file and its registration are all
// it takes for the Planner, `plan --graph toy` and `evaluate --methods toy`
// (run in-process, app::run) to plan with it.
//
// The toy graph: start, goal and the corners of each obstacle's zone box
// (the footprint's box widened by the margin and 1 m), joined wherever the
// exact obstacle field says the segment is free; the one search
// (graph_search.hpp) finds the shortest path. Safe by construction and by
// the Planner's checker, optimal only among those corners.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <boost/geometry.hpp>

#include "cli/in_process_cli.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/planner.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

class ToyGraph : public RouteGraph {
 public:
  explicit ToyGraph(const GraphBuild& in) : field_(in.field) {
    const double out = in.options.margin + 1.0;
    auto corners = [&](Vec2 lo, Vec2 hi) {
      lo -= Vec2::Constant(out), hi += Vec2::Constant(out);
      for (const Vec2& c : {lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())}) {
        if (field_.is_free(c)) corners_.push_back(c);
      }
    };
    for (const EllipticCylinder& c : in.obstacles.ellipses) {
      const double r = std::max(c.footprint.a, c.footprint.b);  // the box of the circle round the ellipse
      corners(c.footprint.centre - Vec2::Constant(r), c.footprint.centre + Vec2::Constant(r));
    }
    for (const PolygonObstacle& p : in.obstacles.polygons) {
      BgBox box;
      boost::geometry::envelope(p.footprint, box);
      corners(to_eigen(box.min_corner()), to_eigen(box.max_corner()));
    }
  }

  PlanResult solve(const PlanningProblem& problem, SearchAlgorithm search, const CostModel*,
                   const SearchBudget& budget) override {
    std::vector<Vec2> points{problem.start, problem.goal};
    points.insert(points.end(), corners_.begin(), corners_.end());
    PlanningGraph graph(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      for (std::size_t j = i + 1; j < points.size(); ++j) {
        if (!field_.segment_free(points[i], points[j])) continue;
        const double w = (points[j] - points[i]).norm();
        boost::add_edge(i, j, w, graph);
        boost::add_edge(j, i, w, graph);
      }
    }
    const SearchResult found = shortest_path(
        graph, 0, 1, search, [&](GraphVertex v) { return (points[v] - problem.goal).norm(); }, {}, budget);
    PlanResult r;
    r.stats.graph_vertices = points.size();
    r.stats.graph_edges = boost::num_edges(graph) / 2;
    r.stats.expanded = found.expanded;
    r.stats.stopped = found.stopped;
    if (!found.found) {
      r.message = "the toy graph has no way from the start to the goal";
      return r;
    }
    r.found = true;
    for (const GraphVertex v : found.path) r.route.points.push_back(points[v]);
    r.cost = found.cost;
    return r;
  }

  std::vector<std::pair<Vec2, Vec2>> edges() const override { return {}; }

 private:
  const ObstacleField& field_;
  std::vector<Vec2> corners_;
};

// The registration.
const bool kRegistered = [] {
  register_graph({"toy", "obstacles' box corners, a test's", {}, [](const GraphBuild& in) {
                    return std::make_unique<ToyGraph>(in);
                  }});
  return true;
}();

}  // namespace

TEST(ToyGraph, PlansRoundADiscOverItsBoxCorners) {
  ASSERT_TRUE(kRegistered);
  ObstacleSet obstacles;
  obstacles.ellipses.push_back(test::disc(0.0, 0.0, 40.0, "rock"));
  Planner planner(obstacles, {.margin = 5.0, .graph = GraphKind{"toy"}});
  const PlanOutcome out = planner.solve({{-300.0, 0.0}, {300.0, 0.0}});
  ASSERT_TRUE(out.result.found) << out.result.message;
  EXPECT_TRUE(out.check.safe);
  // Over the corners (-46, 46) and (46, 46) (or their mirror images): the
  // straight way from (-46, 46) to the goal passes 39.5 m from the centre,
  // inside the 45 m zone, so the route takes both corners.
  const double expected = 2.0 * std::hypot(254.0, 46.0) + 92.0;
  EXPECT_NEAR(out.result.route.length(), expected, 1e-9);
  EXPECT_EQ(out.result.route.points.size(), 4u);
  // No shorter than the true optimum round the zone (tangents and arc).
  const double optimum = 2.0 * std::sqrt(300.0 * 300.0 - 45.0 * 45.0) + 45.0 * (M_PI - 2.0 * std::acos(45.0 / 300.0));
  EXPECT_GT(out.result.route.length(), optimum);
}

TEST(ToyGraph, TheRegistryStatesWhatItCannotDo) {
  ObstacleSet obstacles;
  obstacles.ellipses.push_back(test::disc(0.0, 0.0, 40.0, "rock"));
  PlannerOptions radius{.margin = 5.0, .graph = GraphKind{"toy"}};
  radius.turn_radius_m = 30.0;
  try {
    Planner planner(obstacles, radius);
    FAIL() << "a turning radius was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the toy graph keeps no turning radius"), std::string::npos) << e.what();
  }
  EXPECT_THROW(
      register_graph({"toy", "again", {}, [](const GraphBuild& in) { return std::make_unique<ToyGraph>(in); }}),
      InputError);
  EXPECT_THROW(
      register_graph({"to:y", "bad name", {}, [](const GraphBuild& in) { return std::make_unique<ToyGraph>(in); }}),
      InputError);
  EXPECT_THROW(
      register_graph({"to\ty", "bad name", {}, [](const GraphBuild& in) { return std::make_unique<ToyGraph>(in); }}),
      InputError);
  EXPECT_NE(graph_names_text().find("quadtree, octree or toy"), std::string::npos) << graph_names_text();
}

TEST(ToyGraph, PlanDashDashGraphToy) {
  const std::string obstacles = test::source_file("data/sample_obstacles.geojson");
  const std::vector<std::string> base{"plan", "--obstacles",     obstacles, "--from", "10.2405,54.4470",
                                      "--to", "10.2640,54.4560", "--json"};
  std::vector<std::string> toy = base, exact = base;
  toy.insert(toy.end(), {"--graph", "toy"});
  const test::CliRun r = test::deepguide_cli(toy);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("graph"), "toy");
  EXPECT_GE(j.at("min_clearance_m").get<double>(), 5.0 - 1e-6);
  exact.insert(exact.end(), {"--graph", "visibility"});
  const test::CliRun v = test::deepguide_cli(exact);
  ASSERT_EQ(v.code, 0) << v.err;
  // The reduced visibility graph's route is the optimum (to its polygons' tolerance): the toy's is no shorter.
  EXPECT_GE(j.at("length_m").get<double>(), nlohmann::json::parse(v.out).at("length_m").get<double>() - 0.5);
  // What the entry says it cannot do, said as plan's other refusals are.
  toy.insert(toy.end(), {"--cost", "time", "--current-const", "0.3,90"});
  const test::CliRun timed = test::deepguide_cli(toy);
  EXPECT_EQ(timed.code, 1);
  EXPECT_NE(timed.err.find("the toy graph prices by length only"), std::string::npos) << timed.err;
  const test::CliRun help = test::deepguide_cli({"plan", "--help"});
  EXPECT_NE(help.out.find("toy (obstacles' box corners"), std::string::npos) << help.out;
}

TEST(ToyGraph, EvaluateDashDashMethodsToy) {
  test::ScratchDir dir;
  const std::string suite = dir.file("suite"), out = dir.file("out");
  ASSERT_EQ(test::deepguide_cli({"suite", "generate", suite, "--scenarios", "4", "--seed", "11"}).code, 0);
  const test::CliRun r = test::deepguide_cli(
      {"evaluate", suite, "--methods", "toy,visibility", "--threads", "1", "--no-report", "-q", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(out + "/rows.csv");
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream hs(line);
  for (std::string h; std::getline(hs, h, ',');) header.push_back(h);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t method = column("method"), collided = column("collided"), route = column("route_length_m");
  ASSERT_LT(route, header.size()) << line;
  std::size_t toy_rows = 0;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream cs(line);
    for (std::string c; std::getline(cs, c, ',');) cells.push_back(c);
    if (line.back() == ',') cells.emplace_back();  // the empty note
    if (cells.size() != header.size() || cells[method] != "toy") continue;
    ++toy_rows;
    EXPECT_EQ(cells[collided], "0") << line;
    EXPECT_GT(std::stod(cells[route]), 0.0) << line;
  }
  EXPECT_EQ(toy_rows, 4u);
}
