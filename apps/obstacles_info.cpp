// deepguide obstacles info FILE... [--json]

#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/world/obstacle_summary.hpp"

namespace deepguide::app {
namespace {

struct InfoOptions {
  std::vector<std::string> files;
  FrameOptions frame;
  bool json = false;
};

std::string stats_line(const RangeStats& r, const char* unit) {
  if (r.n == 0) return "-";
  char buf[128];
  std::snprintf(buf, sizeof buf, "min %.2f %s, mean %.2f %s, max %.2f %s", r.min, unit, r.mean, unit, r.max, unit);
  return buf;
}

void print_text(const ObstacleSummary& s) {
  for (const auto& src : s.sources) {
    std::cout << src.path << "  [" << src.driver << ", " << src.crs << "]  " << src.ellipses
              << " elliptical cylinder(s), " << src.polygons << " polygon(s)\n";
  }
  std::printf("count            %zu (%zu elliptical cylinder(s), %zu polygon(s))\n", s.count, s.ellipses, s.polygons);
  std::printf("local frame      %s (%s)\n", s.local_crs_id.c_str(), s.local_crs_name.c_str());
  if (s.has_extent) {
    std::printf("extent           lon %.6f .. %.6f, lat %.6f .. %.6f\n", s.west, s.east, s.south, s.north);
    std::printf("                 %.1f m x %.1f m (east x north)\n", s.max_x - s.min_x, s.max_y - s.min_y);
  }
  std::cout << "semi-major axis  " << stats_line(s.semi_major_m, "m") << "\n";
  std::cout << "semi-minor axis  " << stats_line(s.semi_minor_m, "m") << "\n";
  std::cout << "footprint area   " << stats_line(s.footprint_area_m2, "m2") << "\n";
  std::printf("vertical         %zu height above sea floor, %zu top depth, %zu whole water column\n", s.with_height,
              s.with_top_depth, s.full_column);
}

}  // namespace

void register_obstacles_info(CLI::App& obstacles) {
  auto opts = std::make_shared<InfoOptions>();
  CLI::App* cmd = obstacles.add_subcommand("info", "Count, extent, sizes and CRS of obstacle files");
  cmd->add_option("FILE", opts->files, "Obstacle files (GeoJSON, GeoPackage, Shapefile, CSV, ...)")->required();
  add_frame_options(*cmd, opts->frame);
  cmd->add_flag("--json", opts->json, "Print a JSON object instead of text");
  cmd->callback([opts] {
    const LoadedObstacles loaded = load_obstacles(opts->files, {opts->frame.crs, opts->frame.src_crs});
    const ObstacleSummary summary = summarize(loaded);
    if (opts->json) {
      std::cout << to_json(summary).dump(2) << "\n";
    } else {
      print_text(summary);
    }
  });
}

}  // namespace deepguide::app
