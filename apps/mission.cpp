// deepguide mission check|plan MISSION.yaml [--json]: the mission's complex
// manoeuvres as basic ones, what endangers them, and the plan with every
// conflict evaded or identified (docs/MISSIONS.md).

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/output_paths.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/collision_observation.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/mission/mission_environment.hpp"
#include "deepguide/mission/plan_check.hpp"
#include "deepguide/mission/plan_export.hpp"
#include "deepguide/mission/plan_splice.hpp"
#include "deepguide/render/mission_figure.hpp"
#include "deepguide/render/route_scene.hpp"  // kMinImageWidth, kMaxImageWidth
#include "deepguide/simulation/mission_run.hpp"
#include "deepguide/world/obstacle_io.hpp"

namespace deepguide::app {
namespace {

// The files a mission reads: none of them may be an output.
std::vector<NamedPath> mission_inputs(const std::string& file, const Mission& m) {
  std::vector<NamedPath> in{{"MISSION", file}, {"current_file", m.current_file}};
  for (const std::string& f : m.charts) in.push_back({"charts", f});
  for (const std::string& f : m.obstacles) in.push_back({"obstacles", f});
  return in;
}

struct MissionOptions {
  std::string mission;
  bool json = false;
};

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

void print_plan(const LoadedMission& l, const PlannedMission& planned, const MissionPlanCheck& verdict, bool json) {
  const Mission& m = l.mission;
  const auto lonlat = [&](const Vec2& p) { return m.frame.to_lonlat(p); };
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const Resolution& r : planned.resolutions) {
      const Vec2 ll = lonlat(r.conflict.where);
      nlohmann::json j = {{"with", r.conflict.with},       {"reaction", reaction_name(r.reaction)},
                          {"resolved", r.resolved},         {"time_s", r.time_s},
                          {"lon", ll.x()},                  {"lat", ll.y()},
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
      list.push_back(j);
    }
    nlohmann::json j = {{"mission", m.name},
                        {"crs", m.frame.id()},
                        {"basic_manoeuvres", planned.plan.basics.size()},
                        {"length_m", planned.plan.length_m},
                        {"time_s", plan_duration(planned.plan)},
                        {"original_length_m", l.plan.length_m},
                        {"resolutions", list},
                        {"remaining_conflicts", planned.remaining.size()},
                        {"check", {{"safe", verdict.safe}, {"legs", verdict.legs}, {"problem", verdict.problem}}}};
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("mission          %s (%s)\n", printable(m.name, 120).c_str(), m.frame.id().c_str());
  std::printf("plan             %zu basic manoeuvres, %.0f m, %s (before: %zu, %.0f m, %s)\n",
              planned.plan.basics.size(), planned.plan.length_m, clock_text(plan_duration(planned.plan)).c_str(),
              l.plan.basics.size(), l.plan.length_m, clock_text(plan_duration(l.plan)).c_str());
  if (planned.resolutions.empty()) {
    std::printf("conflicts        none: nothing to evade\n");
  } else {
    std::printf("%8s  %-24s %-9s %-9s %9s %9s %8s  %s\n", "time", "with", "reaction", "result", "leave m", "rejoin m",
                "added m", "lon, lat / why");
  }
  for (const Resolution& r : planned.resolutions) {
    const Vec2 ll = lonlat(r.conflict.where);
    if (r.resolved) {
      std::printf("%8s  %-24s %-9s %-9s %9.0f %9.0f %8.0f  %.5f, %.5f (at %.1f m)%s%s\n", clock_text(r.time_s).c_str(),
                  r.conflict.with.substr(0, 24).c_str(), reaction_name(r.reaction), "resolved", r.depart_m,
                  r.rendezvous_m, r.added_m, ll.x(), ll.y(), r.depth_m, r.note.empty() ? "" : "; ", r.note.c_str());
    } else {
      std::printf("%8s  %-24s %-9s %-9s %9s %9s %8s  %.5f, %.5f: %s\n", clock_text(r.time_s).c_str(),
                  r.conflict.with.substr(0, 24).c_str(), reaction_name(r.reaction), "UNSOLVED", "-", "-", "-", ll.x(),
                  ll.y(), r.problem.c_str());
    }
  }
  for (const Conflict& c : planned.remaining) {
    const Vec2 ll = lonlat(c.where);
    std::printf("REMAINING        %s into the mission, %s at %.5f, %.5f, %.1f m deep\n",
                clock_text(position_at(planned.plan, c.along_m).time_s).c_str(), c.with.c_str(), ll.x(), ll.y(), c.depth_m);
  }
  std::printf("check            %s: %zu legs against every obstacle's zone and top and the sea floor",
              verdict.safe ? "safe" : "UNSAFE", verdict.legs);
  if (std::isfinite(verdict.min_floor_gap_m)) std::printf("; least water under the vehicle %.1f m", verdict.min_floor_gap_m);
  std::printf("\n");
}

// Exit 3, loudly, for a conflict mission control could not resolve: the
// first one's time, place and why (every one is in the printed table).
void throw_if_unresolved(const std::string& file, const LoadedMission& l, const PlannedMission& planned) {
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
    char where[160];
    std::snprintf(where, sizeof where, " at %s into the mission, %.5f, %.5f, %.1f m deep",
                  clock_text(position_at(planned.plan, c.along_m).time_s).c_str(), ll.x(), ll.y(), c.depth_m);
    throw NoRouteError(file + ": " + std::to_string(planned.remaining.size()) +
                       " conflict(s) remain in the planned mission; the first, with " + c.with + where);
  }
  if (first == nullptr) return;
  const Vec2 ll = l.mission.frame.to_lonlat(first->conflict.where);
  char where[160];
  std::snprintf(where, sizeof where, " at %s into the mission, %.5f, %.5f, %.1f m deep: ", clock_text(first->time_s).c_str(),
                ll.x(), ll.y(), first->conflict.depth_m);
  throw NoRouteError(file + ": " + std::to_string(unsolved) + " conflict(s) could not be resolved; the first, with " +
                     first->conflict.with + where + first->problem);
}


// Exit 3 for a plan the current beats somewhere: the first leg, and how many.
void throw_if_beaten(const std::string& file, const LoadedMission& l, const std::vector<BeatenLeg>& beaten) {
  if (beaten.empty()) return;
  const BeatenLeg& b = beaten.front();
  const Vec2 ll = l.mission.frame.to_lonlat(b.where);
  char where[200];
  std::snprintf(where, sizeof where, "%.0f m along (%.5f, %.5f)", b.along_m, ll.x(), ll.y());
  throw NoRouteError(file + ": the " + fixed(l.env.current.norm(), 2) + " m/s current beats the vehicle on " +
                     std::to_string(beaten.size()) + " basic manoeuvre(s); the first, in '" +
                     printable(l.mission.manoeuvres[l.plan.basics[b.basic].source].name) + "' " + where + ", at " +
                     fixed(l.plan.basics[b.basic].speed_mps, 2) + " m/s through the water: no heading holds it");
}
}  // namespace

