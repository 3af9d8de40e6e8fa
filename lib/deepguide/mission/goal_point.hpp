#pragma once
// The seed's Goal Point Generation: where an evasion leaves the mission
// route (its departure) and where it rejoins it (the rendezvous point), on
// the remaining route past the obstacle.
//
// The plan's track is cut into pieces of at most `step_m`, each marked
// endangered when it comes within the planner's zone of an obstacle below
// the obstacle's top, or within the vertical clearance of the sea floor, at
// the track's own depth (the water volume's test: world/water_volume.hpp).
// From the piece where a conflict begins:
//   - the rendezvous is `lead_m` past the end of the endangered run, where
//     runs closer together than `lead_m` count as one run (rejoining in
//     between would only leave again); it is the plan's end at most;
//   - the departure is `lead_m` before the run's start, runs within `lead_m`
//     before it joined likewise, never before `not_before_m` (the end of an
//     earlier evasion) or the plan's start.
// The lead leaves the vehicle room to turn off the route and back onto it:
// mission control takes twice the turn radius plus the corridor.

#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/world/water_volume.hpp"

namespace DEEPGUIDE_API deepguide {

struct TrackDanger {
  std::vector<TrackPoint> points;  ///< the track, at most step_m apart
  std::vector<char> endangered;    ///< per piece k, points[k] -> points[k + 1]
};

/// The plan's track marked piece by piece against `volume` (its field's
/// margin is the zone; its band is ignored: the surface is no danger here).
TrackDanger track_danger(const MissionPlan& plan, const WaterVolume& volume, double step_m);

struct EvasionStretch {
  double depart_m = 0.0;
  double rendezvous_m = 0.0;
};

/// The stretch to replace for the danger that begins `danger_m` along, or
/// none when the run reaches the plan's end (there is nothing to rejoin);
/// then `why` says so.
std::optional<EvasionStretch> goal_points(const TrackDanger& danger, double danger_m, double lead_m,
                                          double not_before_m, std::string* why = nullptr);

}  // namespace deepguide
