#include "deepguide/render/route_plan_figure.hpp"

#include "deepguide/core/format.hpp"
#include "deepguide/render/graph_layers.hpp"
#include "deepguide/render/route_on_chart.hpp"
#include "deepguide/render/route_scene.hpp"

namespace deepguide {
namespace {

const char* kTitle = "deepguide plan";

void add_replay(const RoutePlanReport& report, RouteScene& scene, ObstacleSet& detected) {
  for (const ReplanEvent& d : report.detections) {
    detected.ellipses.insert(detected.ellipses.end(), d.obstacles.ellipses.begin(), d.obstacles.ellipses.end());
    detected.polygons.insert(detected.polygons.end(), d.obstacles.polygons.begin(), d.obstacles.polygons.end());
  }
  scene.detected = &detected;
  for (const Repair& r : report.replay->repairs) {
    if (r.found) scene.repaired_routes.push_back(r.route);
  }
  scene.track = report.replay->track;
}

}  // namespace

void render_route_plan(const RoutePlanReport& report, const std::string& path, bool draw_graph) {
  const RoutePlanRequest& r = report.request;
  const std::string title = route_title(kTitle, report.route, r.margin_m, report.frame);
  if (report.enc_charts) {
    RouteOnChart figure;
    figure.chart.charts = r.charts;
    figure.chart.depth_m = r.depth_m;
    figure.chart.clearance_m = r.vertical_clearance_m;
    figure.chart.chart_options = r.chart;
    figure.chart.local_crs = report.frame.id();
    figure.chart.title = title;
    figure.route = report.route.points;
    render_route_on_chart(figure, path);
    return;
  }
  RouteScene scene;
  scene.obstacles = &report.obstacles;
  scene.margin = r.margin_m;
  scene.route = report.route.points;
  scene.start = r.problem.start;
  scene.goal = r.problem.goal;
  scene.true_north_deg = true_north_deg(report.frame, r.problem.start);
  scene.title = title;
  const auto model = report.model;
  if (model->current) {
    scene.current = [model](const Vec2& p) { return model->current(p, model->depart_s); };
    scene.current_label = std::string("current") + (report.timed ? " at departure" : "") + " (fastest " +
                          fixed(model->max_current_mps, 2) + " m/s)";
  }
  if (model->current || model->economical) {
    for (const PricedLeg& leg : report.priced.legs) {
      const LegCost& c = leg.cost;
      scene.leg_labels.push_back(c.feasible ? fixed(c.speed_mps, 2) + " m/s, " + clock_text(c.time_s) + ", " +
                                                  fixed(c.energy_j / 1e3, 0) + " kJ"
                                            : fixed(c.speed_mps, 2) + " m/s: the current wins");
    }
  }
  ObstacleSet detected;
  if (report.replay) add_replay(report, scene, detected);
  if (draw_graph) add_graph_layers(*report.plan.planner, scene);
  render_route(scene, path);
}

}  // namespace deepguide
