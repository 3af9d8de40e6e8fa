// deepguide chart nogo RASTER|CELL...|FOLDER --depth M [--clearance M] [--tolerance M] [--crs EPSG:n] -o OUT [--json]

#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/charts/no_go_export.hpp"

namespace deepguide::app {

void register_chart_nogo(CLI::App& chart) {
  struct Flags {
    NoGoExportRequest request;
    bool nodata_is_water = false;
    std::string sense = "auto";
    bool json = false;
  };
  auto f = std::make_shared<Flags>();
  NoGoExportRequest& r = f->request;
  CLI::App* cmd = chart.add_subcommand(
      "nogo", "No-go area of a bathymetry raster or of S-57 cells for an operating depth, written as obstacles");
  cmd->add_option("CHART", r.charts,
                  "A bathymetry raster (GeoTIFF, BAG, NetCDF/GMT, ESRI ASCII grid, ...), or S-57 cells (*.000, with "
                  "their updates) and folders of cells")
      ->required();
  cmd->add_option("--depth", r.nogo.operating_depth_m, "Operating depth of the vehicle (m, positive down)")->required();
  add_chart_options(*cmd, r.chart, &r.nogo.vertical_clearance_m);
  cmd->add_option("--tolerance", r.nogo.simplify_tolerance_m,
                  "Simplification tolerance (m): polygons grow by at most this much, never shrink; 0 = exact cells")
      ->capture_default_str();
  cmd->add_option("-o,--output", r.output, "Output obstacle file (.geojson/.json, .gpkg, .csv)")->required();
  cmd->add_option(
      "--crs", r.crs,
      "Local planning frame, a projected CRS in metres such as EPSG:32632 (default: UTM zone of the raster's centre)");
  cmd->add_option("--src-crs", r.src_crs,
                  "CRS of a raster that carries none, e.g. EPSG:4326 (default: such a raster is an error)");
  cmd->add_option("--sense", f->sense, "Cell values are elevation (up positive), depth, or auto (from the file)")
      ->check(CLI::IsMember({"auto", "elevation", "depth"}))
      ->capture_default_str();
  cmd->add_flag("--nodata-is-water", f->nodata_is_water,
                "Treat cells without data as free water (default: they are no-go)");
  cmd->add_flag("--json", f->json, "Print a JSON object instead of text");
  cmd->callback([f] {
    NoGoExportRequest& r = f->request;
    r.nodata_is_no_go = !f->nodata_is_water;
    r.sense = f->sense == "elevation" ? VerticalSense::elevation
              : f->sense == "depth"   ? VerticalSense::depth
                                      : VerticalSense::automatic;
    const NoGoExportReport report = export_no_go(r);
    if (f->json) {
      std::cout << report.to_json().dump(2) << "\n";
    } else {
      std::cout << report.to_text();
    }
  });
}

}  // namespace deepguide::app
