#pragma once
// Random planning cases in a current, shared by the cost-planning tests:
// eight ellipses over 1 km x 1 km, a uniform drift plus a Gaussian eddy, and
// a cost model per case in turn (time, energy, energy at economical speeds,
// time in a tide of 6 h), 20 m integration pieces.
#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "deepguide/planning/cost_model.hpp"
#include "deepguide/planning/route.hpp"
#include "deepguide/world/obstacle.hpp"

namespace deepguide::test {

struct CurrentCase {
  ObstacleSet obstacles;
  std::shared_ptr<CostModel> model;
  PlanningProblem problem;
  int kind = 0;  ///< 0 time, 1 energy, 2 economical energy, 3 time in a tide
};

inline CurrentCase random_current_case(std::mt19937& rng, int scenario) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  CurrentCase c;
  for (int i = 0; i < 8; ++i) {
    EllipticCylinder e;
    e.id = "e" + std::to_string(i);
    const double a = 15.0 + 70.0 * u(rng);
    e.footprint = Ellipse{{1000.0 * u(rng), 1000.0 * u(rng)}, a, a * (0.3 + 0.7 * u(rng)), M_PI * u(rng)};
    c.obstacles.ellipses.push_back(e);
  }
  const double heading = 2.0 * M_PI * u(rng), drift = u(rng);
  const Vec2 uniform = drift * Vec2(std::cos(heading), std::sin(heading));
  const Vec2 eddy(1000.0 * u(rng), 1000.0 * u(rng));
  const double swirl = 1.2 * (u(rng) - 0.5), radius = 150.0 + 300.0 * u(rng);
  c.kind = scenario % 4;
  const int kind = c.kind;
  const double period = 6.0 * 3600.0;
  c.model = std::make_shared<CostModel>();
  CostModel& m = *c.model;
  m.kind = kind == 1 || kind == 2 ? CostKind::energy : CostKind::time;
  m.current = [=](const Vec2& p, double t) -> std::optional<Vec2> {
    const Vec2 r = p - eddy;
    const double q = r.norm() / radius;
    // Eddy speed |swirl| q exp(-q^2) <= |swirl| / sqrt(2e).
    Vec2 v = uniform + swirl * std::exp(-q * q) / radius * Vec2(-r.y(), r.x());
    if (kind == 3) v *= std::cos(2.0 * M_PI * t / period);
    return v;
  };
  m.max_current_mps = drift + std::abs(swirl) / std::sqrt(2.0 * M_E) + 1e-9;
  m.economical = kind == 2;
  m.leg.step_m = 20.0;
  if (kind == 3) {
    m.steady = false;
    m.time_first_s = 0.0;
    m.time_last_s = 1e6;
    m.depart_s = period * u(rng);
  }
  c.problem = PlanningProblem{{-60.0, 1000.0 * u(rng)}, {1060.0, 1000.0 * u(rng)}};
  return c;
}

}  // namespace deepguide::test
