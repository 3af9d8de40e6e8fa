#pragma once
// The reactive level's one small interface (the seed's Reactive Evasive
// Control): vehicle state, the objects the sonar reports and the target in,
// a commanded course over ground and speed out, and an explicit status when the
// method cannot do what it is asked (MOOS-IvP's behaviours do the same).
//
// Every method is found by name in the registry (reactive_registry.hpp),
// each in its own file pair with its own parameters and memory:
//   dipole_field.hpp           (a) uniform flow to the target + a dipole per object
//   geometric_construction.hpp (b) the seed's three-sector construction
//   potential_field.hpp        (c) attractive/repulsive potentials, the baseline
// Objects are the sonar's estimated footprints (not inflated); each method
// keeps params.margin_m away from them with the same security zone, the
// security ellipse below (an ellipse, so that tangents, flows and distances
// stay closed-form; it contains the true offset zone, touching it at the ends
// of the major axis).
// Angles are math angles (rad, counter-clockwise from east), the local frame's
// convention (core/angles.hpp); nautical degrees only at the interfaces.
//
// Behaviour common to all methods (reactive_support.hpp):
//   - no objects: straight to the target;
//   - within arrival_radius_m of the target: status arrived, speed 0;
//   - target inside a security zone: the method steers to the nearest point
//     of the zone boundary instead (status target_in_zone) and stops there
//     (speed 0, still target_in_zone): it never enters the zone to reach it;
//   - vehicle inside a security zone: a course that leads out, status
//     leaving_zone, continuous with the outside course at the boundary;
//   - stalled (the field vanishes, or no free tangent exists): speed 0 and
//     the current course held, so that a mission layer can re-plan.
// Side convention: side +1 passes an object with the vehicle to the left of
// the axis from the object's centre to the target (it circles the object
// clockwise), -1 to the right. A vehicle exactly on the axis takes the side
// its current course points to; with no hint at all it turns to starboard
// (side -1, as COLREGs rule 14 for head-on encounters).

#include <any>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

/// A reactive method, by name: what `simulate --method`, `evaluate --methods`
/// and the figures find it by in the registry (reactive_registry.hpp). The
/// built-in ones are constants; a registered one is ReactiveMethod{"name"}.
struct ReactiveMethod {
  std::string name;
  static const ReactiveMethod dipole, geometric, potential;
  friend bool operator==(const ReactiveMethod&, const ReactiveMethod&) = default;
  friend auto operator<=>(const ReactiveMethod&, const ReactiveMethod&) = default;
};
inline const ReactiveMethod ReactiveMethod::dipole{"dipole"};
inline const ReactiveMethod ReactiveMethod::geometric{"geometric"};
inline const ReactiveMethod ReactiveMethod::potential{"potential"};

inline std::string_view to_string(const ReactiveMethod& method) { return method.name; }

/// What every method is given: the vehicle's security margin, speed and
/// arrival, and how it turns. A method's own parameters (the dipole's blend,
/// the potential's gain, ...) are in `tuning`, by the names its registry
/// entry declares with their defaults and ranges (reactive_registry.hpp);
/// the method reads them into its own struct (e.g. dipole_params).
struct ReactiveParams {
  double margin_m = 10.0;                    ///< security margin around each reported object, >= 0
  double speed_mps = 4.0 * 1852.0 / 3600.0;  ///< commanded speed through the water (cruise), > 0
  double arrival_radius_m = 5.0;             ///< within this of the target: status arrived, >= 0
  /// Distance beyond the security zone within which an object influences the
  /// field methods (dipole, potential; outside it their field is pure attraction), > 0.
  double influence_m = 60.0;
  /// Inside a zone the course turns from the boundary tangent to the outward
  /// normal over this fraction of the way to the centre (an assumed blend;
  /// 0.25 by default; reactive_support.hpp, "Exit blend"), in (0, 1].
  double exit_blend_fraction = 0.25;
  /// The vehicle's hard turning-rate limit (rad/s), for a method that sails
  /// its course (the geometric one: geometric_construction.hpp, "Sailing"):
  /// its course is checked as the vehicle would turn to it, not as a line.
  /// Unset: the vehicle's max_turn_rate in the simulation and the mission
  /// run, none elsewhere; 0: lines alone (the seed's; figures, comparisons).
  std::optional<double> turn_rate_limit = std::nullopt;
  /// How long the vehicle takes to take up a new turning rate (s; the closed
  /// loop as a first-order lag). 0: at once. Filled with turn_rate_limit in
  /// the simulation and the mission run (simulation/simulation.hpp, sailing_params).
  double turn_lag_s = 0.0;
  /// Each method's own parameters by name (the scenario file's keys under
  /// `reactive:`, e.g. "potential_gain"); a name not given takes its
  /// declared default (tuning_value, reactive_registry.hpp).
  std::map<std::string, double, std::less<>> tuning = {};
};

