#include "deepguide/mission/plan_export.hpp"

#include <algorithm>
#include <cmath>

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

std::vector<ExportWaypoint> export_corner_waypoints(const Mission& mission, const MissionPlan& plan) {
  std::vector<ExportWaypoint> out;
  const auto add = [&](const BasicManoeuvre& b, const Vec2& xy, double depth, double along, double time,
                       double radius) {
    ExportWaypoint w;
    w.xy = xy;
    w.lonlat = mission.frame.to_lonlat(xy);
    w.depth_m = depth;
    w.speed_mps = b.speed_mps;
    w.along_m = along;
    w.time_s = time;
    w.radius_m = radius;
    w.role = role_name(b.role);
    w.manoeuvre = b.source < mission.manoeuvres.size() ? mission.manoeuvres[b.source].name : std::string();
    out.push_back(std::move(w));
  };
  double time = 0.0;  // at the start of the basic manoeuvre being read
  for (std::size_t i = 0; i < plan.basics.size(); ++i) {
    const BasicManoeuvre& b = plan.basics[i];
    if (i == 0) add(b, b.from, b.from_depth_m, b.start_m, 0.0, 0.0);
    const double sailing = b.speed_mps > 0.0 ? b.length_m / b.speed_mps : 0.0;
    const bool last = i + 1 == plan.basics.size();
    if (b.kind == BasicManoeuvre::Kind::point) {
      out.back().hold_s += b.hold_s;  // held where the vehicle is
    } else if (b.kind == BasicManoeuvre::Kind::line) {
      // An arc that leaves along the line turns at its own corners; else the line's end is a corner.
      const bool arc_next =
          !last && plan.basics[i + 1].kind == BasicManoeuvre::Kind::arc && joins_smoothly(b, plan.basics[i + 1]);
      if (!arc_next && b.length_m > 0.0) add(b, b.to, b.depth_m, b.start_m + b.length_m, time + sailing, 0.0);
    } else if (b.length_m > 0.0 && b.radius_m > 0.0) {
      const double sweep = b.length_m / b.radius_m;
      const int pieces = std::max(1, static_cast<int>(std::ceil(sweep / (0.5 * M_PI) - 1e-9)));
      const double piece = sweep / pieces;
      const double a0 = std::atan2((b.from - b.centre).y(), (b.from - b.centre).x());
      for (int k = 0; k < pieces; ++k) {
        const double mid = a0 + b.turn * (k + 0.5) * piece;
        const Vec2 corner = b.centre + (b.radius_m / std::cos(0.5 * piece)) * Vec2(std::cos(mid), std::sin(mid));
        const double f = (k + 0.5) / pieces;
        add(b, corner, b.depth_m, b.start_m + f * b.length_m, time + f * sailing, b.radius_m);
      }
      // The arc's end is a waypoint where the route ends or goes on at a corner.
      const bool corner_after = !last && plan.basics[i + 1].length_m > 0.0 && !joins_smoothly(b, plan.basics[i + 1]);
      if (last || corner_after) add(b, b.to, b.depth_m, b.start_m + b.length_m, time + sailing, 0.0);
    }
    time += sailing + (b.kind == BasicManoeuvre::Kind::point ? b.hold_s : 0.0);
  }
  for (std::size_t k = 0; k < out.size(); ++k) out[k].name = waypoint_name(k, out.size());
  return out;
}

ExportRoute export_route(const Mission& mission, const MissionPlan& plan, double arc_tolerance_m, bool corners) {
  ExportRoute r{mission.name, mission.frame,
                corners ? export_corner_waypoints(mission, plan) : export_waypoints(mission, plan, arc_tolerance_m)};
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
    detail::require_exportable_text(mission.name, "mission name", path);
    for (const ComplexManoeuvre& c : mission.manoeuvres)
      detail::require_exportable_text(c.name, "manoeuvre name", path);
    detail::write_atomically(path, options.overwrite,
                             [&](const std::string& temp) { detail::write_plan_yaml(temp, path, mission, plan); });
    return;
  }
  write_route_file(export_route(mission, plan, options.arc_tolerance_m, format == ExportFormat::rtz), path, format,
                   options);
}

}  // namespace deepguide
