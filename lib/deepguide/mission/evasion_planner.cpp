#include "deepguide/mission/evasion_planner.hpp"

#include <limits>
#include <map>
#include <optional>

#include "deepguide/charts/no_go.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/mission_control.hpp"
#include "deepguide/planning/planner.hpp"
#include "deepguide/planning/single_query.hpp"
#include "deepguide/world/obstacle_field.hpp"

namespace deepguide {
namespace {

constexpr double kExtraZone = 0.2;      // m beyond the corridor: mission_control.hpp says why
constexpr double kNoGoTolerance = 2.0;  // m: how far no-go polygons may reach outside the shallow cells

void append(ObstacleSet& to, const ObstacleSet& more) {
  to.ellipses.insert(to.ellipses.end(), more.ellipses.begin(), more.ellipses.end());
  to.polygons.insert(to.polygons.end(), more.polygons.begin(), more.polygons.end());
}

}  // namespace

struct EvasionPlanner::Impl {
  Impl(const Mission& mission, MissionEnvironment environment)
      : env(std::move(environment)),
        frame(mission.frame),
        graph(mission.control.evasion_graph),
        observe(observation_options(mission)),
        zone_margin(observe.margin_m + observe.half_width_m + kExtraZone),
        field(env.obstacles, zone_margin) {
    make_volume();
  }

  MissionEnvironment env;
  LocalFrame frame;
  GraphKind graph;
  ObservationOptions observe;
  double zone_margin;
  ObstacleField field;  // of env.obstacles; the volume points into it
  std::optional<WaterVolume> volume;
  std::map<double, ObstacleSet> floor_at;  // the sea floor's no-go polygons per depth
  std::map<double, ObstacleSet> at_depth;  // what a vehicle at that depth goes around
  std::map<double, ObstacleField> fields;  // their exact fields
  std::map<double, Planner> meshes;        // with graph navmesh: the kept mesh per depth

  void make_volume() {
    volume.emplace(field, env.floor.get(),
                   VolumeOptions{observe.vertical_clearance_m, 0.0, std::numeric_limits<double>::infinity()});
  }

  // Obstacle i of `set` (ellipses first), numbered from `first` in env.obstacles, is under a vehicle at `depth`'s way.
  ObstacleSet blocking(const ObstacleSet& set, std::size_t first_ellipse, std::size_t first_polygon,
                       double depth) const {
    ObstacleSet out;
    const std::size_t ellipses = env.obstacles.ellipses.size();
    for (std::size_t i = 0; i < set.ellipses.size(); ++i) {
      if (volume->zone_top(first_ellipse + i) < depth) out.ellipses.push_back(set.ellipses[i]);
    }
    for (std::size_t j = 0; j < set.polygons.size(); ++j) {
      if (volume->zone_top(ellipses + first_polygon + j) < depth) out.polygons.push_back(set.polygons[j]);
    }
    return out;
  }

  const ObstacleSet& floor_no_go(double depth) {
    auto found = floor_at.find(depth);
    if (found != floor_at.end()) return found->second;
    ObstacleSet out;
    if (env.floor) {
      NoGoOptions o;
      o.operating_depth_m = depth;
      o.vertical_clearance_m = observe.vertical_clearance_m;
      o.simplify_tolerance_m = kNoGoTolerance;
      out.polygons = compute_no_go(*env.floor, frame, o).polygons;
    }
    return floor_at.emplace(depth, std::move(out)).first->second;
  }

  const ObstacleSet& obstacles_at(double depth) {
    auto found = at_depth.find(depth);
    if (found != at_depth.end()) return found->second;
    ObstacleSet out = blocking(env.obstacles, 0, 0, depth);
    append(out, floor_no_go(depth));
    return at_depth.emplace(depth, std::move(out)).first->second;
  }

  // The kept planner at `depth`: built on first use, over everything there.
  Planner& mesh_at(double depth) {
    auto found = meshes.find(depth);
    if (found != meshes.end()) return found->second;
    PlannerOptions options;
    options.margin = zone_margin;
    options.graph = graph;
    return meshes.emplace(depth, Planner(obstacles_at(depth), options)).first->second;
  }

  PlanOutcome plan(double depth, const Vec2& from, const Vec2& to) {
    if (graph_entry(graph).can.covers_area) return mesh_at(depth).solve({from, to, false});
    PlannerOptions options;
    options.margin = zone_margin;
    options.graph = graph;
    return plan_single_query(obstacles_at(depth), {from, to, false}, options).outcome;
  }
};

EvasionPlanner::EvasionPlanner(const Mission& mission, MissionEnvironment environment)
    : impl_(std::make_unique<Impl>(mission, std::move(environment))) {}
EvasionPlanner::~EvasionPlanner() = default;

const MissionEnvironment& EvasionPlanner::environment() const { return impl_->env; }
const ObservationOptions& EvasionPlanner::observe() const { return impl_->observe; }
const WaterVolume& EvasionPlanner::volume() const { return *impl_->volume; }
double EvasionPlanner::zone_margin() const { return impl_->zone_margin; }

void EvasionPlanner::add(const ObstacleSet& found) {
  if (found.empty()) return;
  Impl& m = *impl_;
  const std::size_t first_ellipse = m.env.obstacles.ellipses.size(), first_polygon = m.env.obstacles.polygons.size();
  ObstacleSet all = m.env.obstacles;
  append(all, found);
  // The new field and volume first: a bad obstacle (no top, say) throws here
  // and leaves everything as it was.
  ObstacleField field(all, m.zone_margin);
  m.env.obstacles = std::move(all);
  m.field = std::move(field);  // the same object: the volume's pointer stays good
  m.make_volume();
  m.fields.clear();
  for (auto& [depth, set] : m.at_depth) {
    const ObstacleSet more = m.blocking(found, first_ellipse, first_polygon, depth);
    append(set, more);
    if (auto mesh = m.meshes.find(depth); mesh != m.meshes.end()) mesh->second.insert(more);
  }
}

std::vector<Vec2> EvasionPlanner::route(double depth, const Vec2& from, const Vec2& to, std::string& problem) {
  if ((to - from).norm() < 1e-6) return {from, to};
  try {
    const PlanOutcome plan = impl_->plan(depth, from, to);
    if (!plan.result.found) {
      problem = "no safe route at " + fixed(depth, 1) + " m" + " from " + point_text(from) + " to " + point_text(to) +
                (plan.result.message.empty() ? "" : ": " + plan.result.message);
      return {};
    }
    if (!plan.check.safe) {
      problem = "the route at " + fixed(depth, 1) + " m" + " fails the route checker: " + plan.check.describe();
      return {};
    }
    return plan.result.route.points;
  } catch (const NoRouteError& e) {
    problem = "no safe route at " + fixed(depth, 1) + " m" + ": " + e.what();
  } catch (const InputError& e) {
    problem = "no safe route at " + fixed(depth, 1) + " m" + ": " + e.what();
  }
  return {};
}

bool EvasionPlanner::free_at(double depth, const Vec2& p) {
  auto found = impl_->fields.find(depth);
  if (found == impl_->fields.end()) {
    found = impl_->fields.emplace(depth, ObstacleField(impl_->obstacles_at(depth), impl_->zone_margin)).first;
  }
  return found->second.is_free(p);
}

}  // namespace deepguide
