#include "deepguide/vehicle/sonar.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_distance.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"

namespace deepguide {
namespace {

void require(bool ok, const char* field, const std::string& expected, double got) {
  if (ok) return;
  std::ostringstream s;
  s << got;
  throw input_error({"sonar", "", field}, expected, s.str());
}

}  // namespace

void validate(const SonarParams& p) {
  auto finite_in = [](double v, double lo, double hi) { return std::isfinite(v) && v > lo && v <= hi; };
  require(finite_in(p.range_m, 0.0, 1e5), "range_m", "a range > 0 and <= 100000 m", p.range_m);
  require(finite_in(p.field_of_view, 0.0, 2.0 * kPi), "field_of_view_deg", "a field of view > 0 and <= 360 deg",
          rad_to_deg(p.field_of_view));
  require(finite_in(p.update_rate_hz, 0.0, 1e3), "update_rate_hz", "a rate > 0 and <= 1000 Hz", p.update_rate_hz);
  auto sigma = [](double v) { return std::isfinite(v) && v >= 0.0 && v <= 1e4; };
  require(sigma(p.position_sigma_m), "position_sigma_m", "a standard deviation >= 0 m", p.position_sigma_m);
  require(sigma(p.position_sigma_per_m), "position_sigma_per_m", "a growth >= 0 m per m of range",
          p.position_sigma_per_m);
  require(sigma(p.size_sigma_m), "size_sigma_m", "a standard deviation >= 0 m", p.size_sigma_m);
  require(sigma(p.size_sigma_per_m), "size_sigma_per_m", "a growth >= 0 m per m of range", p.size_sigma_per_m);
}

bool in_sonar_sector(const SonarParams& p, const Vec2& s, double heading, const Ellipse& e, double& range_m,
                     Vec2& nearest) {
  // Cheap rejection first: the ellipse lies within a of its centre.
  const double centre_distance = (e.centre - s).norm();
  if (centre_distance - e.a > p.range_m) return false;

  const EllipseProjection near = project_to_ellipse(e, s);
  range_m = near.inside ? 0.0 : near.distance;
  nearest = near.inside ? s : near.point;
  if (range_m > p.range_m) return false;
  const double half = 0.5 * p.field_of_view;
  if (near.inside || half >= kPi) return true;
  if (std::abs(wrap_pi(math_angle(near.point - s) - heading)) <= half) return true;
  // Nearest point in range but beside the wedge: the ellipse meets the sector
  // exactly when it meets one of the edge segments (see the header).
  return segment_intersects(e, s, s + p.range_m * unit_vector(heading + half)) ||
         segment_intersects(e, s, s + p.range_m * unit_vector(heading - half));
}

Sonar::Sonar(const SonarParams& params) : params_(params), rng_(params.seed) { validate(params_); }

double Sonar::next_scan_s() const { return static_cast<double>(next_scan_) / params_.update_rate_hz; }

bool Sonar::update(double time_s, const Vec2& position, double heading,
                   const std::vector<EllipticCylinder>& obstacles) {
  // Simulation clocks are sums of steps (0.1 + 0.1 + ... is not 0.5): a
  // nanosecond of slack keeps a scan from slipping by one step.
  constexpr double kSlack_s = 1e-9;
  if (!(time_s + kSlack_s >= next_scan_s())) return false;
  const double k = std::floor((time_s + kSlack_s) * params_.update_rate_hz);
  next_scan_ = static_cast<std::uint64_t>(std::max(0.0, k)) + 1;

  detections_.clear();
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const Ellipse& truth = obstacles[i].footprint;
    double range = 0.0;
    Vec2 nearest;
    if (!in_sonar_sector(params_, position, heading, truth, range, nearest)) continue;
    Detection d;
    d.range_m = range;
    d.time_s = time_s;
    d.obstacle = i;
    d.bearing = range > 0.0 ? math_angle(nearest - position) : heading;
    const double sp = params_.position_sigma_m + params_.position_sigma_per_m * range;
    const double ss = params_.size_sigma_m + params_.size_sigma_per_m * range;
    // Always four draws in this order, so one obstacle's errors never depend on a sigma being zero.
    const double ex = normal_(rng_), ey = normal_(rng_), ea = normal_(rng_), eb = normal_(rng_);
    d.estimate = truth;
    d.estimate.centre += Vec2(sp * ex, sp * ey);
    d.estimate.a = std::max(kMinSonarAxis_m, truth.a + ss * ea);
    d.estimate.b = std::max(kMinSonarAxis_m, truth.b + ss * eb);
    if (d.estimate.b > d.estimate.a) {
      std::swap(d.estimate.a, d.estimate.b);
      d.estimate.theta = wrap_pi(d.estimate.theta + kPi / 2.0);
    }
    detections_.push_back(d);
  }
  return true;
}

}  // namespace deepguide
