#pragma once
// Vehicle parameters for the offline simulation, and the YAML vehicle file.
//
// Defaults describe a DeepC-like vehicle. Where each number comes from:
//   seed  = the seed paper, Table 1 (5.8 m, 2.4 t, 4000 m, cruise 4 kn, max 6 kn)
//   model = assumed DeepC-like values for the manoeuvring model (first-order Nomoto yaw with
//           rudder and speed lags; Fossen, Handbook of Marine Craft Hydrodynamics and Motion
//           Control, 2011): no Nomoto K, T have been published for DeepC or a vehicle of its size
//   est.  = an engineering estimate made here, stated as such in docs/SIMULATION.md
// Every number is a parameter so that a calibrated vehicle (turning-circle test
// gives K, the 63 % rise time of r after a rudder step gives T) replaces it.
//
// Inside: SI units and radians. In the file: the unit is in the key, angles in
// degrees, speeds in knots (`_kn`) or m/s (`_mps`), whichever the author likes.
// Rudder and turning-rate limits are magnitudes, so the sign convention of the
// rudder (vehicle_model.hpp) does not enter the file.
//
// The file is a YAML mapping of known keys only; an unknown key, a wrong type, a
// non-finite or out-of-range value, or an inconsistent pair (cruise above max
// speed) is an InputError naming the file, the line and the key. Keys left out
// keep their defaults, so `{}` is the DeepC-like vehicle.

#include <string>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/vehicle/energy_model.hpp"

namespace DEEPGUIDE_API deepguide {

inline constexpr double kMetresPerSecondPerKnot = 1852.0 / 3600.0;

/// The course autopilot's tuning (autopilot.hpp): PID by pole placement on the
/// Nomoto model and a second-order reference model with a turning-rate limit.
struct AutopilotTuning {
  double natural_frequency_rad_s = 0.3;            ///< closed-loop omega_n (model; gives Kp = 1.44)
  double damping_ratio = 1.0;                      ///< closed-loop zeta (model: critically damped)
  double reference_natural_frequency_rad_s = 0.2;  ///< est.: slower than the loop, so it can follow
  /// Reference turning-rate limit: 0.8 K delta_max keeps the rudder out of
  /// saturation (a rule of thumb); 5 deg/s = 0.8 x 6.25 deg/s with the defaults.
  double max_reference_turn_rate = deg_to_rad(5.0);

  bool operator==(const AutopilotTuning&) const = default;
};

struct VehicleParams {
  std::string name = "DeepC-like";
  double length_m = 5.8;                                    ///< seed; informational
  double mass_kg = 2400.0;                                  ///< seed; informational (the Nomoto model hides it in K, T)
  double cruise_speed_mps = 4.0 * kMetresPerSecondPerKnot;  ///< seed: 4 kn
  double max_speed_mps = 6.0 * kMetresPerSecondPerKnot;     ///< seed: 6 kn
  /// est.: 1 kn, the slowest speed with steerage way; the floor of --speed optimal.
  double min_speed_mps = 1.0 * kMetresPerSecondPerKnot;
  double speed_time_constant_s = 20.0;  ///< T_u, model

  double nomoto_gain_per_s = 0.25;            ///< K (r per rad of rudder), model
  double nomoto_time_constant_s = 4.0;        ///< T, model
  double max_rudder = deg_to_rad(25.0);       ///< delta_max, model
  double max_rudder_rate = deg_to_rad(10.0);  ///< model
  double rudder_time_constant_s = 0.5;        ///< T_delta of the rudder servo, model
  /// Hard turning-rate limit. est.: 6 deg/s, just under K delta_max = 6.25 deg/s,
  /// so a hard-over turn at cruise has the radius u / r_max = 19.6 m (3.4 L).
  double max_turn_rate = deg_to_rad(6.0);

  double max_vertical_speed_mps = 0.5;  ///< est.: about U sin(15 deg) at cruise (AUVs pitch up to 20-30 deg)
  double depth_time_constant_s = 10.0;  ///< est.: first-order depth response outside the rate limit
  double max_depth_m = 4000.0;          ///< seed: depth of diving

  double step_s = 0.1;  ///< fixed integration step; Nomoto T is seconds, so 0.1 s is ample

  AutopilotTuning autopilot;
  /// Propulsion power P(v) = P_hotel + k v^3 (energy_model.hpp says where the numbers come from).
  EnergyModel energy;

  bool operator==(const VehicleParams&) const = default;
};

/// The turn radius at `speed_mps` (the radius the autopilot turns on at its largest reference turn rate).
double turn_radius(const VehicleParams& vehicle, double speed_mps);

/// The least radius a planned route should turn on for this vehicle to sail
/// it at `speed_mps` through a current of up to `current_mps`: the course
/// reference turns at most max_reference_turn_rate, over ground that is a
/// radius of (speed + current) / rate; and 15 % more, so the path follower
/// keeps turning rate in hand to correct its errors (at exactly the limit it
/// can only fall behind a turn). Measured on mc1000: docs/SIMULATION.md.
double route_turn_radius(const VehicleParams& vehicle, double speed_mps, double current_mps = 0.0);

/// Checks ranges and consistency; throws InputError naming `source` and the key.
void validate(const VehicleParams& params, const std::string& source = "vehicle");

/// Parses a vehicle YAML document; `source` names it in errors (the file path).
VehicleParams parse_vehicle_yaml(const std::string& text, const std::string& source);

/// Reads a vehicle file; throws InputError for a missing or unreadable file.
VehicleParams read_vehicle_file(const std::string& path);

/// The parameters as a vehicle YAML document (speeds in m/s, angles in degrees,
/// shortest round-trip digits), which parse_vehicle_yaml reads back.
std::string vehicle_yaml(const VehicleParams& params);

}  // namespace deepguide
