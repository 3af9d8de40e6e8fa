// Time and energy routes refined to the continuous optimum
// (planning/route_refinement.hpp), against a reference this file builds on
// its own: Dijkstra over a 48-direction lattice written here, then its own
// continuous refinement (the lattice path resampled to equal legs, each
// vertex moved by golden-section search along x, then y, coarse to fine).
// Both price legs with the same crab model (price_leg) and keep the same
// zones (ObstacleField): what differs is everything that finds the route.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <queue>
#include <random>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/route_refinement.hpp"
#include "deepguide/planning/single_query.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "planning/current_cases.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

constexpr double kCruise = 4.0 * 1852.0 / 3600.0;

std::shared_ptr<CostModel> steady_model(CostKind kind, std::function<Vec2(const Vec2&)> f, double max_current) {
  auto m = std::make_shared<CostModel>();
  m->kind = kind;
  m->current = [f = std::move(f)](const Vec2& p, double) -> std::optional<Vec2> { return f(p); };
  m->max_current_mps = max_current;
  m->speed_mps = kCruise;
  return m;
}

double weight(const CostModel& m, const Vec2& a, const Vec2& b) {
  return edge_weight(m, price_leg(m, a, b, m.depart_s));
}

double total(const CostModel& m, const std::vector<Vec2>& p) {
  double c = 0.0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) c += weight(m, p[i], p[i + 1]);
  return c;
}

// ------------------------------------------------------------- the reference

// Dijkstra over the lattice lo + spacing (i, j) inside [lo, hi], each point
// joined to the 48 directions (i, j) with max(|i|, |j|) <= 4 and gcd 1;
// start and goal join every lattice point within two spacings.
std::vector<Vec2> lattice_route(const CostModel& m, const ObstacleField& field, const Vec2& start, const Vec2& goal,
                                const Vec2& lo, const Vec2& hi, double spacing) {
  const int nx = static_cast<int>((hi.x() - lo.x()) / spacing) + 1;
  const int ny = static_cast<int>((hi.y() - lo.y()) / spacing) + 1;
  const int lattice = nx * ny, s = lattice, g = lattice + 1;
  const auto point = [&](int v) {
    if (v == s) return start;
    if (v == g) return goal;
    return Vec2(lo.x() + spacing * (v % nx), lo.y() + spacing * (v / nx));
  };
  std::vector<std::pair<int, int>> steps;
  for (int i = -4; i <= 4; ++i) {
    for (int j = -4; j <= 4; ++j) {
      if (std::gcd(std::abs(i), std::abs(j)) == 1) steps.push_back({i, j});
    }
  }
  EXPECT_EQ(steps.size(), 48u);
  const auto near = [&](const Vec2& p) {
    std::vector<int> out;
    for (int v = 0; v < lattice; ++v) {
      if ((point(v) - p).norm() <= 2.0 * spacing) out.push_back(v);
    }
    return out;
  };
  const std::vector<int> from_start = near(start), to_goal = near(goal);
  std::vector<double> dist(lattice + 2, std::numeric_limits<double>::infinity());
  std::vector<int> parent(lattice + 2, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  dist[s] = 0.0;
  open.push({0.0, s});
  const auto relax = [&](int u, int v) {
    const Vec2 a = point(u), b = point(v);
    if (!field.segment_free(a, b)) return;
    const double w = weight(m, a, b);
    if (dist[u] + w < dist[v]) {
      dist[v] = dist[u] + w;
      parent[v] = u;
      open.push({dist[v], v});
    }
  };
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u]) continue;
    if (u == g) break;
    if (u == s) {
      for (int v : from_start) relax(u, v);
      continue;
    }
    const int i = u % nx, j = u / nx;
    for (const auto& [di, dj] : steps) {
      if (i + di < 0 || i + di >= nx || j + dj < 0 || j + dj >= ny) continue;
      relax(u, (j + dj) * nx + i + di);
    }
    if (std::find(to_goal.begin(), to_goal.end(), u) != to_goal.end()) relax(u, g);
  }
  std::vector<Vec2> route;
  for (int v = g; v != -1; v = parent[v]) route.insert(route.begin(), point(v));
  return route;
}

// The polyline resampled to n equal legs along its length.
std::vector<Vec2> resampled(const std::vector<Vec2>& p, int n) {
  std::vector<double> at{0.0};
  for (std::size_t i = 0; i + 1 < p.size(); ++i) at.push_back(at.back() + (p[i + 1] - p[i]).norm());
  std::vector<Vec2> out;
  std::size_t k = 0;
  for (int q = 0; q <= n; ++q) {
    const double want = at.back() * q / n;
    while (k + 2 < at.size() && at[k + 1] < want) ++k;
    const double t = at[k + 1] > at[k] ? (want - at[k]) / (at[k + 1] - at[k]) : 0.0;
    out.push_back(p[k] + std::clamp(t, 0.0, 1.0) * (p[k + 1] - p[k]));
  }
  return out;
}

