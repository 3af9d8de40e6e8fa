#include "deepguide/render/mission_web_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "deepguide/charts/chart_info.hpp"
#include "deepguide/charts/chart_obstacles.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/plan_export.hpp"
#include "deepguide/render/obstacle_web_layers.hpp"
#include "deepguide/render/raster_web_image.hpp"
#include "deepguide/simulation/mission_run.hpp"

namespace deepguide {

namespace {

using json = nlohmann::ordered_json;

json rounded(double v, double unit) { return std::round(v / unit) * unit; }

const char* role_colour(const std::string& role) {
  if (role == "evasion") return "#f76707";
  if (role == "identification") return "#ae3ec9";
  return "#f08c00";
}

}  // namespace

WebMap mission_web_map(const LoadedMission& loaded, const PlannedMission& planned, const MissionRun* run,
                       bool as_written) {
  const Mission& mission = loaded.mission;
  const WebMapGeometry to{&mission.frame};
  const MissionPlan& plan = run ? run->plan : as_written ? loaded.plan : planned.plan;
  WebMap map;
  map.title = mission.name + ": " + fixed(plan.length_m / 1000.0, 2) + " km, " + clock_text(plan_duration(plan));
  map.subtitle = std::to_string(planned.resolutions.size()) + " conflict(s), margin " + general(mission.margin_m) +
                 " m, frame " + mission.frame.id() +
                 (run          ? ", simulated"
                  : as_written ? ", as written"
                               : "");

  for (const std::string& chart : mission.charts) {  // a bathymetry raster's depth shading under the layers
    if (!reads_as_enc(chart) && chart_kind(chart) == ChartKind::raster)
      map.images.push_back(raster_depth_image(chart, ""));
  }
  map.layers.push_back(obstacle_web_layer(loaded.env.obstacles, to, "Obstacles and charted no-go"));
  map.layers.push_back(zone_web_layer(loaded.env.obstacles, to, mission.margin_m, 0.05));

  WebMapLayer written = web_map_layer("written", "The plan as written", "#868e96", "#868e96", 0.0, 2.0);
  written.dash = "6 5";
  written.shown = false;
  {
    std::vector<Vec2> line;
    for (const ExportWaypoint& w : export_waypoints(mission, loaded.plan)) line.push_back(w.xy);
    if (line.size() >= 2) written.features.push_back(web_map_feature(to.line(line), {{"plan", "as written"}}));
  }
  map.layers.push_back(std::move(written));

  const std::vector<ExportWaypoint> waypoints = export_waypoints(mission, plan);
  WebMapLayer legs =
      web_map_layer("legs", "The plan's legs (mission, evasion, identification)", "#f08c00", "#f08c00", 0.0, 4.0);
  WebMapLayer points =
      web_map_layer("waypoints", "Waypoints (as mission export writes them)", "#212529", "#ffd43b", 1.0, 1.5);
  points.point_radius_px = 4.0;
  map.table.title = "Waypoints";
  map.table.columns = {"name", "lon", "lat", "depth (m)", "speed (m/s)", "hold (s)", "time (s)", "role", "manoeuvre"};
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const ExportWaypoint& w = waypoints[i];
    const json position = web_map_position(w.lonlat.x(), w.lonlat.y());
    if (i > 0) {
      json props{{"leg", i}, {"manoeuvre", w.manoeuvre}, {"role", w.role}};
      props["length (m)"] = rounded(w.along_m - waypoints[i - 1].along_m, 0.01);
      props["depth (m)"] = rounded(w.depth_m, 0.01);
      props["speed (m/s)"] = rounded(w.speed_mps, 0.001);
      legs.features.push_back(web_map_feature(to.line({waypoints[i - 1].xy, w.xy}), std::move(props),
                                              json{{"color", role_colour(w.role)}}));
    }
    json props{{"waypoint", w.name}, {"lon", position[0]}, {"lat", position[1]}};
    props["depth (m)"] = rounded(w.depth_m, 0.01);
    props["speed (m/s)"] = rounded(w.speed_mps, 0.001);
    if (w.hold_s > 0.0) props["hold (s)"] = rounded(w.hold_s, 0.1);
    if (w.radius_m > 0.0) props["turn radius (m)"] = rounded(w.radius_m, 0.01);
    props["along (m)"] = rounded(w.along_m, 0.01);
    props["time (s)"] = rounded(w.time_s, 0.1);
    props["role"] = w.role;
    props["manoeuvre"] = w.manoeuvre;
    points.features.push_back(web_map_feature(to.point(w.xy), std::move(props)));
    map.table.rows.push_back({w.name, position[0], position[1], rounded(w.depth_m, 0.01), rounded(w.speed_mps, 0.001),
                              rounded(w.hold_s, 0.1), rounded(w.time_s, 0.1), w.role, w.manoeuvre});
  }
  map.layers.push_back(std::move(legs));
  map.layers.push_back(std::move(points));
  if (!waypoints.empty()) {  // the frame's grid round the plan
    Vec2 lo = waypoints.front().xy, hi = waypoints.front().xy;
    for (const ExportWaypoint& w : waypoints) lo = lo.cwiseMin(w.xy), hi = hi.cwiseMax(w.xy);
    const Vec2 pad = Vec2::Constant(0.1 * std::max(hi.x() - lo.x(), hi.y() - lo.y()) + 50.0);
    map.layers.push_back(frame_grid_layer(mission.frame, lo - pad, hi + pad));
  }

  WebMapLayer conflicts = web_map_layer("conflicts", "Where conflicts began", "#c92a2a", "#ff6b6b", 1.0, 2.0);
  conflicts.point_radius_px = 6.0;
  for (const Resolution& r : planned.resolutions) {
    json props{{"with", r.conflict.with},
               {"reaction", r.reaction == ControlRules::Reaction::evade ? "evade" : "identify"},
               {"resolved", r.resolved ? "yes" : "no"}};
    props["along (m)"] = rounded(r.conflict.along_m, 0.1);
    props["depth (m)"] = rounded(r.conflict.depth_m, 0.01);
    if (!r.problem.empty()) props["why not"] = r.problem;
    if (!r.note.empty()) props["note"] = r.note;
    conflicts.features.push_back(web_map_feature(to.point(r.conflict.where), std::move(props)));
  }
  map.layers.push_back(std::move(conflicts));

  if (run) {
    WebMapLayer track = web_map_layer("track", "Track sailed (reactive level in cyan)", "#2f9e44", "#2f9e44", 0.0, 2.5);
    for (std::size_t k = 1; k < run->track.size();) {
      // One line per stretch under one level of control.
      const bool reactive = run->track[k].reactive;
      std::vector<Vec2> stretch{run->track[k - 1].position};
      const double from_s = run->track[k - 1].time_s;
      while (k < run->track.size() && run->track[k].reactive == reactive) stretch.push_back(run->track[k++].position);
      json props{{"control", reactive ? "reactive" : "mission"},
                 {"from (s)", rounded(from_s, 0.1)},
                 {"to (s)", rounded(run->track[k - 1].time_s, 0.1)}};
      track.features.push_back(
          web_map_feature(to.line(stretch), std::move(props), reactive ? json{{"color", "#15aabf"}} : json(nullptr)));
    }
    map.layers.push_back(std::move(track));
    WebMapLayer detected = obstacle_web_layer(run->detected, to, "Objects the sonar found", "#1971c2");
    detected.id = "detected";
    map.layers.push_back(std::move(detected));
  }
  return map;
}

}  // namespace deepguide
