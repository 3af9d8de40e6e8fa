// deepguide render chart FILE... [--depth M] [chart options] [--obstacles FILE...] -o OUT.png|svg [--width PX]

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/output_paths.hpp"
#include "deepguide/render/chart_scene.hpp"
#include "deepguide/render/chart_web_map.hpp"
#include "deepguide/render/route_scene.hpp"  // kMinImageWidth, kMaxImageWidth

namespace deepguide::app {
namespace {

struct RenderChartOptions {
  ChartRenderOptions chart;
  std::string output, html;
  double depth = 0.0;
};

}  // namespace

void register_render_chart(CLI::App& render) {
  auto o = std::make_shared<RenderChartOptions>();
  CLI::App* cmd = render.add_subcommand(
      "chart", "Draw a sea chart: depth shading, land, hazards, no-go area at a depth, scale bar, north arrow");
  cmd->add_option("FILE", o->chart.charts, "Charts: bathymetry rasters, S-57 cells (.000), hazard files")->required();
  cmd->add_option("-o,--output", o->output, "Image to write: .png or .svg");
  cmd->add_option("--html", o->html,
                  "Web map to write (one .html file that works offline: depth areas, land, the no-go with its "
                  "reasons, hazards, soundings, zones of confidence, cells; S-57 charts, with --depth; "
                  "docs/WEB_MAP.md)");
  CLI::Option* depth = cmd->add_option("--depth", o->depth, "Operating depth (m, positive down): draw the no-go area");
  add_chart_options(*cmd, o->chart.chart_options, &o->chart.clearance_m);
  cmd->add_option("--obstacles", o->chart.obstacles, "Further obstacle files to draw (GeoJSON, GeoPackage, ...)")
      ->expected(1, -1);
  cmd->add_option("--crs", o->chart.local_crs, "Local frame, a projected CRS (default: UTM zone of the first chart)");
  cmd->add_option("--src-crs", o->chart.source_crs,
                  "CRS of a raster that carries none, e.g. EPSG:4326 for an ESRI ASCII or GMT grid in lon/lat");
  cmd->add_option("--width", o->chart.width_px, "Image width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(kMinImageWidth, kMaxImageWidth));
  cmd->add_option("--title", o->chart.title, "Title line (default: the files, the CRS and the depth)");
  cmd->callback([o, depth] {
    if (depth->count() > 0) {
      if (!std::isfinite(o->depth)) throw InputError("--depth: expected an operating depth >= 0 m, got a non-number");
      o->chart.depth_m = o->depth;
    }
    if (o->output.empty() && o->html.empty()) {
      throw CLI::ValidationError("render chart", "give -o FILE.png|svg or --html FILE.html (or both)");
    }
    if (!o->html.empty()) {
      check_web_map_path(o->html, "--html");
      std::vector<NamedPath> inputs;
      for (const std::string& f : o->chart.charts) inputs.push_back({"FILE", f});
      for (const std::string& f : o->chart.obstacles) inputs.push_back({"--obstacles", f});
      check_outputs_apart(inputs, {{"-o", o->output}, {"--html", o->html}});
      write_chart_web_map(o->chart, o->html);
      std::printf("web map          %s\n", o->html.c_str());
    }
    if (o->output.empty()) return;
    const ChartLayout layout = render_chart(o->chart, o->output);
    std::printf("wrote            %s (%d x %d px, %s", o->output.c_str(), layout.width, layout.height,
                layout.frame_id.c_str());
    if (std::isfinite(o->chart.depth_m)) std::printf(", %zu no-go polygon(s)", layout.no_go_polygons);
    std::printf(", %zu hazard(s))\n", layout.hazards);
  });
}

}  // namespace deepguide::app
