#pragma once
// Each subcommand registers itself on its parent from its own file.

#include <CLI/CLI.hpp>
#include <string>

namespace deepguide::app {

/// Options every command that reads obstacles or charts shares.
struct FrameOptions {
  std::string crs;      ///< --crs: local planning frame
  std::string src_crs;  ///< --src-crs: CRS of inputs that carry none
};
void add_frame_options(CLI::App& cmd, FrameOptions& options);

void register_obstacles_info(CLI::App& obstacles);
void register_obstacles_convert(CLI::App& obstacles);
void register_plan(CLI::App& app);
void register_check_route(CLI::App& check);

}  // namespace deepguide::app
