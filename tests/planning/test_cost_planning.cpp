// Routes weighed by time and energy in a current (planning/cost_model.hpp):
// closed forms on a straight leg, equality with the length route in still
// water, a jet the energy route avoids (priced independently), A* against
// Dijkstra on 500 random cases, tides that change the route with the
// departure time (ETAs against a step-by-step run), and bad input.
#include <gtest/gtest.h>

#include <boost/geometry.hpp>
#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/single_query.hpp"
#include "planning/current_cases.hpp"
#include "planning/obstacle_builders.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

using deepguide::test::box;

constexpr double kCruise = 4.0 * 1852.0 / 3600.0;

CurrentAtTime steady_current(std::function<Vec2(const Vec2&)> f) {
  return [f = std::move(f)](const Vec2& p, double) -> std::optional<Vec2> { return f(p); };
}

std::shared_ptr<CostModel> model_of(CostKind kind, CurrentAtTime current, double max_current) {
  auto m = std::make_shared<CostModel>();
  m->kind = kind;
  m->current = std::move(current);
  m->max_current_mps = max_current;
  return m;
}

PlannerOptions options_with(std::shared_ptr<const CostModel> cost, SearchAlgorithm search = SearchAlgorithm::astar,
                            GraphKind graph = GraphKind::visibility) {
  PlannerOptions o;
  o.margin = 5.0;
  o.tolerance = 0.5;
  o.graph = graph;
  o.search = search;
  o.cost = std::move(cost);
  return o;
}

// Time along a polyline at speed v through the water, written out here apart
// from edge_cost.cpp: s = d.c + sqrt(v^2 - (d x c)^2), the current at the
// middle of 0.25 m steps (the planner uses 10 m pieces).
double reintegrated_time(const std::vector<Vec2>& pts, const std::vector<double>& speeds,
                         const std::function<Vec2(const Vec2&)>& current) {
  double t = 0.0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Vec2 a = pts[i], b = pts[i + 1];
    const double len = (b - a).norm(), v = speeds[i];
    const Vec2 d = (b - a) / len;
    const auto n = static_cast<int>(std::ceil(len / 0.25));
    const double h = len / n;
    for (int k = 0; k < n; ++k) {
      const Vec2 c = current(a + (k + 0.5) * h * d);
      const double across = d.x() * c.y() - d.y() * c.x();
      t += h / (d.dot(c) + std::sqrt(v * v - across * across));
    }
  }
  return t;
}

}  // namespace

TEST(CostPlanning, UniformCurrentAcrossAStraightLegIsTheClosedForm) {
  // No obstacles: the route is the straight line, 1000 m east with 1 m/s
  // setting north across it: s = sqrt(v^2 - 1).
  const auto current = steady_current([](const Vec2&) { return Vec2(0.0, 1.0); });
  const double s = std::sqrt(kCruise * kCruise - 1.0);
  const double p = EnergyModel{}.power_w(kCruise);
  for (CostKind kind : {CostKind::time, CostKind::energy}) {
    auto m = model_of(kind, current, 1.0);
    Planner planner(ObstacleSet{}, options_with(m));
    const PlanOutcome out = planner.solve({{0.0, 0.0}, {1000.0, 0.0}});
    ASSERT_TRUE(out.result.found);
    ASSERT_EQ(out.result.route.points.size(), 2u);
    const RoutePricing priced = price_route(*m, out.result.route.points);
    EXPECT_NEAR(priced.time_s, 1000.0 / s, 1e-9);
    EXPECT_NEAR(priced.energy_j, p * 1000.0 / s, 1e-6);
    EXPECT_NEAR(out.result.cost, kind == CostKind::time ? 1000.0 / s : p * 1000.0 / s, 1e-6);
  }
}

