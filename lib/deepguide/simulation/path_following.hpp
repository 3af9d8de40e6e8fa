#pragma once
// Following a path of lines and arcs (RouteLeg), not cutting its corners.
//
// Curved-path line of sight (Fossen's LOS on a path with curvature; notes 7.4):
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
// The legs must join without a corner (routes within the turning radius,
// planning/turn_rounding.hpp): at a corner the vehicle would overshoot.

#include <cstddef>
#include <vector>

#include "deepguide/planning/route.hpp"

namespace deepguide {

/// The point of one leg nearest to p (clamped to the leg).
struct PathPoint {
  Vec2 point{0.0, 0.0};
  double to_end_m = 0.0;    ///< along the leg from `point` to the leg's end
  Vec2 tangent{1.0, 0.0};   ///< unit, in the direction of travel
  double curvature = 0.0;   ///< signed, ccw > 0 (1/m)
  double left_m = 0.0;      ///< p's signed distance left of the leg at `point`
  bool past_end = false;    ///< p lies beyond the leg's end (abeam or after)
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
  std::size_t leg = 0;

  struct Command {
    double course = 0.0;       ///< course over ground (math rad)
    double course_rate = 0.0;  ///< feed-forward (rad/s)
    double left_m = 0.0;       ///< cross-track error, left > 0
    bool at_end = false;       ///< past the last leg's end
  };
  /// The command for a vehicle at `position` moving at `ground_velocity`.
  Command steer(const Vec2& position, const Vec2& ground_velocity);
};

}  // namespace deepguide
