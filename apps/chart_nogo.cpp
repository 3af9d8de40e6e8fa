// deepguide chart nogo RASTER|CELL...|FOLDER --depth M [--clearance M] [--tolerance M] [--crs EPSG:n] -o OUT [--json]

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "deepguide/world/enc_cells.hpp"
#include "deepguide/world/enc_no_go.hpp"
#include "deepguide/world/no_go.hpp"
#include "deepguide/world/obstacle_io.hpp"

namespace deepguide::app {
namespace {

struct NoGoCliOptions {
  std::vector<std::string> charts;
  bool restricted = false;
  bool no_zoc = false;
  std::string output;
  std::string crs;
  std::string src_crs;
  std::string sense = "auto";
  bool nodata_is_water = false;
  bool json = false;
  NoGoOptions nogo;
};

// S-57 cells: their no-go (enc_no_go.hpp), the planners' polygons and discs written as obstacles.
void run_enc_nogo(const NoGoCliOptions& o) {
  EncNoGoOptions opts;
  opts.operating_depth_m = o.nogo.operating_depth_m;
  opts.vertical_clearance_m = o.nogo.vertical_clearance_m;
  opts.simplify_tolerance_m = o.nogo.simplify_tolerance_m;
  opts.restricted_areas = o.restricted;
  opts.zone_of_confidence = !o.no_zoc;
  const auto t0 = std::chrono::steady_clock::now();
  const EncNoGo no_go =
      enc_no_go(o.charts, o.crs.empty() ? std::nullopt : std::optional<LocalFrame>(LocalFrame::from_user_crs(o.crs)),
                opts);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_obstacles(o.output, no_go.obstacles, no_go.frame);
  nlohmann::json cells = nlohmann::json::array();
  for (const EncCellSummary& c : no_go.cells) {
    cells.push_back({{"path", c.path}, {"name", c.name}, {"scale", c.compilation_scale}, {"usage_band", c.usage_band},
                     {"edition", c.edition}, {"updates", c.update_number}});
  }
  if (o.json) {
    std::cout << nlohmann::json{{"cells", cells},
                                {"output", o.output},
                                {"local_crs", no_go.frame.id()},
                                {"required_depth_m", no_go.required_depth_m},
                                {"no_go_by_class", no_go.no_go_by_class},
                                {"passable_by_class", no_go.passable_by_class},
                                {"zones_of_confidence", no_go.zoc_areas},
                                {"polygons", no_go.obstacles.polygons.size()},
                                {"discs", no_go.obstacles.ellipses.size()},
                                {"vertices", no_go.vertices},
                                {"seconds", seconds}}
                     .dump(2)
              << "\n";
    return;
  }
  for (const EncCellSummary& c : no_go.cells) {
    std::printf("cell             %s  1:%ld, band %d, edition %s, update %d\n", c.name.c_str(), c.compilation_scale,
                c.usage_band, c.edition.c_str(), c.update_number);
  }
  std::printf("local frame      %s (%s)\n", no_go.frame.id().c_str(), no_go.frame.name().c_str());
  std::printf("rule             charted depth less its zone of confidence < %.2f m (operating) + %.2f m (clearance)%s\n",
              opts.operating_depth_m, opts.vertical_clearance_m, opts.zone_of_confidence ? "" : " (zones ignored)");
  std::printf("no-go            ");
  const char* sep = "";
  for (const auto& [cls, n] : no_go.no_go_by_class) {
    std::printf("%s%s %zu", sep, cls.c_str(), n);
    sep = ", ";
  }
  std::printf("\nplanners         %zu polygon(s) with %zu corners, %zu disc(s) (tolerance %.2f m, outward only)\n",
              no_go.obstacles.polygons.size(), no_go.vertices, no_go.obstacles.ellipses.size(),
              opts.simplify_tolerance_m);
  std::printf("time             %.2f s\n", seconds);
  std::printf("wrote            %s\n", o.output.c_str());
}

}  // namespace

void register_chart_nogo(CLI::App& chart) {
  auto o = std::make_shared<NoGoCliOptions>();
  CLI::App* cmd = chart.add_subcommand(
      "nogo", "No-go area of a bathymetry raster or of S-57 cells for an operating depth, written as obstacles");
  cmd->add_option("CHART", o->charts,
                  "A bathymetry raster (GeoTIFF, BAG, NetCDF/GMT, ESRI ASCII grid, ...), or S-57 cells (*.000, with "
                  "their updates) and folders of cells")
      ->required();
  cmd->add_flag("--restricted", o->restricted,
                "S-57: areas whose RESTRN is entry prohibited, entry restricted or area to be avoided are no-go too");
  cmd->add_flag("--no-zoc", o->no_zoc,
                "S-57: take charted depths and positions as exact (default: less the zone of confidence's uncertainty)");
  cmd->add_option("--depth", o->nogo.operating_depth_m, "Operating depth of the vehicle (m, positive down)")
      ->required();
  cmd->add_option("--clearance", o->nogo.vertical_clearance_m, "Water kept above the sea floor (m)")
      ->capture_default_str();
  cmd->add_option("--tolerance", o->nogo.simplify_tolerance_m,
                  "Simplification tolerance (m): polygons grow by at most this much, never shrink; 0 = exact cells")
      ->capture_default_str();
  cmd->add_option("-o,--output", o->output, "Output obstacle file (.geojson/.json, .gpkg, .csv)")->required();
  cmd->add_option("--crs", o->crs,
                  "Local planning frame, a projected CRS such as EPSG:32632 (default: UTM zone of the raster's centre)");
  cmd->add_option("--src-crs", o->src_crs,
                  "CRS of a raster that carries none, e.g. EPSG:4326 (default: such a raster is an error)");
  cmd->add_option("--sense", o->sense, "Cell values are elevation (up positive), depth, or auto (from the file)")
      ->check(CLI::IsMember({"auto", "elevation", "depth"}))
      ->capture_default_str();
  cmd->add_flag("--nodata-is-water", o->nodata_is_water,
                "Treat cells without data as free water (default: they are no-go)");
  cmd->add_flag("--json", o->json, "Print a JSON object instead of text");
  cmd->callback([o] {
    obstacle_format_for(o->output);  // reject a bad extension before the work
    if (names_enc(o->charts.front()) || o->charts.size() > 1) {
      run_enc_nogo(*o);
      return;
    }
    const std::string& raster = o->charts.front();
    NoGoOptions opts = o->nogo;
    opts.nodata_is_no_go = !o->nodata_is_water;
    opts.bathymetry.assumed_crs = o->src_crs;
    opts.bathymetry.sense = o->sense == "elevation" ? VerticalSense::elevation
                            : o->sense == "depth"   ? VerticalSense::depth
                                                    : VerticalSense::automatic;
    const LocalFrame frame =
        o->crs.empty() ? raster_local_frame(raster, opts.bathymetry) : LocalFrame::from_user_crs(o->crs);
    const auto t0 = std::chrono::steady_clock::now();
    const NoGoArea area = compute_no_go(raster, frame, opts);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ObstacleSet set;
    set.polygons = area.polygons;
    write_obstacles(o->output, set, frame);

    if (o->json) {
      nlohmann::json j = {{"raster", raster},
                          {"output", o->output},
                          {"local_crs", frame.id()},
                          {"operating_depth_m", opts.operating_depth_m},
                          {"vertical_clearance_m", opts.vertical_clearance_m},
                          {"simplify_tolerance_m", opts.simplify_tolerance_m},
                          {"width", area.raster.width},
                          {"height", area.raster.height},
                          {"total_cells", area.total_cells},
                          {"no_go_cells", area.no_go_cells},
                          {"cell_area_m2", area.cell_area_m2},
                          {"polygons", area.polygons.size()},
                          {"area_m2", area.area_m2},
                          {"vertices_before_simplify", area.vertices_before_simplify},
                          {"vertices_after_simplify", area.vertices_after_simplify},
                          {"seconds", seconds}};
      std::cout << j.dump(2) << "\n";
      return;
    }
    std::printf("raster           %s  [%s, %s] %d x %d cells\n", raster.c_str(), area.raster.driver.c_str(),
                area.raster.crs.c_str(), area.raster.width, area.raster.height);
    std::printf("local frame      %s (%s)\n", frame.id().c_str(), frame.name().c_str());
    std::printf("rule             depth < %.2f m (operating) + %.2f m (clearance), land, %s\n",
                opts.operating_depth_m, opts.vertical_clearance_m,
                opts.nodata_is_no_go ? "and cells without data" : "cells without data are water");
    const double pct = area.total_cells > 0 ? 100.0 * static_cast<double>(area.no_go_cells) /
                                                  static_cast<double>(area.total_cells)
                                            : 0.0;
    std::printf("no-go cells      %zu of %zu (%.1f%%), %.1f m2 each\n", area.no_go_cells, area.total_cells, pct,
                area.cell_area_m2);
    std::printf("polygons         %zu, area %.1f m2\n", area.polygons.size(), area.area_m2);
    std::printf("vertices         %zu before, %zu after simplification (tolerance %.2f m, outward only)\n",
                area.vertices_before_simplify, area.vertices_after_simplify, opts.simplify_tolerance_m);
    std::printf("time             %.2f s\n", seconds);
    std::printf("wrote            %s\n", o->output.c_str());
  });
}

}  // namespace deepguide::app