TEST(CostPlanning, InStillWaterTimeAndEnergyRoutesAreTheLengthRoute) {
  std::mt19937 rng(606);
  std::uniform_real_distribution<double> u(0.0, 1000.0), r(10.0, 60.0), ang(0.0, M_PI);
  for (int scenario = 0; scenario < 40; ++scenario) {
    ObstacleSet set;
    for (int i = 0; i < 12; ++i) {
      EllipticCylinder c;
      c.id = "e" + std::to_string(i);
      const double a = r(rng);
      c.footprint = Ellipse{{u(rng), u(rng)}, a, 0.5 * a, ang(rng)};
      set.ellipses.push_back(c);
    }
    Planner length(set, options_with(nullptr));
    const PlanningProblem problem{{-50.0, u(rng)}, {1050.0, u(rng)}};
    const PlanOutcome ref = length.solve(problem);
    ASSERT_TRUE(ref.result.found);
    for (CostKind kind : {CostKind::time, CostKind::energy}) {
      Planner weighed(set, options_with(model_of(kind, {}, 0.0)));
      const PlanOutcome out = weighed.solve(problem);
      ASSERT_TRUE(out.result.found);
      ASSERT_EQ(out.result.route.points.size(), ref.result.route.points.size()) << "scenario " << scenario;
      for (std::size_t i = 0; i < out.result.route.points.size(); ++i) {
        EXPECT_LT((out.result.route.points[i] - ref.result.route.points[i]).norm(), 1e-9);
      }
      const double per_metre = kind == CostKind::time ? 1.0 / kCruise : EnergyModel{}.power_w(kCruise) / kCruise;
      EXPECT_NEAR(out.result.cost, per_metre * ref.result.cost, 1e-9 * out.result.cost);
    }
  }
}

TEST(CostPlanning, TheEnergyRouteGoesAroundAnAdverseJet) {
  // Two islands 800 m tall leave a strait 80 m wide along y = 0; a jet of up
  // to 1.6 m/s sets west through it, against a vehicle bound east at 2.06 m/s.
  ObstacleSet set;
  set.polygons.push_back(box(-500.0, 40.0, 500.0, 840.0, "north-island"));
  set.polygons.push_back(box(-500.0, -840.0, 500.0, -40.0, "south-island"));
  const auto jet = [](const Vec2& p) {
    return Vec2(-1.6 * std::exp(-std::pow(p.y() / 120.0, 2)) * std::exp(-std::pow(p.x() / 900.0, 4)), 0.0);
  };
  const PlanningProblem problem{{-1200.0, 0.0}, {1200.0, 0.0}};
  auto m = model_of(CostKind::energy, steady_current(jet), 1.6);
  const SingleQueryPlan shortest = plan_single_query(set, problem, options_with(nullptr));
  const SingleQueryPlan cheapest = plan_single_query(set, problem, options_with(m));
  ASSERT_TRUE(shortest.outcome.result.found);
  ASSERT_TRUE(cheapest.outcome.result.found);
  EXPECT_TRUE(cheapest.outcome.check.safe) << cheapest.outcome.check.describe();
  const RoutePricing through = price_route(*m, shortest.outcome.result.route.points);
  const RoutePricing around = price_route(*m, cheapest.outcome.result.route.points);
  // The shortest route is the strait (2400 m); the energy route is longer and cheaper by far.
  EXPECT_NEAR(through.length_m, 2400.0, 1e-6);
  EXPECT_GT(around.length_m, 2600.0);
  EXPECT_LT(around.energy_j, 0.7 * through.energy_j) << through.energy_j << " J through, " << around.energy_j;
  // The planner's energy (the search's cost and the route's pricing) against
  // an independent re-integration, within 0.1 %.
  const std::vector<double> cruise(around.legs.size(), kCruise);
  const double redone =
      EnergyModel{}.power_w(kCruise) * reintegrated_time(cheapest.outcome.result.route.points, cruise, jet);
  EXPECT_NEAR(around.energy_j / redone, 1.0, 1e-3);
  EXPECT_NEAR(cheapest.outcome.result.cost / around.energy_j, 1.0, 1e-12);
  const double redone_through =
      EnergyModel{}.power_w(kCruise) * reintegrated_time(shortest.outcome.result.route.points, cruise, jet);
  EXPECT_NEAR(through.energy_j / redone_through, 1.0, 1e-3);

  // At the economical speed per leg the detour still wins; each leg's energy re-integrated at its speed.
  auto eco = std::make_shared<CostModel>(*m);
  eco->economical = true;
  const SingleQueryPlan economical = plan_single_query(set, problem, options_with(eco));
  ASSERT_TRUE(economical.outcome.result.found);
  const RoutePricing e = price_route(*eco, economical.outcome.result.route.points);
  double redone_eco = 0.0;
  for (std::size_t i = 0; i < e.legs.size(); ++i) {
    const double v = e.legs[i].cost.speed_mps;
    EXPECT_GE(v, eco->min_speed_mps - 1e-12);
    EXPECT_LE(v, eco->max_speed_mps + 1e-12);
    const std::vector<Vec2> leg{economical.outcome.result.route.points[i],
                                economical.outcome.result.route.points[i + 1]};
    redone_eco += EnergyModel{}.power_w(v) * reintegrated_time(leg, {v}, jet);
  }
  EXPECT_NEAR(e.energy_j / redone_eco, 1.0, 1e-3);
  EXPECT_LE(e.energy_j, around.energy_j * (1.0 + 1e-9));  // choosing the speed can only save
}

