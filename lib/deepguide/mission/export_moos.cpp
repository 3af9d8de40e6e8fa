// A pHelmIvP behaviour file (.bhv) for MOOS-IvP: the plan as legs of one
// depth and speed, each a BHV_Waypoint with a BHV_ConstantDepth, holds as
// BHV_StationKeep, chained by the variable DG_LEG (each leg's endflag starts
// the next). Points are local coordinates: metres east and north of the
// origin (the plan's start) in the origin's UTM zone as MOOSGeodesy's
// LatLong2LocalUTM picks it (the classic zones, with the Norway and Svalbard
// exceptions); the header says which origin to set in the .moos file.
// ConstantDepth holds one depth per leg, where the plan ramps along a line:
// a leg takes the shallower of the depths at its two ends (the vehicle dives
// late and climbs early, always shallower than the checked plan). A hold
// lasts its time plus the time to change depth at the vehicle's vertical
// speed, so a surfacing does not eat into a GPS fix.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

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

}  // namespace

LocalFrame moos_local_utm(double lon_deg, double lat_deg) {
  return LocalFrame::from_user_crs("EPSG:" + std::to_string(moos_utm_epsg(lon_deg, lat_deg)), "MOOS UTM zone");
}

void write_plan_moos(const std::string& path, const ExportInput& in) {
  const std::vector<ExportWaypoint>& wps = in.waypoints;
  const Vec2 origin_ll = wps.front().lonlat;
  const LocalFrame utm = moos_local_utm(origin_ll.x(), origin_ll.y());
  const double vertical = std::max(in.mission.vehicle.max_vertical_speed_mps, 1e-3);
  // The depth a leg arriving at waypoint k holds (the header).
  const auto leg_depth = [&](std::size_t k) { return std::min(wps[k].depth_m, wps[k - 1].depth_m); };
  const Vec2 origin = utm.from_lonlat(origin_ll);
  const auto local = [&](const ExportWaypoint& w) {
    const Vec2 p = utm.from_lonlat(w.lonlat) - origin;
    return fixed(p.x(), 3) + "," + fixed(p.y(), 3);
  };
  std::ofstream out(path, std::ios::binary);
  out << "// deepguide mission plan for pHelmIvP: " << comment_text(in.mission.name) << "\n"
      << "// In the .moos file's global section (local x, y are metres east and north of it, UTM zone "
      << utm.id() << "):\n"
      << "//   LatOrigin  = " << fixed(origin_ll.y(), 9) << "\n"
      << "//   LongOrigin = " << fixed(origin_ll.x(), 9) << "\n"
      << "// Legs of one depth and speed run in order while DEPLOY = true; DG_LEG says which.\n\n"
      << "initialize DEPLOY = false\ninitialize DG_LEG = 1\n";
  int leg = 0;
  std::size_t i = 1;
  const auto header = [&](const std::string& type, const std::string& name) {
    out << "\nBehavior = " << type << "\n{\n  name      = " << name << "\n  pwt       = 100\n"
        << "  condition = DEPLOY = true\n  condition = DG_LEG = " << leg << "\n";
  };
  const auto depth = [&](double d) {
    header("BHV_ConstantDepth", "dg_depth_" + std::to_string(leg));
    out << "  depth     = " << fixed(d, 3) << "\n}\n";
  };
  while (i < wps.size()) {
    ++leg;
    if (wps[i].hold_s > 0.0 || (wps[i].xy - wps[i - 1].xy).norm() < 1e-6) {
      // A point: station keeping where it is, at its depth, for its hold.
      header("BHV_StationKeep", "dg_hold_" + std::to_string(leg));
      const double change = std::abs(wps[i].depth_m - wps[i - 1].depth_m) / vertical;
      out << "  endflag   = DG_LEG = " << leg + 1 << "\n  station_pt = " << local(wps[i])
          << "\n  duration  = " << fixed(wps[i].hold_s + change, 1) << "\n  duration_idle_decay = false\n}\n";
      depth(wps[i].depth_m);
      ++i;
      continue;
    }
    std::size_t j = i;
    std::string points;
    while (j < wps.size() && wps[j].hold_s <= 0.0 && (wps[j].xy - wps[j - 1].xy).norm() >= 1e-6 &&
           std::abs(leg_depth(j) - leg_depth(i)) < 1e-6 && std::abs(wps[j].speed_mps - wps[i].speed_mps) < 1e-9) {
      points += (points.empty() ? "" : " : ") + local(wps[j]);
      ++j;
    }
    header("BHV_Waypoint", "dg_leg_" + std::to_string(leg));
    out << "  endflag   = DG_LEG = " << leg + 1 << "\n  speed     = " << fixed(wps[i].speed_mps, 3)
        << "\n  capture_radius = 3\n  slip_radius    = 8\n  points    = " << points << "\n}\n";
    depth(leg_depth(i));
    i = j;
  }
  out.close();
  if (!out) throw InputError(in.destination + ": could not write the behaviour file");
}

}  // namespace deepguide::detail
