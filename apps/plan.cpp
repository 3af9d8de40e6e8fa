// deepguide plan --obstacles FILE... --from X,Y --to X,Y [--cost length|time|energy]
//                [--current FILE | --current-const SPEED,DIR] [...] -o ROUTE.geojson|gpx|kml|rtz|csv|plan|bhv [--json]
// The flags; apps/plan_run.cpp runs the command.

#include <memory>

#include "deepguide/planning/graph_registry.hpp"
#include "plan_command.hpp"

namespace deepguide::app {

void register_plan(CLI::App& app) {
  auto c = std::make_shared<PlanCommand>();
  RoutePlanRequest& r = c->request;
  CLI::App* cmd = app.add_subcommand("plan", "Plan a safe shortest route around the obstacles");
  cmd->add_option("--obstacles", c->obstacles, "Obstacle files (GeoJSON, GeoPackage, Shapefile, CSV, ...)")
      ->expected(1, -1);
  cmd->add_option("--chart", r.charts,
                  "Charts: bathymetry rasters (no-go at --depth), S-57 cells, hazard files (GeoPackage, ...)")
      ->expected(1, -1);
  cmd->add_option("--from", c->from, "Start: lon,lat, or x,y in the --crs frame")->required();
  cmd->add_option("--to", c->to, "Goal: lon,lat, or x,y in the --crs frame")->required();
  cmd->add_option("-o,--output", c->out.route_file,
                  "Route file to write; its extension picks the format: .geojson, .gpx, .kml, .rtz, .csv, .plan, .bhv");
  add_frame_options(*cmd, c->frame);
  cmd->add_option("--margin", r.margin_m, "Safety margin to every obstacle (m)")->capture_default_str();
  cmd->add_option(
      "--turn-radius", r.turn_radius_m,
      "The vehicle's least turning radius (m): every arc of the route is at least this wide "
      "(--graph quadtree needs --smooth; default with --vehicle: what the vehicle can follow at the planned speed)");
  cmd->add_option("--from-heading", c->from_heading,
                  "The vehicle's heading at the start (deg, clockwise from true north): the route leaves along it, "
                  "turning no tighter than the turning radius (Dubins ends; the tangent graph)");
  cmd->add_option("--to-heading", c->to_heading,
                  "The heading the route reaches the goal on (deg, clockwise from true north; as --from-heading)");
  cmd->add_option("--tolerance", r.tolerance_m, "How far zone polygons may reach beyond the zones (m)")
      ->capture_default_str();
  cmd->add_option(
      "--depth", r.depth_m,
      "Operating depth (m); obstacles whose top_depth_m lies deeper than depth + --vertical-clearance are passed over");
  add_chart_options(*cmd, r.chart, &r.vertical_clearance_m);
  cmd->add_option("--graph", c->graph,
                  graph_help_text() +
                      ". Default: navmesh for a route by length on S-57 charts (without --waypoint-grid), tangent "
                      "with a heading, else visibility");
  cmd->add_option("--search", c->search, "astar or dijkstra")->capture_default_str();
  cmd->add_option("--max-expansions", r.max_expansions,
                  "The search's budget: at most this many vertices examined per search (0: none); a search that "
                  "runs out says so (exit 3)")
      ->capture_default_str();
  cmd->add_flag("--json", c->out.json, "Print the summary as JSON");
  cmd->add_flag("--escape", r.problem.escape, "A start inside a safety zone first leaves it the shortest way");
  cmd->add_option("--render", c->out.render, "Also draw the route chart (obstacles, zones, route) as .png or .svg");
  cmd->add_flag("--render-graph", c->render_graph, "With --render: draw the zone polygons and the planning graph");
  cmd->add_option("--html", c->out.html,
                  "Also write a web map of the route (one .html file that works offline: the chart's no-go with "
                  "its reasons, obstacles, zones, legs and waypoints; docs/WEB_MAP.md)");
  cmd->add_option("--cost", c->cost, "What the route minimises: length, time or energy (in the current)")
      ->capture_default_str();
  auto* current = cmd->add_option("--current", r.current_file,
                                  "Sea-current field (NetCDF u/v, possibly with a time axis; or a two-band raster)");
  cmd->add_option("--current-const", c->current_const,
                  "A uniform current SPEED_MPS,DIR_DEG (direction it sets towards, clockwise from north)")
      ->excludes(current);
  cmd->add_option("--vehicle", r.vehicle, "Vehicle file (speeds, energy model; data/vehicles/deepc.yaml)");
  cmd->add_option("--speed", r.speed,
                  "Speed through the water: cruise (the vehicle's), optimal (least energy per leg), or m/s")
      ->capture_default_str();
  cmd->add_option("--waypoint-grid", r.waypoint_grid_m,
                  "Open-water vertices SPACING_M apart around start and goal, so time and energy routes can bend "
                  "where the current changes (visibility graphs)");
  cmd->add_flag("--no-refine", c->no_refine,
                "Time and energy routes: keep the graph's route instead of refining it to the continuous optimum "
                "near it (docs/PLANNING.md)");
  cmd->add_option(
         "--min-cell", r.min_cell_m,
         "Quadtree: the smallest cell side (m); octree: the smallest cell's height (its width follows the dive angle)")
      ->capture_default_str();
  cmd->add_flag("--smooth", r.smooth,
                "Quadtree, octree: shortcut the cell-centre route where the straight line is free (and flyable)");
  add_depth_flags(*cmd, c->depth);
  cmd->add_option("--replan-events", r.replan_events,
                  "Quadtree or navmesh: replay sonar detections (an obstacle file with detected_at_m), repaired by "
                  "D* Lite or cut out of the mesh, and write each repaired route (ROUTE_repair_K.geojson)");
  cmd->add_option("--depart", c->depart,
                  "Departure time (UTC, e.g. 2019-03-07T15:00:00Z); default: the current field's first time");
  cmd->callback([c] { run_plan(*c); });
}

}  // namespace deepguide::app