TEST(CostPlanning, AWaypointGridLetsTheRouteBendAroundAJetInOpenWater) {
  // No obstacles at all: a jet up to 1.5 m/s, about 300 m wide and 1.4 km
  // long, sets west along y = 0, right against a 3 km leg east. Without
  // open-water vertices the route is the straight line through it; with a
  // 100 m lattice it bends out of the jet (which fades beyond |y| = 300 m).
  const auto jet = [](const Vec2& p) {
    return Vec2(-1.5 * std::exp(-std::pow(p.y() / 150.0, 2)) * std::exp(-std::pow(p.x() / 700.0, 2)), 0.0);
  };
  auto m = model_of(CostKind::energy, steady_current(jet), 1.5);
  const PlanningProblem problem{{-1500.0, 0.0}, {1500.0, 0.0}};
  PlannerOptions graph_only = options_with(m);
  graph_only.refine = false;  // the graph's own route (refinement would leave the line: test_route_refinement.cpp)
  Planner straight(ObstacleSet{}, graph_only);
  const PlanOutcome line = straight.solve(problem);
  ASSERT_TRUE(line.result.found);
  EXPECT_EQ(line.result.route.points.size(), 2u);
  PlannerOptions gridded = options_with(m);
  gridded.grid = waypoint_grid_for(problem.start, problem.goal, 100.0);
  Planner lattice(ObstacleSet{}, gridded);
  const PlanOutcome bent = lattice.solve(problem);
  ASSERT_TRUE(bent.result.found);
  EXPECT_GT(bent.result.stats.open_water_vertices, 1000u);
  const RoutePricing through = price_route(*m, line.result.route.points);
  const RoutePricing around = price_route(*m, bent.result.route.points);
  EXPECT_LT(around.energy_j, 0.8 * through.energy_j) << through.energy_j << " J straight, " << around.energy_j;
  double farthest = 0.0;
  for (const Vec2& p : bent.result.route.points) farthest = std::max(farthest, std::abs(p.y()));
  EXPECT_GT(farthest, 200.0);  // out of the jet's core
  // Re-integrated independently, within 0.1 %.
  const std::vector<double> cruise(around.legs.size(), kCruise);
  EXPECT_NEAR(
      around.energy_j / (EnergyModel{}.power_w(kCruise) * reintegrated_time(bent.result.route.points, cruise, jet)),
      1.0, 1e-3);
  // A* and Dijkstra agree on the lattice too.
  gridded.search = SearchAlgorithm::dijkstra;
  gridded.refine = false;
  PlannerOptions gridded_astar = gridded;
  gridded_astar.search = SearchAlgorithm::astar;
  Planner lattice_dijkstra(ObstacleSet{}, gridded), lattice_astar(ObstacleSet{}, gridded_astar);
  const double graph_cost = lattice_astar.solve(problem).result.cost;
  EXPECT_NEAR(lattice_dijkstra.solve(problem).result.cost, graph_cost, 1e-9 * graph_cost);
  // Refinement (on by default) moved the lattice route off its vertices: never costlier.
  EXPECT_LE(bent.result.cost, graph_cost * (1.0 + 1e-12));
}

