// The OMPL peer of bench_planning: OMPL's asymptotically optimal sampling
// planners on the same scenarios, with the same exact collision test as ours.
// Compiled into bench_planning only when CMake finds OMPL (Debian: libompl-dev).
//
// Set-up, as an OMPL user would write it: a 2-D RealVectorStateSpace bounded
// to the scenario area, ObstacleField::is_free as the StateValidityChecker,
// a MotionValidator that calls ObstacleField::segment_free (exact, no
// discretisation: the same test our checker applies), path length as the
// optimisation objective with OMPL's default cost threshold (never satisfied,
// so every planner uses its whole budget), planners with their default
// parameters, no path simplification.
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/config.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "deepguide/world/obstacle_field.hpp"

namespace ob = ompl::base;
namespace og = ompl::geometric;
using deepguide::ObstacleField;
using deepguide::Vec2;

namespace deepguide_bench {

namespace {

Vec2 to_vec(const ob::State* s) {
  const auto* r = s->as<ob::RealVectorStateSpace::StateType>();
  return {r->values[0], r->values[1]};
}

/// Exact motion validation: the closed segment keeps the margin from every
/// obstacle footprint (ObstacleField::segment_free), no sampling along it.
class ExactMotionValidator : public ob::MotionValidator {
 public:
  ExactMotionValidator(const ob::SpaceInformationPtr& si, const ObstacleField& field)
      : ob::MotionValidator(si), field_(field) {}

  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    const bool ok = field_.segment_free(to_vec(s1), to_vec(s2));
    ok ? ++valid_ : ++invalid_;
    return ok;
  }

  /// With an invalid motion, the last free state along it (bisection on the
  /// free prefix to 1e-6 of its length) and its fraction.
  bool checkMotion(const ob::State* s1, const ob::State* s2, std::pair<ob::State*, double>& last_valid) const override {
    const Vec2 a = to_vec(s1), b = to_vec(s2);
    if (field_.segment_free(a, b)) {
      ++valid_;
      return true;
    }
    ++invalid_;
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 20 && field_.is_free(a); ++i) {
      const double mid = 0.5 * (lo + hi);
      (field_.segment_free(a, a + mid * (b - a)) ? lo : hi) = mid;
    }
    if (last_valid.first != nullptr) si_->getStateSpace()->interpolate(s1, s2, lo, last_valid.first);
    last_valid.second = lo;
    return false;
  }

 private:
  const ObstacleField& field_;
};

ob::PlannerPtr make_planner(const std::string& name, const ob::SpaceInformationPtr& si) {
  if (name == "RRT*") return std::make_shared<og::RRTstar>(si);
  if (name == "Informed RRT*") return std::make_shared<og::InformedRRTstar>(si);
  if (name == "BIT*") return std::make_shared<og::BITstar>(si);
  if (name == "PRM*") return std::make_shared<og::PRMstar>(si);
  throw std::invalid_argument("unknown OMPL planner '" + name + "'");
}

}  // namespace

std::string ompl_peer_version() {
  // Debian's config.h leaves OMPL_VERSION empty; the numeric parts are set.
  return std::to_string(OMPL_MAJOR_VERSION) + "." + std::to_string(OMPL_MINOR_VERSION) + "." +
         std::to_string(OMPL_PATCH_VERSION);
}

void ompl_peer_init(unsigned seed) {
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(seed);  // before any RNG exists: the run's sampling is repeatable up to timing
}

bool ompl_peer_solve(const ObstacleField& field, const Vec2& lo, const Vec2& hi, const Vec2& start, const Vec2& goal,
                     const std::string& planner_name, double budget_s, std::vector<Vec2>& path, double& elapsed_s) {
  const auto t0 = std::chrono::steady_clock::now();
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, lo.x());
  bounds.setLow(1, lo.y());
  bounds.setHigh(0, hi.x());
  bounds.setHigh(1, hi.y());
  space->setBounds(bounds);

  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker([&field](const ob::State* s) { return field.is_free(to_vec(s)); });
  si->setMotionValidator(std::make_shared<ExactMotionValidator>(si, field));
  si->setup();

  ob::ScopedState<ob::RealVectorStateSpace> s(space), g(space);
  s[0] = start.x();
  s[1] = start.y();
  g[0] = goal.x();
  g[1] = goal.y();
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->setStartAndGoalStates(s, g);
  pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));

  ob::PlannerPtr planner = make_planner(planner_name, si);
  planner->setProblemDefinition(pdef);
  planner->setup();
  planner->solve(budget_s);
  elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  path.clear();
  if (!pdef->hasExactSolution()) return false;
  const auto* geometric = pdef->getSolutionPath()->as<og::PathGeometric>();
  for (std::size_t i = 0; i < geometric->getStateCount(); ++i) path.push_back(to_vec(geometric->getState(i)));
  return true;
}

}  // namespace deepguide_bench
