#include "deepguide/mission/collision_observation.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <utility>

#include "deepguide/world/water_volume.hpp"

namespace deepguide {
namespace {
constexpr double kChordTolerance = 0.1;  // m: arcs as chords at most this far inside
}  // namespace

std::vector<Conflict> observe_collisions(const MissionPlan& plan, const ObstacleSet& obstacles, const SeaFloor* floor,
                                         const ObservationOptions& options) {
  const ObstacleField field(obstacles, options.margin_m + options.half_width_m + kChordTolerance);
  // The surface is no danger here (a GPS update goes there on purpose): the band is the whole column.
  const WaterVolume volume(field, floor, {options.vertical_clearance_m, 0.0, std::numeric_limits<double>::infinity()});
  const std::vector<TrackPoint> track = plan_polyline(plan, kChordTolerance);
  std::vector<Conflict> out;
  std::set<std::pair<std::size_t, std::size_t>> seen;  // (basic, obstacle); obstacle npos = the floor
  for (std::size_t k = 0; k + 1 < track.size(); ++k) {
    const TrackPoint& p = track[k];
    const TrackPoint& q = track[k + 1];
    const std::size_t basic = q.basic;
    const Vec3 a(p.xy.x(), p.xy.y(), p.depth_m), b(q.xy.x(), q.xy.y(), q.depth_m);
    const auto report = [&](std::size_t obstacle, double t, const std::string& with) {
      if (!seen.insert({basic, obstacle}).second) return;
      const Vec3 at = a + t * (b - a);
      out.push_back({basic, basic, obstacle, with, p.along_m + t * (q.along_m - p.along_m), at.head<2>(), at.z()});
    };
    if (floor != nullptr) {
      if (const auto t = floor->first_below(a, b, options.vertical_clearance_m)) report(kSeaFloor, *t, "the sea floor");
    }
    const Vec2 lo = p.xy.cwiseMin(q.xy), hi = p.xy.cwiseMax(q.xy);
    for (std::size_t i : field.near(lo, hi, field.margin())) {
      if (const auto t = volume.first_in_zone(i, a, b)) report(i, *t, field.obstacle_name(i));
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const Conflict& x, const Conflict& y) { return x.along_m < y.along_m; });
  // One conflict for a run of consecutive manoeuvres endangered by the same
  // obstacle from the very start of each next one (the header).
  std::vector<Conflict> merged;
  for (const Conflict& c : out) {
    const auto same =
        std::find_if(merged.rbegin(), merged.rend(), [&](const Conflict& m) { return m.obstacle == c.obstacle; });
    if (same != merged.rend() && c.basic == same->last_basic + 1 && c.along_m <= plan.basics[c.basic].start_m + 1e-6) {
      same->last_basic = c.basic;
      continue;
    }
    merged.push_back(c);
  }
  return merged;
}

}  // namespace deepguide
