#include "deepguide/simulation/contacts.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "deepguide/core/angles.hpp"

namespace deepguide {
namespace {

constexpr std::size_t kDirections = 16;

const std::array<Vec2, kDirections>& directions() {
  static const std::array<Vec2, kDirections> dirs = [] {
    std::array<Vec2, kDirections> d;
    for (std::size_t i = 0; i < kDirections; ++i) d[i] = unit_vector(kPi * static_cast<double>(i) / kDirections);
    return d;
  }();
  return dirs;
}

// Half-width w(u) = sqrt(a^2 (u.major)^2 + b^2 (u.minor)^2).
double half_width(const Ellipse& e, const Vec2& major, const Vec2& u) {
  const double p = u.dot(major);
  const double q = u.x() * -major.y() + u.y() * major.x();
  return std::sqrt(e.a * e.a * p * p + e.b * e.b * q * q);
}

}  // namespace

double ellipse_hausdorff_distance(const Ellipse& a, const Ellipse& b) {
  const Vec2 dc = a.centre - b.centre;
  const Vec2 ma = a.major_dir(), mb = b.major_dir();
  double worst = 0.0;
  for (const Vec2& u : directions()) {
    worst = std::max(worst, std::abs(u.dot(dc)) + std::abs(half_width(a, ma, u) - half_width(b, mb, u)));
  }
  return worst;
}

ContactMemory::ContactMemory(const ContactParams& params, const SonarParams& sonar) : params_(params), sonar_(sonar) {}

double ContactMemory::noise_scale(double range_m) const {
  return sonar_.position_sigma_m + sonar_.position_sigma_per_m * range_m + sonar_.size_sigma_m +
         sonar_.size_sigma_per_m * range_m;
}

void ContactMemory::update(std::span<const Detection> detections, double time_s) {
  const std::size_t n_old = ellipses_.size();
  pairs_.clear();
  for (std::size_t d = 0; d < detections.size(); ++d) {
    const Ellipse& det = detections[d].estimate;
    const double det_noise = noise_scale(detections[d].range_m);
    for (std::size_t c = 0; c < n_old; ++c) {
      const double gate = params_.gate_m + 3.0 * (noise_m_[c] + det_noise);
      // The centre distance is a lower bound of d_H: prune before the 16 directions.
      if ((ellipses_[c].centre - det.centre).squaredNorm() > gate * gate) continue;
      const double dist = ellipse_hausdorff_distance(ellipses_[c], det);
      if (dist <= gate) pairs_.push_back({dist, c, d});
    }
  }
  std::sort(pairs_.begin(), pairs_.end(), [](const Pair& x, const Pair& y) {
    if (x.distance != y.distance) return x.distance < y.distance;
    return x.contact != y.contact ? x.contact < y.contact : x.detection < y.detection;
  });
  contact_taken_.assign(n_old, 0);
  detection_taken_.assign(detections.size(), 0);
  for (const Pair& p : pairs_) {
    if (contact_taken_[p.contact] || detection_taken_[p.detection]) continue;
    contact_taken_[p.contact] = detection_taken_[p.detection] = 1;
    ellipses_[p.contact] = detections[p.detection].estimate;
    last_seen_s_[p.contact] = time_s;
    noise_m_[p.contact] = noise_scale(detections[p.detection].range_m);
  }
  for (std::size_t d = 0; d < detections.size(); ++d) {
    if (detection_taken_[d]) continue;
    ellipses_.push_back(detections[d].estimate);
    last_seen_s_.push_back(time_s);
    noise_m_.push_back(noise_scale(detections[d].range_m));
  }

  if (!std::isfinite(params_.memory_s)) return;
  std::size_t kept = 0;
  for (std::size_t c = 0; c < ellipses_.size(); ++c) {
    if (time_s - last_seen_s_[c] > params_.memory_s) continue;
    ellipses_[kept] = ellipses_[c];
    last_seen_s_[kept] = last_seen_s_[c];
    noise_m_[kept] = noise_m_[c];
    ++kept;
  }
  ellipses_.resize(kept);
  last_seen_s_.resize(kept);
  noise_m_.resize(kept);
}

}  // namespace deepguide
