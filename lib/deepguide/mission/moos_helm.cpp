#include "deepguide/mission/moos_helm.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/export_writers.hpp"

namespace deepguide {
namespace {

// The UTM zone MOOSGeodesy's LLtoUTM uses, as an EPSG code.
int moos_utm_epsg(double lon, double lat) {
  int zone = static_cast<int>(std::floor((lon + 180.0) / 6.0)) + 1;
  if (lat >= 56.0 && lat < 64.0 && lon >= 3.0 && lon < 12.0) zone = 32;
  if (lat >= 72.0 && lat < 84.0) {
    if (lon >= 0.0 && lon < 9.0)
      zone = 31;
    else if (lon >= 9.0 && lon < 21.0)
      zone = 33;
    else if (lon >= 21.0 && lon < 33.0)
      zone = 35;
    else if (lon >= 33.0 && lon < 42.0)
      zone = 37;
  }
  zone = std::clamp(zone, 1, 60);
  return (lat >= 0.0 ? 32600 : 32700) + zone;
}

// Distance from p to the polyline.
double distance_to(const std::vector<Vec2>& line, const Vec2& p) {
  double best = line.empty() ? INFINITY : (p - line.front()).norm();
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Vec2 a = line[i - 1], d = line[i] - a;
    const double l2 = d.squaredNorm();
    const double t = l2 > 0.0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, (p - (a + t * d)).norm());
  }
  return best;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace

LocalFrame moos_local_utm(double lon_deg, double lat_deg) {
  return LocalFrame::from_user_crs("EPSG:" + std::to_string(moos_utm_epsg(lon_deg, lat_deg)), "MOOS UTM zone");
}

std::vector<Vec2> MoosPlan::track() const {
  std::vector<Vec2> t{Vec2(0.0, 0.0)};
  for (const MoosPhase& p : phases) t.insert(t.end(), p.points.begin(), p.points.end());
  return t;
}

MoosPlan moos_plan(const ExportRoute& route) {
  const std::vector<ExportWaypoint>& wps = route.waypoints;
  if (wps.empty()) throw InputError("a MOOS-IvP plan needs at least one waypoint");
  const Vec2 origin_ll = wps.front().lonlat;
  MoosPlan plan{moos_local_utm(origin_ll.x(), origin_ll.y()), origin_ll};
  // The helm captures a waypoint within the capture radius, or passes it when it was within the
  // slip radius and the distance grows; a waypoint inside the turning circle is orbited forever
  // with small radii, so both grow with the turn, and the lead keeps the vehicle on the track line.
  plan.turn_radius_m = route.turn_radius_m > 0.0 ? route.turn_radius_m : 10.0;
  plan.capture_radius_m = std::max(3.0, 0.25 * plan.turn_radius_m);
  plan.slip_radius_m = std::max(2.0 * plan.capture_radius_m, plan.turn_radius_m);
  plan.lead_m = std::max(plan.capture_radius_m, 0.5 * plan.turn_radius_m);
  const double vertical = std::max(route.vertical_speed_mps, 1e-3);
  const Vec2 origin = plan.utm.from_lonlat(origin_ll);
  const auto local = [&](const ExportWaypoint& w) -> Vec2 { return plan.utm.from_lonlat(w.lonlat) - origin; };
  std::size_t i = 1;
  while (i < wps.size()) {
    if (wps[i].hold_s > 0.0 || (wps[i].xy - wps[i - 1].xy).norm() < 1e-6) {
      // A point. A stopped vehicle changes depth only on buoyancy: reach the depth while loitering
      // around the point, for the time the change takes at the vertical speed and half again.
      const double change = std::abs(wps[i].depth_m - wps[i - 1].depth_m);
      if (change > 0.5) {
        plan.phases.push_back({MoosPhase::Kind::reach_depth,
                               {local(wps[i])},
                               wps[i].depth_m,
                               std::max(wps[i].speed_mps, 0.5),
                               1.5 * change / vertical + 10.0});
      }
      if (wps[i].hold_s > 0.0) {
        plan.phases.push_back({MoosPhase::Kind::hold, {local(wps[i])}, wps[i].depth_m, 0.0, wps[i].hold_s});
      }
      ++i;
      continue;
    }
    // A leg: the waypoints that arrive at one depth and speed, held at that depth from the leg's start.
    MoosPhase leg{MoosPhase::Kind::waypoints, {}, wps[i].depth_m, wps[i].speed_mps, 0.0};
    std::size_t j = i;
    while (j < wps.size() && wps[j].hold_s <= 0.0 && (wps[j].xy - wps[j - 1].xy).norm() >= 1e-6 &&
           std::abs(wps[j].depth_m - wps[i].depth_m) < 1e-6 && std::abs(wps[j].speed_mps - wps[i].speed_mps) < 1e-9) {
      leg.points.push_back(local(wps[j]));
      ++j;
    }
    plan.phases.push_back(std::move(leg));
    i = j;
  }
  return plan;
}

std::vector<std::string> moos_domains(double deepest_m, double top_speed_mps) {
  // Course and speed are optional: between two phases the helm runs one iteration in which the
  // ending behaviour has completed and the next one's condition is not yet true. With mandatory
  // domains it posts IVPHELM_ALLSTOP = MissingDecVars (speed 0) for that iteration at every phase
  // change; optional, the controllers keep the last course and speed. Depth stays mandatory (a
  // phase's depth behaviour runs through the change), and with no behaviour active at all the
  // helm still stops: NothingToDo, after DG_DONE.
  const int speed = static_cast<int>(std::ceil(std::max(top_speed_mps, 0.5)));
  const int depth = static_cast<int>(std::ceil(std::max(deepest_m, 0.0) + 10.0));
  return {"course:0:359:360:optional",
          "speed:0:" + std::to_string(speed) + ":" + std::to_string(speed * 20 + 1) + ":optional",
          "depth:0:" + std::to_string(depth) + ":" + std::to_string(depth * 5 + 1)};
}

std::string moos_community(const MoosPlan& plan, double deepest_m, double top_speed_mps,
                           const MoosCommunityOptions& o) {
  std::ostringstream m;
  const Vec2 first =
      plan.phases.empty() || plan.phases.front().points.empty() ? Vec2(0.0, 1.0) : plan.phases.front().points.front();
  const double heading = std::fmod(std::atan2(first.x(), first.y()) * 180.0 / M_PI + 360.0, 360.0);
  m << "// deepguide: a headless community sailing " << o.behaviour_file << " in simulation\n"
    << "ServerHost   = localhost\nServerPort   = " << o.port << "\nCommunity    = deepguide\n"
    << "MOOSTimeWarp = " << fixed(o.time_warp, 0) << "\n\n"
    << "LatOrigin  = " << fixed(plan.origin_lonlat.y(), 9) << "\nLongOrigin = " << fixed(plan.origin_lonlat.x(), 9)
    << "\n\nProcessConfig = ANTLER\n{\n  MSBetweenLaunches = 200\n"
    << "  Run = MOOSDB        @ NewConsole = false\n  Run = pLogger       @ NewConsole = false\n"
    << "  Run = uSimMarineV22 @ NewConsole = false\n  Run = pMarinePIDV22 @ NewConsole = false\n"
    << "  Run = pHelmIvP      @ NewConsole = false\n  Run = uTimerScript  @ NewConsole = false\n}\n\n"
    << "ProcessConfig = pLogger\n{\n  AppTick = 10\n  CommsTick = 10\n  File = " << o.log_name
    << "\n  PATH = ./\n  FileTimeStamp = false\n  AsyncLog = true\n  SyncLog = false\n"
    << "  Log = NAV_X @ 0\n  Log = NAV_Y @ 0\n  Log = NAV_DEPTH @ 0\n  Log = DG_LEG @ 0\n  Log = DG_DONE @ 0\n"
    << "  Log = DEPLOY @ 0\n  Log = IVPHELM_ALLSTOP @ 0\n  Log = IVPHELM_STATE @ 0\n  Log = BHV_WARNING @ 0\n"
    << "  Log = BHV_ERROR @ 0\n}\n\n"
    << "ProcessConfig = uSimMarineV22\n{\n  AppTick = 10\n  CommsTick = 10\n  start_pos = x=0, y=0, speed=0, heading="
    << fixed(heading, 1) << ", depth=0\n  max_speed = 5\n  buoyancy_rate = 0.025\n  max_acceleration = 0\n"
    << "  max_deceleration = 0.5\n  max_depth_rate = 0.5\n  max_depth_rate_speed = 2.0\n  thrust_factor = 20\n"
    << "  turn_rate = 70\n  prefix = NAV\n}\n\n"
    << "ProcessConfig = pMarinePIDV22\n{\n  AppTick = 20\n  CommsTick = 20\n  speed_factor = 20\n"
    << "  yaw_pid_kp = 0.5\n  yaw_pid_kd = 0.1\n  yaw_pid_ki = 0.012\n  yaw_pid_integral_limit = 0.07\n"
    << "  yaw_pid_ki_limit = 0.2\n  maxrudder = 100\n  speed_pid_kp = 0.8\n  speed_pid_kd = 0.1\n"
    << "  speed_pid_ki = 0.11\n  speed_pid_ki_limit = 0.07\n  maxthrust = 100\n  depth_control = true\n"
    << "  z_to_pitch_pid_kp = 0.12\n  z_to_pitch_pid_kd = 0\n  z_to_pitch_pid_ki = 0.004\n"
    << "  z_to_pitch_pid_integral_limit = 0.05\n  maxpitch = 15\n  pitch_pid_kp = 1.5\n  pitch_pid_kd = 0.3\n"
    << "  pitch_pid_ki = 0\n  pitch_pid_integral_limit = 0\n  maxelevator = 13\n}\n\n"
    << "ProcessConfig = pHelmIvP\n{\n  AppTick = 4\n  CommsTick = 4\n  behaviors = " << o.behaviour_file << "\n";
  for (const std::string& d : moos_domains(deepest_m, top_speed_mps)) m << "  domain = " << d << "\n";
  m << "}\n\n// engage the helm, then deploy: the .bhv's conditions need both\n"
    << "ProcessConfig = uTimerScript\n{\n  AppTick = 4\n  CommsTick = 4\n  paused = false\n"
    << "  event = var=MOOS_MANUAL_OVERRIDE, val=false, time=5\n  event = var=DEPLOY, val=true, time=6\n}\n";
  return m.str();
}

MoosLog read_moos_alog(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": expected a pLogger .alog file that can be read");
  MoosLog log;
  std::string line;
  double x = NAN, y = NAN, depth = 0.0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '%') continue;
    std::istringstream ss(line);
    double t = NAN;
    std::string var, source;
    if (!(ss >> t >> var >> source)) continue;
    std::string value;
    std::getline(ss, value);
    value.erase(0, value.find_first_not_of(" \t"));
    value.erase(value.find_last_not_of(" \t\r") + 1);
    try {
      if (var == "NAV_X") {
        x = std::stod(value);
      } else if (var == "NAV_Y") {
        y = std::stod(value);
        if (std::isfinite(x)) log.nav.push_back({t, x, y, depth});
      } else if (var == "NAV_DEPTH") {
        depth = std::stod(value);
      } else if (var == "DG_LEG") {
        const int leg = static_cast<int>(std::lround(std::stod(value)));
        if (log.legs.empty() || log.legs.back().second != leg) log.legs.emplace_back(t, leg);
      } else if (var == "IVPHELM_ALLSTOP" && value != "clear") {
        log.allstops.emplace_back(t, value);
      } else if (var == "IVPHELM_STATE") {
        if (log.helm_states.empty() || log.helm_states.back() != value) log.helm_states.push_back(value);
      } else if (var == "DEPLOY" && value == "true" && !log.deploy_s) {
        log.deploy_s = t;
      } else if (var == "DG_DONE" && value == "true" && !log.done_s) {
        log.done_s = t;
      }
    } catch (const std::exception&) {
      throw InputError(path + ": " + var + " at " + std::to_string(t) + " s: expected a number, got '" +
                       printable(value) + "'");
    }
  }
  if (log.nav.empty()) throw InputError(path + ": expected NAV_X and NAV_Y lines (is pLogger logging them?)");
  return log;
}

