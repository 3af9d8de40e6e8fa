// deepguide chart prepare CELL|FOLDER... --depth M [chart options] [--tolerance M] [--crs EPSG:n] -o AREA.gpkg
//                        [--graphs LIST|none] [--margin M] [--zone-tolerance M] [--turn-radius M]
//                        [--overwrite] [--json]

#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/charts/prepared_chart.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/prepared_graphs.hpp"

namespace deepguide::app {
namespace {
struct PrepareOptions {
  std::vector<std::string> charts;
  std::string output, crs;
  EncNoGoOptions enc;
  std::vector<std::string> graphs{"navmesh"};
  PlannerOptions planner;
  bool overwrite = false, json = false;
};
}  // namespace

void register_chart_prepare(CLI::App& chart) {
  auto o = std::make_shared<PrepareOptions>();
  CLI::App* cmd = chart.add_subcommand(
      "prepare",
      "Judge S-57 cells at one depth once and keep their no-go in a GeoPackage that plan --chart and "
      "check route --chart read");
  cmd->add_option("CHART", o->charts, "S-57 cells (*.000, with their updates) and folders of cells")->required();
  cmd->add_option("--depth", o->enc.operating_depth_m, "Operating depth of the vehicle (m, positive down)")->required();
  cmd->add_option("--tolerance", o->enc.simplify_tolerance_m,
                  "How far the planners' polygons may grow outward when simplified (m); 0 = exact")
      ->capture_default_str();
  add_chart_options(*cmd, o->enc, &o->enc.vertical_clearance_m);
  cmd->add_option("--crs", o->crs, "Local planning frame, a projected CRS (default: UTM zone of the first cell)");
  cmd->add_option("-o,--output", o->output, "The prepared chart to write (.gpkg)")->required();
  cmd->add_option("--graphs", o->graphs,
                  "Graphs to build once and keep in the file for plan --chart (" +
                      graph_names_text([](const GraphEntry& e) { return static_cast<bool>(e.save); }) +
                      "), or none; plan loads one only for the same margin, tolerance and turning radius")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--margin", o->planner.margin, "The kept graphs' safety margin to every obstacle (m), as plan's")
      ->capture_default_str();
  cmd->add_option("--zone-tolerance", o->planner.tolerance,
                  "The kept graphs' zone polygon tolerance (m), as plan's --tolerance")
      ->capture_default_str();
  cmd->add_option("--turn-radius", o->planner.turn_radius_m,
                  "The kept graphs' turning radius (m), as plan's --turn-radius; 0 = none")
      ->capture_default_str();
  cmd->add_flag("--overwrite", o->overwrite, "Replace an existing output file");
  cmd->add_flag("--json", o->json, "Print a JSON object instead of text");
  cmd->callback([o] {
    std::vector<GraphKind> graphs;
    for (const std::string& g : o->graphs) {
      if (g != "none") graphs.push_back(GraphKind{g});
    }
    const ChartPreparation done =
        prepare_chart(o->charts, o->crs, o->enc, o->output, o->overwrite,
                      graphs.empty() ? PreparedGraphsMaker{} : graph_preparer(graphs, o->planner));
    std::cout << (o->json ? done.to_json().dump(2) + "\n" : done.to_text());
  });
}

}  // namespace deepguide::app
