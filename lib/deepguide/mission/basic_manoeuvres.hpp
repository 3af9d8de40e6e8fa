#pragma once
// The seed's Missionplanhandler: complex manoeuvres become basic ones, the
// simple geometric shapes the vehicle passes in a fixed order: straight lines,
// arcs at the vehicle's turn radius, and points (with a hold time), each with
// its depth and speed.
//
// - track: a line from where the vehicle is to each waypoint; each corner is
//   rounded by an arc of the turn radius when both legs leave room for it
//   (tangent length R tan(turn / 2)), else it stays a corner and a warning
//   says so.
// - goto: one line.
// - survey (lawnmower): lines at the heading across the area, one line
//   spacing apart (the first half a spacing in from the area's edge), each
//   spanning the area along its line (a concave area's notch is crossed),
//   boustrophedon; ends are extended to a common turning line and joined by
//   a quarter arc, a straight and a quarter arc. The spacing must be at least
//   twice the turn radius. A line from where the vehicle is to the first line.
// - gps_update: a point at the surface (depth 0) held for hold_s, then a
//   point back at the manoeuvre's depth (the dive).
// - identify: around: a line tangent to the path at distance_m from the
//   object's outline, joining it anticlockwise without a corner (from inside
//   the path: a line to its nearest point), then one lap along that path
//   (its true offset curve, identification/offset_path.hpp, as circular arcs
//   within 0.1 m of it: 8 to 16 for the usual objects, where 72 lines
//   were); align: a line to the
//   point at distance_m from the outline facing the approach, and a point
//   held there (the identification system aligns from there).
// The first line of each manoeuvre changes depth from the previous depth to
// its own; the others keep it. The turn radius at speed v is v / the
// autopilot's largest reference turning rate (23.6 m at 4 kn for DeepC).

#include <cstddef>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/biarc.hpp"
#include "deepguide/mission/mission.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct BasicManoeuvre {
  enum class Kind { line, arc, point };
  Kind kind = Kind::line;
  Vec2 from{0.0, 0.0};
  Vec2 to{0.0, 0.0};
  Vec2 centre{0.0, 0.0};  ///< arcs
  double radius_m = 0.0;  ///< arcs
  int turn = 0;           ///< arcs: +1 anticlockwise (turning left), -1 clockwise
  double from_depth_m = 0.0;
  double depth_m = 0.0;  ///< at its end (lines may change depth; arcs and points keep it)
  double speed_mps = 0.0;
  double hold_s = 0.0;     ///< points: how long the vehicle stays
  std::size_t source = 0;  ///< index of the complex manoeuvre it comes from
  double start_m = 0.0;    ///< distance along the mission (horizontal track) where it begins
  double length_m = 0.0;   ///< horizontal length (0 for points)
  /// Why it is there: the mission's own, or put in by mission control
  /// (mission/mission_control.hpp) to evade or to identify an obstacle.
  enum class Role { mission, evasion, identification };
  Role role = Role::mission;

  /// The point s metres along it (clamped).
  Vec2 point_at(double s) const;
  /// The unit direction of travel s metres along it (clamped); zero for a point.
  Vec2 direction_at(double s) const;
  /// How long it takes at its speed, its hold included.
  double duration_s() const { return hold_s + (speed_mps > 0.0 ? length_m / speed_mps : 0.0); }
};

struct MissionPlan {
  std::vector<BasicManoeuvre> basics;
  double length_m = 0.0;
  std::vector<std::string> warnings;  ///< one line each, naming the manoeuvre
};

/// Whether `next` leaves in the direction `before` arrives (no corner where they join).
bool joins_smoothly(const BasicManoeuvre& before, const BasicManoeuvre& next);

/// How long the plan takes at its speeds and holds (s).
double plan_duration(const MissionPlan& plan);

// turn_radius and route_turn_radius: vehicle/vehicle_params.hpp.

/// Expands the mission (the header). `obstacles` (local frame) are where
/// identify finds its object. Throws InputError naming the file and the
/// manoeuvre for an identify object that is not among them, a survey whose
/// spacing is under twice the turn radius or whose area holds no line, or a
/// turn radius below the vehicle's.
MissionPlan expand_mission(const Mission& mission, const ObstacleSet& obstacles);

/// The lap round an object at `distance_m` from its outline, as identify
/// around sails it: from the point where the line from `from` meets the path
/// tangentially going anticlockwise (or, from within kLapTolerance_m of the
/// path or inside it, the path's nearest point), one lap anticlockwise as
/// circular arcs within kLapTolerance_m of the path
/// (identification/offset_path.hpp, offset_lap_arcs).
struct IdentificationLap {
  Vec2 start{0.0, 0.0};
  std::vector<CircleArc> arcs;  ///< the last ends at start
};
inline constexpr double kLapTolerance_m = 0.1;
IdentificationLap identification_lap(const Ellipse& object, double distance_m, const Vec2& from);

/// The plan as a polyline of the horizontal track (arcs as chords no more
/// than `tolerance_m` off), with the depth at each point.
struct TrackPoint {
  Vec2 xy;
  double depth_m;
  std::size_t basic;  ///< the basic manoeuvre it belongs to
  double along_m;     ///< distance along the mission (arc lengths for arcs)
};
std::vector<TrackPoint> plan_polyline(const MissionPlan& plan, double tolerance_m = 0.25);

}  // namespace deepguide
