// QGroundControl's plan file (https://docs.qgroundcontrol.com, "Plan File
// Format"): fileType "Plan", version 1, and a mission of SimpleItems, version 2.
// Each waypoint is MAV_CMD_NAV_WAYPOINT (16) in MAV_FRAME_GLOBAL_RELATIVE_ALT
// (3): params [hold s, acceptance radius m, pass radius m, yaw (null: keep),
// lat, lon, altitude], the altitude being minus the depth, as ArduSub reads a
// depth. The acceptance radius carries the turn: ArduPilot takes a waypoint
// as reached within it and heads for the next, and a vehicle turning on
// radius R through a course change theta leaves the line R tan(theta / 2)
// before the corner (where the arc of the planned turn begins). So that is
// the radius, at least 2 m, at most half the shorter leg (two turns never
// overlap); 2 m at the ends and where the vehicle holds (it must get there). ArduSub takes an altitude of exactly 0 as
// "keep the current altitude", so a point at the surface (a GPS fix) is written 1 cm deep. Before the first waypoint
// and wherever the speed changes, MAV_CMD_DO_CHANGE_SPEED (178): params [speed type 1 (ground speed), m/s, throttle -1
// (no change), 0, 0, 0, 0]. The vehicle type is MAV_TYPE_SUBMARINE (12), the firmware ArduPilot (3); the planned home
// is the start at the surface.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "deepguide/core/error.hpp"
#include "deepguide/mission/export_writers.hpp"

namespace deepguide::detail {
namespace {

constexpr int kNavWaypoint = 16;
constexpr int kChangeSpeed = 178;
constexpr int kFrameGlobalRelativeAlt = 3;
constexpr int kFrameMission = 2;
constexpr int kSubmarine = 12;
constexpr int kArduPilot = 3;
constexpr double kAcceptanceRadius_m = 2.0;
constexpr double kSurface_m = 0.01;  // the header: 0 would mean "stay at the current depth"

double altitude(double depth_m) { return -std::max(depth_m, kSurface_m); }

double acceptance_radius(const ExportRoute& route, std::size_t k) {
  const auto& w = route.waypoints;
  if (k == 0 || k + 1 >= w.size() || w[k].hold_s > 0.0) return kAcceptanceRadius_m;
  const double radius = w[k].radius_m > 0.0 ? w[k].radius_m : route.turn_radius_m;
  const Vec2 in = w[k].xy - w[k - 1].xy, out = w[k + 1].xy - w[k].xy;
  if (!(radius > 0.0) || in.norm() == 0.0 || out.norm() == 0.0) return kAcceptanceRadius_m;
  const double turn = std::abs(std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out)));
  const double lead = radius * std::tan(0.5 * std::min(turn, 0.999 * M_PI));
  return std::max(kAcceptanceRadius_m, std::min(lead, 0.5 * std::min(in.norm(), out.norm())));
}

nlohmann::json item(int id, int command, int frame, const nlohmann::json& params, double altitude) {
  return {{"AMSLAltAboveTerrain", nullptr},
          {"Altitude", altitude},
          {"AltitudeMode", 1},
          {"autoContinue", true},
          {"command", command},
          {"doJumpId", id},
          {"frame", frame},
          {"params", params},
          {"type", "SimpleItem"}};
}

}  // namespace

void write_plan_qgc(const std::string& path, const ExportInput& in) {
  nlohmann::json items = nlohmann::json::array();
  int id = 1;
  double speed = -1.0;
  double cruise = 0.0;
  for (std::size_t k = 0; k < in.route.waypoints.size(); ++k) {
    const ExportWaypoint& w = in.route.waypoints[k];
    if (std::abs(w.speed_mps - speed) > 1e-9) {
      speed = w.speed_mps;
      cruise = std::max(cruise, speed);
      items.push_back(item(id++, kChangeSpeed, kFrameMission, {1, speed, -1, 0, 0, 0, 0}, 0.0));
    }
    items.push_back(
        item(id++, kNavWaypoint, kFrameGlobalRelativeAlt,
             {w.hold_s, acceptance_radius(in.route, k), 0, nullptr, w.lonlat.y(), w.lonlat.x(), altitude(w.depth_m)},
             altitude(w.depth_m)));
  }
  const ExportWaypoint& start = in.route.waypoints.front();
  const nlohmann::json plan = {
      {"fileType", "Plan"},
      {"version", 1},
      {"groundStation", "QGroundControl"},
      {"geoFence", {{"circles", nlohmann::json::array()}, {"polygons", nlohmann::json::array()}, {"version", 2}}},
      {"rallyPoints", {{"points", nlohmann::json::array()}, {"version", 2}}},
      {"mission",
       {{"version", 2},
        {"firmwareType", kArduPilot},
        {"vehicleType", kSubmarine},
        {"cruiseSpeed", cruise},
        {"hoverSpeed", cruise},
        {"plannedHomePosition", {start.lonlat.y(), start.lonlat.x(), 0.0}},
        {"items", items}}}};
  std::ofstream out(path, std::ios::binary);
  out << plan.dump(4) << "\n";
  out.close();
  if (!out) throw InputError(in.destination + ": could not write the plan file");
}

}  // namespace deepguide::detail
