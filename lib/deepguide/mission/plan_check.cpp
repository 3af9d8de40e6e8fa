#include "deepguide/mission/plan_check.hpp"

#include <algorithm>

#include "deepguide/core/format.hpp"
#include "deepguide/vehicle/autopilot.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "deepguide/world/water_volume.hpp"

namespace deepguide {
namespace {
constexpr double kChordTolerance = 0.05;  // m

// legs_beaten_by_current on the plan's track (arcs as chords).
std::vector<BeatenLeg> beaten_on(const MissionPlan& plan, const std::vector<TrackPoint>& track, const Vec2& current) {
  std::vector<BeatenLeg> out;
  if (current.norm() == 0.0) return out;
  for (std::size_t k = 0; k + 1 < track.size(); ++k) {
    const TrackPoint& p = track[k];
    const TrackPoint& q = track[k + 1];
    const Vec2 d = q.xy - p.xy;
    const double speed = plan.basics[q.basic].speed_mps;
    if (d.norm() == 0.0 || speed <= 0.0 || (!out.empty() && out.back().basic == q.basic)) continue;
    if (!ground_speed_along(d.normalized(), current, speed)) out.push_back({q.basic, p.along_m, p.xy});
  }
  return out;
}
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
  const std::vector<BeatenLeg> beaten = beaten_on(plan, track, env.current);
  if (out.safe && !beaten.empty()) {
    const BeatenLeg& b = beaten.front();
    out.safe = false;
    out.along_m = b.along_m;
    out.basic = b.basic;
    out.where = Vec3(b.where.x(), b.where.y(), plan.basics[b.basic].depth_m);
    out.problem = "the " + fixed(env.current.norm(), 2) + " m/s current beats the vehicle's " +
                  fixed(plan.basics[b.basic].speed_mps, 2) + " m/s through the water: no heading holds this leg (" +
                  std::to_string(beaten.size()) + " basic manoeuvre(s) so)";
  }
  return out;
}

std::vector<BeatenLeg> legs_beaten_by_current(const MissionPlan& plan, const Vec2& current) {
  if (current.norm() == 0.0) return {};
  return beaten_on(plan, plan_polyline(plan, kChordTolerance), current);
}

}  // namespace deepguide
