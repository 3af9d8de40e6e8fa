#include "deepguide/currents/current_summary.hpp"

#include <algorithm>
#include <cmath>

#include "deepguide/core/utc_time.hpp"

namespace deepguide {

CurrentSummary summarize_current(const CurrentField& f) {
  CurrentSummary s;
  s.source = f.source;
  s.driver = f.driver;
  s.crs = f.crs;
  s.crs_source = f.crs_source;
  s.u_name = f.u_name;
  s.v_name = f.v_name;
  s.width = f.nx();
  s.height = f.ny();
  s.steps = f.steps();
  s.extent = f.extent;
  if (!f.times_s.empty()) {
    s.time_first_s = f.times_s.front();
    s.time_last_s = f.times_s.back();
  }
  s.depth_m = f.depth_m;
  s.depth_levels = f.depth_levels;
  if (f.constant) {
    s.u_min = s.u_max = f.constant_velocity.x();
    s.v_min = s.v_max = f.constant_velocity.y();
    s.min_speed_mps = s.max_speed_mps = f.constant_velocity.norm();
    return s;
  }
  double umin = INFINITY, umax = -INFINITY, vmin = INFINITY, vmax = -INFINITY, smin = INFINITY, smax = -INFINITY;
  for (std::size_t i = 0; i < f.u.size(); ++i) {
    const double u = f.u[i], v = f.v[i];
    if (std::isnan(u) || std::isnan(v)) {
      ++s.fill_nodes;
      continue;
    }
    ++s.valid_nodes;
    umin = std::min(umin, u);
    umax = std::max(umax, u);
    vmin = std::min(vmin, v);
    vmax = std::max(vmax, v);
    const double sp = std::hypot(u, v);
    smin = std::min(smin, sp);
    smax = std::max(smax, sp);
  }
  if (s.valid_nodes > 0) {
    s.u_min = umin;
    s.u_max = umax;
    s.v_min = vmin;
    s.v_max = vmax;
    s.min_speed_mps = smin;
    s.max_speed_mps = smax;
  }
  return s;
}

nlohmann::json to_json(const CurrentSummary& s) {
  const auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  const auto time = [](double v) { return std::isfinite(v) ? nlohmann::json(format_utc(v)) : nlohmann::json(); };
  return {{"source", s.source},
          {"driver", s.driver},
          {"crs", s.crs},
          {"crs_source", s.crs_source},
          {"u_name", s.u_name},
          {"v_name", s.v_name},
          {"width", s.width},
          {"height", s.height},
          {"steps", s.steps},
          {"extent",
           {{"west", number(s.extent.west)},
            {"east", number(s.extent.east)},
            {"south", number(s.extent.south)},
            {"north", number(s.extent.north)}}},
          {"time_first_s", number(s.time_first_s)},
          {"time_last_s", number(s.time_last_s)},
          {"time_first", time(s.time_first_s)},
          {"time_last", time(s.time_last_s)},
          {"depth_m", s.depth_m},
          {"depth_levels", s.depth_levels},
          {"valid_nodes", s.valid_nodes},
          {"fill_nodes", s.fill_nodes},
          {"min_speed_mps", number(s.min_speed_mps)},
          {"max_speed_mps", number(s.max_speed_mps)},
          {"u_min", number(s.u_min)},
          {"u_max", number(s.u_max)},
          {"v_min", number(s.v_min)},
          {"v_max", number(s.v_max)}};
}

}  // namespace deepguide
