#include "deepguide/mission/mission_environment.hpp"
#include "deepguide/charts/raster_sea_floor.hpp"

#include <cmath>

#include "deepguide/currents/current_field.hpp"

#include <cstdio>
#include <limits>

#include "deepguide/charts/chart_info.hpp"
#include "deepguide/charts/chart_obstacles.hpp"
#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/charts/enc_sea_floor.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/world/obstacle_field.hpp"
#include "deepguide/world/water_volume.hpp"

namespace deepguide {

Vec2 constant_current(const Mission& mission) {
  if (mission.current.empty()) return Vec2::Zero();
  const CurrentField c = parse_constant_current(mission.current, mission.source + ": environment.current");
  const double speed = c.constant_velocity.norm();
  if (speed == 0.0) return Vec2::Zero();
  const double dir_deg = std::atan2(c.constant_velocity.x(), c.constant_velocity.y()) * 180.0 / M_PI;
  const double a = mission.frame.heading_to_local(dir_deg, mission.start);
  return speed * Vec2(std::cos(a), std::sin(a));
}

std::vector<std::string> enc_charts_of(const Mission& mission) {
  std::vector<std::string> enc;
  for (const std::string& path : mission.charts) {
    if (names_enc(path) || chart_kind(path) == ChartKind::s57) enc.push_back(path);
  }
  return enc;
}

MissionEnvironment load_environment(const Mission& mission, const ChartOptions& chart) {
  MissionEnvironment env;
  env.current = constant_current(mission);
  if (!mission.obstacles.empty()) {
    env.obstacles = load_obstacles(mission.obstacles, {mission.frame.id(), ""}).obstacles;
  }
  std::vector<std::string> vectors, enc;
  std::string raster;
  for (const std::string& path : mission.charts) {
    const ChartKind kind = names_enc(path) ? ChartKind::s57 : chart_kind(path);
    if (kind == ChartKind::s57) {
      enc.push_back(path);  // S-57 cells: the sea floor they chart (enc_sea_floor.hpp)
    } else if (kind != ChartKind::raster) {
      vectors.push_back(path);
    } else if (raster.empty()) {
      raster = path;
    } else {
      throw InputError(mission.source + ": environment.charts: expected one bathymetry raster, got a second: " + path);
    }
  }
  if (!vectors.empty()) {
    ChartObstacleOptions options;  // no depth: every hazard stays, with its top
    options.clearance_m = mission.vertical_clearance_m;
    const ChartObstacles charted = chart_obstacles(vectors, mission.frame, options);
    env.obstacles.ellipses.insert(env.obstacles.ellipses.end(), charted.obstacles.ellipses.begin(),
                                  charted.obstacles.ellipses.end());
    env.obstacles.polygons.insert(env.obstacles.polygons.end(), charted.obstacles.polygons.begin(),
                                  charted.obstacles.polygons.end());
  }
  if (!raster.empty() && !enc.empty()) {
    throw InputError(mission.source +
                     ": environment.charts: expected one sea floor, got a bathymetry raster and S-57 "
                     "cells");
  }
  if (!enc.empty() || !raster.empty()) {
    // The box around everything the plan visits (survey turns reach past
    // the area, laps round an object), 200 m wider.
    Vec2 lo = mission.start, hi = mission.start;
    for (const TrackPoint& p : plan_polyline(expand_mission(mission, env.obstacles))) {
      lo = lo.cwiseMin(p.xy);
      hi = hi.cwiseMax(p.xy);
    }
    const Vec2 pad = Vec2::Constant(200.0);
    env.floor = std::make_shared<const SeaFloor>(
        enc.empty() ? raster_sea_floor(raster, mission.frame, lo - pad, hi + pad, 0.0)
                    : enc_sea_floor(enc, mission.frame, lo - pad, hi + pad, 5.0, enc_options(chart)));
  }
  return env;
}

void check_positions(const Mission& mission, const MissionEnvironment& env) {
  const ObstacleField field(env.obstacles, 0.0);
  const WaterVolume volume(field, nullptr, {0.0, 0.0, std::numeric_limits<double>::infinity()});
  for (const ComplexManoeuvre& c : mission.manoeuvres) {
    std::vector<Vec2> points;
    if (const auto* t = std::get_if<TrackSpec>(&c.spec)) points = t->waypoints;
    if (const auto* g = std::get_if<GotoSpec>(&c.spec)) points = {g->position};
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Vec2& p = points[k];
      const std::string where = mission.source + ": " + c.line + ": " + c.type + " '" + printable(c.name) + "': " +
                                (c.type == "track" ? "waypoint " + std::to_string(k + 1) : std::string("position"));
      char at[96];
      std::snprintf(at, sizeof at, " (%.1f, %.1f)", p.x(), p.y());
      if (env.floor && env.floor->depth_at(p) <= 0.0) {
        throw InputError(where + at + ": expected a position at sea, got one on land (or where the chart has no data)");
      }
      if (env.floor && env.floor->depth_at(p) < c.depth_m) {
        char why[160];
        std::snprintf(why, sizeof why, ": expected water deeper than the manoeuvre's %.1f m, got %.1f m", c.depth_m,
                      env.floor->depth_at(p));
        throw InputError(where + at + why);
      }
      for (std::size_t i : field.near(p, p, 0.0)) {
        if (field.distance_to(i, p) < 0.0 && c.depth_m > volume.zone_top(i)) {
          throw InputError(where + at + ": expected a position outside every obstacle, got one inside '" +
                           field.obstacle_name(i) + "'");
        }
      }
    }
  }
}

LoadedMission load_mission(const std::string& path, const ChartOptions& chart) {
  LoadedMission l{read_mission(path), {}, {}};
  l.env = load_environment(l.mission, chart);
  check_positions(l.mission, l.env);
  l.plan = expand_mission(l.mission, l.env.obstacles);
  return l;
}

}  // namespace deepguide
