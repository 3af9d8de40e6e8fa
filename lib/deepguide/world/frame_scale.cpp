#include "deepguide/world/frame_scale.hpp"

#include <cmath>
#include <limits>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {

FrameScaleRange frame_scale_over(const LocalFrame& frame, const LonLatExtent& area) {
  FrameScaleRange r;
  if (area.empty()) return r;
  r.least = std::numeric_limits<double>::infinity();
  r.greatest = -r.least;
  // One point is one sample; an area is sampled on its edges and inside.
  const int kSteps = area.west == area.east && area.south == area.north ? 0 : 8;
  for (int i = 0; i <= kSteps; ++i) {
    for (int j = 0; j <= kSteps; ++j) {
      const double u = kSteps == 0 ? 0.0 : static_cast<double>(i) / kSteps;
      const double v = kSteps == 0 ? 0.0 : static_cast<double>(j) / kSteps;
      const Eigen::Vector2d at(area.west + (area.east - area.west) * u, area.south + (area.north - area.south) * v);
      const LocalFrame::Scale s = frame.scale_at(at);
      if (!std::isfinite(s.least) || !std::isfinite(s.greatest)) {
        if (r.known) r.unknown_at = at;
        r.known = false;
        continue;
      }
      if (s.least < r.least) r.least = s.least, r.least_at = at;
      if (s.greatest > r.greatest) r.greatest = s.greatest, r.greatest_at = at;
    }
  }
  if (!r.known && !std::isfinite(r.least)) r.least = r.greatest = std::nan("");
  return r;
}

std::string stereographic_crs_for(const LonLatExtent& area) {
  const Eigen::Vector2d c = area.centre();
  // Rounded so that the CRS reads well in a message and a route file; a
  // hundredth of a degree off the centre costs nothing of the rule's band.
  return "+proj=stere +lat_0=" + fixed(c.y(), 2) + " +lon_0=" + fixed(c.x(), 2) +
         " +k=1 +x_0=0 +y_0=0 +datum=WGS84 +units=m +no_defs";
}

namespace {

std::string position(const Eigen::Vector2d& ll) { return "lon " + fixed(ll.x(), 4) + ", lat " + fixed(ll.y(), 4); }

}  // namespace

void require_true_scale(const LocalFrame& frame, const LonLatExtent& area, const std::string& what) {
  const FrameScaleRange r = frame_scale_over(frame, area);
  const std::string advice = "; deepguide measures in true metres and allows a frame " +
                             fixed(100.0 * (1.0 - kLeastFrameScale), 2) + " % short and " +
                             fixed(100.0 * (kGreatestFrameScale - 1.0), 2) +
                             " % long (docs/PLANNING.md); leave `local_crs` out and deepguide chooses one, or give '" +
                             stereographic_crs_for(area) + "'";
  const std::string head = what + ": the local frame '" + printable(frame.id(), 80) + "'";
  if (!r.known) throw InputError(head + " cannot tell its scale at " + position(r.unknown_at) + advice);
  if (r.greatest > kGreatestFrameScale) {
    throw InputError(head + " stretches distances by " + fixed(100.0 * (r.greatest - 1.0), 2) + " % at " +
                     position(r.greatest_at) + advice);
  }
  if (r.least < kLeastFrameScale) {
    throw InputError(head + " shrinks distances by " + fixed(100.0 * (1.0 - r.least), 2) + " % at " +
                     position(r.least_at) + advice);
  }
}

void require_true_scale(const LocalFrame& frame, const std::vector<Eigen::Vector2d>& lonlat, const std::string& what) {
  require_true_scale(frame, extent_of(lonlat), what);
}

LocalFrame default_frame_for(const LonLatExtent& area) {
  const Eigen::Vector2d c = area.centre();
  if (area.south >= -80.0 && area.north <= 84.0) {
    LocalFrame utm = LocalFrame::utm_for(c.x(), c.y());
    const FrameScaleRange r = frame_scale_over(utm, area);
    if (r.known && r.least >= kLeastFrameScale && r.greatest <= kGreatestFrameScale) return utm;
  }
  return LocalFrame::from_user_crs(stereographic_crs_for(area), "the local frame");
}

}  // namespace deepguide
