#include "deepguide/mission/goal_point.hpp"

#include <algorithm>
#include <cmath>

namespace deepguide {

TrackDanger track_danger(const MissionPlan& plan, const WaterVolume& volume, double step_m) {
  TrackDanger out;
  const std::vector<TrackPoint> track = plan_polyline(plan, 0.1);
  for (std::size_t k = 0; k < track.size(); ++k) {
    if (k == 0) {
      out.points.push_back(track[0]);
      continue;
    }
    const TrackPoint& p = track[k - 1];
    const TrackPoint& q = track[k];
    const int n = std::max(1, static_cast<int>(std::ceil((q.along_m - p.along_m) / step_m)));
    for (int i = 1; i <= n; ++i) {
      const double f = static_cast<double>(i) / n;
      out.points.push_back({p.xy + f * (q.xy - p.xy), p.depth_m + f * (q.depth_m - p.depth_m), q.basic,
                            p.along_m + f * (q.along_m - p.along_m)});
    }
  }
  const ObstacleField& field = volume.field();
  const double clearance = volume.options().vertical_clearance_m;
  for (std::size_t k = 0; k + 1 < out.points.size(); ++k) {
    const TrackPoint& p = out.points[k];
    const TrackPoint& q = out.points[k + 1];
    const Vec3 a(p.xy.x(), p.xy.y(), p.depth_m), b(q.xy.x(), q.xy.y(), q.depth_m);
    bool hit = volume.floor() != nullptr && volume.floor()->first_below(a, b, clearance).has_value();
    if (!hit) {
      for (std::size_t i : field.near(p.xy.cwiseMin(q.xy), p.xy.cwiseMax(q.xy), field.margin())) {
        if (volume.first_in_zone(i, a, b)) {
          hit = true;
          break;
        }
      }
    }
    out.endangered.push_back(hit ? 1 : 0);
  }
  return out;
}

std::optional<EvasionStretch> goal_points(const TrackDanger& danger, double danger_m, double lead_m,
                                          double not_before_m, std::string* why) {
  const std::vector<TrackPoint>& pts = danger.points;
  const std::size_t pieces = danger.endangered.size();
  if (pieces == 0) {
    if (why != nullptr) *why = "the plan has no track to leave and rejoin";
    return std::nullopt;
  }
  // The piece where the danger begins: the first endangered one reaching danger_m.
  std::size_t first = 0;
  while (first + 1 < pieces && pts[first + 1].along_m <= danger_m) ++first;
  const double step = pts[first + 1].along_m - pts[first].along_m;
  while (first + 1 < pieces && !danger.endangered[first] && pts[first].along_m <= danger_m + step) ++first;
  if (!danger.endangered[first] || pts[first].along_m > danger_m + step) {
    // The scan's zone is wider than observation's corridor, so this means the two disagree: say so, do not guess.
    if (why != nullptr) *why = "the danger scan finds nothing where observation found the conflict";
    return std::nullopt;
  }
  std::size_t last = first;
  // Forward: the run, and the runs that follow it within the lead.
  for (std::size_t k = first + 1; k < pieces; ++k) {
    if (pts[k].along_m - pts[last + 1].along_m >= lead_m) break;
    if (danger.endangered[k]) last = k;
  }
  if (last + 1 == pieces && danger.endangered[last]) {
    if (why != nullptr) *why = "the danger lasts to the mission's end: there is no route left to rejoin";
    return std::nullopt;
  }
  // Backward: runs that end within the lead before it.
  for (std::size_t k = first; k-- > 0;) {
    if (pts[first].along_m - pts[k + 1].along_m >= lead_m || pts[k + 1].along_m <= not_before_m) break;
    if (danger.endangered[k]) first = k;
  }
  EvasionStretch s;
  s.rendezvous_m = std::min(pts[last + 1].along_m + lead_m, pts.back().along_m);
  s.depart_m = std::max({pts[first].along_m - lead_m, not_before_m, pts.front().along_m});
  return s;
}

}  // namespace deepguide
