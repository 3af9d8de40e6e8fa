#pragma once
// Our routes and MOOS-IvP's helm (pHelmIvP), both ways:
// - moos_plan: the phases a .bhv file runs, one after another (what the
//   writer in export_moos.cpp prints): legs of waypoints at one depth and
//   speed, loiters that reach a hold's depth, and holds;
// - read_moos_alog and compare_sailed: a pLogger .alog of a run read back and
//   set against the plan (did every phase run in order to the end flag, how
//   far from the route the vehicle sailed, did it reach each depth).
// docs/MISSIONS.md, "MOOS-IvP", says how a community runs the file.

#include <optional>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/mission/route_export.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

struct MoosPhase {
  enum class Kind { waypoints, reach_depth, hold };
  Kind kind = Kind::waypoints;
  std::vector<Vec2> points;  ///< local x, y: a leg's waypoints; the station of a reach or a hold
  double depth_m = 0.0;      ///< held through the phase: a leg's end waypoint's depth
  double speed_mps = 0.0;
  double duration_s = 0.0;  ///< reach and hold phases
};

struct MoosPlan {
  LocalFrame utm;      ///< MOOSGeodesy's UTM zone of the origin
  Vec2 origin_lonlat;  ///< the route's start: LatOrigin, LongOrigin
  double turn_radius_m = 0.0;
  double capture_radius_m = 0.0;
  double slip_radius_m = 0.0;
  double lead_m = 0.0;
  std::vector<MoosPhase> phases = {};
  /// The route in local x, y (the origin, then every phase's points): what the vehicle should sail.
  std::vector<Vec2> track() const;
};

/// The phases of the route as the .bhv runs them (the header).
MoosPlan moos_plan(const ExportRoute& route);

/// A headless community that sails the .bhv in simulation (pAntler runs it):
/// MOOSDB, pLogger (an .alog named `log_name` in the working folder),
/// uSimMarineV22 starting at the origin, pMarinePIDV22, pHelmIvP with the
/// domains the plan needs (course and speed optional: see the .cpp), and
/// uTimerScript posting MOOS_MANUAL_OVERRIDE = false and DEPLOY = true.
struct MoosCommunityOptions {
  std::string behaviour_file = "mission.bhv";
  std::string log_name = "sail";
  double time_warp = 40.0;
  int port = 9003;
};
std::string moos_community(const MoosPlan& plan, double deepest_m, double top_speed_mps,
                           const MoosCommunityOptions& options = {});

/// The helm's decision domains for the plan (pHelmIvP `domain =` values).
std::vector<std::string> moos_domains(double deepest_m, double top_speed_mps);

/// What a run's pLogger .alog says (times in seconds from the log's start).
struct MoosLog {
  struct Nav {
    double t, x, y, depth;
  };
  std::vector<Nav> nav;                                  ///< NAV_X, NAV_Y, NAV_DEPTH
  std::vector<std::pair<double, int>> legs;              ///< DG_LEG as posted (changes only)
  std::vector<std::pair<double, std::string>> allstops;  ///< IVPHELM_ALLSTOP other than "clear"
  std::vector<std::string> helm_states;                  ///< IVPHELM_STATE values, in order, without repeats
  std::optional<double> deploy_s;                        ///< DEPLOY = true
  std::optional<double> done_s;                          ///< DG_DONE = true
};

/// Reads the .alog. Throws InputError naming the file for one that is
/// missing or has no NAV_X line.
MoosLog read_moos_alog(const std::string& path);

struct SailedReport {
  bool done = false;                              ///< DG_DONE = true was posted
  bool in_order = false;                          ///< DG_LEG went 1, 2, ..., phases + 1
  std::size_t phases_run = 0;                     ///< phases that ended
  std::vector<std::string> allstops_before_done;  ///< the helm stopped while phases remained
  double median_off_m = 0.0;  ///< horizontal distance from the route along the legs (not the reach loiters)
  double p95_off_m = 0.0;
  double max_off_m = 0.0;
  double worst_depth_miss_m = 0.0;    ///< |depth - the phase's| at each phase's end, the worst
  std::size_t worst_depth_phase = 0;  ///< 1-based
  double sailed_s = 0.0;              ///< from DEPLOY to DG_DONE (or the log's end)
};

SailedReport compare_sailed(const MoosPlan& plan, const MoosLog& log);

/// The frame MOOSGeodesy's LatLong2LocalUTM works in for an origin: its UTM
/// zone as the classic LLtoUTM picks it (Norway's 32V and Svalbard's zones included).
LocalFrame moos_local_utm(double lon_deg, double lat_deg);

}  // namespace deepguide