void register_mission_simulate(CLI::App& mission);

void register_mission(CLI::App& app) {
  CLI::App* mission = app.add_subcommand("mission", "Mission plans: check (basic manoeuvres and conflicts), plan (conflicts evaded or identified), export (the plan for the vehicle or ground station), simulate (the two-level guidance)");
  mission->require_subcommand(1);
  auto o = std::make_shared<MissionOptions>();
  CLI::App* check = mission->add_subcommand(
      "check", "Read a mission, expand it into basic manoeuvres and list the obstacles and shoals that endanger them");
  check->add_option("MISSION", o->mission, "Mission file (YAML; docs/MISSIONS.md)")->required();
  check->add_flag("--json", o->json, "Print the result as JSON");
  check->callback([o] {
    const LoadedMission l = load_mission(o->mission);
    const Mission& m = l.mission;
    const MissionEnvironment& env = l.env;
    const MissionPlan& plan = l.plan;
    const ObservationOptions observe = observation_options(m);
    const std::vector<Conflict> conflicts = observe_collisions(plan, env.obstacles, env.floor.get(), observe);
    const double time_s = plan_duration(plan);
    // Whether mission control can resolve each: what it cannot is reported here already.
    const PlannedMission planned = plan_mission(m, env, plan);
    const std::vector<BeatenLeg> beaten = legs_beaten_by_current(plan, env.current);
    std::vector<const Resolution*> unavoidable;
    for (const Resolution& r : planned.resolutions) {
      if (!r.resolved) unavoidable.push_back(&r);
    }
    const auto lonlat = [&](const Vec2& p) { return m.frame.to_lonlat(p); };
    if (o->json) {
      nlohmann::json j = {{"mission", m.name},           {"file", o->mission},
                          {"crs", m.frame.id()},          {"manoeuvres", m.manoeuvres.size()},
                          {"basic_manoeuvres", plan.basics.size()}, {"length_m", plan.length_m},
                          {"time_s", time_s},             {"obstacles", env.obstacles.size()},
                          {"sea_floor", env.floor != nullptr}, {"warnings", plan.warnings}};
      nlohmann::json list = nlohmann::json::array();
      for (const Conflict& c : conflicts) {
        const Vec2 ll = lonlat(c.where);
        list.push_back({{"along_m", c.along_m},
                        {"manoeuvre", m.manoeuvres[plan.basics[c.basic].source].name},
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
      for (const Resolution* r : unavoidable) {
        const Vec2 ll = lonlat(r->conflict.where);
        cannot.push_back({{"with", r->conflict.with}, {"time_s", r->time_s}, {"lon", ll.x()}, {"lat", ll.y()},
                          {"depth_m", r->conflict.depth_m}, {"problem", r->problem}});
      }
      j["unavoidable"] = cannot;
      nlohmann::json against = nlohmann::json::array();
      for (const BeatenLeg& b : beaten) {
        const Vec2 ll = lonlat(b.where);
        against.push_back({{"basic", b.basic}, {"manoeuvre", m.manoeuvres[plan.basics[b.basic].source].name},
                           {"along_m", b.along_m}, {"lon", ll.x()}, {"lat", ll.y()}});
      }
      j["beaten_by_current"] = against;
      std::cout << j.dump(2) << "\n";
      throw_if_unresolved(o->mission, l, planned);
      throw_if_beaten(o->mission, l, beaten);
      return;
    }
    std::printf("mission          %s (%s, %s)\n", printable(m.name, 120).c_str(), printable(o->mission, 240).c_str(),
                m.frame.id().c_str());
    std::printf("manoeuvres       %zu complex, %zu basic; %.0f m, %.0f s (%.1f h) at their speeds and holds\n",
                m.manoeuvres.size(), plan.basics.size(), plan.length_m, time_s, time_s / 3600.0);
    std::printf("environment      %zu obstacle(s), %s\n", env.obstacles.size(),
                env.floor ? "a sea floor from the chart" : "no sea floor (no bathymetry chart)");
    for (const std::string& w : plan.warnings) std::printf("warning          %s\n", w.c_str());
    std::printf("%4s %-40s %6s %10s %9s\n", "#", "manoeuvre", "basics", "from m", "length m");
    for (std::size_t i = 0; i < m.manoeuvres.size(); ++i) {
      std::size_t count = 0;
      double from = -1.0, length = 0.0;
      for (const BasicManoeuvre& b : plan.basics) {
        if (b.source != i) continue;
        if (count++ == 0) from = b.start_m;
        length += b.length_m;
      }
      std::printf("%4zu %-40s %6zu %10.0f %9.0f\n", i + 1, (m.manoeuvres[i].type + " '" + printable(m.manoeuvres[i].name) + "'").substr(0, 40).c_str(),
                  count, from, length);
    }
    if (!m.current_file.empty()) {
      std::printf("current          %s: not checked against the vehicle's speed (a constant current is)\n",
                  printable(m.current_file).c_str());
    }
    for (const BeatenLeg& b : beaten) {
      if (&b - beaten.data() == 10) {
        std::printf("CURRENT          ... and %zu more basic manoeuvre(s) (--json lists them all)\n", beaten.size() - 10);
        break;
      }
      const Vec2 ll = lonlat(b.where);
      std::printf("CURRENT          %.0f m along, %s (basic %zu) at %.5f, %.5f: the %.2f m/s current beats the vehicle's "
                  "%.2f m/s; no heading holds it\n",
                  b.along_m, printable(m.manoeuvres[plan.basics[b.basic].source].name).c_str(), b.basic, ll.x(), ll.y(),
                  env.current.norm(), plan.basics[b.basic].speed_mps);
    }
    if (conflicts.empty()) {
      std::printf("conflicts        none: no obstacle or shoal endangers the plan\n");
      throw_if_beaten(o->mission, l, beaten);
      return;
    }
    std::printf("conflicts        %zu (corridor %.1f m = margin + half the width; %.1f m over tops and the floor)\n",
                conflicts.size(), m.margin_m + observe.half_width_m, m.vertical_clearance_m);
    std::printf("%9s %8s  %-28s %-10s %-24s %7s  %s\n", "along m", "time", "manoeuvre", "basic", "with", "depth m",
                "lon, lat");
    for (const Conflict& c : conflicts) {
      const Vec2 ll = lonlat(c.where);
      const BasicManoeuvre& b = plan.basics[c.basic];
      const std::string basics = c.last_basic > c.basic ? std::to_string(c.last_basic - c.basic + 1) + " basics"
                                                        : std::string(kind_name(b.kind));
      std::printf("%9.0f %8s  %-28s %-10s %-24s %7.1f  %.5f, %.5f\n", c.along_m,
                  clock_text(position_at(plan, c.along_m).time_s).c_str(),
                  printable(m.manoeuvres[b.source].name, 28).c_str(), basics.c_str(), printable(c.with, 24).c_str(),
                  c.depth_m, ll.x(), ll.y());
    }
    for (const Resolution* r : unavoidable) {
      const Vec2 ll = lonlat(r->conflict.where);
      std::printf("UNAVOIDABLE      %s into the mission, %s at %.5f, %.5f, %.1f m deep: %s\n", clock_text(r->time_s).c_str(),
                  r->conflict.with.c_str(), ll.x(), ll.y(), r->conflict.depth_m, r->problem.c_str());
    }
    throw_if_unresolved(o->mission, l, planned);
    throw_if_beaten(o->mission, l, beaten);
  });

  CLI::App* plan = mission->add_subcommand(
      "plan", "Read a mission and resolve every conflict by its rules (evade, or identify), then check the whole plan");
  plan->add_option("MISSION", o->mission, "Mission file (YAML; docs/MISSIONS.md)")->required();
  plan->add_flag("--json", o->json, "Print the result as JSON");
  plan->callback([o] {
    const LoadedMission l = load_mission(o->mission);
    const PlannedMission planned = plan_mission(l.mission, l.env, l.plan);
    const MissionPlanCheck verdict = check_mission_plan(planned.plan, l.env, observation_options(l.mission));
    print_plan(l, planned, verdict, o->json);
    throw_if_unresolved(o->mission, l, planned);
    if (!verdict.safe) {
      const Vec2 ll = l.mission.frame.to_lonlat(verdict.where.head<2>());
      char where[160];
      std::snprintf(where, sizeof where, " %.0f m along, %.5f, %.5f, %.1f m deep: ", verdict.along_m, ll.x(), ll.y(),
                    verdict.where.z());
      throw NoRouteError(o->mission + ": the planned mission fails the plan checker" + where + verdict.problem);
    }
  });

  struct ExportCli {
    std::string output, format, route_name;
    bool overwrite = false, as_written = false;
    double tolerance = 0.5;
  };
  auto e = std::make_shared<ExportCli>();
  CLI::App* exp = mission->add_subcommand(
      "export", "Plan a mission (every conflict resolved and checked) and write it for the vehicle or ground station");
  exp->add_option("MISSION", o->mission, "Mission file (YAML; docs/MISSIONS.md)")->required();
  exp->add_option("-o,--output", e->output, "File to write; its extension picks the format unless --format is given")
      ->required();
  exp->add_option("--format", e->format, "yaml (basic manoeuvres), geojson, gpx, kml, csv, plan (QGroundControl), "
                                         "moos (pHelmIvP .bhv), rtz (IEC 61174)");
  exp->add_flag("--overwrite", e->overwrite, "Replace the output file if it exists");
  exp->add_option("--route-name", e->route_name, "RTZ routeName (default: the file's name without extension)");
  exp->add_flag("--as-written", e->as_written, "Export the plan as written, without mission control's changes");
  exp->add_option("--arc-tolerance", e->tolerance, "How far waypoints along arcs may cut inside them (m)")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 100.0));
  exp->callback([o, e] {
    const ExportFormat format = e->format.empty() ? export_format_for(e->output) : parse_export_format(e->format);
    const LoadedMission l = load_mission(o->mission);
    check_outputs_apart(mission_inputs(o->mission, l.mission), {{"-o", e->output}});
    const PlannedMission planned = plan_mission(l.mission, l.env, l.plan);
    if (!e->as_written) {
      throw_if_unresolved(o->mission, l, planned);
      const MissionPlanCheck verdict = check_mission_plan(planned.plan, l.env, observation_options(l.mission));
      if (!verdict.safe) throw NoRouteError(o->mission + ": the planned mission fails the plan checker: " + verdict.problem);
    } else {
      if (!planned.resolutions.empty()) {
        std::fprintf(stderr, "warning: exporting the plan as written with %zu conflict(s) unresolved\n",
                     planned.resolutions.size());
      }
      if (const std::size_t n = legs_beaten_by_current(l.plan, l.env.current).size(); n > 0) {
        std::fprintf(stderr, "warning: exporting the plan as written; the current beats the vehicle on %zu basic "
                     "manoeuvre(s)\n", n);
      }
    }
    const MissionPlan& plan = e->as_written ? l.plan : planned.plan;
    export_plan(l.mission, plan, e->output, format, {e->tolerance, e->overwrite, e->route_name});
    const std::size_t waypoints =
        export_route(l.mission, plan, e->tolerance, format == ExportFormat::rtz).waypoints.size();
    std::printf("wrote %s (%s): %zu basic manoeuvres, %zu waypoints, %.0f m\n", e->output.c_str(),
                to_string(format).c_str(), plan.basics.size(), waypoints, plan.length_m);
  });
  register_mission_simulate(*mission);
}

void register_mission_simulate(CLI::App& mission) {
  struct Options {
    std::string mission, render;
    std::vector<std::string> unknown;
    std::uint64_t seed = 1;
    double delay = 5.0;
    double zoom = 0.0;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = mission.add_subcommand(
      "simulate", "Sail the planned mission in simulation: the plan level follows it, the sonar finds objects nobody "
                  "knew, the reactive level evades them while the route is repaired (the seed's Fig. 4)");
  cmd->add_option("MISSION", o->mission, "Mission file (YAML; docs/MISSIONS.md)")->required();
  cmd->add_option("--unknown", o->unknown, "Obstacle files of objects nobody knew (the simulation's truth only)");
  cmd->add_option("--seed", o->seed, "The sonar's noise")->capture_default_str();
  cmd->add_option("--planning-delay", o->delay, "Seconds the evasion planner takes on the vehicle")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 600.0));
  cmd->add_option("--render", o->render, "Also draw the mission and the track sailed (.png or .svg)");
  cmd->add_option("--zoom", o->zoom, "With --render: show only this many metres around the first object found")
      ->check(CLI::Range(10.0, 1e5));
  cmd->add_flag("--json", o->json, "Print the result as JSON");
  cmd->callback([o] {
    const LoadedMission l = load_mission(o->mission);
    check_outputs_apart(mission_inputs(o->mission, l.mission), {{"--render", o->render}});
    if (!o->render.empty() && l.mission.charts.empty() && l.mission.obstacles.empty()) {
      throw InputError("--render: expected a mission with charts or obstacle files to draw it over");
    }
    const PlannedMission planned = plan_mission(l.mission, l.env, l.plan);
    throw_if_unresolved(o->mission, l, planned);
    throw_if_beaten(o->mission, l, legs_beaten_by_current(planned.plan, l.env.current));
    ObstacleSet unknown;
    if (!o->unknown.empty()) unknown = load_obstacles(o->unknown, {l.mission.frame.id(), ""}).obstacles;
    MissionRunOptions options;
    options.seed = o->seed;
    options.planning_delay_s = o->delay;
    const MissionRun run = run_mission(l.mission, l.env, planned.plan, unknown, options);
    const auto lonlat = [&](const Vec2& p) { return l.mission.frame.to_lonlat(p); };
    if (o->json) {
      nlohmann::json events = nlohmann::json::array();
      for (const MissionEvent& e : run.events) {
        const Vec2 ll = lonlat(e.where);
        events.push_back({{"time_s", e.time_s}, {"lon", ll.x()}, {"lat", ll.y()}, {"what", e.what}, {"alarm", e.alarm}});
      }
      const nlohmann::json j = {{"mission", l.mission.name},   {"completed", run.completed},
                                {"collided", run.collided},    {"time_s", run.time_s},
                                {"length_m", run.length_m},    {"min_clearance_m", run.min_clearance_m},
                                {"replans", run.replans},      {"detected", run.detected.size()},
                                {"events", events}};
      std::cout << j.dump(2) << "\n";
    } else {
      std::printf("mission          %s: %s in %s, %.0f m sailed; %zu unknown object(s) found, %zu replan(s)\n",
                  printable(l.mission.name, 120).c_str(), run.completed ? "completed" : "NOT completed",
                  clock_text(run.time_s).c_str(),
                  run.length_m, run.detected.size(), run.replans);
      if (std::isfinite(run.min_clearance_m)) {
        std::printf("clearance        %.1f m at least to the footprints of obstacles the vehicle was not above\n", run.min_clearance_m);
      }
      for (const MissionEvent& e : run.events) {
        const Vec2 ll = lonlat(e.where);
        std::printf("%8s  %.5f, %.5f  %s%s\n", clock_text(e.time_s).c_str(), ll.x(), ll.y(), e.alarm ? "ALARM: " : "",
                    e.what.c_str());
      }
    }
    if (!o->render.empty()) {
      render_mission(simulated_mission_figure(l.mission, l.plan, planned, run, o->zoom), o->render);
    }
    for (const MissionEvent& e : run.events) {
      if (!e.alarm) continue;
      const Vec2 ll = lonlat(e.where);
      char where[128];
      std::snprintf(where, sizeof where, " at %s into the mission, %.5f, %.5f: ", clock_text(e.time_s).c_str(), ll.x(), ll.y());
      throw NoRouteError(o->mission + ": simulation" + where + e.what);
    }
  });
}

