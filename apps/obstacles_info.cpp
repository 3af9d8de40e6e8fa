// deepguide obstacles info FILE... [--json]

#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/obstacle_files/obstacle_summary.hpp"

namespace deepguide::app {
namespace {

struct InfoOptions {
  std::vector<std::string> files;
  FrameOptions frame;
  bool json = false;
};

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
      std::cout << to_text(summary);
    }
  });
}

}  // namespace deepguide::app