// Golden-section search of f over [a, b].
double golden(const std::function<double(double)>& f, double a, double b) {
  const double r = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = b - r * (b - a), x2 = a + r * (b - a), f1 = f(x1), f2 = f(x2);
  for (int k = 0; k < 40; ++k) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - r * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + r * (b - a), f2 = f(x2);
    }
  }
  return 0.5 * (a + b);
}

// The reference's continuous refinement: 16, 32, ..., 256 equal legs; at
// each, sweeps moving every inner vertex along x, then y, to the least cost
// of its two legs, a move kept only when both legs stay free.
std::vector<Vec2> reference_refined(const CostModel& m, const ObstacleField& field, std::vector<Vec2> route) {
  for (int n = 16; n <= 256; n *= 2) {
    route = resampled(route, n);
    for (int sweep = 0; sweep < 200; ++sweep) {
      const double before = total(m, route);
      for (std::size_t i = 1; i + 1 < route.size(); ++i) {
        for (const Vec2& axis : {Vec2(1.0, 0.0), Vec2(0.0, 1.0)}) {
          const Vec2 a = route[i - 1], b = route[i + 1], p = route[i];
          const double r = 0.5 * std::min((p - a).norm(), (b - p).norm());
          const auto local = [&](double t) {
            const double c = weight(m, a, p + t * axis) + weight(m, p + t * axis, b);
            return std::isfinite(c) ? c : 1e30;
          };
          const double t = golden(local, -r, r);
          const Vec2 q = p + t * axis;
          if (local(t) < local(0.0) && field.segment_free(a, q) && field.segment_free(q, b)) route[i] = q;
        }
      }
      if (before - total(m, route) < 1e-9 * before) break;
    }
  }
  return route;
}

struct Reference {
  double lattice_cost = 0.0;
  double cost = 0.0;
  std::vector<Vec2> route;
};

Reference reference(const CostModel& m, const ObstacleField& field, const Vec2& start, const Vec2& goal, const Vec2& lo,
                    const Vec2& hi, double spacing) {
  Reference ref;
  const std::vector<Vec2> lattice = lattice_route(m, field, start, goal, lo, hi, spacing);
  ref.lattice_cost = total(m, lattice);
  ref.route = reference_refined(m, field, lattice);
  ref.cost = total(m, ref.route);
  return ref;
}

// Every leg keeps the margin and the route's cost is what the planner said.
void expect_sound(const PlanOutcome& out, const CostModel& m, const ObstacleField& field) {
  ASSERT_TRUE(out.result.found) << out.result.message;
  EXPECT_TRUE(out.check.safe) << out.check.describe();
  const auto& p = out.result.route.points;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    EXPECT_GE(field.segment_clearance(p[i], p[i + 1]).distance, field.margin() - 1e-9) << "leg " << i;
  }
  EXPECT_NEAR(price_route(m, p).cost / out.result.cost, 1.0, 1e-12);
}

// A jet east along y = 2500 m (1.2 m/s, 1.2 km wide), and a vortex turning
// anticlockwise round (10 km, -1 km) (Lamb-Oseen, 0.9 m/s at most) whose
// northern side sets west across the straight line y = 0; an island (600 m
// across) in the jet's core.
Vec2 jet_and_vortex(const Vec2& p) {
  const double y = (p.y() - 2500.0) / 1200.0;
  Vec2 c(1.2 * std::exp(-y * y), 0.0);
  const Vec2 r = p - Vec2(10000.0, -1000.0);
  const double rc = 2000.0, q2 = r.squaredNorm() / (rc * rc);
  // Lamb-Oseen: v(r) = G / r (1 - exp(-r^2 / rc^2)), scaled to 0.9 m/s at its peak (r = 1.12 rc).
  const double peak = (1.0 - std::exp(-1.2564)) / std::sqrt(1.2564);
  if (q2 > 1e-12) c += 0.9 / peak * (1.0 - std::exp(-q2)) / std::sqrt(q2) * Vec2(-r.y(), r.x()) / r.norm();
  return c;
}

ObstacleSet island() {
  ObstacleSet set;
  EllipticCylinder e;
  e.id = "island";
  e.footprint = Ellipse{{10000.0, 2500.0}, 300.0, 300.0, 0.0};
  set.ellipses.push_back(e);
  return set;
}

// Under the sanitizers one lattice spacing and coarser references (test_support.hpp).
constexpr bool kSanitized = test::kCaseDivisor > 1;
std::vector<double> spacings(std::vector<double> all) { return kSanitized ? std::vector<double>{all[1]} : all; }

}  // namespace

