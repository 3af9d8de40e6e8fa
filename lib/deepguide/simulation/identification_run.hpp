#pragma once
// The identification run: the plant (plant.hpp: vehicle, autopilot, current)
// driven by one identification unit, aligning (identification/aligning.hpp)
// or going around (identification/going_around.hpp), with the object and the
// parameters of the scenario's identify section (scenario.hpp). There is no
// sonar: the object is known (the mission names it); every TRUE obstacle
// counts for the clearance.
//
// Loop, at t_k = k h (sample k describes the state at t_k):
//   1. the current at the vehicle; at least the top speed (aligning's
//      max_speed_mps, else the vehicle's) -> end `overpowered` (the unit
//      could only head into it at full speed, losing ground: a clear failure
//      rather than a spin)
//   2. the unit's command (course over ground, speed, mode) -> autopilot
//   3. record sample k; a mode different from sample k-1's is a ModeSwitch,
//      logged with the time and the position of sample k
//   4. stop: the vehicle is inside a true obstacle, the object or another
//      (`collided`: a run that hit something has failed, however well it
//      held); aligning has held the position for hold_time_s without leaving
//      the positioning mode (`held`; leaving it restarts the hold); going
//      around has completed its laps (`laps_done`); t_k >= the time limit
//      (`time_out`). A failure names the obstacle, and for aligning whether
//      the held point itself lies inside one (nothing can hold it then).
//   5. step the plant
// The vehicle starts on start_heading (default: towards the object's centre)
// at the unit's speed, at depth_m. Deterministic: no random numbers.
//
// In position: aligning, from the first sample in the positioning mode
// within position_tolerance_m of the held point g; going around, from the
// first tracking sample within position_tolerance_m of the path whose
// course over ground is within 20 degrees of the path's direction (a vehicle
// crossing the path at an angle on its way in is not on it yet).
// Statistics, over the samples from that one on (the hold), as RMS and max:
//   station-keeping error   |p - g|                               (aligning)
//   cross-track error       aligning: the offset across the current's axis
//                           through g; going around: e, the signed distance
//                           from the path (positive outside)
//   distance-to-object error  the signed distance to the object's footprint
//                           minus the requested one (aligning: g's; going
//                           around: D)
// plus the vehicle's (SimulationStats: time, path, energy, rates) over the
// whole run, the minimum clearance to every true obstacle, the time to
// position, the laps and the mode switches.
// Time limit: the scenario's max_time_s, else 3 x the straight time to the
// object plus the laps' length at the unit's speed + 300 s (+ hold_time_s
// when aligning), at most kMaxSimulationTime_s.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/simulation/simulation.hpp"

namespace DEEPGUIDE_API deepguide {

/// The unit's mode: aligning's areas, going around's modes, and overpowered.
enum class IdentifyPhase { evasive, positioning, steering, tracking, done, overpowered };
std::string_view to_string(IdentifyPhase phase);

struct IdentifySample {
  TrajectorySample vehicle;  ///< the shared columns (sector 0, status ok: no reactive method)
  IdentifyPhase phase = IdentifyPhase::evasive;
  double object_distance_m = 0.0;  ///< signed distance to the object's footprint (negative inside)
  double distance_error_m = 0.0;   ///< object_distance_m - the requested distance
  double cross_track_m = 0.0;      ///< header
  double goal_error_m = 0.0;       ///< aligning: |p - g|; going around: |e|
  double laps = 0.0;               ///< going around: laps done; aligning 0

  bool operator==(const IdentifySample&) const = default;
};

struct ModeSwitch {
  double time_s = 0.0;
  Vec2 position{0.0, 0.0};
  IdentifyPhase from = IdentifyPhase::evasive, to = IdentifyPhase::evasive;
};

/// RMS and max |x| of a quantity over the hold.
struct ErrorStats {
  double rms = 0.0, max_abs = 0.0;
};

struct IdentifyStats {
  SimulationStats vehicle;  ///< over the whole run; `reached`: it did what was asked (held, laps_done)
  bool in_position = false;
  double time_to_position_s = 0.0;  ///< valid when in_position
  double hold_s = 0.0;              ///< time from first reaching position to the end
  /// Times the vehicle left position after reaching it (out of the shade, or
  /// back to steering); aligning's hold then starts again.
  int position_lost = 0;
  ErrorStats station_keeping_m;  ///< aligning only (0 going around)
  ErrorStats cross_track_m;
  ErrorStats distance_error_m;
  double requested_distance_m = 0.0;  ///< from the object's footprint
  double laps = 0.0;
  std::size_t mode_switches = 0;
};

enum class IdentifyEnd { held, laps_done, overpowered, collided, time_out };
std::string_view to_string(IdentifyEnd end);

struct IdentifyResult {
  IdentifyMode mode = IdentifyMode::align;
  std::vector<IdentifySample> trajectory;              ///< empty when not recorded
  IdentifyPhase start_phase = IdentifyPhase::evasive;  ///< the mode at t = 0
  std::vector<ModeSwitch> switches;                    ///< every change after it
  IdentifyStats stats;
  IdentifyEnd end = IdentifyEnd::time_out;
  std::size_t samples = 0;
  Vec2 goal{0.0, 0.0};  ///< aligning: the held point g (at the end; it turns with the current)
  /// Why the run failed (overpowered, collided, time_out), one line with time and place; empty otherwise.
  std::string failure;
};

/// The time limit (header).
double identify_max_time_s(const Scenario& scenario);

/// A scenario file with an identify section, in `mode` ("align" or
/// "around"; empty: the section's own), as `identify` runs it. Throws
/// InputError naming `what_mode` (the caller's name for the mode) for
/// another mode, and the file for one without an identify section.
Scenario read_identification_scenario(const std::string& path, const std::string& mode,
                                      const std::string& what_mode = "`mode`");

/// Runs the scenario's identify section in its mode. Throws InputError for an
/// invalid scenario or one without an identify section.
IdentifyResult simulate_identification(const Scenario& scenario, const SimulationOptions& options = {});

}  // namespace deepguide
