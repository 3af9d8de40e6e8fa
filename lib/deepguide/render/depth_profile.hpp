#pragma once
// The depth profile of a route planned in depth (plan --graph octree
// --render): the vertical section along the route's horizontal track, with
// distance along the track across and depth down.
//
// Drawn, back to front: the octree's cells the section cuts (free light,
// occupied grey, each cell's edges, so the seed's Fig. 7 shows in depth), the
// depth band's top and bottom, each obstacle whose zone the track crosses
// (from its top down, its top less the clearance dashed), the sea floor
// (brown, with the clearance line above it), and the route with its
// waypoints. Depth grows downwards; the vertical exaggeration is stated.
// Layout (design units at 1200 px wide): title band 52 | y title 22 | plot
// 420 | distance numbers and title 52 | legend | 10.

#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/planning/depth_planning.hpp"

namespace DEEPGUIDE_API deepguide {

struct DepthProfileLayout {
  int width = 0;
  int height = 0;
  double unit = 1.0;
  double along_m = 0.0;                            ///< the track's horizontal length
  double depth_top_m = 0.0, depth_bottom_m = 0.0;  ///< the depth axis
  double exaggeration = 1.0;                       ///< vertical scale over horizontal scale
  std::size_t obstacles_crossed = 0;               ///< obstacles whose zone the track crosses
};

/// Draws the profile of plan's route to `path` (.png or .svg), atomically.
/// Throws InputError for a plan without a route in depth or a bad width.
DepthProfileLayout render_depth_profile(const DepthPlan& plan, const std::string& title, const std::string& path,
                                        int width_px = 1200);

}  // namespace deepguide
