#include "deepguide/render/mission_figure.hpp"

#include <algorithm>
#include <numbers>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/mission_environment.hpp"
#include "deepguide/simulation/mission_run.hpp"

namespace deepguide {
namespace {

// The plan's track split where the role changes: one polyline per run.
struct Run {
  BasicManoeuvre::Role role;
  std::vector<Vec2> points;
};

std::vector<Run> runs_of(const MissionPlan& plan) {
  std::vector<Run> out;
  const std::vector<TrackPoint> track = plan_polyline(plan, 0.5);
  for (std::size_t k = 1; k < track.size(); ++k) {
    const BasicManoeuvre::Role role = plan.basics[track[k].basic].role;
    if (out.empty() || out.back().role != role) out.push_back({role, {track[k - 1].xy}});
    out.back().points.push_back(track[k].xy);
  }
  return out;
}

}  // namespace

MissionFigure mission_figure_for(const Mission& mission, const MissionPlan& written, const PlannedMission& planned) {
  MissionFigure f;
  f.charts = mission.charts;
  f.obstacles = mission.obstacles;
  f.crs = mission.frame.id();
  f.plan = &planned.plan;
  f.written = &written;
  for (const Resolution& r : planned.resolutions) {
    f.conflicts.push_back(r.conflict.where);
    if (!r.resolved) f.unresolved.push_back(r.conflict.where);
  }
  return f;
}

MissionFigure simulated_mission_figure(const Mission& mission, const MissionPlan& written,
                                       const PlannedMission& planned, const MissionRun& run, double zoom_m) {
  MissionFigure f = mission_figure_for(mission, written, planned);
  f.plan = &run.plan;
  for (const MissionSample& p : run.track) {
    f.track.push_back(p.position);
    f.track_reactive.push_back(p.reactive);
  }
  const auto first_reactive =
      std::find_if(run.track.begin(), run.track.end(), [](const MissionSample& p) { return p.reactive; });
  // The sample before the first reactive one is where the reactive level took the helm.
  if (first_reactive != run.track.end()) {
    f.marks.emplace_back((first_reactive == run.track.begin() ? first_reactive : first_reactive - 1)->position, "A");
  }
  f.detected = &run.detected;
  if (zoom_m > 0.0 && !run.detected.ellipses.empty()) {
    const Vec2 c = run.detected.ellipses.front().footprint.centre;
    f.extent.extend(c - Vec2::Constant(zoom_m));
    f.extent.extend(c + Vec2::Constant(zoom_m));
  }
  f.title = mission.name + ", simulated: " + (run.completed ? "completed" : "NOT completed") + " in " +
            clock_text(run.time_s) + ", " + std::to_string(run.detected.size()) + " unknown object(s), " +
            std::to_string(run.replans) + " replan(s)";
  return f;
}

ChartLayout render_mission(const MissionFigure& f, const std::string& path, const MissionStyle& style) {
  if (f.plan == nullptr || f.plan->basics.empty()) throw InputError(path + ": expected a mission plan to draw");
  if (!f.track_reactive.empty() && f.track_reactive.size() != f.track.size()) {
    throw InputError(path + ": expected one reactive flag per track point");
  }
  const std::vector<Run> runs = runs_of(*f.plan);
  const std::vector<Run> written = f.written != nullptr ? runs_of(*f.written) : std::vector<Run>{};
  WorldBox box;
  for (const auto* set : {&runs, &written}) {
    for (const Run& r : *set) {
      for (const Vec2& p : r.points) box.extend(p);
    }
  }
  for (const Vec2& p : f.track) box.extend(p);
  const double pad = std::max(150.0, 0.1 * std::max(box.width(), box.height()));

  ChartRenderOptions o;
  o.charts = f.charts;
  o.obstacles = f.obstacles;
  if (o.charts.empty()) std::swap(o.charts, o.obstacles);  // obstacle files alone draw as a chart of hazards
  if (o.charts.empty()) throw InputError(path + ": expected a mission with charts or obstacle files to draw it over");
  o.local_crs = f.crs;
  o.title = f.title;
  o.width_px = f.width_px;
  o.extent = f.extent.empty() ? box.padded(pad) : f.extent;
  const auto colour = [&](BasicManoeuvre::Role role) {
    switch (role) {
      case BasicManoeuvre::Role::evasion: return style.evasion;
      case BasicManoeuvre::Role::identification: return style.identification;
      case BasicManoeuvre::Role::mission: break;
    }
    return style.mission;
  };
  o.overlay = [&](Canvas& canvas, const ViewTransform& view, double u) {
    const auto px = [&](const std::vector<Vec2>& pts) {
      std::vector<Vec2> out;
      out.reserve(pts.size());
      for (const Vec2& p : pts) out.push_back(view.to_pixel(p));
      return out;
    };
    for (const Run& r : written)
      canvas.stroke_polyline(px(r.points), Stroke{style.written, 1.4 * u, {5.0 * u, 4.0 * u}});
    if (f.detected != nullptr) {
      for (const EllipticCylinder& c : f.detected->ellipses) {
        std::vector<Vec2> ring;
        for (int k = 0; k < 48; ++k) ring.push_back(c.footprint.point_at(2.0 * std::numbers::pi * k / 48));
        canvas.shape(px(ring), Rgba{style.conflict.r, style.conflict.g, style.conflict.b, 0.35},
                     Stroke{style.conflict, 1.4 * u, {}});
      }
    }
    for (const Run& r : runs) {
      const Rgba c = colour(r.role);
      canvas.stroke_polyline(px(r.points), Stroke{style.casing, 4.8 * u, {}});
      canvas.stroke_polyline(px(r.points), Stroke{c, 2.4 * u, {}});
    }
    if (!f.track.empty()) {
      canvas.stroke_polyline(px(f.track), Stroke{style.casing, 3.8 * u, {}});
      // Runs of one level each, sharing their end points so the line has no gaps.
      const auto level = [&](std::size_t i) { return !f.track_reactive.empty() && f.track_reactive[i]; };
      std::size_t begin = 0;
      while (begin + 1 < f.track.size()) {
        const bool reactive = level(begin + 1);
        std::size_t end = begin + 1;
        while (end + 1 < f.track.size() && level(end + 1) == reactive) ++end;
        const std::vector<Vec2> piece(f.track.begin() + static_cast<std::ptrdiff_t>(begin),
                                      f.track.begin() + static_cast<std::ptrdiff_t>(end) + 1);
        canvas.stroke_polyline(px(piece), Stroke{reactive ? style.reactive : style.track, 1.8 * u, {}});
        begin = end;
      }
    }
    for (const Vec2& p : f.conflicts) {
      canvas.circle(view.to_pixel(p), 7.0 * u, std::nullopt, Stroke{style.casing, 4.4 * u, {}});
      canvas.circle(view.to_pixel(p), 7.0 * u, std::nullopt, Stroke{style.conflict, 2.2 * u, {}});
    }
    for (const Vec2& p : f.unresolved) {
      const Vec2 c = view.to_pixel(p);
      const double s = 8.0 * u;
      const Stroke cross{style.conflict, 3.0 * u, {}};
      canvas.stroke_polyline({c + Vec2(-s, -s), c + Vec2(s, s)}, cross);
      canvas.stroke_polyline({c + Vec2(-s, s), c + Vec2(s, -s)}, cross);
    }
    for (const auto& [where, label] : f.marks) {
      const Vec2 c = view.to_pixel(where);
      canvas.circle(c, 4.5 * u, style.end, Stroke{Rgba{1.0, 1.0, 1.0, 1.0}, 1.5 * u, {}});
      canvas.text_with_halo(c + Vec2(-9.0 * u, -7.0 * u), label, 17.0 * u, style.end, Rgba{1.0, 1.0, 1.0, 0.9}, 3.0 * u,
                            TextAlign::right);
    }
    const Vec2 start = f.plan->basics.front().from, end = f.plan->basics.back().to;
    canvas.circle(view.to_pixel(start), 6.0 * u, style.start, Stroke{Rgba{1.0, 1.0, 1.0, 1.0}, 1.5 * u, {}});
    canvas.circle(view.to_pixel(end), 6.0 * u, style.end, Stroke{Rgba{1.0, 1.0, 1.0, 1.0}, 1.5 * u, {}});
  };
  o.overlay_legend.push_back({style.mission, 2.4, false, "mission"});
  bool evades = false, identifies = false;
  for (const Run& r : runs) {
    evades = evades || r.role == BasicManoeuvre::Role::evasion;
    identifies = identifies || r.role == BasicManoeuvre::Role::identification;
  }
  if (evades) o.overlay_legend.push_back({style.evasion, 2.4, false, "evasion"});
  if (identifies) o.overlay_legend.push_back({style.identification, 2.4, false, "identification lap"});
  if (!written.empty()) o.overlay_legend.push_back({style.written, 1.4, true, "as written"});
  if (!f.conflicts.empty()) {
    o.overlay_legend.push_back(
        {style.conflict, 2.2, false, f.unresolved.empty() ? "conflict (ring)" : "conflict (ring), unresolved (cross)"});
  }
  const bool reactive = std::find(f.track_reactive.begin(), f.track_reactive.end(), true) != f.track_reactive.end();
  if (!f.track.empty())
    o.overlay_legend.push_back({style.track, 1.8, false, reactive ? "track, plan level" : "track sailed"});
  if (reactive) o.overlay_legend.push_back({style.reactive, 1.8, false, "track, reactive level"});
  if (f.detected != nullptr && !f.detected->empty()) {
    o.overlay_legend.push_back({style.conflict, 5.0, false, "object the sonar found (its estimate)"});
  }
  return render_chart(o, path);
}

ChartLayout render_mission_file(const std::string& mission, const std::string& path, const MissionFileFigure& o) {
  const LoadedMission l = load_mission(mission);
  const PlannedMission planned = plan_mission(l.mission, l.env, l.plan);
  MissionFigure f = mission_figure_for(l.mission, l.plan, planned);
  if (o.as_written) {
    f.plan = &l.plan;
    f.written = nullptr;
  }
  f.width_px = o.width_px;
  const MissionPlan& shown = *f.plan;
  f.title = !o.title.empty()
                ? o.title
                : printf_text("%s: %.2f km, %s; %zu conflict(s), %zu resolved", printable(l.mission.name, 120).c_str(),
                              shown.length_m / 1000.0, clock_text(plan_duration(shown)).c_str(),
                              planned.resolutions.size(), planned.resolutions.size() - f.unresolved.size());
  return render_mission(f, path);
}

}  // namespace deepguide
