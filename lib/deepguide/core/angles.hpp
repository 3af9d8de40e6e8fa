#pragma once
// The one place where angle conventions are fixed.
//
// At every interface (files, command line, reports) angles are nautical:
// degrees, clockwise from north (a heading or course). Inside the library all
// geometry uses the mathematical convention: radians, counter-clockwise from
// the +x axis, where x = easting and y = northing of the local metric frame.
// Convert at the interface, never in the middle of a computation.
//
//   math angle  a = pi/2 - heading        heading = pi/2 - a
//   north  = heading 0    = math pi/2     = vector (0, 1)
//   east   = heading 90   = math 0        = vector (1, 0)
//   south  = heading 180  = math -pi/2    = vector (0, -1)
//   west   = heading 270  = math pi       = vector (-1, 0)

#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

constexpr double deg_to_rad(double deg) { return deg * kPi / 180.0; }
constexpr double rad_to_deg(double rad) { return rad * 180.0 / kPi; }

/// Wraps an angle in radians to [-pi, pi).
inline double wrap_pi(double a) {
  double w = std::fmod(a + kPi, kTwoPi);
  if (w < 0.0) w += kTwoPi;
  // -tiny + 2 pi can round up to 2 pi, which would give +pi.
  const double r = w - kPi;
  return r >= kPi ? -kPi : r;
}

/// Wraps an angle in radians to [0, 2 pi).
inline double wrap_two_pi(double a) {
  double w = std::fmod(a, kTwoPi);
  if (w < 0.0) w += kTwoPi;
  return w >= kTwoPi ? 0.0 : w;
}

/// Wraps degrees to [0, 360).
inline double wrap_360(double deg) {
  double w = std::fmod(deg, 360.0);
  if (w < 0.0) w += 360.0;
  return w >= 360.0 ? 0.0 : w;
}

/// Nautical heading in degrees (clockwise from north) -> internal math angle in radians.
inline double heading_deg_to_math_rad(double heading_deg) { return wrap_pi(kPi / 2.0 - deg_to_rad(heading_deg)); }

/// Internal math angle in radians -> nautical heading in degrees, in [0, 360).
inline double math_rad_to_heading_deg(double math_rad) { return wrap_360(rad_to_deg(kPi / 2.0 - math_rad)); }

/// Unit vector (east, north) of a math angle.
inline Eigen::Vector2d unit_vector(double math_rad) { return {std::cos(math_rad), std::sin(math_rad)}; }

/// Math angle of a vector (east, north).
inline double math_angle(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }

/// Nautical course in degrees [0, 360) of a vector (east, north).
inline double course_deg_of(const Eigen::Vector2d& v) { return wrap_360(rad_to_deg(std::atan2(v.x(), v.y()))); }

/// Unit vector (east, north) of a nautical course in degrees.
inline Eigen::Vector2d vector_of_course_deg(double course_deg) {
  const double c = deg_to_rad(course_deg);
  return {std::sin(c), std::cos(c)};
}

}  // namespace deepguide
