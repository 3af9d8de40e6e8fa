#pragma once
// plan --graph octree: what apps/plan.cpp hands over once it has read the
// frame, the obstacles and the start and goal (apps/plan_depth.cpp).

#include <string>
#include <vector>

#include "deepguide/geometry/vec2.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace deepguide::app {

struct DepthCommand {
  const LocalFrame* frame = nullptr;
  ObstacleSet obstacles;
  std::vector<std::string> charts;  ///< one bathymetry raster becomes the sea floor; vector charts add obstacles
  std::string src_crs;
  Vec2 start{0.0, 0.0}, goal{0.0, 0.0};
  double depth = 0.0, from_depth = 0.0, to_depth = 0.0;  ///< NaN when not given
  std::string depth_band;   ///< "TOP,BOTTOM" or empty
  double max_dive = 0.0;    ///< NaN: from the vehicle
  std::string vehicle;
  double min_cell = 2.0;
  bool smooth = false;
  double margin = 5.0, vertical_clearance = 2.0;
  std::string search = "astar";
  std::string output, render, render_profile;
  bool json = false;
};

void run_plan_in_depth(const DepthCommand& command);

}  // namespace deepguide::app
