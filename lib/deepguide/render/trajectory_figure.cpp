#include "deepguide/render/trajectory_figure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace deepguide {
namespace {

void end_cross(Canvas& c, const Vec2& at, const Rgba& color, double u) {
  const double r = 7.0 * u;
  const std::vector<std::pair<Vec2, Vec2>> x{{at + Vec2(-r, -r), at + Vec2(r, r)},
                                             {at + Vec2(-r, r), at + Vec2(r, -r)}};
  c.stroke_segments(x, Stroke{rgb_hex(0xffffff), 6.0 * u, {}});
  c.stroke_segments(x, Stroke{color, 3.0 * u, {}});
}

/// A red ring where a run was deepest inside an obstacle.
void collision_ring(Canvas& c, const Vec2& at, double u) {
  c.circle(at, 9.0 * u, std::nullopt, Stroke{rgb_hex(0xffffff), 5.0 * u, {}});
  c.circle(at, 9.0 * u, std::nullopt, Stroke{rgb_hex(0xc92a2a), 2.6 * u, {}});
}

}  // namespace

TrajectoryFigure trajectory_figure_for(const Scenario& scenario, std::span<const ReactiveMethod> methods) {
  TrajectoryFigure f;
  f.map = reactive_map_for(scenario, "Trajectories of the reactive methods: " + scenario.name);
  for (const ReactiveMethod& m : methods) f.runs.push_back(simulate(scenario, m, {true}));
  return f;
}

std::string run_summary(const SimulationResult& run) {
  const SimulationStats& s = run.stats;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s in %.1f s, %.1f m, ", std::string(to_string(run.end)).c_str(), s.time_s,
                s.path_length_m);
  std::string text = std::string(to_string(run.method)) + ": " + buf;
  if (std::isfinite(s.min_clearance_m)) {
    std::snprintf(buf, sizeof buf, "min clearance %.1f m, ", s.min_clearance_m);
    text += buf;
  }
  std::snprintf(buf, sizeof buf, "max |r| %.1f \u00b0/s", rad_to_deg(s.max_abs_rate));
  text += buf;
  if (s.collided) text += ", COLLIDED";
  return text;
}

ReactiveMapLayout render_trajectory_figure(const TrajectoryFigure& figure, const std::string& path) {
  image_format_for(path);
  ReactiveMapLayout l;
  try {
    if (figure.runs.empty()) throw InputError("trajectory figure: expected at least one run");
    WorldBox tracks;
    for (const SimulationResult& run : figure.runs) {
      if (run.trajectory.empty()) {
        throw InputError("trajectory figure: expected a recorded trajectory for the " +
                         std::string(to_string(run.method)) + " method");
      }
      for (const TrajectorySample& s : run.trajectory) tracks.extend(s.position);
    }
    const bool collided =
        std::any_of(figure.runs.begin(), figure.runs.end(), [](const SimulationResult& r) { return r.stats.collided; });
    l = reactive_map_layout(figure.map, tracks, figure.width_px, figure.runs.size() + (collided ? 1 : 0), 1);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  const double u = l.unit;
  Canvas canvas(path, l.width, l.height);
  begin_reactive_map(canvas, figure.map, l);
  for (const SimulationResult& run : figure.runs) {
    std::vector<Vec2> line;
    line.reserve(run.trajectory.size());
    for (const TrajectorySample& s : run.trajectory) line.push_back(l.view.to_pixel(s.position));
    canvas.stroke_polyline(line, Stroke{figure.map.style.background, 5.0 * u, {}});
    canvas.stroke_polyline(line, Stroke{method_color(run.method), 2.6 * u, {}});
  }
  bool collided = false;
  for (const SimulationResult& run : figure.runs) {
    if (run.end != SimulationEnd::reached) {
      end_cross(canvas, l.view.to_pixel(run.trajectory.back().position), method_color(run.method), u);
    }
    if (run.stats.collided) {
      collided = true;
      const auto deepest = std::min_element(
          run.trajectory.begin(), run.trajectory.end(),
          [](const TrajectorySample& a, const TrajectorySample& b) { return a.clearance_m < b.clearance_m; });
      collision_ring(canvas, l.view.to_pixel(deepest->position), u);
    }
  }
  std::vector<LegendEntry> legend;
  for (const SimulationResult& run : figure.runs) {
    const Rgba color = method_color(run.method);
    const bool short_of_target = run.end != SimulationEnd::reached;
    legend.push_back({run_summary(run), [color, short_of_target, u](Canvas& c, const Vec2& m) {
                        c.stroke_polyline({m - Vec2(15 * u, 0), m + Vec2(15 * u, 0)}, Stroke{color, 2.6 * u, {}});
                        if (short_of_target) end_cross(c, m + Vec2(15 * u, 0), color, u);
                      }});
  }
  if (collided) {
    legend.push_back({"collision: the deepest point inside an obstacle",
                      [u](Canvas& c, const Vec2& m) { collision_ring(c, m, u); }});
  }
  end_reactive_map(canvas, figure.map, l, legend);
  canvas.finish();
  return l;
}

}  // namespace deepguide
