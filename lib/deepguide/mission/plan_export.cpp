#include "deepguide/mission/plan_export.hpp"

#include <algorithm>

#include "deepguide/core/error.hpp"
#include "deepguide/mission/export_writers.hpp"

namespace deepguide {

const char* role_name(BasicManoeuvre::Role role) {
  switch (role) {
    case BasicManoeuvre::Role::evasion: return "evasion";
    case BasicManoeuvre::Role::identification: return "identification";
    case BasicManoeuvre::Role::mission: break;
  }
  return "mission";
}

std::vector<ExportWaypoint> export_waypoints(const Mission& mission, const MissionPlan& plan, double arc_tolerance_m) {
  std::vector<ExportWaypoint> out;
  const std::vector<TrackPoint> track = plan_polyline(plan, arc_tolerance_m);
  double time = 0.0;
  for (std::size_t k = 0; k < track.size(); ++k) {
    const TrackPoint& p = track[k];
    const BasicManoeuvre& b = plan.basics[p.basic];
    ExportWaypoint w;
    w.xy = p.xy;
    w.lonlat = mission.frame.to_lonlat(p.xy);
    w.depth_m = p.depth_m;
    w.speed_mps = b.speed_mps;
    w.along_m = p.along_m;
    if (k > 0) {
      const ExportWaypoint& before = out.back();
      time += before.hold_s + (b.speed_mps > 0.0 ? (p.along_m - track[k - 1].along_m) / b.speed_mps : 0.0);
      if (b.kind == BasicManoeuvre::Kind::point) w.hold_s = b.hold_s;
    }
    w.time_s = time;
    w.role = role_name(b.role);
    if (b.kind == BasicManoeuvre::Kind::arc && k > 0 && track[k - 1].basic == p.basic) w.radius_m = b.radius_m;
    w.manoeuvre = b.source < mission.manoeuvres.size() ? mission.manoeuvres[b.source].name : std::string();
    out.push_back(std::move(w));
  }
  for (std::size_t k = 0; k < out.size(); ++k) out[k].name = waypoint_name(k, out.size());
  return out;
}

ExportRoute export_route(const Mission& mission, const MissionPlan& plan, double arc_tolerance_m) {
  ExportRoute r{mission.name, mission.frame, export_waypoints(mission, plan, arc_tolerance_m)};
  r.length_m = plan.length_m;
  double fastest = 0.0;
  for (const BasicManoeuvre& b : plan.basics) fastest = std::max(fastest, b.speed_mps);
  r.turn_radius_m = turn_radius(mission.vehicle, fastest);
  r.vertical_speed_mps = mission.vehicle.max_vertical_speed_mps;
  r.max_speed_mps = mission.vehicle.max_speed_mps;
  if (!r.waypoints.empty()) {
    const ExportWaypoint& end = r.waypoints.back();
    r.properties = {{"mission", mission.name}, {"time_s", end.time_s + end.hold_s}};
  }
  return r;
}

void export_plan(const Mission& mission, const MissionPlan& plan, const std::string& path, ExportFormat format,
                 const ExportOptions& options) {
  if (plan.basics.empty()) throw InputError(path + ": expected a plan with at least one manoeuvre to export");
  if (format == ExportFormat::yaml) {
    detail::write_atomically(path, options.overwrite, [&](const std::string& temp) {
      detail::write_plan_yaml(temp, path, mission, plan);
    });
    return;
  }
  write_route_file(export_route(mission, plan, options.arc_tolerance_m), path, format, options);
}

}  // namespace deepguide
