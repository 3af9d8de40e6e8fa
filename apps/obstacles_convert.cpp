// deepguide obstacles convert IN... OUT

#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/core/output_paths.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"

namespace deepguide::app {
namespace {
struct ConvertOptions {
  std::vector<std::string> paths;  // inputs..., output last
  FrameOptions frame;
};
}  // namespace

void register_obstacles_convert(CLI::App& obstacles) {
  auto opts = std::make_shared<ConvertOptions>();
  CLI::App* cmd = obstacles.add_subcommand(
      "convert", "Convert obstacle files; the output format follows OUT's extension (.geojson, .gpkg, .csv)");
  // One positional list: CLI11 cannot put a required positional after an open-ended one.
  cmd->add_option("IN... OUT", opts->paths,
                  "Input obstacle files (several are merged), then the output file (.geojson/.json, .gpkg, .csv)")
      ->required()
      ->expected(2, -1);
  add_frame_options(*cmd, opts->frame);
  cmd->callback([opts] {
    const std::string output = opts->paths.back();
    const std::vector<std::string> inputs(opts->paths.begin(), opts->paths.end() - 1);
    obstacle_format_for(output);  // reject a bad extension before reading anything
    std::vector<NamedPath> named;
    for (const std::string& f : inputs) named.push_back({"input", f});
    check_outputs_apart(named, {{"output", output}});
    const LoadedObstacles loaded = load_obstacles(inputs, {opts->frame.crs, opts->frame.src_crs});
    write_obstacles(output, loaded.obstacles, loaded.frame);
    std::cerr << "wrote " << loaded.obstacles.size() << " obstacles to " << output << "\n";
  });
}

}  // namespace deepguide::app
