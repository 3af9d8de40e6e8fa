#pragma once
// `plan`'s flags as apps/plan.cpp binds them: most straight into the
// library's request, the rest parsed by apps/plan_run.cpp; the route in
// depth's own flags and run in apps/plan_depth.cpp.

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "deepguide/planning/route_plan_report.hpp"

namespace deepguide::app {

struct DepthFlags {
  double from_depth = std::nan(""), to_depth = std::nan("");  ///< default --depth
  std::string depth_band;                                     ///< "TOP,BOTTOM" or empty
  double max_dive = std::nan("");                             ///< NaN: from the vehicle
  std::string render_profile;
};
void add_depth_flags(CLI::App& cmd, DepthFlags& flags);
/// Bad input for the graph asked for: depth flags without --graph octree, or
/// 2-D flags with it. `flags_2d`: the 2-D-only flags given.
void check_depth_flags(bool in_depth, const DepthFlags& flags, bool flags_2d);

struct PlanOutputs {
  std::string route_file, render, html;
  bool json = false;
};
/// Shares the 2-D request's obstacles, charts, ends, depth, margin, cells and vehicle.
void run_plan_in_depth(const LocalFrame& frame, const RoutePlanRequest& shared, const DepthFlags& flags,
                       const PlanOutputs& outputs);

struct PlanCommand {
  RoutePlanRequest request;  ///< most flags land here directly
  std::vector<std::string> obstacles;
  std::string from, to, graph, search = "astar", cost = "length";  // graph: empty = default_plan_graph
  std::string current_const, depart;
  std::optional<double> from_heading, to_heading;  ///< deg, clockwise from true north
  bool no_refine = false, render_graph = false;
  FrameOptions frame;
  PlanOutputs out;
  DepthFlags depth;
};

/// Parses what the library does not take as text, reads the frame, the
/// obstacles and the ends, plans (in depth with --graph octree), writes,
/// draws and prints.
void run_plan(PlanCommand& command);

}  // namespace deepguide::app