TEST(RouteRefinement, AppliesOnlyWhereTheCurrentChangesFromPlaceToPlace) {
  auto m = steady_model(
      CostKind::time, [](const Vec2&) { return Vec2(0.5, 0.2); }, 0.6);
  EXPECT_TRUE(refinement_applies(*m));
  m->uniform = true;
  EXPECT_FALSE(refinement_applies(*m));
  m->uniform = false;
  m->kind = CostKind::length;
  EXPECT_FALSE(refinement_applies(*m));
  m->kind = CostKind::energy;
  m->current = nullptr;
  EXPECT_FALSE(refinement_applies(*m));
}

TEST(RouteRefinement, AStraightLegInAUniformCurrentStaysStraight) {
  // The optimum in a uniform current is the straight leg (time is a norm of
  // the displacement): refinement has nothing to gain and returns it as it was.
  const auto m = steady_model(
      CostKind::time, [](const Vec2&) { return Vec2(0.7, -0.4); }, 0.9);
  const auto free = [](const Vec2&, const Vec2&) { return true; };
  const RefinedRoute r = refine_route(*m, {{0.0, 0.0}, {3000.0, 1000.0}}, free);
  ASSERT_EQ(r.points.size(), 2u);
  EXPECT_EQ(r.cost_after, r.cost_before);
  // A bent route in it comes back to (nearly) the straight leg's cost, with few vertices.
  const RefinedRoute bent = refine_route(*m, {{0.0, 0.0}, {1500.0, 1400.0}, {3000.0, 1000.0}}, free);
  const double straight = weight(*m, {0.0, 0.0}, {3000.0, 1000.0});
  EXPECT_LT(bent.cost_after, bent.cost_before);
  EXPECT_NEAR(bent.cost_after / straight, 1.0, 1e-5);
  EXPECT_LE(bent.points.size(), 8u);
}

TEST(RouteRefinement, RefusesBadRoutes) {
  const auto m = steady_model(
      CostKind::time, [](const Vec2&) { return Vec2(0.1, 0.0); }, 0.1);
  const auto free = [](const Vec2&, const Vec2&) { return true; };
  EXPECT_THROW(refine_route(*m, {{0.0, 0.0}}, free), InputError);
  EXPECT_THROW(refine_route(*m, {{0.0, 0.0}, {NAN, 1.0}}, free), InputError);
  // An infeasible route (a 3 m/s head current everywhere) comes back as it was.
  const auto head = steady_model(
      CostKind::time, [](const Vec2&) { return Vec2(-3.0, 0.0); }, 3.0);
  const RefinedRoute r = refine_route(*head, {{0.0, 0.0}, {500.0, 10.0}, {1000.0, 0.0}}, free);
  EXPECT_EQ(r.points.size(), 3u);
  EXPECT_FALSE(std::isfinite(r.cost_before));
}

TEST(RouteRefinement, NeverCostlierAndEveryLegKeepsTheMargin) {
  // Random ellipses, a uniform current plus an eddy, each cost model in turn
  // (time, energy, economical energy, time in a tide): the refined route
  // costs no more than the graph's, keeps the margin leg by leg, and its
  // cost is its pricing from the departure.
  std::mt19937 rng(4242);
  int gained = 0, cases = 0;
  for (int scenario = 0; scenario < test::cases(120); ++scenario) {
    const test::CurrentCase c = test::random_current_case(rng, scenario);
    const ObstacleSet& set = c.obstacles;
    const auto& m = c.model;
    const PlanningProblem& problem = c.problem;
    PlannerOptions o;
    o.margin = 5.0;
    o.cost = m;
    if (scenario % 3 == 1) o.grid = waypoint_grid_for(problem.start, problem.goal, 90.0);
    PlannerOptions graph_only = o;
    graph_only.refine = false;
    const PlanOutcome graph = Planner(set, graph_only).solve(problem);
    const PlanOutcome refined = Planner(set, o).solve(problem);
    ASSERT_EQ(graph.result.found, refined.result.found) << "scenario " << scenario;
    if (!refined.result.found) continue;
    ++cases;
    const ObstacleField field(set, o.margin);
    expect_sound(refined, *m, field);
    EXPECT_LE(refined.result.cost, graph.result.cost * (1.0 + 1e-12)) << "scenario " << scenario;
    if (refined.result.cost < graph.result.cost * (1.0 - 1e-4)) ++gained;
  }
  std::printf("refined %d routes, %d of them by more than 0.01 %%\n", cases, gained);
  EXPECT_GT(cases, test::cases(120) / 2);
  EXPECT_GT(gained, cases / 4);
}

