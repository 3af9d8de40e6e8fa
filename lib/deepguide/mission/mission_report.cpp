#include "deepguide/mission/mission_report.hpp"

#include <cmath>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/plan_export.hpp"
#include "deepguide/mission/plan_splice.hpp"

namespace deepguide {
namespace {

const char* kind_name(BasicManoeuvre::Kind kind) {
  switch (kind) {
    case BasicManoeuvre::Kind::line: return "line";
    case BasicManoeuvre::Kind::arc: return "arc";
    case BasicManoeuvre::Kind::point: return "point";
  }
  return "?";
}

const char* reaction_name(ControlRules::Reaction r) {
  return r == ControlRules::Reaction::identify ? "identify" : "evade";
}

const std::string& manoeuvre_name(const LoadedMission& l, std::size_t basic) {
  return l.mission.manoeuvres[l.plan.basics[basic].source].name;
}

nlohmann::json resolution_json(const Resolution& r, const Vec2& ll) {
  nlohmann::json j = {{"with", r.conflict.with},
                      {"reaction", reaction_name(r.reaction)},
                      {"resolved", r.resolved},
                      {"time_s", r.time_s},
                      {"lon", ll.x()},
                      {"lat", ll.y()},
                      {"depth_m", r.conflict.depth_m}};
  if (!r.note.empty()) j["note"] = r.note;
  if (r.resolved) {
    j["depart_m"] = r.depart_m;
    j["rendezvous_m"] = r.rendezvous_m;
    j["evasion_depth_m"] = r.depth_m;
    j["added_m"] = r.added_m;
  } else {
    j["problem"] = r.problem;
  }
  return j;
}

}  // namespace

std::vector<NamedPath> mission_input_files(const std::string& file, const Mission& m) {
  std::vector<NamedPath> in{{"MISSION", file}, {"current_file", m.current_file}};
  for (const std::string& f : m.charts) in.push_back({"charts", f});
  for (const std::string& f : m.obstacles) in.push_back({"obstacles", f});
  return in;
}

std::optional<std::string> unresolved_conflicts(const std::string& file, const LoadedMission& l,
                                                const PlannedMission& planned) {
  std::size_t unsolved = 0;
  const Resolution* first = nullptr;
  for (const Resolution& r : planned.resolutions) {
    if (r.resolved) continue;
    if (unsolved++ == 0) first = &r;
  }
  if (first == nullptr && !planned.remaining.empty()) {
    // Every conflict was dealt with, yet observation still finds one: never let that pass quietly.
    const Conflict& c = planned.remaining.front();
    const Vec2 ll = l.mission.frame.to_lonlat(c.where);
    return file + ": " + std::to_string(planned.remaining.size()) +
           " conflict(s) remain in the planned mission; the first, with " + c.with +
           printf_text(" at %s into the mission, %.5f, %.5f, %.1f m deep",
                       clock_text(position_at(planned.plan, c.along_m).time_s).c_str(), ll.x(), ll.y(), c.depth_m);
  }
  if (first == nullptr) return std::nullopt;
  const Vec2 ll = l.mission.frame.to_lonlat(first->conflict.where);
  return file + ": " + std::to_string(unsolved) + " conflict(s) could not be resolved; the first, with " +
         first->conflict.with +
         printf_text(" at %s into the mission, %.5f, %.5f, %.1f m deep: ", clock_text(first->time_s).c_str(), ll.x(),
                     ll.y(), first->conflict.depth_m) +
         first->problem;
}

std::optional<std::string> legs_beaten(const std::string& file, const LoadedMission& l,
                                       const std::vector<BeatenLeg>& beaten) {
  if (beaten.empty()) return std::nullopt;
  const BeatenLeg& b = beaten.front();
  const Vec2 ll = l.mission.frame.to_lonlat(b.where);
  return file + ": the " + fixed(l.env.current.norm(), 2) + " m/s current beats the vehicle on " +
         std::to_string(beaten.size()) + " basic manoeuvre(s); the first, in '" +
         printable(manoeuvre_name(l, b.basic)) + "' " +
         printf_text("%.0f m along (%.5f, %.5f)", b.along_m, ll.x(), ll.y()) + ", at " +
         fixed(l.plan.basics[b.basic].speed_mps, 2) + " m/s through the water: no heading holds it";
}

// ---- mission check

MissionCheckReport check_mission_file(const std::string& path, const ChartOptions& chart) {
  MissionCheckReport r;
  r.file = path;
  r.loaded = load_mission(path, chart);
  const LoadedMission& l = r.loaded;
  r.observe = observation_options(l.mission);
  r.conflicts = observe_collisions(l.plan, l.env.obstacles, l.env.floor.get(), r.observe);
  // Whether mission control can resolve each: what it cannot is reported here already.
  r.planned = plan_mission(l.mission, l.env, l.plan);
  r.beaten = legs_beaten_by_current(l.plan, l.env.current);
  r.chart_quality = phase_quality(l.mission, l.plan, chart);
  return r;
}

std::optional<std::string> MissionCheckReport::failure() const {
  if (auto why = unresolved_conflicts(file, loaded, planned)) return why;
  return legs_beaten(file, loaded, beaten);
}

nlohmann::json MissionCheckReport::to_json() const {
  const Mission& m = loaded.mission;
  const MissionPlan& plan = loaded.plan;
  nlohmann::json j = {{"mission", m.name},
                      {"file", file},
                      {"crs", m.frame.id()},
                      {"manoeuvres", m.manoeuvres.size()},
                      {"basic_manoeuvres", plan.basics.size()},
                      {"length_m", plan.length_m},
                      {"time_s", plan_duration(plan)},
                      {"obstacles", loaded.env.obstacles.size()},
                      {"sea_floor", loaded.env.floor != nullptr},
                      {"warnings", plan.warnings}};
  nlohmann::json list = nlohmann::json::array();
  for (const Conflict& c : conflicts) {
    const Vec2 ll = m.frame.to_lonlat(c.where);
    list.push_back({{"along_m", c.along_m},
                    {"manoeuvre", manoeuvre_name(loaded, c.basic)},
                    {"basic", c.basic},
                    {"basics", c.last_basic - c.basic + 1},
                    {"kind", kind_name(plan.basics[c.basic].kind)},
                    {"with", c.with},
                    {"time_s", position_at(plan, c.along_m).time_s},
                    {"depth_m", c.depth_m},
                    {"lon", ll.x()},
                    {"lat", ll.y()}});
  }
  j["conflicts"] = list;
  nlohmann::json cannot = nlohmann::json::array();
  for (const Resolution& r : planned.resolutions) {
    if (r.resolved) continue;
    const Vec2 ll = m.frame.to_lonlat(r.conflict.where);
    cannot.push_back({{"with", r.conflict.with},
                      {"time_s", r.time_s},
                      {"lon", ll.x()},
                      {"lat", ll.y()},
                      {"depth_m", r.conflict.depth_m},
                      {"problem", r.problem}});
  }
  j["unavoidable"] = cannot;
  nlohmann::json against = nlohmann::json::array();
  for (const BeatenLeg& b : beaten) {
    const Vec2 ll = m.frame.to_lonlat(b.where);
    against.push_back({{"basic", b.basic},
                       {"manoeuvre", manoeuvre_name(loaded, b.basic)},
                       {"along_m", b.along_m},
                       {"lon", ll.x()},
                       {"lat", ll.y()}});
  }
  j["beaten_by_current"] = against;
  if (!chart_quality.empty()) j["chart_quality"] = phase_quality_json(chart_quality, m.frame);
  return j;
}

std::string MissionCheckReport::to_text() const {
  const Mission& m = loaded.mission;
  const MissionPlan& plan = loaded.plan;
  const MissionEnvironment& env = loaded.env;
  const double time_s = plan_duration(plan);
  std::string t =
      report_line("mission", printable(m.name, 120) + " (" + printable(file, 240) + ", " + m.frame.id() + ")");
  t += report_line("manoeuvres",
                   printf_text("%zu complex, %zu basic; %.0f m, %.0f s (%.1f h) at their speeds and holds",
                               m.manoeuvres.size(), plan.basics.size(), plan.length_m, time_s, time_s / 3600.0));
  t +=
      report_line("environment", std::to_string(env.obstacles.size()) + " obstacle(s), " +
                                     (env.floor ? "a sea floor from the chart" : "no sea floor (no bathymetry chart)"));
  for (const std::string& w : plan.warnings) t += report_line("warning", w);
  t += printf_text("%4s %-40s %6s %10s %9s\n", "#", "manoeuvre", "basics", "from m", "length m");
  for (std::size_t i = 0; i < m.manoeuvres.size(); ++i) {
    std::size_t count = 0;
    double from = -1.0, length = 0.0;
    for (const BasicManoeuvre& b : plan.basics) {
      if (b.source != i) continue;
      if (count++ == 0) from = b.start_m;
      length += b.length_m;
    }
    const std::string name = (m.manoeuvres[i].type + " '" + printable(m.manoeuvres[i].name) + "'").substr(0, 40);
    t += printf_text("%4zu %-40s %6zu %10.0f %9.0f\n", i + 1, name.c_str(), count, from, length);
  }
  t += phase_quality_text(chart_quality, m.frame);
  if (!m.current_file.empty()) {
    t += report_line("current", printable(m.current_file) +
                                    ": not checked against the vehicle's speed (a constant "
                                    "current is)");
  }
  for (const BeatenLeg& b : beaten) {
    if (&b - beaten.data() == 10) {
      t += report_line("CURRENT", "... and " + std::to_string(beaten.size() - 10) +
                                      " more basic manoeuvre(s) (the JSON report lists them all)");
      break;
    }
    const Vec2 ll = m.frame.to_lonlat(b.where);
    t += report_line("CURRENT", printf_text("%.0f m along, %s (basic %zu) at %.5f, %.5f: the %.2f m/s current beats "
                                            "the vehicle's %.2f m/s; no heading holds it",
                                            b.along_m, printable(manoeuvre_name(loaded, b.basic)).c_str(), b.basic,
                                            ll.x(), ll.y(), env.current.norm(), plan.basics[b.basic].speed_mps));
  }
  if (conflicts.empty()) return t + report_line("conflicts", "none: no obstacle or shoal endangers the plan");
  t += report_line("conflicts",
                   printf_text("%zu (corridor %.1f m = margin + half the width; %.1f m over tops and the "
                               "floor)",
                               conflicts.size(), m.margin_m + observe.half_width_m, m.vertical_clearance_m));
  t += printf_text("%9s %8s  %-28s %-10s %-24s %7s  %s\n", "along m", "time", "manoeuvre", "basic", "with", "depth m",
                   "lon, lat");
  for (const Conflict& c : conflicts) {
    const Vec2 ll = m.frame.to_lonlat(c.where);
    const BasicManoeuvre& b = plan.basics[c.basic];
    const std::string basics = c.last_basic > c.basic ? std::to_string(c.last_basic - c.basic + 1) + " basics"
                                                      : std::string(kind_name(b.kind));
    t += printf_text("%9.0f %8s  %-28s %-10s %-24s %7.1f  %.5f, %.5f\n", c.along_m,
                     clock_text(position_at(plan, c.along_m).time_s).c_str(),
                     printable(m.manoeuvres[b.source].name, 28).c_str(), basics.c_str(), printable(c.with, 24).c_str(),
                     c.depth_m, ll.x(), ll.y());
  }
  for (const Resolution& r : planned.resolutions) {
    if (r.resolved) continue;
    const Vec2 ll = m.frame.to_lonlat(r.conflict.where);
    t += report_line("UNAVOIDABLE",
                     printf_text("%s into the mission, %s at %.5f, %.5f, %.1f m deep: %s", clock_text(r.time_s).c_str(),
                                 r.conflict.with.c_str(), ll.x(), ll.y(), r.conflict.depth_m, r.problem.c_str()));
  }
  return t;
}

// ---- mission plan

MissionPlanReport plan_mission_file(const std::string& path, const ChartOptions& chart) {
  MissionPlanReport r;
  r.file = path;
  r.loaded = load_mission(path, chart);
  r.planned = plan_mission(r.loaded.mission, r.loaded.env, r.loaded.plan);
  r.verdict = check_mission_plan(r.planned.plan, r.loaded.env, observation_options(r.loaded.mission));
  r.chart_quality = phase_quality(r.loaded.mission, r.planned.plan, chart);
  return r;
}

std::optional<std::string> MissionPlanReport::failure() const {
  if (auto why = unresolved_conflicts(file, loaded, planned)) return why;
  if (verdict.safe) return std::nullopt;
  const Vec2 ll = loaded.mission.frame.to_lonlat(verdict.where.head<2>());
  return file + ": the planned mission fails the plan checker" +
         printf_text(" %.0f m along, %.5f, %.5f, %.1f m deep: ", verdict.along_m, ll.x(), ll.y(), verdict.where.z()) +
         verdict.problem;
}

nlohmann::json MissionPlanReport::to_json() const {
  const Mission& m = loaded.mission;
  nlohmann::json list = nlohmann::json::array();
  for (const Resolution& r : planned.resolutions)
    list.push_back(resolution_json(r, m.frame.to_lonlat(r.conflict.where)));
  nlohmann::json j = {{"mission", m.name},
                      {"crs", m.frame.id()},
                      {"basic_manoeuvres", planned.plan.basics.size()},
                      {"length_m", planned.plan.length_m},
                      {"time_s", plan_duration(planned.plan)},
                      {"original_length_m", loaded.plan.length_m},
                      {"resolutions", list},
                      {"remaining_conflicts", planned.remaining.size()},
                      {"check", {{"safe", verdict.safe}, {"legs", verdict.legs}, {"problem", verdict.problem}}}};
  if (!chart_quality.empty()) j["chart_quality"] = phase_quality_json(chart_quality, m.frame);
  return j;
}

std::string MissionPlanReport::to_text() const {
  const Mission& m = loaded.mission;
  const MissionPlan& plan = planned.plan;
  std::string t = report_line("mission", printable(m.name, 120) + " (" + m.frame.id() + ")");
  t +=
      report_line("plan", printf_text("%zu basic manoeuvres, %.0f m, %s (before: %zu, %.0f m, %s)", plan.basics.size(),
                                      plan.length_m, clock_text(plan_duration(plan)).c_str(), loaded.plan.basics.size(),
                                      loaded.plan.length_m, clock_text(plan_duration(loaded.plan)).c_str()));
  if (planned.resolutions.empty()) {
    t += report_line("conflicts", "none: nothing to evade");
  } else {
    t += printf_text("%8s  %-24s %-9s %-9s %9s %9s %8s  %s\n", "time", "with", "reaction", "result", "leave m",
                     "rejoin m", "added m", "lon, lat / why");
  }
  for (const Resolution& r : planned.resolutions) {
    const Vec2 ll = m.frame.to_lonlat(r.conflict.where);
    const std::string with = r.conflict.with.substr(0, 24);
    if (r.resolved) {
      t +=
          printf_text("%8s  %-24s %-9s %-9s %9.0f %9.0f %8.0f  %.5f, %.5f (at %.1f m)%s%s\n",
                      clock_text(r.time_s).c_str(), with.c_str(), reaction_name(r.reaction), "resolved", r.depart_m,
                      r.rendezvous_m, r.added_m, ll.x(), ll.y(), r.depth_m, r.note.empty() ? "" : "; ", r.note.c_str());
    } else {
      t += printf_text("%8s  %-24s %-9s %-9s %9s %9s %8s  %.5f, %.5f: %s\n", clock_text(r.time_s).c_str(), with.c_str(),
                       reaction_name(r.reaction), "UNSOLVED", "-", "-", "-", ll.x(), ll.y(), r.problem.c_str());
    }
  }
  for (const Conflict& c : planned.remaining) {
    const Vec2 ll = m.frame.to_lonlat(c.where);
    t += report_line("REMAINING", printf_text("%s into the mission, %s at %.5f, %.5f, %.1f m deep",
                                              clock_text(position_at(plan, c.along_m).time_s).c_str(), c.with.c_str(),
                                              ll.x(), ll.y(), c.depth_m));
  }
  std::string check = printf_text("%s: %zu legs against every obstacle's zone and top and the sea floor",
                                  verdict.safe ? "safe" : "UNSAFE", verdict.legs);
  if (std::isfinite(verdict.min_floor_gap_m))
    check += printf_text("; least water under the vehicle %.1f m", verdict.min_floor_gap_m);
  return t + report_line("check", check) + phase_quality_text(chart_quality, m.frame);
}

// ---- mission export

MissionExportReport export_mission_file(const MissionExportRequest& request) {
  MissionExportReport report;
  report.format = request.format ? *request.format : export_format_for(request.output);
  const LoadedMission l = load_mission(request.mission, request.chart);
  check_outputs_apart(mission_input_files(request.mission, l.mission), {{"-o", request.output}});
  const PlannedMission planned = plan_mission(l.mission, l.env, l.plan);
  if (!request.as_written) {
    if (auto why = unresolved_conflicts(request.mission, l, planned)) throw NoRouteError(*why);
    const MissionPlanCheck verdict = check_mission_plan(planned.plan, l.env, observation_options(l.mission));
    if (!verdict.safe)
      throw NoRouteError(request.mission + ": the planned mission fails the plan checker: " + verdict.problem);
  } else {
    if (!planned.resolutions.empty()) {
      report.warnings.push_back("exporting the plan as written with " + std::to_string(planned.resolutions.size()) +
                                " conflict(s) unresolved");
    }
    if (const std::size_t n = legs_beaten_by_current(l.plan, l.env.current).size(); n > 0) {
      report.warnings.push_back("exporting the plan as written; the current beats the vehicle on " + std::to_string(n) +
                                " basic manoeuvre(s)");
    }
  }
  const MissionPlan& plan = request.as_written ? l.plan : planned.plan;
  export_plan(l.mission, plan, request.output, report.format, request.options);
  report.basic_manoeuvres = plan.basics.size();
  report.waypoints = export_route(l.mission, plan, request.options.arc_tolerance_m, report.format == ExportFormat::rtz)
                         .waypoints.size();
  report.length_m = plan.length_m;
  return report;
}

std::string MissionExportReport::to_text(const std::string& output) const {
  return printf_text("wrote %s (%s): %zu basic manoeuvres, %zu waypoints, %.0f m\n", output.c_str(),
                     to_string(format).c_str(), basic_manoeuvres, waypoints, length_m);
}

}  // namespace deepguide
