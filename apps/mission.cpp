// deepguide mission check|plan|export|simulate MISSION.yaml, render mission:
// the work and the reports are library calls (mission/mission_report.hpp,
// simulation/mission_run_report.hpp; docs/MISSIONS.md).

#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/charts/chart_options.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/output_paths.hpp"
#include "deepguide/mission/mission_report.hpp"
#include "deepguide/render/mission_figure.hpp"
#include "deepguide/render/mission_web_map.hpp"
#include "deepguide/render/route_scene.hpp"  // kMinImageWidth, kMaxImageWidth
#include "deepguide/simulation/mission_run_report.hpp"

namespace deepguide::app {
namespace {

struct MissionOptions {
  std::string mission, html;
  bool json = false;
  ChartOptions chart;
};

// Printed first, then said loudly: exit 3 with the report's one-line reason.
template <class Report>
void print_then_fail(const Report& report, bool json) {
  std::cout << (json ? report.to_json().dump(2) + "\n" : report.to_text());
  if (const auto why = report.failure()) throw NoRouteError(*why);
}

}  // namespace

void register_mission_simulate(CLI::App& mission);

void register_mission(CLI::App& app) {
  CLI::App* mission = app.add_subcommand(
      "mission",
      "Mission plans: check (basic manoeuvres and conflicts), plan (conflicts evaded or identified), export (the plan "
      "for the vehicle or ground station), simulate (the two-level guidance)");
  mission->require_subcommand(1);
  auto o = std::make_shared<MissionOptions>();
  CLI::App* check = mission->add_subcommand(
      "check", "Read a mission, expand it into basic manoeuvres and list the obstacles and shoals that endanger them");
  check->add_option("MISSION", o->mission, "Mission file (YAML; docs/MISSIONS.md)")->required();
  check->add_flag("--json", o->json, "Print the result as JSON");
  add_chart_options(*check, o->chart, nullptr);
  check->add_option("--html", o->html,
                    "Also write the mission as written and its conflicts as a web map (one .html file that works "
                    "offline; docs/WEB_MAP.md)");
  check->callback([o] {
    if (!o->html.empty()) {
      check_web_map_path(o->html, "--html");
      check_outputs_apart({{"MISSION", o->mission}}, {{"--html", o->html}});
    }
    const MissionCheckReport report = check_mission_file(o->mission, o->chart);
    if (!o->html.empty()) {
      check_outputs_apart(mission_input_files(o->mission, report.loaded.mission), {{"--html", o->html}});
      write_web_map(mission_web_map(report.loaded, report.planned, nullptr, true), o->html);
    }
    print_then_fail(report, o->json);
  });

  CLI::App* plan = mission->add_subcommand(
      "plan", "Read a mission and resolve every conflict by its rules (evade, or identify), then check the whole plan");
  plan->add_option("MISSION", o->mission, "Mission file (YAML; docs/MISSIONS.md)")->required();
  plan->add_flag("--json", o->json, "Print the result as JSON");
  add_chart_options(*plan, o->chart, nullptr);
  plan->add_option("--html", o->html,
                   "Also write the planned mission as a web map (one .html file that works offline; docs/WEB_MAP.md)");
  plan->callback([o] {
    if (!o->html.empty()) {
      check_web_map_path(o->html, "--html");
      check_outputs_apart({{"MISSION", o->mission}}, {{"--html", o->html}});
    }
    const MissionPlanReport report = plan_mission_file(o->mission, o->chart);
    if (!o->html.empty()) {
      check_outputs_apart(mission_input_files(o->mission, report.loaded.mission), {{"--html", o->html}});
      write_web_map(mission_web_map(report.loaded, report.planned), o->html);
    }
    print_then_fail(report, o->json);
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
  exp->add_option("--format", e->format,
                  "yaml (basic manoeuvres), geojson, gpx, kml, csv, plan (QGroundControl), "
                  "moos (pHelmIvP .bhv), rtz (IEC 61174)");
  exp->add_flag("--overwrite", e->overwrite, "Replace the output file if it exists");
  exp->add_option("--route-name", e->route_name, "RTZ routeName (default: the file's name without extension)");
  exp->add_flag("--as-written", e->as_written, "Export the plan as written, without mission control's changes");
  exp->add_option("--arc-tolerance", e->tolerance, "How far waypoints along arcs may cut inside them (m)")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 100.0));
  add_chart_options(*exp, o->chart, nullptr);
  exp->callback([o, e] {
    MissionExportRequest request{o->mission,    e->output, std::nullopt, {e->tolerance, e->overwrite, e->route_name},
                                 e->as_written, o->chart};
    if (!e->format.empty()) request.format = parse_export_format(e->format);
    const MissionExportReport report = export_mission_file(request);
    for (const std::string& w : report.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    std::cout << report.to_text(e->output);
  });
  register_mission_simulate(*mission);
}

void register_mission_simulate(CLI::App& mission) {
  struct Options {
    std::string mission, render, html;
    std::vector<std::string> unknown;
    std::uint64_t seed = 1;
    double delay = 5.0;
    double zoom = 0.0;
    bool json = false;
    ChartOptions chart;
  };
  auto o = std::make_shared<Options>();
  CLI::App* cmd = mission.add_subcommand(
      "simulate",
      "Sail the planned mission in simulation: the plan level follows it, the sonar finds objects nobody "
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
  cmd->add_option("--html", o->html,
                  "Also write the mission and the track sailed as a web map (one .html file that works offline; "
                  "docs/WEB_MAP.md)");
  cmd->add_flag("--json", o->json, "Print the result as JSON");
  add_chart_options(*cmd, o->chart, nullptr);
  cmd->callback([o] {
    if (!o->html.empty()) check_web_map_path(o->html, "--html");
    MissionRunRequest request{o->mission,         o->unknown, {}, {{"--render", o->render}, {"--html", o->html}},
                              !o->render.empty(), o->chart};
    request.options.seed = o->seed;
    request.options.planning_delay_s = o->delay;
    const MissionRunReport report = simulate_mission_file(request);
    std::cout << (o->json ? report.to_json().dump(2) + "\n" : report.to_text());
    if (!o->render.empty()) {
      const LoadedMission& l = report.loaded;
      render_mission(simulated_mission_figure(l.mission, l.plan, report.planned, report.run, o->zoom), o->render);
    }
    if (!o->html.empty()) write_web_map(mission_web_map(report.loaded, report.planned, &report.run), o->html);
    if (const auto why = report.failure()) throw NoRouteError(*why);
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
      "mission",
      "Draw a mission over its chart: the plan with its evasions and identification laps, the plan as "
      "written, and where conflicts began");
  cmd->add_option("MISSION", o->mission, "Mission file (YAML; docs/MISSIONS.md)")->required();
  cmd->add_option("-o,--output", o->output, "Image to write: .png or .svg")->required();
  cmd->add_option("--width", o->width, "Image width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(kMinImageWidth, kMaxImageWidth));
  cmd->add_option("--title", o->title, "Title line (default: the mission's name, length and time)");
  cmd->add_flag("--as-written", o->as_written, "Draw the plan as written, without mission control's changes");
  cmd->callback([o] {
    render_mission_file(o->mission, o->output, {o->title, o->width, o->as_written});
    std::cout << "wrote " << o->output << "\n";
  });
}

}  // namespace deepguide::app
