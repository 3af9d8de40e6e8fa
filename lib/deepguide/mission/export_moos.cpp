// A pHelmIvP behaviour file (.bhv) for MOOS-IvP, checked with the real helm
// (docs/MISSIONS.md, "MOOS-IvP"): the plan as legs of one depth and speed,
// each a BHV_Waypoint with a BHV_ConstantDepth, holds as BHV_StationKeep,
// chained by the variable DG_LEG (each leg's endflag starts the next; the
// last posts DG_DONE = true). Points are local coordinates: metres east and
// north of the origin (the plan's start) in the origin's UTM zone as
// MOOSGeodesy's LatLong2LocalUTM picks it (the classic zones, with the Norway
// and Svalbard exceptions); the header says which origin to set in the .moos
// file and what the community must post.
//
// What the helm needs, learnt by running it:
// - a leg's depth is the depth at its end waypoint: the vehicle is there on
//   arrival, as the plan says (the helm gives one depth per behaviour);
// - BHV_ConstantDepth lasts until its leg ends (`duration = no-time-limit`);
//   with the default it completes at once and the helm stops all;
// - capture and slip radii and the track-line lead scale with the vehicle's
//   turn radius: a waypoint inside the turning circle is orbited forever;
// - a hold at another depth first loiters around its point until that depth
//   can be reached at the vehicle's vertical speed (a stopped vehicle changes
//   depth only on buoyancy), then keeps station for the hold.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/export_writers.hpp"
#include "deepguide/world/local_frame.hpp"

