#include "deepguide/render/identification_figure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/identification/lee_goal.hpp"
#include "deepguide/identification/offset_path.hpp"
#include "deepguide/render/plot_furniture.hpp"

namespace deepguide {
namespace {

constexpr double kArrowSpacing = 56.0;  // design units

Rgba with_alpha(Rgba c, double a) {
  c.a = a;
  return c;
}

// The current the run started in at `p` (the field at time 0, or the uniform one).
Vec2 current_at(const Scenario& sc, const Vec2& p) {
  if (!sc.current_field) return sc.current;
  return sc.current_field->sample(p, sc.current_time_offset_s).value_or(Vec2(0.0, 0.0));
}

// The flow shade's polygon: the borderline's segment across the object, carried `length` m downstream.
std::vector<Vec2> shade_polygon(const Ellipse& safety, const Vec2& e, double length) {
  const Vec2 n(-e.y(), e.x());
  const double w = shade_half_width(safety, e);
  const Vec2 c = safety.centre;
  return {c + w * n, c - w * n, c - w * n + length * e, c + w * n + length * e};
}

void switch_dot(Canvas& c, const Vec2& at, const Rgba& color, double u) {
  c.circle(at, 5.0 * u, color, Stroke{rgb_hex(0xffffff), 1.6 * u, {}});
}

}  // namespace

Rgba phase_color(IdentifyPhase phase) {
  switch (phase) {
    case IdentifyPhase::evasive: return rgb_hex(0xd55e00);      // vermillion, the geometric method's
    case IdentifyPhase::positioning: return rgb_hex(0x0072b2);  // blue
    case IdentifyPhase::steering: return rgb_hex(0xcc79a7);     // reddish purple
    case IdentifyPhase::tracking: return rgb_hex(0x009e73);     // bluish green
    case IdentifyPhase::done: return rgb_hex(0x000000);
    case IdentifyPhase::overpowered: return rgb_hex(0xc92a2a);  // red
  }
  return rgb_hex(0x000000);
}

IdentificationFigure identification_figure_for(const Scenario& scenario) {
  IdentificationFigure f;
  f.scenario = scenario;
  f.run = simulate_identification(scenario, {true});
  const IdentifySpec& id = *scenario.identify;
  const bool aligning = id.mode == IdentifyMode::align;
  f.map = reactive_map_for(scenario, "");
  f.map.margin_m = aligning ? id.align.standoff_m : 0.0;
  const double c = scenario.current.norm();
  if (aligning) {
    f.map.target = f.run.goal;
    f.map.target_label = "held point";
    f.map.title = "Aligning to '" + id.object_id + "'" +
                  (scenario.current_field ? " in a current field"
                   : c > 0.0              ? " in a " + fixed(c, 1) + " m/s current"
                                          : " in still water") +
                  ": " + scenario.name;
  } else {
    // Where the vehicle was first on the path (identification_run.hpp), else where it began tracking.
    const auto on_path = std::find_if(f.run.trajectory.begin(), f.run.trajectory.end(), [&](const IdentifySample& x) {
      return f.run.stats.in_position && x.vehicle.time_s >= f.run.stats.time_to_position_s;
    });
    const auto join = std::find_if(f.run.switches.begin(), f.run.switches.end(),
                                   [](const ModeSwitch& s) { return s.to == IdentifyPhase::tracking; });
    f.map.target = on_path != f.run.trajectory.end() ? on_path->vehicle.position
                   : join != f.run.switches.end()    ? join->position
                                                     : scenario.start;
    f.map.target_label = on_path != f.run.trajectory.end() ? "on the path" : "tracking from";
    f.map.title = "Going around '" + id.object_id + "' at " + general(id.around.distance_m) + " m, " +
                  general(id.around.laps) + (id.around.laps == 1.0 ? " lap" : " laps") + ", object to " +
                  (id.around.direction > 0 ? "port" : "starboard") + ": " + scenario.name;
  }
  return f;
}

std::string identification_summary(const IdentifyResult& run) {
  const IdentifyStats& s = run.stats;
  const bool aligning = run.mode == IdentifyMode::align;
  std::string text;
  if (!s.in_position) {
    text = std::string(to_string(run.end)) + " at " + fixed(s.vehicle.time_s, 0) + " s, never in position; ";
  } else if (aligning) {
    text = "held " + fixed(s.hold_s, 0) + " s from " + fixed(s.time_to_position_s, 0) + " s; distance error RMS " +
           fixed(s.distance_error_m.rms, 2) + " m, station keeping " + fixed(s.station_keeping_m.rms, 2) + " m; ";
  } else {
    text = fixed(s.laps, 1) + " laps in " + fixed(s.vehicle.time_s, 0) + " s; cross-track RMS " +
           fixed(s.cross_track_m.rms, 2) + " m, max " + fixed(s.cross_track_m.max_abs, 2) + " m; ";
  }
  if (!run.failure.empty()) text += "FAILED; ";
  if (std::isfinite(s.vehicle.min_clearance_m)) text += "min clearance " + fixed(s.vehicle.min_clearance_m, 1) + " m";
  if (s.vehicle.collided) text += ", COLLIDED";
  return text;
}

ReactiveMapLayout render_identification_figure(const IdentificationFigure& figure, const std::string& path) {
  image_format_for(path);
  const Scenario& sc = figure.scenario;
  const IdentifyResult& run = figure.run;
  ReactiveMapLayout l;
  std::vector<IdentifyPhase> phases;              // in the order they appear
  for (const IdentifySample& x : run.trajectory)  // `done` is the last sample only: nothing to draw
    if (x.phase != IdentifyPhase::done && std::find(phases.begin(), phases.end(), x.phase) == phases.end())
      phases.push_back(x.phase);
  const bool aligning = run.mode == IdentifyMode::align;
  try {
    if (run.trajectory.empty() || !sc.identify) {
      throw InputError("identification figure: expected a recorded run of an identify section");
    }
    WorldBox extra;
    for (const IdentifySample& x : run.trajectory) extra.extend(x.vehicle.position);
    if (!aligning) {
      for (int i = 0; i < 64; ++i)
        extra.extend(
            offset_point(sc.identify->object, sc.identify->around.distance_m, 2.0 * std::numbers::pi * i / 64));
    }
    // Mode colours, the current, the path or the areas, and the outcome.
    l = reactive_map_layout(figure.map, extra, figure.width_px, phases.size() + 3, 2);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  const double u = l.unit;
  const IdentifySpec& id = *sc.identify;
  const ReactiveMapStyle& style = figure.map.style;
  Canvas canvas(path, l.width, l.height);
  begin_reactive_map(canvas, figure.map, l);
  auto px = [&](const Vec2& w) { return l.view.to_pixel(w); };
  const double diagonal = (l.area.max - l.area.min).norm();
  const Rgba area_color = rgb_hex(0x56b4e9);  // sky blue
  const Stroke guide{rgb_hex(0x495057), 1.6 * u, {9.0 * u, 5.0 * u}};

  // The current, under everything else drawn here.
  std::vector<std::pair<Vec2, Vec2>> arrows;
  const double spacing = kArrowSpacing * u;
  double strongest = 0.0;
  for (double y = l.plot.y + 0.5 * spacing; y < l.plot.y + l.plot.height; y += spacing) {
    for (double x = l.plot.x + 0.5 * spacing; x < l.plot.x + l.plot.width; x += spacing) {
      const Vec2 w = l.view.to_world(Vec2(x, y));
      if (std::any_of(figure.map.objects.begin(), figure.map.objects.end(),
                      [&](const Ellipse& o) { return security_ellipse(o, figure.map.margin_m).contains(w); })) {
        continue;
      }
      const Vec2 c = current_at(sc, w);
      strongest = std::max(strongest, c.norm());
      if (c.norm() > 0.0) add_arrow(arrows, Vec2(x, y), c.normalized(), 0.55 * spacing);
    }
  }
  const Stroke arrow_stroke{rgb_hex(0x9aa4ae), 1.3 * u, {}};
  canvas.stroke_segments(arrows, arrow_stroke);

  if (aligning) {
    const Ellipse safety = security_ellipse(id.object, id.align.standoff_m);
    const Vec2 e = (run.goal - id.object.centre).normalized();
    std::vector<Vec2> shade = shade_polygon(safety, e, diagonal);
    for (Vec2& p : shade) p = px(p);
    canvas.shape(shade, with_alpha(area_color, 0.18), Stroke{area_color, 1.4 * u, {}});
    // The object on top of the shade that starts at its centre.
    std::vector<Vec2> object = ellipse_outline(id.object, 180);
    for (Vec2& p : object) p = px(p);
    canvas.fill_rings({object}, style.obstacle);
    const Vec2 n(-e.y(), e.x());
    canvas.stroke_polyline({px(id.object.centre - diagonal * n), px(id.object.centre + diagonal * n)}, guide);
    const Vec2 lee = px(lee_goal_point(safety, e));
    canvas.circle(lee, 4.0 * u, style.background, Stroke{style.text, 1.6 * u, {}});
    // The shade's label near the far end of the stretch the plot shows, on the side away from the approach.
    double reach = 0.0;
    while (reach < diagonal && l.area.contains(run.goal + (reach + 5.0) * e)) reach += 5.0;
    canvas.text_with_halo(px(run.goal + 0.9 * reach * e - 0.8 * shade_half_width(safety, e) * n),
                          "positioning area (flow shade)", 13.0 * u, style.text, style.sea, 2.5 * u, TextAlign::right);
    canvas.text_with_halo(px(id.object.centre - 0.22 * diagonal * e + 0.08 * diagonal * n), "evasive area", 13.0 * u,
                          style.text, style.sea, 2.5 * u, TextAlign::centre);
  } else {
    std::vector<Vec2> ring;
    for (int i = 0; i < 360; ++i) {
      ring.push_back(px(offset_point(id.object, id.around.distance_m, 2.0 * std::numbers::pi * i / 360)));
    }
    canvas.stroke_polyline(ring, guide, true);
  }

  // The track, one stretch per mode.
  std::size_t begin = 0;
  while (begin < run.trajectory.size()) {
    std::size_t end = begin;
    while (end + 1 < run.trajectory.size() && run.trajectory[end + 1].phase == run.trajectory[begin].phase) ++end;
    std::vector<Vec2> line;
    // Each stretch starts where the last one ended, so the track has no gaps.
    for (std::size_t k = begin == 0 ? 0 : begin - 1; k <= end; ++k)
      line.push_back(px(run.trajectory[k].vehicle.position));
    canvas.stroke_polyline(line, Stroke{style.background, 5.0 * u, {}});
    canvas.stroke_polyline(line, Stroke{phase_color(run.trajectory[begin].phase), 2.6 * u, {}});
    begin = end + 1;
  }
  for (const ModeSwitch& s : run.switches) {
    const Vec2 at = px(s.position);
    switch_dot(canvas, at, phase_color(s.to), u);
    canvas.text_with_halo(at + Vec2(9.0 * u, 16.0 * u), fixed(s.time_s, 0) + " s", 12.0 * u, style.text, style.sea,
                          2.5 * u);
  }

  std::vector<LegendEntry> legend;
  for (IdentifyPhase p : phases) {
    const Rgba color = phase_color(p);
    legend.push_back({std::string(to_string(p)) + " mode", [color, u](Canvas& c, const Vec2& m) {
                        c.stroke_polyline({m - Vec2(15 * u, 0), m + Vec2(15 * u, 0)}, Stroke{color, 2.6 * u, {}});
                      }});
  }
  legend.push_back({"current (" + fixed(strongest, 2) + " m/s" + (sc.current_field ? " at most, at the start)" : ")"),
                    [arrow_stroke, u](Canvas& c, const Vec2& m) {
                      std::vector<std::pair<Vec2, Vec2>> a;
                      add_arrow(a, m, Vec2(1.0, 0.0), 26.0 * u);
                      c.stroke_segments(a, arrow_stroke);
                    }});
  if (aligning) {
    legend.push_back({"positioning area; lee goal point (o)", [area_color, u](Canvas& c, const Vec2& m) {
                        const std::vector<Vec2> box{m + Vec2(-15 * u, -8 * u), m + Vec2(15 * u, -8 * u),
                                                    m + Vec2(15 * u, 8 * u), m + Vec2(-15 * u, 8 * u)};
                        c.shape(box, with_alpha(area_color, 0.18), Stroke{area_color, 1.4 * u, {}});
                      }});
  } else {
    legend.push_back({"path " + general(id.around.distance_m) + " m off the object", [guide](Canvas& c, const Vec2& m) {
                        c.stroke_polyline({m - Vec2(18, 0), m + Vec2(18, 0)}, guide);
                      }});
  }
  legend.push_back(
      {identification_summary(run), [u](Canvas& c, const Vec2& m) { switch_dot(c, m, rgb_hex(0x495057), u); }});
  end_reactive_map(canvas, figure.map, l, legend);
  canvas.finish();
  return l;
}

}  // namespace deepguide
