#include "deepguide/mission/plan_check.hpp"

#include <algorithm>

#include "deepguide/world/obstacle_field.hpp"
#include "deepguide/world/water_volume.hpp"

namespace deepguide {
namespace {
constexpr double kChordTolerance = 0.05;  // m
}  // namespace

MissionPlanCheck check_mission_plan(const MissionPlan& plan, const MissionEnvironment& env,
                                    const ObservationOptions& options) {
  const ObstacleField field(env.obstacles, options.margin_m + options.half_width_m + kChordTolerance);
  // The surface is part of the plan (GPS fixes): the band is the whole column.
  const WaterVolume volume(field, env.floor.get(),
                           {options.vertical_clearance_m, 0.0, std::numeric_limits<double>::infinity()});
  const std::vector<TrackPoint> track = plan_polyline(plan, kChordTolerance);
  MissionPlanCheck out;
  for (std::size_t k = 0; k + 1 < track.size(); ++k) {
    const TrackPoint& p = track[k];
    const TrackPoint& q = track[k + 1];
    const Vec3 a(p.xy.x(), p.xy.y(), p.depth_m), b(q.xy.x(), q.xy.y(), q.depth_m);
    ++out.legs;
    if (env.floor) out.min_floor_gap_m = std::min(out.min_floor_gap_m, env.floor->lowest_gap(a, b).gap_m);
    const WaterVolume::Verdict v = volume.check_segment(a, b);
    if (v.blocked && out.safe) {
      out.safe = false;
      out.along_m = p.along_m;
      out.basic = q.basic;
      out.where = v.where;
      out.problem = v.reason;
    }
  }
  return out;
}

}  // namespace deepguide