namespace deepguide::detail {
namespace {

// The mission's name on one comment line.
std::string comment_text(const std::string& s) {
  std::string out;
  for (char c : s) out += (c == '\n' || c == '\r') ? ' ' : c;
  return out;
}

// The UTM zone MOOSGeodesy's LLtoUTM uses, as an EPSG code.
int moos_utm_epsg(double lon, double lat) {
  int zone = static_cast<int>(std::floor((lon + 180.0) / 6.0)) + 1;
  if (lat >= 56.0 && lat < 64.0 && lon >= 3.0 && lon < 12.0) zone = 32;
  if (lat >= 72.0 && lat < 84.0) {
    if (lon >= 0.0 && lon < 9.0) zone = 31;
    else if (lon >= 9.0 && lon < 21.0) zone = 33;
    else if (lon >= 21.0 && lon < 33.0) zone = 35;
    else if (lon >= 33.0 && lon < 42.0) zone = 37;
  }
  zone = std::clamp(zone, 1, 60);
  return (lat >= 0.0 ? 32600 : 32700) + zone;
}

std::string x_of(const std::string& xy) { return xy.substr(0, xy.find(',')); }
std::string y_of(const std::string& xy) { return xy.substr(xy.find(',') + 1); }

double max_depth(const std::vector<ExportWaypoint>& wps) {
  double d = 0.0;
  for (const ExportWaypoint& w : wps) d = std::max(d, w.depth_m);
  return d;
}

}  // namespace

LocalFrame moos_local_utm(double lon_deg, double lat_deg) {
  return LocalFrame::from_user_crs("EPSG:" + std::to_string(moos_utm_epsg(lon_deg, lat_deg)), "MOOS UTM zone");
}

void write_plan_moos(const std::string& path, const ExportInput& in) {
  const ExportRoute& route = in.route;
  const std::vector<ExportWaypoint>& wps = route.waypoints;
  const Vec2 origin_ll = wps.front().lonlat;
  const LocalFrame utm = moos_local_utm(origin_ll.x(), origin_ll.y());
  const double vertical = std::max(route.vertical_speed_mps, 1e-3);
  const double turn = route.turn_radius_m > 0.0 ? route.turn_radius_m : 10.0;
  const double capture = std::max(3.0, 0.25 * turn);
  const double slip = std::max(2.0 * capture, turn);
  const double lead = std::max(capture, 0.5 * turn);
  const Vec2 origin = utm.from_lonlat(origin_ll);
  const auto local = [&](const ExportWaypoint& w) {
    const Vec2 p = utm.from_lonlat(w.lonlat) - origin;
    return fixed(p.x(), 3) + "," + fixed(p.y(), 3);
  };
  std::ostringstream out;
  out << "// deepguide route for pHelmIvP: " << comment_text(route.name) << "\n"
      << "// In the .moos file's global section (local x, y are metres east and north of it, UTM zone "
      << utm.id() << "):\n"
      << "//   LatOrigin  = " << fixed(origin_ll.y(), 9) << "\n"
      << "//   LongOrigin = " << fixed(origin_ll.x(), 9) << "\n"
      << "// pHelmIvP needs: domain = course:0:359:360, speed:0:" << fixed(std::ceil(route.max_speed_mps > 0.0 ? route.max_speed_mps : 4.0), 0)
      << ":81, depth:0:" << fixed(std::ceil(max_depth(wps) + 10.0), 0) << ":201 (or finer);\n"
      << "// the community posts MOOS_MANUAL_OVERRIDE = false, then DEPLOY = true. Legs run in order\n"
      << "// (DG_LEG says which); DG_DONE = true when the last ends.\n"
      << "// Capture radius " << fixed(capture, 1) << " m, slip radius " << fixed(slip, 1) << " m, lead "
      << fixed(lead, 1) << " m, for a turn radius of " << fixed(turn, 1) << " m.\n\n"
      << "initialize DEPLOY = false\ninitialize DG_LEG = 1\ninitialize DG_DONE = false\n";
  // Phases: each a behaviour plus its depth; the last one's endflag ends the route.
  struct Phase {
    std::string body;  // the behaviour's lines after its name, condition and endflag
    std::string type;
    std::string name;
    double depth_m;
  };
  std::vector<Phase> phases;
  std::size_t i = 1;
  while (i < wps.size()) {
    const std::string n = std::to_string(phases.size() + 1);
    if (wps[i].hold_s > 0.0 || (wps[i].xy - wps[i - 1].xy).norm() < 1e-6) {
      const double change = std::abs(wps[i].depth_m - wps[i - 1].depth_m);
      if (change > 0.5) {
        // Reach the hold's depth while moving: loiter around the point for the time the change takes, and half again.
        phases.push_back({"  speed     = " + fixed(std::max(wps[i].speed_mps, 0.5), 3) +
                              "\n  polygon   = format=radial, x=" + x_of(local(wps[i])) + ", y=" + y_of(local(wps[i])) + ", radius=" +
                              fixed(1.5 * turn, 1) + ", pts=8\n  duration  = " + fixed(1.5 * change / vertical + 10.0, 1) +
                              "\n  duration_idle_decay = false\n",
                          "BHV_Loiter", "dg_reach_" + n, wps[i].depth_m});
      }
      const std::string m = std::to_string(phases.size() + 1);
      phases.push_back({"  station_pt = " + local(wps[i]) + "\n  duration  = " + fixed(std::max(wps[i].hold_s, 1.0), 1) +
                            "\n  duration_idle_decay = false\n",
                        "BHV_StationKeep", "dg_hold_" + m, wps[i].depth_m});
      ++i;
      continue;
    }
    std::size_t j = i;
    std::string points;
    while (j < wps.size() && wps[j].hold_s <= 0.0 && (wps[j].xy - wps[j - 1].xy).norm() >= 1e-6 &&
           std::abs(wps[j].depth_m - wps[i].depth_m) < 1e-6 && std::abs(wps[j].speed_mps - wps[i].speed_mps) < 1e-9) {
      points += (points.empty() ? "" : " : ") + local(wps[j]);
      ++j;
    }
    phases.push_back({"  speed     = " + fixed(wps[i].speed_mps, 3) + "\n  capture_radius = " + fixed(capture, 1) +
                          "\n  slip_radius    = " + fixed(slip, 1) + "\n  lead      = " + fixed(lead, 1) +
                          "\n  lead_damper = 1\n  points    = " + points + "\n",
                      "BHV_Waypoint", "dg_leg_" + n, wps[i].depth_m});
    i = j;
  }
  for (std::size_t k = 0; k < phases.size(); ++k) {
    const Phase& p = phases[k];
    const std::string condition = "  pwt       = 100\n  condition = DEPLOY = true\n  condition = DG_LEG = " +
                                  std::to_string(k + 1) + "\n";
    out << "\nBehavior = " << p.type << "\n{\n  name      = " << p.name << "\n" << condition
        << "  endflag   = DG_LEG = " << k + 2 << "\n"
        << (k + 1 == phases.size() ? "  endflag   = DG_DONE = true\n" : "") << p.body << "}\n";
    out << "\nBehavior = BHV_ConstantDepth\n{\n  name      = dg_depth_" << k + 1 << "\n" << condition
        << "  duration  = no-time-limit\n  depth     = " << fixed(p.depth_m, 3) << "\n}\n";
  }
  std::ofstream file(path, std::ios::binary);
  file << out.str();
  file.close();
  if (!file) throw InputError(in.destination + ": could not write the behaviour file");
}

}  // namespace deepguide::detail
