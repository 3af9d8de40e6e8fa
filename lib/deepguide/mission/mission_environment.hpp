#pragma once
// What a mission sails in, read from its environment section into its frame:
// obstacles (obstacle files, and the hazards of vector charts with their
// tops: nothing is dropped for being deep, the depth rules decide) and the
// sea floor of its one bathymetry raster, over the box around everything the
// plan visits (expanded into basic manoeuvres: survey turns and laps reach
// past the waypoints), 200 m wider, at the raster's own resolution.

#include <memory>
#include <string>
#include <vector>

#include "deepguide/charts/chart_options.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/mission.hpp"
#include "deepguide/world/obstacle.hpp"
#include "deepguide/world/sea_floor.hpp"

namespace DEEPGUIDE_API deepguide {

struct MissionEnvironment {
  ObstacleSet obstacles;
  std::shared_ptr<const SeaFloor> floor;  ///< null without a bathymetry raster
  /// The constant current (m/s, local frame; `current: SPEED,DIR`), zero
  /// without one. A current_file is not in it (see constant_current).
  Vec2 current{0.0, 0.0};
};

/// The mission's constant current in its local frame (the direction turned
/// from true north at the start); zero without one. A current_file gives
/// zero here: what reads it says so.
Vec2 constant_current(const Mission& mission);

/// The S-57 cells (and folders and exchange sets of them) among the mission's charts.
std::vector<std::string> enc_charts_of(const Mission& mission);

/// Throws InputError (naming the file) for an unreadable file or more than
/// one raster. S-57 cells are read by `chart` (chart_options.hpp).
MissionEnvironment load_environment(const Mission& mission, const ChartOptions& chart = {});

/// Refuses positions nobody can sail to: a track waypoint or goto position
/// on land (the floor at or above the surface) or inside an obstacle's
/// footprint below its top, at the manoeuvre's depth. Throws InputError
/// naming the file, the manoeuvre's line and name, the waypoint and why.
void check_positions(const Mission& mission, const MissionEnvironment& environment);

/// A mission read, its environment loaded, its positions checked and its
/// manoeuvres expanded: what every mission command starts from.
struct LoadedMission {
  Mission mission;
  MissionEnvironment env;
  MissionPlan plan;  ///< the plan as written (expand_mission)
};

/// read_mission, load_environment, check_positions, expand_mission; throws
/// what they throw.
LoadedMission load_mission(const std::string& path, const ChartOptions& chart = {});

}  // namespace deepguide
