#pragma once
// What planning a mission's evasions keeps between one conflict and the next,
// and between one plan_mission call and the next on a vehicle under way
// (simulation/mission_run.hpp): the mission's environment, per depth what a
// vehicle there goes around (the obstacles whose top it does not clear and
// the sea floor's no-go polygons there), the exact field of those, and, with
// `control.evasion_graph: navmesh`, a navigation mesh of that water.
//
// The visibility graphs are built for each evasion round its ends
// (plan_single_query); the mesh is built once per depth and every later
// evasion at that depth is a Polyanya search on it. Obstacles the vehicle
// finds under way (add) are cut into each kept mesh as new constraints
// (Planner::insert), without triangulating the rest again, and every route
// is still checked against all of them.

#include <memory>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/mission/collision_observation.hpp"
#include "deepguide/mission/mission.hpp"
#include "deepguide/mission/mission_environment.hpp"
#include "deepguide/world/water_volume.hpp"

namespace DEEPGUIDE_API deepguide {

class EvasionPlanner {
 public:
  EvasionPlanner(const Mission& mission, MissionEnvironment environment);
  ~EvasionPlanner();
  EvasionPlanner(const EvasionPlanner&) = delete;  // the volume points into the field
  EvasionPlanner& operator=(const EvasionPlanner&) = delete;

  /// The mission's environment with every obstacle added since.
  const MissionEnvironment& environment() const;
  const ObservationOptions& observe() const;
  /// The water volume of environment() that observation and goal points judge.
  const WaterVolume& volume() const;
  /// The zone the evasions keep to: the corridor (margin + half the vehicle's width) plus 0.2 m.
  double zone_margin() const;

  /// Obstacles found after the start (a sonar's contacts): into the
  /// environment, and into every kept mesh without a rebuild.
  void add(const ObstacleSet& found);

  /// The shortest route at `depth` from `from` to `to` round everything a
  /// vehicle there must go around, checked by the independent checker; empty,
  /// with `problem` saying why in one line, when there is none.
  std::vector<Vec2> route(double depth, const Vec2& from, const Vec2& to, std::string& problem);
  /// p is outside every zone at `depth`.
  bool free_at(double depth, const Vec2& p);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace deepguide