TEST(CostPlanning, WaypointGridsAreCheckedAndAvoidTheZones) {
  using deepguide::test::expect_error;
  const auto error_of = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  expect_error(error_of([] { waypoint_grid_for({0, 0}, {1000, 0}, 0.0); }), {"`spacing_m`", "> 0"});
  expect_error(error_of([] { waypoint_grid_for({0, 0}, {1000, 0}, -5.0); }), {"`spacing_m`", "-5"});
  expect_error(error_of([] {
                 waypoint_grid_for({0, 0}, {1e6, 1e6}, 10.0);
               }),
               {"`spacing_m`", "at most 40000", "spacing of at least"});
  expect_error(error_of([] {
                 PlannerOptions o = options_with(nullptr, SearchAlgorithm::astar, GraphKind::tangent);
                 o.grid = waypoint_grid_for({0, 0}, {1000, 0}, 50.0);
                 Planner p(ObstacleSet{}, o);
               }),
               {"`waypoint_grid`", "visibility"});
  // Lattice points never lie inside a zone, and routes through the lattice pass the checker.
  ObstacleSet set;
  set.polygons.push_back(box(-100.0, -300.0, 100.0, 300.0, "reef"));
  auto m = model_of(CostKind::time,
                    steady_current([](const Vec2& p) { return Vec2(0.0, 0.8 * std::tanh(p.x() / 300.0)); }), 0.8);
  PlannerOptions o = options_with(m);
  o.grid = waypoint_grid_for({-800.0, 0.0}, {800.0, 0.0}, 37.0);
  Planner planner(set, o);
  const PlanOutcome out = planner.solve({{-800.0, 0.0}, {800.0, 0.0}});
  ASSERT_TRUE(out.result.found);
  EXPECT_TRUE(out.check.safe) << out.check.describe();
  EXPECT_GE(out.check.min_clearance_m, 5.0 - 1e-6);
}

TEST(CostPlanning, AStarEqualsDijkstraOn500RandomCases) {
  // Random ellipses, a uniform current plus an eddy, and each cost model in
  // turn (time, energy, energy at economical speeds, time in a tide).
  std::mt19937 rng(2026);
  int compared = 0;
  for (int scenario = 0; scenario < test::cases(500); ++scenario) {
    const test::CurrentCase c = test::random_current_case(rng, scenario);
    const ObstacleSet& set = c.obstacles;
    const auto& m = c.model;
    const PlanningProblem& problem = c.problem;
    const int kind = c.kind;
    PlannerOptions with_astar = options_with(m, SearchAlgorithm::astar);
    with_astar.refine = false;  // the graphs' optima compared (refinement: test_route_refinement.cpp)
    // Every seventh case also has open-water vertices (a 90 m lattice), across all four models.
    if (scenario % 7 == 3) with_astar.grid = waypoint_grid_for(problem.start, problem.goal, 90.0);
    PlannerOptions with_dijkstra = with_astar;
    with_dijkstra.search = SearchAlgorithm::dijkstra;
    Planner astar(set, with_astar);
    Planner dijkstra(set, with_dijkstra);
    const PlanOutcome a = astar.solve(problem), d = dijkstra.solve(problem);
    ASSERT_EQ(a.result.found, d.result.found) << "scenario " << scenario;
    if (!a.result.found) continue;
    ++compared;
    EXPECT_NEAR(a.result.cost, d.result.cost, 1e-9 * d.result.cost) << "scenario " << scenario << " kind " << kind;
    EXPECT_TRUE(a.check.safe) << a.check.describe();
    // The search's cost is the route's, priced leg after leg from the departure.
    EXPECT_NEAR(price_route(*m, a.result.route.points).cost / a.result.cost, 1.0, 1e-9) << "scenario " << scenario;
    // And one query over only the obstacles that matter finds the same cost.
    if (scenario % 5 == 0 || scenario % 7 == 3) {
      const SingleQueryPlan one = plan_single_query(set, problem, with_astar);
      ASSERT_TRUE(one.outcome.result.found);
      EXPECT_NEAR(one.outcome.result.cost, d.result.cost, 1e-9 * d.result.cost) << "scenario " << scenario;
    }
  }
  EXPECT_GE(compared, test::cases(480));
}

