// The geometric construction sailed by a vehicle that turns at most
// max_turn_rate (issue 23, item 4; geometric_construction.hpp, "Sailing"),
// on Monte Carlo scenarios in which the construction of lines alone drove
// the DeepC-like vehicle (6 deg/s at most, 19.6 m radius at cruise) into an
// obstacle that its sonar had seen at 120 m. Each is sailed again both ways:
// the construction of lines (turn_rate_limit 0) must still collide in most,
// so the scenarios still test what they were chosen for, and the sailed
// construction in none.
#include <gtest/gtest.h>

#include <cstdio>

#include "deepguide/evaluation/monte_carlo.hpp"
#include "deepguide/simulation/simulation.hpp"

using namespace deepguide;

namespace {

// Scenario k of the 10,000-scenario suite in docs/PERFORMANCE.md
// (deepguide suite generate DIR --scenarios 10000 --seed 2026 --on-demand).
Scenario suite_scenario(int index) {
  MonteCarloParams params;
  params.scenarios = 10000;
  params.seed = 2026;
  return monte_carlo_scenario(params, index);
}

}  // namespace

TEST(GeometricSailing, ScenariosWhereTheLinesCollidedAreSailedClear) {
  // Why the lines collided, found with a trace of each: a line of sight
  // grazing a zone, blocked in one scan and free in the next, so the turn
  // began too late (7532); a tangent grazing another zone, so the course
  // flipped between two ways round (8619); a turn across a near zone, asked
  // for when a far zone's tangent slipped behind it (2277, 8697); and
  // others of the 41 (of 10,000) that are sailed clear now.
  int lines_collided = 0, count = 0;
  for (const int index : {7532, 8619, 2277, 8697, 7961, 4329, 7806, 2922, 6120, 5470, 5007, 6499}) {
    Scenario sc = suite_scenario(index);
    const SimulationResult sailed = simulate(sc, ReactiveMethod::geometric, {.record_trajectory = false});
    EXPECT_FALSE(sailed.stats.collided) << "scenario " << index << ": " << sailed.stats.min_clearance_m << " m";
    EXPECT_TRUE(sailed.stats.reached) << "scenario " << index;
    sc.reactive.turn_rate_limit = 0.0;
    const SimulationResult lines = simulate(sc, ReactiveMethod::geometric, {.record_trajectory = false});
    std::printf("scenario %d: least clearance %.2f m sailed, %.2f m by the lines\n", index,
                sailed.stats.min_clearance_m, lines.stats.min_clearance_m);
    lines_collided += lines.stats.collided ? 1 : 0;
    ++count;
  }
  EXPECT_GE(lines_collided, count - 2);
}

TEST(GeometricSailing, TurnsSailedWithTheVehiclesLagKeepClearWhereTheInstantTurnCollided) {
  // The 15 that still collided when the turn was checked as one that starts
  // at once at the full rate (session of 2026-11-27: 41 -> 15), the worst of
  // them here. Traces: the turn the check approved began 4-7 s late (DeepC's
  // course loop building up the rate, or undoing a turn the other way) and
  // cut the zone; or both ways round cut it from where the vehicle was. With
  // the lag in the check, a later change of side and the fan (header), each
  // is sailed clear (each obstacle had been in the sonar's view from about
  // 120 m: avoidable collisions, CollisionEnvelope).
  for (const int index : {5489, 3032, 2580}) {
    Scenario sc = suite_scenario(index);
    const SimulationResult sailed = simulate(sc, ReactiveMethod::geometric, {.record_trajectory = false});
    EXPECT_FALSE(sailed.stats.collided) << "scenario " << index << ": " << sailed.stats.min_clearance_m << " m";
    EXPECT_TRUE(sailed.stats.reached) << "scenario " << index;
    EXPECT_GT(sailed.stats.min_clearance_m, 0.5 * sc.reactive.margin_m) << "scenario " << index;
  }
}
