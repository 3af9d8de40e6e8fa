#pragma once
// A forward-looking sonar for the offline simulation: the seed's "limited
// perceptive faculty of the sonar" and its "inexact" objects, whose position and
// dimensions vary stochastically and get worse with distance.
//
// Field of view. The sonar sits at the vehicle's position and looks along its
// heading. Its sector is the closed set of points p with |p - s| <= range_m and
// |ssa(angle(p - s) - heading)| <= field_of_view / 2. An elliptic cylinder is
// DETECTED when its footprint meets the sector. Tested as: the ellipse's nearest
// point to the sonar lies in the sector, or one of the sector's two edge
// segments enters the ellipse. That is exact: if the nearest point p is within
// range but outside the wedge and some point q of the ellipse is in the sector,
// the segment p-q lies in the ellipse (convex) and within range (the disc is
// convex) and leaves the wedge, so it crosses an edge segment. The sonar inside
// an ellipse detects it at range 0. Polygon obstacles are charted, not sonar
// contacts, and are not reported. The vertical beam is not modelled: the sonar
// sees every cylinder whatever its height or top depth.
//
// Measurement. range_m is the distance from the sonar to the ellipse's nearest
// point (the first echo), bearing the direction to it. The estimated ellipse is
// the true one with
//   centre + (N(0, sp), N(0, sp)),  sp = position_sigma_m + position_sigma_per_m * range
//   a + N(0, ss), b + N(0, ss),     ss = size_sigma_m + size_sigma_per_m * range
// each axis kept >= kMinSonarAxis_m (and re-sorted a >= b, the orientation
// turned by 90 deg when they swap); the orientation is exact. The draws come
// from a std::mt19937_64 the sonar owns, seeded from params.seed, four per
// detection in the order of the obstacle list: the same seed, positions and
// obstacles give the same detections, whatever else the program draws.
//
// Refresh. Scans happen at t = k / update_rate_hz, k = 0, 1, 2, ... (times
// counted, not summed, so they do not drift). update() called at a time before
// the next scan returns false and leaves the last detections as they were; at
// or after it, it scans once and schedules the next scan time after `time_s`.
// Defaults are engineering estimates for an obstacle-avoidance FLS (120 m,
// 120 deg, 2 Hz, 0.5 m + 1 % of range) and are parameters.

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

inline constexpr double kMinSonarAxis_m = 0.1;

struct SonarParams {
  double range_m = 120.0;
  double field_of_view = deg_to_rad(120.0);  ///< full horizontal opening (rad), centred on the heading
  double update_rate_hz = 2.0;
  double position_sigma_m = 0.5;       ///< s0 of the centre error (per axis)
  double position_sigma_per_m = 0.01;  ///< s1: metres of error per metre of range
  double size_sigma_m = 0.25;          ///< s0 of the semi-axis error
  double size_sigma_per_m = 0.01;      ///< s1 of the semi-axis error
  std::uint64_t seed = 1;
};

/// Throws InputError naming the field for a non-finite or out-of-range value.
void validate(const SonarParams& params);

struct Detection {
  Ellipse estimate;          ///< the ellipse the sonar reports (local frame)
  double range_m = 0.0;      ///< true distance sonar -> nearest point of the obstacle
  double bearing = 0.0;      ///< math angle (rad) of that nearest point seen from the sonar
  double time_s = 0.0;       ///< scan time
  std::size_t obstacle = 0;  ///< index of the true obstacle in the list scanned (for evaluation)

  /// Bit-for-bit equality (for reproducibility checks).
  bool operator==(const Detection& o) const {
    return estimate.centre == o.estimate.centre && estimate.a == o.estimate.a && estimate.b == o.estimate.b &&
           estimate.theta == o.estimate.theta && range_m == o.range_m && bearing == o.bearing && time_s == o.time_s &&
           obstacle == o.obstacle;
  }
};

/// True if `footprint` meets the sonar sector at `position` looking along
/// `heading` (math rad); then `range_m` and `nearest` receive the distance to
/// its nearest point and that point (the sonar's position when inside).
bool in_sonar_sector(const SonarParams& params, const Vec2& position, double heading, const Ellipse& footprint,
                     double& range_m, Vec2& nearest);

class Sonar {
 public:
  explicit Sonar(const SonarParams& params);

  /// Scans if `time_s` has reached the next scan time; returns true if it did.
  bool update(double time_s, const Vec2& position, double heading, const std::vector<EllipticCylinder>& obstacles);

  /// The detections of the last scan (empty before the first).
  const std::vector<Detection>& detections() const { return detections_; }
  double next_scan_s() const;
  const SonarParams& params() const { return params_; }

 private:
  SonarParams params_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  std::uint64_t next_scan_ = 0;  ///< index k of the next scan time k / rate
  std::vector<Detection> detections_;
};

}  // namespace deepguide
