// deepguide plan: the work is plan_route_request (planning/route_plan_report.hpp),
// or plan_depth_request with --graph octree (apps/plan_depth.cpp).

#include <cstdio>
#include <iostream>
#include <memory>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/output_paths.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/mission/route_export.hpp"
#include "deepguide/mission/route_plan_export.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/render/canvas.hpp"
#include "deepguide/render/route_plan_figure.hpp"
#include "deepguide/render/route_web_map.hpp"
#include "plan_command.hpp"

namespace deepguide::app {
namespace {

// --crs, else the UTM zone of the obstacles (when there are any), else of the start (--from is lon,lat then).
LocalFrame read_frame_and_ends(PlanCommand& c) {
  ObstacleReadOptions read{c.frame.crs, c.frame.src_crs};
  if (c.frame.crs.empty()) read.fallback_lonlat = parse_lonlat(c.from, "--from");
  LoadedObstacles loaded = load_obstacles(c.obstacles, read);
  c.request.obstacles = std::move(loaded.obstacles);
  const LocalFrame& frame = loaded.frame;
  PlanningProblem& p = c.request.problem;
  p.start = parse_position(c.from, "--from", frame, !c.frame.crs.empty());
  p.goal = parse_position(c.to, "--to", frame, !c.frame.crs.empty());
  if (c.from_heading) p.start_heading = frame.heading_to_local(*c.from_heading, p.start);
  if (c.to_heading) p.goal_heading = frame.heading_to_local(*c.to_heading, p.goal);
  return frame;
}

}  // namespace

void run_plan(PlanCommand& c) {
  RoutePlanRequest& r = c.request;
  r.graph = c.graph.empty() ? default_plan_graph(r.charts, parse_cost_kind(c.cost), r.waypoint_grid_m.has_value(),
                                                 c.from_heading || c.to_heading)
                            : parse_graph_kind(c.graph);
  const bool in_depth = graph_entry(r.graph).can.in_depth;
  check_depth_flags(in_depth, c.depth,
                    c.cost != "length" || !r.current_file.empty() || !c.current_const.empty() || r.waypoint_grid_m ||
                        r.problem.escape || !r.replan_events.empty() || !c.depart.empty() || c.render_graph ||
                        c.from_heading || c.to_heading || !c.out.html.empty());
  if (!c.out.render.empty()) image_format_for(c.out.render);  // before the work, not after
  if (!c.out.html.empty()) check_web_map_path(c.out.html, "--html");
  std::vector<NamedPath> inputs{
      {"--current", r.current_file}, {"--vehicle", r.vehicle}, {"--replan-events", r.replan_events}};
  for (const std::string& f : c.obstacles) inputs.push_back({"--obstacles", f});
  for (const std::string& f : r.charts) inputs.push_back({"--chart", f});
  check_outputs_apart(inputs, {{"-o", c.out.route_file},
                               {"--render", c.out.render},
                               {"--render-profile", c.depth.render_profile},
                               {"--html", c.out.html}});
  if (!c.out.route_file.empty()) route_file_format(c.out.route_file);  // a mission's .yaml is not a route
  r.search = parse_search(c.search);
  r.cost = parse_cost_kind(c.cost);
  r.refine = !c.no_refine;
  r.src_crs = c.frame.src_crs;
  r.route_file = c.out.route_file;
  if (c.obstacles.empty() && r.charts.empty())
    throw CLI::ValidationError("plan", "give --obstacles FILE... or --chart FILE... (or both)");
  const LocalFrame frame = read_frame_and_ends(c);
  if (in_depth) return run_plan_in_depth(frame, r, c.depth, c.out);
  if (!c.current_const.empty()) {
    r.current = std::make_shared<const CurrentField>(parse_constant_current(c.current_const, "--current-const"));
    r.current_source = "--current-const " + c.current_const;
  }
  if (!c.depart.empty()) r.depart_s = parse_utc(c.depart, "--depart");
  const RoutePlanReport report = plan_route_request(frame, r);
  for (const std::string& w : report.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (!c.out.route_file.empty()) write_route_plan(report, c.out.route_file);
  if (!c.out.render.empty()) render_route_plan(report, c.out.render, c.render_graph);
  if (!c.out.html.empty()) write_web_map(route_web_map(report), c.out.html);
  // Written and printed first, then said loudly: a replay where the vehicle is walled in is exit 3.
  if (c.out.json) {
    std::cout << report.to_json().dump(2) << "\n";
  } else {
    std::cout << report.to_text();
    if (!c.out.route_file.empty()) std::cout << report_line("wrote", c.out.route_file);
    if (!c.out.render.empty()) std::cout << report_line("rendered", c.out.render);
    if (!c.out.html.empty()) std::cout << report_line("web map", c.out.html);
  }
  if (const auto why = report.stop_reason()) throw NoRouteError(*why);
}

}  // namespace deepguide::app
