#pragma once
// Going around an object at a given distance (the seed's Figs. 15-16): a
// guidance unit in the manner of a MOOS-IvP behaviour. Vehicle position in,
// course and speed out, with the mode it is in.
//
// The path is the offset curve at distance D (offset_path.hpp), travelled
// anticlockwise (direction +1, the object to port) or clockwise (-1, the
// object to starboard). The cross-track error e is the signed distance from
// the path, positive outside.
//   steering   |e| > switch_m: straight at the nearest point of the path.
//              That segment runs along the object's normal, so it never
//              crosses the object.
//   tracking   |e| <= switch_m: lookahead line of sight (Breivik & Fossen, CDC 2008) on the
//              path's tangent direction alpha, in math angles:
//                chi = alpha + direction * atan(e / lookahead_m)
//              Outside the path (e > 0) this turns towards the object. Back
//              to steering only beyond 2 switch_m, so the mode does not flicker.
//              The command carries chi's rate for the autopilot's
//              feed-forward (autopilot.hpp), from the ground velocity v:
//                d chi/dt = (v . t) / (rho + e)
//                         + direction * lookahead (v . n) / (lookahead^2 + e^2)
//              (t the anticlockwise tangent, n the outward normal, rho the
//              path's radius of curvature at the nearest point: the nearest
//              point moves at (v . t) rho / (rho + e), the tangent turns at
//              1 / rho per metre of it, and e changes at v . n). Without it
//              the autopilot's reference lags a turning course by 2 r / w_r,
//              and the real vehicle ran 3-13 m outside the tight ends of a
//              40 x 18 m wreck's path. (Pure pursuit of a point ahead on the
//              path leads instead, but cuts the corner: with the feed-forward
//              it settled 6 m inside.)
// Laps count the unwrapped change of the ellipse parameter t of the nearest
// path point, in the travel direction, from the moment tracking starts. The
// run is done when `laps` laps are complete (status done, speed 0).

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"

namespace DEEPGUIDE_API deepguide {

struct AroundParams {
  double distance_m = 20.0;  ///< D, from the object's footprint, > 0
  int direction = 1;         ///< +1 anticlockwise (object to port), -1 clockwise
  double laps = 1.0;         ///< laps to go, > 0
  /// LOS lookahead distance (rule of thumb: a few vehicle lengths, 15-30 m for DeepC), > 0. 25 m: with
  /// 20 m the real vehicle, joining a 30 m path round a 40 x 18 m wreck in a
  /// 1 m/s current, turned at its limit and overshot by 6 m (cross-track RMS
  /// 1.07 m over two laps); with 25 m 4 m (0.72 m), and the still-water RMS
  /// grows from 0.40 to 0.45 m. Longer than the vehicle's turning circle over
  /// ground is the rule (23.6 m at cruise, 35 m downstream in 1 m/s).
  double lookahead_m = 25.0;
  /// Steering -> tracking within this cross-track distance, > 0. About twice
  /// the turning radius: joining closer, at right angles, the
  /// vehicle overshoots by up to its radius (10 m: 8 m inside a 20 m path).
  double switch_m = 40.0;
  double speed_mps = 4.0 * 1852.0 / 3600.0;  ///< commanded speed through the water, > 0
};

/// Throws InputError naming the first bad field.
void validate(const AroundParams& params);

enum class AroundMode { steering, tracking, done };

struct AroundMemory {
  AroundMode mode = AroundMode::steering;
  bool started = false;  ///< tracking has begun (the lap count runs)
  double last_t = 0.0;   ///< ellipse parameter of the nearest path point at the last call
  double turned = 0.0;   ///< unwrapped parameter change in the travel direction (rad)
  double laps_done() const;
};

struct AroundCommand {
  double course = 0.0;  ///< math rad
  double speed_mps = 0.0;
  AroundMode mode = AroundMode::steering;
  double cross_track_m = 0.0;  ///< e, positive outside the path
  double path_course = 0.0;    ///< alpha: the path's direction of travel at the nearest point (math rad)
  /// d chi / dt for the autopilot's feed-forward (rad/s, ccw positive; header),
  /// 0 while steering or without a ground velocity.
  double course_rate = 0.0;
};

/// `ground_velocity` (m/s) only feeds the course rate; zero gives none.
AroundCommand around_command(const Ellipse& object, const AroundParams& params, AroundMemory& memory, const Vec2& p,
                             const Vec2& ground_velocity = Vec2(0.0, 0.0));

}  // namespace deepguide
