// deepguide obstacles import DETECTIONS... --store STORE.gpkg [--merge-distance M] [--json]

#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/obstacle_files/obstacle_store.hpp"

namespace deepguide::app {
namespace {
struct ImportOptions {
  std::vector<std::string> detections;
  std::string store;
  FrameOptions frame;
  double merge_distance_m = ObstacleStoreOptions{}.merge_distance_m;
  bool json = false;
};
}  // namespace

void register_obstacles_import(CLI::App& obstacles) {
  auto opts = std::make_shared<ImportOptions>();
  CLI::App* cmd = obstacles.add_subcommand(
      "import", "Add sonar detections to the stored-obstacle database (a GeoPackage); re-sighted objects merge");
  cmd->add_option("DETECTIONS", opts->detections,
                  "Detection files: Points with semi_major_m etc., optional time, mission, contact_id")
      ->required();
  cmd->add_option("--store", opts->store, "The obstacle store, a GeoPackage (.gpkg); created if missing")->required();
  cmd->add_option("--merge-distance", opts->merge_distance_m,
                  "Centres closer than this (m) are one object; overlapping footprints merge too")
      ->capture_default_str();
  add_frame_options(*cmd, opts->frame);
  cmd->add_flag("--json", opts->json, "Print a JSON object instead of text");
  cmd->callback([opts] {
    ObstacleStoreOptions options;
    options.merge_distance_m = opts->merge_distance_m;
    options.local_crs = opts->frame.crs;
    options.source_crs = opts->frame.src_crs;
    const ImportSummary s = import_detections(opts->store, opts->detections, options);
    std::cout << (opts->json ? to_json(s).dump(2) + "\n" : to_text(s));
  });
}

}  // namespace deepguide::app
