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
// - behaviour names must not begin with another's (the helm takes dg_leg_10
//   for a duplicate of dg_leg_1): phases are numbered to one width;
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
#include "deepguide/mission/moos_helm.hpp"
#include "deepguide/world/local_frame.hpp"

namespace deepguide::detail {
namespace {

// The route's name on one comment line.
std::string comment_text(const std::string& s) {
  std::string out;
  for (char c : s) out += (c == '\n' || c == '\r') ? ' ' : c;
  return out;
}

std::string xy(const Vec2& p) { return fixed(p.x(), 3) + "," + fixed(p.y(), 3); }

}  // namespace

void write_plan_moos(const std::string& path, const ExportInput& in) {
  const ExportRoute& route = in.route;
  const MoosPlan plan = moos_plan(route);
  double deepest = 0.0;
  for (const ExportWaypoint& w : route.waypoints) deepest = std::max(deepest, w.depth_m);
  const double top_speed = route.max_speed_mps > 0.0 ? route.max_speed_mps : 4.0;
  std::ostringstream out;
  out << "// deepguide route for pHelmIvP: " << comment_text(route.name) << "\n"
      << "// In the .moos file's global section (local x, y are metres east and north of it, UTM zone " << plan.utm.id()
      << "):\n"
      << "//   LatOrigin  = " << fixed(plan.origin_lonlat.y(), 9) << "\n"
      << "//   LongOrigin = " << fixed(plan.origin_lonlat.x(), 9) << "\n"
      << "// pHelmIvP needs these decision domains (or finer; course and speed optional, docs/MISSIONS.md):\n";
  for (const std::string& d : moos_domains(deepest, top_speed)) out << "//   domain = " << d << "\n";
  out << "// The community posts MOOS_MANUAL_OVERRIDE = false, then DEPLOY = true. Phases run in order\n"
      << "// (DG_LEG says which); DG_DONE = true when the last ends.\n"
      << "// Capture radius " << fixed(plan.capture_radius_m, 1) << " m, slip radius " << fixed(plan.slip_radius_m, 1)
      << " m, lead " << fixed(plan.lead_m, 1) << " m, for a turn radius of " << fixed(plan.turn_radius_m, 1)
      << " m.\n\ninitialize DEPLOY = false\ninitialize DG_LEG = 1\ninitialize DG_DONE = false\n";
  const std::size_t width = std::max<std::size_t>(3, std::to_string(plan.phases.size()).size());
  for (std::size_t k = 0; k < plan.phases.size(); ++k) {
    const MoosPhase& p = plan.phases[k];
    std::string number = std::to_string(k + 1);
    number.insert(0, width - number.size(), '0');
    const std::string condition =
        "  pwt       = 100\n  condition = DEPLOY = true\n  condition = DG_LEG = " + std::to_string(k + 1) + "\n";
    const char* type = p.kind == MoosPhase::Kind::waypoints     ? "BHV_Waypoint"
                       : p.kind == MoosPhase::Kind::reach_depth ? "BHV_Loiter"
                                                                : "BHV_StationKeep";
    const char* name = p.kind == MoosPhase::Kind::waypoints     ? "dg_leg_"
                       : p.kind == MoosPhase::Kind::reach_depth ? "dg_reach_"
                                                                : "dg_hold_";
    out << "\nBehavior = " << type << "\n{\n  name      = " << name << number << "\n"
        << condition << "  endflag   = DG_LEG = " << k + 2 << "\n"
        << (k + 1 == plan.phases.size() ? "  endflag   = DG_DONE = true\n" : "");
    switch (p.kind) {
      case MoosPhase::Kind::waypoints: {
        std::string points;
        for (const Vec2& q : p.points) points += (points.empty() ? "" : " : ") + xy(q);
        out << "  speed     = " << fixed(p.speed_mps, 3) << "\n  capture_radius = " << fixed(plan.capture_radius_m, 1)
            << "\n  slip_radius    = " << fixed(plan.slip_radius_m, 1) << "\n  lead      = " << fixed(plan.lead_m, 1)
            << "\n  lead_damper = 1\n  points    = " << points << "\n";
        break;
      }
      case MoosPhase::Kind::reach_depth:
        out << "  speed     = " << fixed(p.speed_mps, 3)
            << "\n  polygon   = format=radial, x=" << fixed(p.points[0].x(), 3) << ", y=" << fixed(p.points[0].y(), 3)
            << ", radius=" << fixed(1.5 * plan.turn_radius_m, 1) << ", pts=8\n  duration  = " << fixed(p.duration_s, 1)
            << "\n  duration_idle_decay = false\n";
        break;
      case MoosPhase::Kind::hold:
        out << "  station_pt = " << xy(p.points[0]) << "\n  duration  = " << fixed(p.duration_s, 1)
            << "\n  duration_idle_decay = false\n";
        break;
    }
    out << "}\n\nBehavior = BHV_ConstantDepth\n{\n  name      = dg_depth_" << number << "\n"
        << condition << "  duration  = no-time-limit\n  depth     = " << fixed(p.depth_m, 3) << "\n}\n";
  }
  std::ofstream file(path, std::ios::binary);
  file << out.str();
  file.close();
  if (!file) throw InputError(in.destination + ": could not write the behaviour file");
}

}  // namespace deepguide::detail
