#pragma once
// A simulation on disk: the trajectory as CSV, the statistics as JSON.
//
// CSV: one header line, one row per sample, comma-separated, '.' decimals,
// angles in nautical degrees (clockwise from north, [0, 360)), turning rates
// in deg/s CLOCKWISE positive (a turn to starboard is positive, the nautical
// sense; the library's r is counter-clockwise), fixed decimals (millimetres,
// thousandths of a degree):
//   time_s,x_m,y_m,heading_deg,course_cmd_deg,rate_cmd_deg_s,rate_ref_deg_s,
//   rate_deg_s,speed_mps,clearance_m,sector,status,course_unreachable
// (rate_cmd: the commanded course's raw rate; rate_ref: the autopilot's
// reference; rate: the vehicle's; simulation.hpp)
// x_m, y_m are in the scenario's frame (its CRS when it has one);
// clearance_m is "inf" without obstacles; status is the reactive status name
// (reactive_method.hpp); course_unreachable is 0 or 1. Written atomically.
//
// The identification run's CSV (identification_run.hpp): the same first ten
// columns, then
//   mode,object_distance_m,distance_error_m,cross_track_m,goal_error_m,laps,course_unreachable
// (mode: evasive, positioning, steering, tracking, done or overpowered).
//
// JSON: the statistics with the unit in every name, rates in deg/s (magnitudes),
// min_clearance_m null without obstacles, plus the scenario name, the method,
// the seed, why the run ended, samples and contacts remembered.

#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/simulation/identification_run.hpp"
#include "deepguide/simulation/simulation.hpp"

namespace DEEPGUIDE_API deepguide {

/// A sample's first ten CSV columns (header above) in their units, at full
/// precision: what the file rounds, and what deepguide.simulate gives Python.
struct VehicleColumns {
  double time_s, x_m, y_m, heading_deg, course_cmd_deg, rate_cmd_deg_s, rate_ref_deg_s, rate_deg_s, speed_mps,
      clearance_m;
};
VehicleColumns vehicle_columns(const TrajectorySample& sample);

/// The CSV text of a trajectory (header above).
std::string trajectory_csv(std::span<const TrajectorySample> trajectory);

/// Writes trajectory_csv to `path` atomically; throws InputError when it cannot.
void write_trajectory_csv(const std::string& path, std::span<const TrajectorySample> trajectory);

/// The run's statistics as JSON (header above), keys in a fixed order.
nlohmann::ordered_json simulation_json(const Scenario& scenario, const SimulationResult& result);
/// What `simulate` prints: the scenario, method and seed, then each of the
/// JSON's values on a line (numbers to 3 decimals).
std::string simulation_text(const Scenario& scenario, const SimulationResult& result);

/// The identification run's CSV text (header above), and the same written atomically.
std::string identification_csv(std::span<const IdentifySample> trajectory);
void write_identification_csv(const std::string& path, std::span<const IdentifySample> trajectory);

/// The identification run's statistics and mode switches as JSON: errors as
/// {rms, max} in metres, null where the mode has no such measure.
nlohmann::ordered_json identification_json(const Scenario& scenario, const IdentifyResult& result);
/// What `identify` prints: the end, time to position, hold, the errors, the
/// vehicle's clearance, time, path and energy, and each mode switch.
std::string identification_text(const Scenario& scenario, const IdentifyResult& result);

}  // namespace deepguide
