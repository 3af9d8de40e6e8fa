// deepguide chart info FILE|FOLDER... [--depth M] [chart options] [--crs EPSG:n] [--src-crs CRS] [--json]

#include <cmath>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/charts/chart_info.hpp"
#include "deepguide/charts/chart_options.hpp"
#include "deepguide/core/error.hpp"

namespace deepguide::app {
namespace {

struct ChartInfoCliOptions {
  std::vector<std::string> files;
  std::string crs, src_crs;
  double depth = 0.0;
  double clearance = 2.0;
  ChartOptions chart;
  bool json = false;
};

}  // namespace

void register_chart_info(CLI::App& chart) {
  auto o = std::make_shared<ChartInfoCliOptions>();
  CLI::App* cmd = chart.add_subcommand(
      "info", "Layers, extent, CRS, depth range, hazards and the no-go area at a depth of chart files");
  cmd->add_option("FILE", o->files,
                  "Charts: bathymetry rasters, S-57 cells (.000), folders of cells and exchange sets (ENC_ROOT), "
                  "hazard files")
      ->required();
  CLI::Option* depth =
      cmd->add_option("--depth", o->depth, "Operating depth (m, positive down): also report the no-go area");
  add_chart_options(*cmd, o->chart, &o->clearance);
  cmd->add_option("--crs", o->crs, "Local frame for areas, a projected CRS (default: UTM zone of the chart)");
  cmd->add_option("--src-crs", o->src_crs,
                  "CRS of a chart that carries none, e.g. EPSG:4326 for an ESRI ASCII or GMT grid in lon/lat");
  cmd->add_flag("--json", o->json, "Print JSON (an array, one object per file) instead of text");
  cmd->callback([o, depth] {
    ChartInfoOptions options;
    options.source_crs = o->src_crs;
    options.clearance_m = o->clearance;
    options.chart = o->chart;
    options.local_crs = o->crs;
    if (depth->count() > 0) {
      if (!std::isfinite(o->depth)) throw InputError("--depth: expected an operating depth >= 0 m, got a non-number");
      options.depth_m = o->depth;
    }
    nlohmann::json all = nlohmann::json::array();
    for (const std::string& file : o->files) {
      const ChartInfo info = chart_info(file, options);
      if (o->json) {
        all.push_back(to_json(info));
      } else {
        std::cout << to_text(info);
      }
    }
    if (o->json) std::cout << all.dump(2) << "\n";
  });
}

}  // namespace deepguide::app