TEST(RouteRefinement, JetAndVortexTimeAndEnergyWithinATenthOfAPercentOfTheReference) {
  const ObstacleSet set = island();
  const ObstacleField field(set, 10.0);
  const Vec2 start(1000.0, 0.0), goal(19000.0, 0.0);
  for (const CostKind kind : {CostKind::time, CostKind::energy}) {
    const auto m = steady_model(kind, jet_and_vortex, 2.1);
    m->leg.step_m = 50.0;
    const Reference ref =
        reference(*m, field, start, goal, {0.0, -6000.0}, {20000.0, 6000.0}, kSanitized ? 500.0 : 250.0);
    std::printf("%s: reference lattice %.1f, refined %.1f (%zu points)\n", to_string(kind).c_str(), ref.lattice_cost,
                ref.cost, ref.route.size());
    for (const double spacing : spacings({2000.0, 1000.0, 500.0})) {
      PlannerOptions o;
      o.margin = 10.0;
      o.cost = m;
      o.grid = waypoint_grid_for(start, goal, spacing);
      PlannerOptions graph_only = o;
      graph_only.refine = false;
      const PlanOutcome graph = Planner(set, graph_only).solve({start, goal});
      const PlanOutcome out = Planner(set, o).solve({start, goal});
      expect_sound(out, *m, field);
      std::printf("  lattice %.0f m: graph %.1f (%+.3f %%), refined %.1f (%+.4f %%), %zu waypoints\n", spacing,
                  graph.result.cost, 100.0 * (graph.result.cost / ref.cost - 1.0), out.result.cost,
                  100.0 * (out.result.cost / ref.cost - 1.0), out.result.route.points.size());
      EXPECT_LE(out.result.cost, 1.001 * ref.cost) << to_string(kind) << " at " << spacing << " m";
    }
  }
  // Energy at the economical speed per leg: the reference prices legs the same way.
  if (kSanitized) return;
  const auto eco = steady_model(CostKind::energy, jet_and_vortex, 2.1);
  eco->leg.step_m = 100.0;
  eco->economical = true;
  const Reference ref = reference(*eco, field, start, goal, {0.0, -6000.0}, {20000.0, 6000.0}, 500.0);
  PlannerOptions o;
  o.margin = 10.0;
  o.cost = eco;
  o.grid = waypoint_grid_for(start, goal, 1000.0);
  const PlanOutcome out = Planner(set, o).solve({start, goal});
  expect_sound(out, *eco, field);
  std::printf("economical energy: reference %.1f, refined %.1f (%+.4f %%)\n", ref.cost, out.result.cost,
              100.0 * (out.result.cost / ref.cost - 1.0));
  EXPECT_LE(out.result.cost, 1.001 * ref.cost);
}

TEST(RouteRefinement, GulfStreamTimeAndEnergyWithinATenthOfAPercentOfTheReference) {
  // The docs' case (PLANNING.md, costs in a current): the real HYCOM forecast
  // and the two synthetic banks, from north-east to south-west against the stream.
  DEEPGUIDE_REAL_FILE_OR_SKIP(hycom, "currents-hycom/hycom_glby_930_2019030712_t003_uv3z.nc");
  const LoadedObstacles banks = load_obstacles({test::source_file("data/gulf_stream_banks.geojson")});
  const LocalFrame& frame = banks.frame;
  const Vec2 start = frame.from_lonlat(-74.80, 35.10), goal = frame.from_lonlat(-75.40, 34.60);
  const ObstacleField field(banks.obstacles, 5.0);
  const auto field_data = std::make_shared<const CurrentField>(load_current_field(hycom));
  for (const CostKind kind : {CostKind::time, CostKind::energy}) {
    auto m = std::make_shared<CostModel>();
    m->kind = kind;
    m->speed_mps = kCruise;
    const Vec2 lo = start.cwiseMin(goal) - Vec2(25000.0, 25000.0), hi = start.cwiseMax(goal) + Vec2(25000.0, 25000.0);
    attach_current(*m, field_data, frame, lo, hi);
    const Reference ref = reference(*m, field, start, goal, lo, hi, kSanitized ? 2000.0 : 1000.0);
    std::printf("%s: reference lattice %.1f, refined %.1f (%zu points)\n", to_string(kind).c_str(), ref.lattice_cost,
                ref.cost, ref.route.size());
    for (const double spacing : spacings({4000.0, 2000.0, 1000.0})) {
      PlannerOptions o;
      o.margin = 5.0;
      o.cost = m;
      o.grid = waypoint_grid_for(start, goal, spacing);
      const SingleQueryPlan plan = plan_single_query(banks.obstacles, {start, goal}, o);
      expect_sound(plan.outcome, *m, field);
      std::printf("  lattice %.0f m: refined %.1f (%+.4f %%), %zu waypoints\n", spacing, plan.outcome.result.cost,
                  100.0 * (plan.outcome.result.cost / ref.cost - 1.0), plan.outcome.result.route.points.size());
      EXPECT_LE(plan.outcome.result.cost, 1.001 * ref.cost) << to_string(kind) << " at " << spacing << " m";
    }
  }
}