/// Throws InputError naming the first bad field (non-finite, or outside the
/// range documented above or declared by its method), or a tuning name no
/// registered method declares.
void validate(const ReactiveParams& params);

/// The security zone of `object` for margin d, as an ellipse: semi-axes
///   a' = a + d,   b' = sqrt((a + d)(d + b^2/a)).
/// It contains the offset zone (object (+) disc(d)): the support functions
/// must satisfy h'(u) >= h(u) + d; with t = h(u) in [b, a] both sides are
/// quadratic in t, equal at t = a, and the condition reduces to b' >= b + d and
/// b'^2 >= (a + d)(d + b^2/a), the second the larger (difference d (a - b)^2 / a).
/// That is, the ellipse osculates the offset curve at the major-axis ends
/// (equal curvature radius b^2/a + d). A circle (a = b) gives the circle a + d.
Ellipse security_ellipse(const Ellipse& object, double margin_m);

struct ReactiveInput {
  double time_s = 0.0;
  Vec2 position{0.0, 0.0};  ///< local frame (m)
  double course = 0.0;      ///< current course over ground (math rad), for tie-breaks
  double speed_mps = 0.0;
  Vec2 target{0.0, 0.0};
  std::span<const Ellipse> objects;  ///< reported footprints (local frame), not inflated
  double turn_rate = 0.0;  ///< present turning rate (rad/s, ccw > 0), for a method that sails its course; 0 unknown
};

enum class ReactiveStatus {
  ok,              ///< a course towards the target
  arrived,         ///< within arrival_radius_m of the target
  leaving_zone,    ///< inside a security zone, leading out (the geometric method's sector 3)
  target_in_zone,  ///< the target lies inside a security zone: heading for the nearest reachable point
  stalled,         ///< the field vanishes here (stagnation point, local minimum): course held
};
std::string_view to_string(ReactiveStatus status);

struct ReactiveCommand {
  double course = 0.0;     ///< commanded course over ground (math rad)
  double speed_mps = 0.0;  ///< commanded speed through the water
  /// Feed-forward for the autopilot: how fast `course` turns (rad/s, ccw
  /// positive), known to guidance that follows a curved path; 0 otherwise.
  double course_rate = 0.0;
  ReactiveStatus status = ReactiveStatus::ok;
  int sector = 0;                     ///< the geometric method's sector 1, 2 or 3; 0 for the others
  std::ptrdiff_t active_object = -1;  ///< index into objects of the object steered around, -1 none
};

/// What a method remembers between calls, one per vehicle and method
/// (value-initialise to start): the method's own state, of a type its file
/// declares (the dipole's SideLatch, the geometric method's GeometricMemory,
/// none for the potential field), made on the first call (method_state).
struct ReactiveMemory {
  std::any state;
};

/// The method's state in `memory`, made fresh when it holds none, or another
/// method's.
template <class State>
State& method_state(ReactiveMemory& memory) {
  if (!memory.state.has_value() || memory.state.type() != typeid(State)) memory.state = State{};
  return std::any_cast<State&>(memory.state);
}

/// One control step of `method` (found in the registry). Throws InputError for bad params, a
/// non-finite position or target, or an object that is not an ellipse
/// (a >= b > 0, finite), and for a method no entry has.
ReactiveCommand reactive_command(const ReactiveMethod& method, const ReactiveParams& params, ReactiveMemory& memory,
                                 const ReactiveInput& input);

/// The method's memoryless gradient direction at `point` (unit vector, zero
/// where the field vanishes or at the target): what the figures of gradient
/// lines draw. The geometric method takes each object's side from the
/// symmetry-axis rule (no latch); the dipole method has no axis tie-break, so
/// its field vanishes at the front stagnation point.
Vec2 reactive_gradient(const ReactiveMethod& method, const ReactiveParams& params, const Vec2& point,
                       const Vec2& target, std::span<const Ellipse> objects);

}  // namespace deepguide
