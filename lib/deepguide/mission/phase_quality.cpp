#include "deepguide/mission/phase_quality.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/mission_environment.hpp"

namespace deepguide {

namespace {

// Arcs as chords at most 5 cm inside them (the plan checker's tolerance).
constexpr double kChordToleranceM = 0.05;

}  // namespace

std::vector<PhaseQuality> phase_quality(const Mission& mission, const MissionPlan& plan, const ChartOptions& chart) {
  std::vector<PhaseQuality> out;
  const std::vector<std::string> cells = enc_charts_of(mission);
  if (cells.empty() || plan.basics.empty()) return out;

  // Each phase's track: the start of its first basic manoeuvre, then every point of its own.
  std::map<std::size_t, std::vector<Vec2>> tracks;
  std::map<std::size_t, PhaseQuality> phases;
  for (const TrackPoint& p : plan_polyline(plan, kChordToleranceM)) {
    const BasicManoeuvre& b = plan.basics[p.basic];
    std::vector<Vec2>& track = tracks[b.source];
    PhaseQuality& q = phases[b.source];
    if (track.empty()) {
      track.push_back(b.from);
      q.from_m = b.start_m;
      q.depth_m = b.from_depth_m;
    }
    if ((track.back() - p.xy).norm() > 1e-9) track.push_back(p.xy);
    q.depth_m = std::max({q.depth_m, b.from_depth_m, b.depth_m});
  }

  std::map<double, EncNoGo> no_go_at;  // by required depth
  for (auto& [source, q] : phases) {
    const std::vector<Vec2>& track = tracks[source];
    if (track.size() < 2) continue;
    const ComplexManoeuvre& c = mission.manoeuvres[source];
    q.manoeuvre = source;
    q.type = c.type;
    q.name = c.name;
    q.required_depth_m = q.depth_m + mission.vertical_clearance_m;
    auto it = no_go_at.find(q.required_depth_m);
    if (it == no_go_at.end()) {
      EncNoGoOptions o = enc_options(chart, q.depth_m, mission.vertical_clearance_m);
      o.planner_obstacles = false;  // the features are what the quality is measured on
      it = no_go_at.emplace(q.required_depth_m, enc_no_go(cells, mission.frame, o)).first;
    }
    q.quality = route_quality(track, it->second);
    out.push_back(std::move(q));
  }
  return out;
}

nlohmann::json phase_quality_json(const std::vector<PhaseQuality>& phases, const LocalFrame& frame) {
  nlohmann::json list = nlohmann::json::array();
  for (const PhaseQuality& p : phases) {
    nlohmann::json j = p.quality.to_json(frame);
    j["manoeuvre"] = p.manoeuvre + 1;
    j["type"] = p.type;
    j["name"] = p.name;
    j["depth_m"] = p.depth_m;
    j["required_depth_m"] = p.required_depth_m;
    j["from_m"] = p.from_m;
    j["length_m"] = p.quality.length_m;
    list.push_back(std::move(j));
  }
  return list;
}

std::string phase_quality_text(const std::vector<PhaseQuality>& phases, const LocalFrame& frame) {
  std::string t;
  for (const PhaseQuality& p : phases) {
    t += report_line("phase " + std::to_string(p.manoeuvre + 1),
                     p.type + " '" + printable(p.name) + "': " + fixed(p.quality.length_m, 0) + " m from " +
                         fixed(p.from_m, 0) + " m along, at " + general(p.depth_m, 4) + " m (required depth " +
                         general(p.required_depth_m, 4) + " m)");
    t += p.quality.to_text(frame);
  }
  return t;
}

}  // namespace deepguide
