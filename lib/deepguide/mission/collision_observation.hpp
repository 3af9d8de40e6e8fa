#pragma once
// The seed's Collision Observation: which basic manoeuvres of the plan an
// obstacle endangers, and from where along the mission.
//
// An obstacle endangers a manoeuvre where its track comes within the
// corridor (the safety margin plus half the vehicle's width) of the
// obstacle's footprint while deeper than the obstacle's top less the
// vertical clearance (world/water_volume.hpp, whose zone is exactly this);
// the sea floor endangers it where it comes within the vertical clearance of
// the floor (land included: the floor there is above the surface). Arcs are
// checked as chords no more than 0.1 m inside them, the corridor widened by
// that much. Each (manoeuvre, obstacle) pair is found once, at its first
// point; a run of consecutive basic manoeuvres endangered by the same
// obstacle without a break (each next one from its very start: a survey
// turn, the lap round an object) makes one conflict, and a later pass by the
// same obstacle is a conflict of its own.

#include <cstddef>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/world/obstacle.hpp"
#include "deepguide/world/sea_floor.hpp"

namespace DEEPGUIDE_API deepguide {

struct Conflict {
  std::size_t basic = 0;       ///< the (first) basic manoeuvre endangered
  std::size_t last_basic = 0;  ///< the last of the consecutive ones endangered by the same obstacle
  /// The obstacle (ellipses first, then polygons, as ObstacleField counts), or kSeaFloor.
  std::size_t obstacle = 0;
  std::string with;      ///< the obstacle's name, or "the sea floor"
  double along_m = 0.0;  ///< where along the mission the danger begins
  Vec2 where{0.0, 0.0};
  double depth_m = 0.0;
};

inline constexpr std::size_t kSeaFloor = static_cast<std::size_t>(-1);

struct ObservationOptions {
  double margin_m = 5.0;
  double half_width_m = 0.5;  ///< half the vehicle's width (DeepC: about 1 m across)
  double vertical_clearance_m = 2.0;
};

/// Every conflict of the plan, in order along the mission. `floor` may be null.
std::vector<Conflict> observe_collisions(const MissionPlan& plan, const ObstacleSet& obstacles, const SeaFloor* floor,
                                         const ObservationOptions& options);

}  // namespace deepguide
