#pragma once
// A simulation scenario: vehicle, start, target, the TRUE obstacles, current,
// sonar, the reactive method's parameters and the run's rules; and its YAML
// file (docs/SIMULATION.md, data/scenarios/one_obstacle.yaml).
//
// Frame. Positions are in a local metric frame, x east, y north (m). Without
// a geographic anchor that frame is all there is: true north is +y and a
// current can only be a constant. The frame becomes a CRS (LocalFrame) when
// the file names one (`crs: EPSG:32632`), else when it reads an
// `obstacles_file` (the UTM zone of the obstacles, as everywhere in
// deepguide), else when a position is given as lon/lat (the UTM zone of the
// start). Then x, y are that CRS's coordinates, lon/lat positions are
// transformed, nautical angles are taken from TRUE north (the meridian
// convergence is applied at the point), and a gridded `current_file` can be
// sampled.
//
// The file is a YAML mapping of known keys only (the reader follows
// vehicle_params.cpp): an unknown or duplicate key, a wrong type, a value out
// of range, a missing file is one InputError line naming the file, the line,
// the key and what was expected. Paths inside the file are relative to its
// folder. Keys and defaults:
//   name                   text (default: the file name)
//   vehicle                path of a vehicle file (vehicle_params.hpp); default DeepC-like
//   crs                    projected CRS of the frame (optional)
//   start, target          {x: M, y: M} or {lon: DEG, lat: DEG}        (required)
//   start_heading_deg      nautical; default: the bearing start -> target
//   depth_m                operating depth, >= 0 and <= the vehicle's max depth (default 0)
//   obstacles              list of {id, x|lon, y|lat, semi_major_m, semi_minor_m
//                          (default = semi_major_m), orientation_deg (default 0)}
//   obstacles_file         an obstacle file (obstacle_io.hpp); Point features only
//   current                "SPEED_MPS,DIR_DEG" (sets towards, clockwise from north); default none
//   current_file           a current field (current_field.hpp), taken at depth_m (one
//                          without a CRS is read in the frame's); a time-dependent
//                          field starts at its first time step
//   seed                   the sonar's random seed (unsigned integer, default 1)
//   sonar                  {range_m (0 = no sonar), field_of_view_deg, update_rate_hz,
//                           position_sigma_m, position_sigma_per_m, size_sigma_m, size_sigma_per_m}
//   reactive               ReactiveParams: {margin_m, arrival_radius_m (> 0 here), influence_m,
//                           potential_gain, speed_mps (default: the vehicle's cruise speed),
//                           exit_blend_fraction, dipole_axis_band_m, dipole_blend_m,
//                           potential_stall_fraction}
//   contacts               {gate_m, memory_s (default: the whole run)}        (contacts.hpp)
//   energy                 {hotel_power_w, propulsion_k_w_per_mps3}
//   max_time_s             default 3 x straight-line time + 300 s, at most kMaxSimulationTime_s
//   stall_time_s           stop when the method has commanded speed 0 short of the
//                          target this long (stalled; default 30)
//   no_progress_s          stop when the distance to the target has not shrunk by
//                          kProgress_m for this long (default 300)
//   reversal_dead_band_deg_s  heading reversals ignore |r_ref| below this (default 0.5)
//   identify               the identification run's section (deepguide identify; IdentifySpec
//                          below; data/scenarios/align_in_current.yaml): {object (an obstacle's
//                          id), mode (align | around), hold_time_s, position_tolerance_m,
//                          align: {standoff_m, hold_buffer_m, approach_m, approach_radius_m,
//                          position_gain_per_s, max_approach_mps, lookahead_m, still_mps, speed_mps,
//                          slack_fraction},
//                          around: {distance_m, side (port | starboard: where the object is),
//                          laps, lookahead_m, switch_m, speed_mps}}. With it, target is optional
//                          (the object's centre when left out; the identify run does not use it).
//
// Whole-scenario rules (validate(), also applied to scenarios built in code):
// the start and the target must lie outside every TRUE obstacle footprint (a
// vehicle cannot be inside rock, and a target inside one can only be reached
// through a collision); inside a security zone (the margin) both are allowed,
// and the reactive method reports leaving_zone / target_in_zone.
// With `identify`, the target is not checked (the object's centre is inside
// the object), and the identify section's own rules apply: its parameters
// (aligning.hpp, going_around.hpp), the start outside the object's safety
// ellipse, speeds up to the vehicle's, and for going around a path the
// vehicle can turn on (check_offset_path_fits with the radius of the
// autopilot's largest reference turning rate at the around speed plus a
// uniform current's speed: over ground, downstream, the circle the vehicle
// turns on is that much wider; 23.6 m at cruise in still water).
// Vertical extents (height_m, top_depth_m) are ignored, as by the sonar:
// every obstacle blocks the operating depth.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/currents/current_sampling.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/identification/aligning.hpp"
#include "deepguide/identification/going_around.hpp"
#include "deepguide/reactive/reactive_method.hpp"
#include "deepguide/simulation/contacts.hpp"
#include "deepguide/vehicle/energy_model.hpp"
#include "deepguide/vehicle/sonar.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