TEST(CostPlanning, TheTideChoosesTheSideAndTheEtasHold) {
  // An island 600 m square; north of it the tidal stream sets east when the
  // one south of it sets west, reversing every half period (12.42 h).
  ObstacleSet set;
  set.polygons.push_back(box(-300.0, -300.0, 300.0, 300.0, "island"));
  const double period = 12.42 * 3600.0, amp = 1.2;
  const auto field = [=](const Vec2& p, double t) {
    return Vec2(amp * std::tanh(p.y() / 150.0) * std::cos(2.0 * M_PI * t / period), 0.0);
  };
  auto m = model_of(
      CostKind::time, [=](const Vec2& p, double t) -> std::optional<Vec2> { return field(p, t); }, amp);
  m->steady = false;
  m->time_first_s = 0.0;
  m->time_last_s = 2.0 * period;
  const PlanningProblem problem{{-1500.0, 0.0}, {1500.0, 0.0}};
  std::vector<std::vector<Vec2>> routes;
  for (double depart : {0.0, 0.5 * period}) {
    m->depart_s = depart;
    const SingleQueryPlan plan = plan_single_query(set, problem, options_with(m));
    ASSERT_TRUE(plan.outcome.result.found);
    EXPECT_TRUE(plan.outcome.check.safe);
    const std::vector<Vec2>& pts = plan.outcome.result.route.points;
    routes.push_back(pts);
    const RoutePricing priced = price_route(*m, pts);
    ASSERT_TRUE(priced.feasible);
    // Step by step through the field (dt = 0.5 s), apart from the planner's pieces.
    double t = depart;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      const Vec2 d = (pts[i + 1] - pts[i]).normalized();
      double left = (pts[i + 1] - pts[i]).norm();
      Vec2 x = pts[i];
      const double dt = 0.5;
      while (left > 0.0) {
        const Vec2 c = field(x, t);
        const double across = d.x() * c.y() - d.y() * c.x();
        const double s = d.dot(c) + std::sqrt(kCruise * kCruise - across * across);
        if (s * dt >= left) {
          t += left / s;
          left = 0.0;
        } else {
          t += dt;
          x += s * dt * d;
          left -= s * dt;
        }
      }
      EXPECT_NEAR((priced.legs[i].arrive_s - depart) / (t - depart), 1.0, 0.01) << "leg " << i;
    }
    EXPECT_NEAR((priced.legs.back().arrive_s - depart) / (t - depart), 1.0, 1e-3);
  }
  // Leaving at high water the vehicle rides the east-setting stream north of
  // the island; half a period later that stream sets west, and it goes south.
  auto side = [](const std::vector<Vec2>& pts) {
    double y = 0.0;
    for (const Vec2& p : pts) y += p.y();
    return y;
  };
  EXPECT_GT(side(routes[0]), 0.0);
  EXPECT_LT(side(routes[1]), 0.0);
}

TEST(CostPlanning, LeavingLaterNeverArrivesEarlier) {
  // FIFO on 2000 random legs in a fast, strong tide (period 40 min, up to
  // 1.8 m/s against a 2.06 m/s vehicle): two vehicles on one line cannot
  // overtake each other, and the time marching keeps that to 1e-6 s.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double period = 2400.0;
  auto m = model_of(
      CostKind::time,
      [&](const Vec2& p, double t) -> std::optional<Vec2> {
        const double phase = 2.0 * M_PI * t / period + 0.002 * p.x();
        return Vec2(1.8 * std::sin(phase), 0.6 * std::cos(0.003 * p.y() + phase));
      },
      1.9);
  m->steady = false;
  m->time_first_s = 0.0;
  m->time_last_s = 1e7;
  int legs = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec2 a(2000.0 * u(rng), 2000.0 * u(rng)), b(2000.0 * u(rng), 2000.0 * u(rng));
    const double t = 20000.0 * u(rng), delay = 300.0 * u(rng);
    const LegCost now = price_leg(*m, a, b, t), later = price_leg(*m, a, b, t + delay);
    if (!now.feasible || !later.feasible) continue;
    ++legs;
    EXPECT_GE(t + delay + later.time_s, t + now.time_s - 1e-6) << "leg " << k;
  }
  EXPECT_GT(legs, 500);
}