void register_render_mission(CLI::App& render) {
  struct Options {
    std::string mission, output, title;
    int width = 1200;
    bool as_written = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = render.add_subcommand(
      "mission", "Draw a mission over its chart: the plan with its evasions and identification laps, the plan as "
                 "written, and where conflicts began");
  cmd->add_option("MISSION", o->mission, "Mission file (YAML; docs/MISSIONS.md)")->required();
  cmd->add_option("-o,--output", o->output, "Image to write: .png or .svg")->required();
  cmd->add_option("--width", o->width, "Image width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(kMinImageWidth, kMaxImageWidth));
  cmd->add_option("--title", o->title, "Title line (default: the mission's name, length and time)");
  cmd->add_flag("--as-written", o->as_written, "Draw the plan as written, without mission control's changes");
  cmd->callback([o] {
    const LoadedMission l = load_mission(o->mission);
    const PlannedMission planned = plan_mission(l.mission, l.env, l.plan);
    MissionFigure f = mission_figure_for(l.mission, l.plan, planned);
    if (o->as_written) {
      f.plan = &l.plan;
      f.written = nullptr;
    }
    f.width_px = o->width;
    const MissionPlan& shown = *f.plan;
    char title[256];
    std::snprintf(title, sizeof title, "%s: %.2f km, %s; %zu conflict(s), %zu resolved", printable(l.mission.name, 120).c_str(),
                  shown.length_m / 1000.0, clock_text(plan_duration(shown)).c_str(), planned.resolutions.size(),
                  planned.resolutions.size() - f.unresolved.size());
    f.title = o->title.empty() ? std::string(title) : o->title;
    render_mission(f, o->output);
    std::printf("wrote %s\n", o->output.c_str());
  });
}

}  // namespace deepguide::app