class CurrentSampler;

/// Longest run a scenario may ask for (55.6 h, past DeepC's 40 h endurance):
/// it bounds the trajectory's memory (2e6 samples at 0.1 s).
inline constexpr double kMaxSimulationTime_s = 2.0e5;
/// What counts as progress towards the target for no_progress_s (m).
inline constexpr double kProgress_m = 1.0;

enum class IdentifyMode { align, around };
std::string_view to_string(IdentifyMode mode);
std::optional<IdentifyMode> parse_identify_mode(std::string_view name);

/// The scenario's identify section: what to identify and how (header).
struct IdentifySpec {
  std::string object_id;  ///< an obstacle's id; the object is that obstacle
  Ellipse object;         ///< its true footprint (local frame)
  IdentifyMode mode = IdentifyMode::align;
  AlignParams align;
  AroundParams around;
  /// Aligning ends after holding the position this long (s, from the time it is reached), > 0.
  double hold_time_s = 300.0;
  /// In position: within this of the held point (aligning) or of the path (going around), > 0 m.
  double position_tolerance_m = 2.0;
};

struct Scenario {
  std::string name;
  std::string source = "scenario";  ///< the file, named in messages
  VehicleParams vehicle;
  SonarParams sonar;  ///< range_m == 0: no sonar (seed = the scenario's seed)
  ReactiveParams reactive;
  Vec2 start{0.0, 0.0};
  Vec2 target{0.0, 0.0};
  std::optional<double> start_heading;  ///< math rad; nullopt = towards the target
  double depth_m = 0.0;
  std::vector<EllipticCylinder> obstacles;              ///< the truth (local frame)
  Vec2 current{0.0, 0.0};                               ///< uniform current (m/s, local frame) when no field
  std::shared_ptr<const CurrentSampler> current_field;  ///< when set, replaces `current`
  double current_time_offset_s = 0.0;                   ///< the field's time (epoch s) at simulation time 0
  ContactParams contacts;
  EnergyModel energy;
  double max_time_s = std::numeric_limits<double>::quiet_NaN();  ///< NaN: default_max_time_s()
  double stall_time_s = 30.0;
  double no_progress_s = 300.0;
  double reversal_dead_band = deg_to_rad(0.5);  ///< rad/s
  std::optional<LocalFrame> frame;              ///< the CRS when the scenario has one
  std::optional<IdentifySpec> identify;         ///< the identify section, when the file has one
};

/// 3 x the straight-line time at the reactive speed + 300 s, at most kMaxSimulationTime_s.
double default_max_time_s(const Scenario& scenario);

/// Checks every value and the whole-scenario rules (header); throws InputError
/// naming scenario.source and the key.
void validate(const Scenario& scenario);

/// Parses a scenario document; `source` names it in errors and `base_dir` is
/// the folder relative paths start from.
Scenario parse_scenario_yaml(const std::string& text, const std::string& source, const std::string& base_dir);

/// The largest scenario file read_scenario_file takes (large obstacle sets go in an obstacles_file).
inline constexpr std::uintmax_t kMaxScenarioFileBytes = 4u << 20;

/// Reads a scenario file (at most kMaxScenarioFileBytes); throws InputError for a missing, unreadable or invalid file.
Scenario read_scenario_file(const std::string& path);

}  // namespace deepguide
