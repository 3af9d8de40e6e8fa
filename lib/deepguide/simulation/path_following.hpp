#pragma once
// Following a path of lines and arcs (RouteLeg), not cutting its corners.
//
// Curved-path line of sight (Fossen's LOS on a path with curvature; docs/SIMULATION.md, "Following a route"):
// with P the point of the path nearest the vehicle, alpha the path's course
// there, kappa its signed curvature (ccw > 0) and e the vehicle's signed
// distance left of the path,
//   chi_d  = alpha - atan(e / lookahead)
//   chi_d' = kappa_e (v . t) - lookahead (v . n) / (lookahead^2 + e^2)
// where v is the ground velocity, t the path's unit tangent, n its left
// normal and kappa_e the curvature of the parallel curve through the vehicle
// (1 / (rho - e) for a left turn of radius rho). The second line is the
// autopilot's feed-forward (AutopilotSetpoint::course_rate): without it the
// course reference lags a turning path by 2 chi' / w_r. The set-point is a
// course over ground, so the autopilot crabs into a current (autopilot.hpp):
// that is the current compensation.
//
// P is searched on the leg being followed; the next leg is taken once the
// vehicle is abeam of the current leg's end or beyond, so nothing is cut.
// Routes within the turning radius (planning/turn_rounding.hpp) join without
// a corner. Where two legs do meet at a corner (a mission's evasion, a track
// whose legs leave no room for a fillet), turning at the corner would
// overshoot it by about a turning radius: with corner_radius_m R the next leg
// is taken R tan(|turn| / 2) before the corner, where a turn of radius R
// round it would begin, so the vehicle cuts it by about R (1 / cos(turn / 2)
// - 1) on the inside instead (turns beyond 150 degrees are led as 150).

#include <cstddef>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/route.hpp"

namespace DEEPGUIDE_API deepguide {

/// The point of one leg nearest to p (clamped to the leg).
struct PathPoint {
  Vec2 point{0.0, 0.0};
  double to_end_m = 0.0;   ///< along the leg from `point` to the leg's end
  Vec2 tangent{1.0, 0.0};  ///< unit, in the direction of travel
  double curvature = 0.0;  ///< signed, ccw > 0 (1/m)
  double left_m = 0.0;     ///< p's signed distance left of the leg at `point`
  bool past_end = false;   ///< p lies beyond the leg's end (abeam or after)
};
PathPoint nearest_on_leg(const RouteLeg& leg, const Vec2& p);

/// The follower's state: which leg it is on.
struct PathFollower {
  std::vector<RouteLeg> legs;
  double lookahead_m = 20.0;
  /// How far ahead along the path the feed-forward takes its curvature (m):
  /// the course reference needs a few seconds to take up a new turning rate,
  /// so starting the feed-forward this much early splits the lag about evenly
  /// before and after a change of curvature.
  double lead_m = 0.0;
  /// The radius corners are turned on (see above); 0: at the corner.
  double corner_radius_m = 0.0;
  std::size_t leg = 0;

  struct Command {
    double course = 0.0;       ///< course over ground (math rad)
    double course_rate = 0.0;  ///< feed-forward (rad/s)
    double left_m = 0.0;       ///< cross-track error, left > 0
    double to_end_m = 0.0;     ///< along the leg followed, from the vehicle's place on it to its end
    bool at_end = false;       ///< past the last leg's end
  };
  /// The command for a vehicle at `position` moving at `ground_velocity`.
  Command steer(const Vec2& position, const Vec2& ground_velocity);
};

}  // namespace deepguide
