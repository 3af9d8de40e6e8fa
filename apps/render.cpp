// deepguide render route --obstacles FILE... --route ROUTE [--margin M] [--graph KIND] [--width PX] -o OUT.png|svg

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/planning/graph_registry.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/route_io.hpp"
#include "deepguide/render/graph_layers.hpp"
#include "deepguide/render/route_scene.hpp"

// Under AddressSanitizer, fontconfig's caches (reached through Cairo's text)
// show up as leaks at exit; they are third-party, once per process, and freed
// only by FcFini(). These hooks, read by the sanitizer runtime and inert in
// other builds, suppress exactly those reports and keep stderr clean.
extern "C" const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }

namespace deepguide::app {

namespace {

struct RenderRouteOptions {
  std::vector<std::string> obstacles;
  std::string route, output, title;
  FrameOptions frame;
  double margin = 5.0;
  double tolerance = PlannerOptions{}.tolerance;
  std::string graph = "none";
  int width = 1200;
};

}  // namespace

void register_render_route(CLI::App& render) {
  auto o = std::make_shared<RenderRouteOptions>();
  CLI::App* cmd = render.add_subcommand(
      "route", "Draw obstacles, safety zones, optionally the planning graph, and a route as PNG or SVG");
  cmd->add_option("--obstacles", o->obstacles, "Obstacle files (GeoJSON, GeoPackage, Shapefile, CSV, ...)")
      ->required()
      ->expected(1, -1);
  cmd->add_option("--route", o->route, "Route file (GeoJSON, GPX, KML, ... with a LineString)")->required();
  cmd->add_option("-o,--output", o->output, "Image to write: .png or .svg")->required();
  add_frame_options(*cmd, o->frame);
  cmd->add_option("--margin", o->margin, "Safety margin drawn around every obstacle (m)")->capture_default_str();
  cmd->add_option("--tolerance", o->tolerance, "Zone polygon tolerance for --graph (m)")->capture_default_str();
  cmd->add_option("--graph", o->graph,
                  "Planning graph to draw: none, or a plan --graph kind (visibility, visibility-full, ...)")
      ->capture_default_str();
  cmd->add_option("--width", o->width, "Image width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(kMinImageWidth, kMaxImageWidth));
  cmd->add_option("--title", o->title, "Title line (default: route file, length, waypoints, margin, CRS)");
  cmd->callback([o] {
    image_format_for(o->output);  // fail fast, before reading anything
    if (!std::isfinite(o->margin) || o->margin < 0.0) {
      throw InputError("--margin: expected a safety margin >= 0 m, got " + std::to_string(o->margin));
    }
    std::optional<GraphKind> graph;
    if (o->graph != "none") {
      const auto plane = [](const GraphEntry& e) { return !e.can.in_depth; };
      const std::vector<GraphEntry> entries = graph_entries();
      if (std::none_of(entries.begin(), entries.end(),
                       [&](const GraphEntry& e) { return e.name == o->graph && plane(e); })) {
        throw InputError("--graph: expected none, " + graph_names_text(plane) + ", got '" + printable(o->graph) + "'");
      }
      graph = GraphKind{o->graph};
    }
    const LoadedObstacles loaded = load_obstacles(o->obstacles, {o->frame.crs, o->frame.src_crs});
    const Route route = read_route(o->route, loaded.frame);

    RouteScene scene;
    scene.obstacles = &loaded.obstacles;
    scene.margin = o->margin;
    scene.route = route.points;
    if (!route.points.empty()) {
      scene.start = route.points.front();
      scene.goal = route.points.back();
      scene.true_north_deg = true_north_deg(loaded.frame, route.points.front());
    }
    scene.title = o->title.empty()
                      ? route_title(std::filesystem::path(o->route).filename().string(), route, o->margin, loaded.frame)
                      : o->title;
    std::optional<Planner> planner;
    if (graph) {
      planner.emplace(loaded.obstacles,
                      PlannerOptions{.margin = o->margin, .tolerance = o->tolerance, .graph = *graph});
      add_graph_layers(*planner, scene);
    }
    render_route(scene, o->output, o->width);
    std::printf("wrote            %s\n", o->output.c_str());
  });
}

}  // namespace deepguide::app
