// deepguide check route ROUTE (--obstacles FILE... | --chart CELL|FOLDER... --depth D) [--margin M] [--json] [--html F]

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/output_paths.hpp"
#include "deepguide/planning/route_file_check.hpp"
#include "deepguide/render/route_check_web_map.hpp"

namespace deepguide::app {

void register_check_route(CLI::App& check) {
  auto o = std::make_shared<RouteFileCheckOptions>();
  auto frame = std::make_shared<FrameOptions>();
  auto json = std::make_shared<bool>(false);
  auto html = std::make_shared<std::string>();
  CLI::App* cmd = check.add_subcommand(
      "route",
      "Check a route against obstacles (exact clearance) or S-57 charts at a depth (the first crossing "
      "named); exit 1 when the route is unsafe");
  cmd->add_option("ROUTE", o->route, "Route file: RTZ (an ECDIS's), GPX (OpenCPN's), GeoJSON, KML, ... with a line")
      ->required();
  cmd->add_option("--obstacles", o->obstacles, "Obstacle files")->expected(1, -1);
  cmd->add_option("--chart", o->charts,
                  "S-57 cells (*.000, updates beside them), folders of cells, or a prepared chart (.gpkg)")
      ->expected(1, -1);
  cmd->add_option("--depth", o->operating_depth_m, "Operating depth (m, positive down), for --chart");
  add_chart_options(*cmd, o->chart, &o->vertical_clearance_m);
  add_frame_options(*cmd, *frame);
  cmd->add_option("--margin", o->margin_m, "Safety margin the route must keep (m)")->capture_default_str();
  cmd->add_flag("--json", *json, "Print the verdict as JSON");
  cmd->add_option("--html", *html,
                  "Also write the check as a web map (one .html file that works offline; written for an unsafe route "
                  "too; docs/WEB_MAP.md)");
  cmd->callback([o, frame, json, html] {
    if (o->obstacles.empty() && o->charts.empty()) {
      throw CLI::ValidationError("check route", "give --obstacles FILE... or --chart CELL... (or both)");
    }
    if (!std::isfinite(o->margin_m) || o->margin_m < 0.0) {
      throw InputError("--margin: expected a safety margin >= 0 m, got " + std::to_string(o->margin_m));
    }
    if (!o->charts.empty() && std::isnan(o->operating_depth_m)) {
      throw InputError("--depth: expected the operating depth (m) to check against S-57 charts");
    }
    o->crs = frame->crs;
    o->src_crs = frame->src_crs;
    if (!html->empty()) {
      check_web_map_path(*html, "--html");
      std::vector<NamedPath> inputs{{"ROUTE", o->route}};
      for (const std::string& f : o->obstacles) inputs.push_back({"--obstacles", f});
      for (const std::string& f : o->charts) inputs.push_back({"--chart", f});
      check_outputs_apart(inputs, {{"--html", *html}});
    }
    const RouteFileCheckReport report = check_route_file(*o);
    // The page first: an unsafe route is where an operator wants to look.
    if (!html->empty()) write_web_map(route_check_web_map(report, *o), *html);
    if (*json) {
      std::cout << report.to_json().dump(2) << "\n";
    } else if (report.safe) {
      std::cout << report.to_text() << "\n";
    }
    if (!report.safe) throw InputError(o->route + ": " + report.why);
  });
}

}  // namespace deepguide::app
