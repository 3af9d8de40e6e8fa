#include "deepguide/simulation/mission_run_report.hpp"

#include <cmath>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/mission_report.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"

namespace deepguide {

MissionRunReport simulate_mission_file(const MissionRunRequest& request) {
  MissionRunReport r;
  r.file = request.mission;
  r.loaded = load_mission(request.mission, request.chart);
  const LoadedMission& l = r.loaded;
  check_outputs_apart(mission_input_files(r.file, l.mission), request.outputs);
  if (request.drawn && l.mission.charts.empty() && l.mission.obstacles.empty()) {
    throw InputError(r.file + ": expected a mission with charts or obstacle files to draw its run over");
  }
  r.planned = plan_mission(l.mission, l.env, l.plan);
  if (auto why = unresolved_conflicts(r.file, l, r.planned)) throw NoRouteError(*why);
  if (auto why = legs_beaten(r.file, l, legs_beaten_by_current(r.planned.plan, l.env.current)))
    throw NoRouteError(*why);
  ObstacleSet unknown;
  if (!request.unknown.empty()) unknown = load_obstacles(request.unknown, {l.mission.frame.id(), ""}).obstacles;
  r.run = run_mission(l.mission, l.env, r.planned.plan, unknown, request.options);
  return r;
}

nlohmann::json MissionRunReport::to_json() const {
  nlohmann::json events = nlohmann::json::array();
  for (const MissionEvent& e : run.events) {
    const Vec2 ll = loaded.mission.frame.to_lonlat(e.where);
    events.push_back({{"time_s", e.time_s}, {"lon", ll.x()}, {"lat", ll.y()}, {"what", e.what}, {"alarm", e.alarm}});
  }
  return {{"mission", loaded.mission.name}, {"completed", run.completed},      {"collided", run.collided},
          {"time_s", run.time_s},           {"length_m", run.length_m},        {"min_clearance_m", run.min_clearance_m},
          {"replans", run.replans},         {"detected", run.detected.size()}, {"events", events}};
}

std::string MissionRunReport::to_text() const {
  std::string t = report_line(
      "mission", printf_text("%s: %s in %s, %.0f m sailed; %zu unknown object(s) found, %zu replan(s)",
                             printable(loaded.mission.name, 120).c_str(), run.completed ? "completed" : "NOT completed",
                             clock_text(run.time_s).c_str(), run.length_m, run.detected.size(), run.replans));
  if (std::isfinite(run.min_clearance_m)) {
    t += report_line("clearance", fixed(run.min_clearance_m, 1) +
                                      " m at least to the footprints of obstacles the vehicle was not above");
  }
  for (const MissionEvent& e : run.events) {
    const Vec2 ll = loaded.mission.frame.to_lonlat(e.where);
    t += printf_text("%8s  %.5f, %.5f  %s%s\n", clock_text(e.time_s).c_str(), ll.x(), ll.y(), e.alarm ? "ALARM: " : "",
                     e.what.c_str());
  }
  return t;
}

std::optional<std::string> MissionRunReport::failure() const {
  for (const MissionEvent& e : run.events) {
    if (!e.alarm) continue;
    const Vec2 ll = loaded.mission.frame.to_lonlat(e.where);
    return file + ": simulation" +
           printf_text(" at %s into the mission, %.5f, %.5f: ", clock_text(e.time_s).c_str(), ll.x(), ll.y()) + e.what;
  }
  return std::nullopt;
}

}  // namespace deepguide
