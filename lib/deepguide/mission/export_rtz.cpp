// IEC 61174 Route Plan Exchange Format (RTZ) 1.0, written with libxml2 and
// valid against the RTZ 1.0 schema:
//   <route xmlns="http://www.cirm.org/RTZ/1/0" version="1.0">
//     <routeInfo routeName="(the file's name)" routeAuthor="deepguide"/>
//     <waypoints>
//       <defaultWaypoint radius="(the vehicle's turn, NM)">
//         <leg starboardXTD portsideXTD="(the margin, NM)" safetyDepth="(m)"
//              speedMax="(the vehicle's top speed, kn)" geometryType="Loxodrome"/>
//       </defaultWaypoint>
//       <waypoint id="1" name="001" [radius="(an arc's, NM)"]><position lat lon/>
//         <extensions><extension manufacturer="deepguide" name="underwater" version="1.0">
//           <depth_m>8</depth_m><hold_s>0</hold_s></extension></extensions>
//       </waypoint> ...
//     </waypoints>
//     <schedules><schedule id="1" name="planned"><calculated>
//       <sheduleElement waypointId="1" speed="(kn, the leg arriving)" [eta] [stay]/> ...
// The planned speed is the schedule's, not the leg's speedMax (the highest
// speed allowed). RTZ 1.0 spells the element "sheduleElement"; 1.1 fixed it.
// ETAs need a departure time; without one the schedule has speeds and stays.
// Positions have 9 decimals (0.1 mm); RTZ has no depth or hold, so they go in
// the extension, which chart systems that do not know it skip.
#include <libxml/tree.h>
#include <libxml/xmlerror.h>
#include <libxml/xmlsave.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/mission/export_writers.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"

namespace deepguide::detail {
namespace {

constexpr double kMetresPerNauticalMile = 1852.0;

const xmlChar* x(const char* s) { return reinterpret_cast<const xmlChar*>(s); }

void quiet(void*, const char*, ...) {}

void set(xmlNodePtr node, const char* name, const std::string& value) { xmlNewProp(node, x(name), x(value.c_str())); }

std::string nautical_miles(double metres) { return fixed(metres / kMetresPerNauticalMile, 6); }
std::string knots(double mps) { return fixed(mps / kMetresPerSecondPerKnot, 3); }

// xsd:time, as RTZ 1.0 types a stay.
std::string clock_time(double seconds) {
  const int s = static_cast<int>(std::lround(std::clamp(seconds, 0.0, 86399.0)));
  return printf_text("%02d:%02d:%02d", s / 3600, (s / 60) % 60, s % 60);
}

}  // namespace

void write_plan_rtz(const std::string& path, const ExportInput& in) {
  const ExportRoute& r = in.route;
  std::unique_ptr<xmlDoc, decltype(&xmlFreeDoc)> doc(xmlNewDoc(x("1.0")), &xmlFreeDoc);
  xmlNodePtr route = xmlNewNode(nullptr, x("route"));
  xmlDocSetRootElement(doc.get(), route);
  xmlNsPtr ns = xmlNewNs(route, x("http://www.cirm.org/RTZ/1/0"), nullptr);
  xmlSetNs(route, ns);
  set(route, "version", "1.0");
  xmlNodePtr info = xmlNewChild(route, ns, x("routeInfo"), nullptr);
  set(info, "routeName", in.route_name);
  set(info, "routeAuthor", "deepguide");
  if (!r.name.empty() && r.name != in.route_name) set(info, "vesselVoyage", r.name);
  xmlNodePtr waypoints = xmlNewChild(route, ns, x("waypoints"), nullptr);
  xmlNodePtr defaults = xmlNewChild(waypoints, ns, x("defaultWaypoint"), nullptr);
  if (r.turn_radius_m > 0.0) set(defaults, "radius", nautical_miles(r.turn_radius_m));
  xmlNodePtr default_leg = xmlNewChild(defaults, ns, x("leg"), nullptr);
  if (std::isfinite(r.xtd_m)) {
    set(default_leg, "starboardXTD", nautical_miles(r.xtd_m));
    set(default_leg, "portsideXTD", nautical_miles(r.xtd_m));
  }
  if (std::isfinite(r.safety_depth_m)) set(default_leg, "safetyDepth", fixed(r.safety_depth_m, 2));
  if (r.max_speed_mps > 0.0) set(default_leg, "speedMax", knots(r.max_speed_mps));
  set(default_leg, "geometryType", "Loxodrome");
  for (std::size_t i = 0; i < r.waypoints.size(); ++i) {
    const ExportWaypoint& w = r.waypoints[i];
    xmlNodePtr wp = xmlNewChild(waypoints, ns, x("waypoint"), nullptr);
    set(wp, "id", std::to_string(i + 1));
    set(wp, "name", w.name);
    if (w.radius_m > 0.0) set(wp, "radius", nautical_miles(w.radius_m));
    xmlNodePtr pos = xmlNewChild(wp, ns, x("position"), nullptr);
    set(pos, "lat", fixed(w.lonlat.y(), 9));
    set(pos, "lon", fixed(w.lonlat.x(), 9));
    xmlNodePtr ext = xmlNewChild(xmlNewChild(wp, ns, x("extensions"), nullptr), ns, x("extension"), nullptr);
    set(ext, "manufacturer", "deepguide");
    set(ext, "name", "underwater");
    set(ext, "version", "1.0");
    xmlNewChild(ext, ns, x("depth_m"), x(fixed(w.depth_m, 3).c_str()));
    xmlNewChild(ext, ns, x("hold_s"), x(fixed(w.hold_s, 1).c_str()));
  }
  xmlNodePtr calculated =
      xmlNewChild(xmlNewChild(xmlNewChild(route, ns, x("schedules"), nullptr), ns, x("schedule"), nullptr), ns,
                  x("calculated"), nullptr);
  set(calculated->parent, "id", "1");
  set(calculated->parent, "name", "planned");
  for (std::size_t i = 0; i < r.waypoints.size(); ++i) {
    const ExportWaypoint& w = r.waypoints[i];
    xmlNodePtr e = xmlNewChild(calculated, ns, x("sheduleElement"), nullptr);
    set(e, "waypointId", std::to_string(i + 1));
    if (r.depart_utc_s) set(e, "eta", format_utc(*r.depart_utc_s + w.time_s));
    if (w.hold_s > 0.0) set(e, "stay", clock_time(w.hold_s));
    set(e, "speed", knots(w.speed_mps));
  }
  xmlSetGenericErrorFunc(nullptr, quiet);  // the failure is our one-line error, not libxml2's lines on stderr
  const int written = xmlSaveFormatFileEnc(path.c_str(), doc.get(), "UTF-8", 1);
  xmlSetGenericErrorFunc(nullptr, nullptr);
  if (written < 0) throw InputError(in.destination + ": could not write the RTZ file");
}

}  // namespace deepguide::detail