TEST(CostPlanning, ACurrentStrongerThanTheVehicleEverywhereLeavesNoFeasibleRoute) {
  // 3 m/s setting east; the vehicle makes 2.06 m/s and its goal lies west.
  ObstacleSet set;
  set.polygons.push_back(box(-20.0, -20.0, 20.0, 20.0, "rock"));
  auto m = model_of(CostKind::time, steady_current([](const Vec2&) { return Vec2(3.0, 0.0); }), 3.0);
  const SingleQueryPlan plan = plan_single_query(set, {{500.0, 0.0}, {-500.0, 10.0}}, options_with(m));
  EXPECT_FALSE(plan.outcome.result.found);
  EXPECT_NE(plan.outcome.result.message.find("no feasible route"), std::string::npos) << plan.outcome.result.message;
  EXPECT_NE(plan.outcome.result.message.find("current is stronger than the vehicle"), std::string::npos);
}

TEST(CostPlanning, BadModelsAreRefused) {
  using deepguide::test::expect_error;
  const auto refused = [](const CostModel& m) {
    try {
      validate(m);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CostModel m;
  m.kind = CostKind::energy;
  m.leg.energy.hotel_power_w = -5.0;
  expect_error(refused(m), {"hotel_power_w", "> 0", "-5"});
  m.leg.energy = {};
  m.leg.energy.propulsion_k_w_per_mps3 = -60.0;
  expect_error(refused(m), {"propulsion_k_w_per_mps3", "-60"});
  m.leg.energy = {};
  m.speed_mps = 9.0;
  expect_error(refused(m), {"`speed`", "maximum"});
  m.speed_mps = kCruise;
  // A departure outside a time-dependent field's axis.
  m.steady = false;
  m.time_first_s = 1.5e9;
  m.time_last_s = 1.5e9 + 86400.0;
  m.depart_s = 1.5e9 - 3600.0;
  expect_error(refused(m), {"`depart_s`", "2017-07-14T02:40:00Z", "2017-07-15T02:40:00Z", "2017-07-14T01:40:00Z"});
  m.depart_s = 1.5e9 + 3600.0;
  EXPECT_EQ(refused(m), "");
  m.economical = true;
  expect_error(refused(m), {"`speed` optimal", "steady"});
  m.kind = CostKind::time;
  m.steady = true;
  expect_error(refused(m), {"`speed` optimal", "`cost` energy", "`speed` 3.08"});
  m.kind = CostKind::energy;
  // The planner refuses the tangent graph for time and energy.
  m.economical = false;
  m.steady = true;
  try {
    Planner planner(ObstacleSet{},
                    options_with(std::make_shared<CostModel>(m), SearchAlgorithm::astar, GraphKind::tangent));
    FAIL() << "the tangent graph took an energy model";
  } catch (const InputError& e) {
    expect_error(e.what(), {"`cost` energy", "visibility"});
  }
}

TEST(CostPlanning, ALegStillUnderWayAfterTheForecastIsInfeasible) {
  auto m = model_of(
      CostKind::time, [](const Vec2&, double) -> std::optional<Vec2> { return Vec2(0.0, 0.0); }, 0.0);
  m->steady = false;
  m->time_first_s = 0.0;
  m->time_last_s = 400.0;  // 823 m in 400 s at cruise
  m->leg.step_m = 300.0;   // pieces far longer than the overshoot: the arrival is checked, not only the pieces
  EXPECT_TRUE(price_leg(*m, {0.0, 0.0}, {820.0, 0.0}, 0.0).feasible);
  EXPECT_FALSE(price_leg(*m, {0.0, 0.0}, {826.0, 0.0}, 0.0).feasible);
  // A route whose second of three legs outlasts the forecast: that leg and the
  // rest are infeasible, the first keeps its time, and nothing throws.
  const RoutePricing r = price_route(*m, {{0.0, 0.0}, {500.0, 0.0}, {1000.0, 0.0}, {1500.0, 0.0}});
  EXPECT_FALSE(r.feasible);
  ASSERT_EQ(r.legs.size(), 3u);
  EXPECT_TRUE(r.legs[0].cost.feasible);
  EXPECT_NEAR(r.legs[0].arrive_s, 500.0 / kCruise, 1e-9);
  EXPECT_FALSE(r.legs[1].cost.feasible);
  EXPECT_FALSE(r.legs[2].cost.feasible);
  EXPECT_DOUBLE_EQ(r.legs[2].cost.length_m, 500.0);
}
