// Uses the installed library through its umbrella header: a distance, a
// route planned round a disc and checked, and an error of the library caught
// here (its type crosses the library's boundary).
#include <deepguide/deepguide.hpp>
#include <iostream>

int main() {
  using namespace deepguide;
  Ellipse e;
  e.a = 2.0;
  e.b = 1.0;
  const double d = signed_distance(e, {5.0, 0.0});
  ObstacleSet obstacles;
  obstacles.ellipses.push_back({"rock", Ellipse{{0.0, 0.0}, 40.0, 40.0, 0.0}, std::nullopt, std::nullopt});
  Planner planner(obstacles, {.margin = 5.0, .graph = GraphKind::tangent});
  const PlanOutcome out = planner.solve({{-300.0, 0.0}, {300.0, 0.0}});
  bool refused = false;
  try {
    Planner bad(obstacles, {.margin = -1.0});
  } catch (const InputError&) {
    refused = true;
  }
  std::cout << "deepguide " << kVersion << " distance " << d << ", route " << out.result.exact_length_m << " m\n";
  return d == 3.0 && out.result.found && out.check.safe && refused ? 0 : 1;
}
