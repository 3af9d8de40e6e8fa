// deepguide check route ROUTE --obstacles FILE... [--margin M] [--json]

#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/planning/route_check.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/world/obstacle_io.hpp"

namespace deepguide::app {
namespace {
struct CheckOptions {
  std::string route;
  std::vector<std::string> obstacles;
  FrameOptions frame;
  double margin = 5.0;
  bool json = false;
};
}  // namespace

void register_check_route(CLI::App& check) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* cmd = check.add_subcommand(
      "route", "Exact clearance of every route segment to every obstacle; exit 1 when the route is unsafe");
  cmd->add_option("ROUTE", o->route, "Route file (GeoJSON, GPX, KML, ... with a LineString)")->required();
  cmd->add_option("--obstacles", o->obstacles, "Obstacle files")->required()->expected(1, -1);
  add_frame_options(*cmd, o->frame);
  cmd->add_option("--margin", o->margin, "Safety margin the route must keep (m)")->capture_default_str();
  cmd->add_flag("--json", o->json, "Print the verdict as JSON");
  cmd->callback([o] {
    const LoadedObstacles loaded = load_obstacles(o->obstacles, {o->frame.crs, o->frame.src_crs});
    const Route route = read_route(o->route, loaded.frame);
    if (!std::isfinite(o->margin) || o->margin < 0.0) {
      throw InputError("--margin: expected a safety margin >= 0 m, got " + std::to_string(o->margin));
    }
    const ObstacleField field(loaded.obstacles, o->margin);
    const RouteCheck check = check_route(route.points, field);
    if (o->json) {
      std::cout << nlohmann::json{{"safe", check.safe},
                                  {"min_clearance_m", check.min_clearance_m},
                                  {"worst_segment", check.worst_segment},
                                  {"worst_obstacle", check.worst_obstacle},
                                  {"margin_m", o->margin},
                                  {"length_m", route.length()}}
                       .dump(2)
                << "\n";
    } else if (check.safe) {
      std::cout << "safe: " << check.describe() << "\n";
    }
    if (!check.safe) throw InputError(o->route + ": " + check.describe());
  });
}

}  // namespace deepguide::app
