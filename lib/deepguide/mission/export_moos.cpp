// A pHelmIvP behaviour file (.bhv) for MOOS-IvP: the plan as legs of one
// depth and speed, each a BHV_Waypoint with a BHV_ConstantDepth, holds as
// BHV_StationKeep, chained by the variable DG_LEG (each leg's endflag starts
// the next). Points are local coordinates: metres east and north of the
// origin (the plan's start) in the origin's UTM zone, which is what
// MOOSGeodesy's LatLong2LocalUTM gives for LatOrigin/LongOrigin; the header
// says which origin to set in the .moos file.
#include <cmath>
#include <cstdio>
#include <fstream>

#include "deepguide/core/error.hpp"
#include "deepguide/mission/export_writers.hpp"
#include "deepguide/world/local_frame.hpp"

namespace deepguide::detail {
namespace {

std::string num(double v, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// The mission's name on one comment line.
std::string comment_text(const std::string& s) {
  std::string out;
  for (char c : s) out += (c == '\n' || c == '\r') ? ' ' : c;
  return out;
}

}  // namespace

void write_plan_moos(const std::string& path, const ExportInput& in) {
  const std::vector<ExportWaypoint>& wps = in.waypoints;
  const Vec2 origin_ll = wps.front().lonlat;
  const LocalFrame utm = LocalFrame::utm_for(origin_ll.x(), origin_ll.y());
  const Vec2 origin = utm.from_lonlat(origin_ll);
  const auto local = [&](const ExportWaypoint& w) {
    const Vec2 p = utm.from_lonlat(w.lonlat) - origin;
    return num(p.x(), 3) + "," + num(p.y(), 3);
  };
  std::ofstream out(path, std::ios::binary);
  out << "// deepguide mission plan for pHelmIvP: " << comment_text(in.mission.name) << "\n"
      << "// In the .moos file's global section (local x, y are metres east and north of it, UTM zone "
      << utm.id() << "):\n"
      << "//   LatOrigin  = " << num(origin_ll.y(), 9) << "\n"
      << "//   LongOrigin = " << num(origin_ll.x(), 9) << "\n"
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
    out << "  depth     = " << num(d, 3) << "\n}\n";
  };
  while (i < wps.size()) {
    ++leg;
    if (wps[i].hold_s > 0.0 || (wps[i].xy - wps[i - 1].xy).norm() < 1e-6) {
      // A point: station keeping where it is, at its depth, for its hold.
      header("BHV_StationKeep", "dg_hold_" + std::to_string(leg));
      out << "  endflag   = DG_LEG = " << leg + 1 << "\n  station_pt = " << local(wps[i])
          << "\n  duration  = " << num(wps[i].hold_s, 1) << "\n  duration_idle_decay = false\n}\n";
      depth(wps[i].depth_m);
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
    header("BHV_Waypoint", "dg_leg_" + std::to_string(leg));
    out << "  endflag   = DG_LEG = " << leg + 1 << "\n  speed     = " << num(wps[i].speed_mps, 3)
        << "\n  capture_radius = 3\n  slip_radius    = 8\n  points    = " << points << "\n}\n";
    depth(wps[i].depth_m);
    i = j;
  }
  out.close();
  if (!out) throw InputError(in.destination + ": could not write the behaviour file");
}

}  // namespace deepguide::detail