SailedReport compare_sailed(const MoosPlan& plan, const MoosLog& log) {
  SailedReport r;
  r.done = log.done_s.has_value();
  const std::size_t n = plan.phases.size();
  // DG_LEG: the initial 1 (initialize), then each endflag's next.
  r.in_order = !log.legs.empty();
  int expect = 1;
  for (const auto& [t, leg] : log.legs) {
    if (leg != expect) r.in_order = false;
    expect = leg + 1;
  }
  r.phases_run = log.legs.empty() ? 0 : static_cast<std::size_t>(std::max(0, log.legs.back().second - 1));
  r.in_order = r.in_order && r.phases_run == n;
  const double start = log.deploy_s.value_or(log.nav.front().t);
  const double end = log.done_s.value_or(log.nav.back().t);
  for (const auto& [t, why] : log.allstops) {
    if (t >= start && t < end) r.allstops_before_done.push_back(why);
  }
  // Off the route: along the legs only (a reach loiters around its point on purpose).
  const std::vector<Vec2> track = plan.track();
  std::vector<double> off;
  std::size_t next = 0;
  int leg = 0;
  for (const MoosLog::Nav& s : log.nav) {
    while (next < log.legs.size() && log.legs[next].first <= s.t) leg = log.legs[next++].second;
    if (s.t < start || s.t > end || leg < 1 || static_cast<std::size_t>(leg) > n) continue;
    if (plan.phases[static_cast<std::size_t>(leg - 1)].kind != MoosPhase::Kind::waypoints) continue;
    off.push_back(distance_to(track, Vec2(s.x, s.y)));
  }
  r.median_off_m = quantile(off, 0.5);
  r.p95_off_m = quantile(off, 0.95);
  r.max_off_m = off.empty() ? NAN : *std::max_element(off.begin(), off.end());
  // Each phase's end: the time DG_LEG moved past it; the depth then against the phase's.
  for (std::size_t k = 1; k < log.legs.size(); ++k) {
    const std::size_t phase = static_cast<std::size_t>(log.legs[k].second - 2);  // the phase that just ended
    if (phase >= n) continue;
    const double t = log.legs[k].first;
    auto it =
        std::lower_bound(log.nav.begin(), log.nav.end(), t, [](const MoosLog::Nav& s, double v) { return s.t < v; });
    if (it == log.nav.end()) --it;
    const double miss = std::abs(it->depth - plan.phases[phase].depth_m);
    if (miss > r.worst_depth_miss_m) r.worst_depth_miss_m = miss, r.worst_depth_phase = phase + 1;
  }
  r.sailed_s = end - start;
  return r;
}

}  // namespace deepguide
