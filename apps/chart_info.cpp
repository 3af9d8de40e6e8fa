// deepguide chart info FILE... [--depth M] [--clearance M] [--crs EPSG:n] [--src-crs CRS] [--json]

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/world/chart_info.hpp"

namespace deepguide::app {
namespace {

struct ChartInfoCliOptions {
  std::vector<std::string> files;
  std::string crs, src_crs;
  double depth = 0.0;
  double clearance = 2.0;
  bool json = false;
};

std::string range(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return "-";
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.2f .. %.2f m", lo, hi);
  return buf;
}

void print_text(const ChartInfo& c) {
  std::printf("%s  [%s, %s, %s]\n", c.path.c_str(), to_string(c.kind), c.driver.c_str(), c.crs.c_str());
  for (const ChartLayer& l : c.layers) {
    std::printf("  layer          %-14s %zu %s%s%s\n", l.name.c_str(), l.features,
                c.kind == ChartKind::raster ? "cells" : "feature(s)", l.detail.empty() ? "" : ", ", l.detail.c_str());
  }
  if (std::isfinite(c.extent.west)) {
    std::printf("extent           lon %.6f .. %.6f, lat %.6f .. %.6f\n", c.extent.west, c.extent.east, c.extent.south,
                c.extent.north);
    std::printf("                 %.1f m x %.1f m (east x north, %s)\n", c.width_m, c.height_m, c.local_crs.c_str());
  }
  if (c.kind == ChartKind::raster) {
    std::printf("raster           %d x %d cells of %g x %g, %.1f %% valid", c.raster_width, c.raster_height, c.cell_x_m,
                std::abs(c.cell_y_m), 100.0 * c.valid_fraction);
    if (c.has_nodata) std::printf(", NoData %g", c.nodata);
    std::printf("\nvertical         %s\n", c.vertical_sense.c_str());
  }
  std::printf("depth range      %s%s\n", range(c.min_depth_m, c.max_depth_m).c_str(),
              c.kind == ChartKind::vector ? " (hazard tops)" : "");
  std::printf("hazards          %zu", c.hazards);
  if (c.kind == ChartKind::s57) std::printf(" (+ %zu land area feature(s))", c.land_features);
  std::printf("\n");
  if (c.kind == ChartKind::s57) {
    std::printf("zones of conf.   ");
    if (c.zoc_areas.empty()) std::printf("none (M_QUAL absent: depths and positions taken as unassessed)");
    const char* sep = "";
    for (const auto& [zoc, n] : c.zoc_areas) {
      std::printf("%sCATZOC %s: %zu area(s)", sep, zoc.c_str(), n);
      sep = ", ";
    }
    std::printf("\n");
  }
  if (c.no_go) {
    const NoGoSummary& n = *c.no_go;
    std::printf("no-go at %g m    %.0f m2 (clearance %g m), %zu polygon(s)", n.depth_m, n.area_m2, n.clearance_m,
                n.polygons);
    if (c.kind == ChartKind::raster) {
      std::printf(
          ", %zu of %zu cells (%.1f %%)", n.no_go_cells, n.total_cells,
          n.total_cells > 0 ? 100.0 * static_cast<double>(n.no_go_cells) / static_cast<double>(n.total_cells) : 0.0);
    } else {
      std::printf(", %zu %s passed over", n.hazards_passable, c.kind == ChartKind::s57 ? "feature(s)" : "hazard(s)");
    }
    std::printf("\n");
    if (!n.no_go_by_class.empty()) {
      std::printf("no-go by class   ");
      const char* sep = "";
      for (const auto& [cls, k] : n.no_go_by_class) {
        std::printf("%s%s %zu", sep, cls.c_str(), k);
        sep = ", ";
      }
      std::printf(" (%zu polygon corners for the planners)\n", n.vertices);
    }
  }
}

}  // namespace

void register_chart_info(CLI::App& chart) {
  auto o = std::make_shared<ChartInfoCliOptions>();
  CLI::App* cmd = chart.add_subcommand(
      "info", "Layers, extent, CRS, depth range, hazards and the no-go area at a depth of chart files");
  cmd->add_option("FILE", o->files, "Charts: bathymetry rasters, S-57 cells (.000), hazard files")->required();
  CLI::Option* depth =
      cmd->add_option("--depth", o->depth, "Operating depth (m, positive down): also report the no-go area");
  cmd->add_option("--clearance", o->clearance, "Vertical clearance above the sea floor and hazards (m)")
      ->capture_default_str();
  cmd->add_option("--crs", o->crs, "Local frame for areas, a projected CRS (default: UTM zone of the chart)");
  cmd->add_option("--src-crs", o->src_crs,
                  "CRS of a chart that carries none, e.g. EPSG:4326 for an ESRI ASCII or GMT grid in lon/lat");
  cmd->add_flag("--json", o->json, "Print JSON (an array, one object per file) instead of text");
  cmd->callback([o, depth] {
    ChartInfoOptions options;
    options.source_crs = o->src_crs;
    options.clearance_m = o->clearance;
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
        print_text(info);
      }
    }
    if (o->json) std::cout << all.dump(2) << "\n";
  });
}

}  // namespace deepguide::app
