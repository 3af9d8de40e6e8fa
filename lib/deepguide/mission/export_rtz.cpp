// IEC 61174 Route Plan Exchange Format (RTZ) 1.0, written with libxml2:
//   <route xmlns="http://www.cirm.org/RTZ/1/0" version="1.0">
//     <routeInfo routeName="..."/>
//     <waypoints>
//       <waypoint id="1" name="1"><position lat=".." lon=".."/>
//         <leg speedMax="knots"/>                 (the leg arriving here)
//         <extensions><extension manufacturer="deepguide" name="underwater" version="1.0">
//           <depth_m>8</depth_m><hold_s>0</hold_s></extension></extensions>
//       </waypoint> ...
// Positions have 9 decimals (0.1 mm); RTZ has no depth, so it goes in the
// extension, which chart systems that do not know it skip.
#include <libxml/tree.h>
#include <libxml/xmlerror.h>
#include <libxml/xmlsave.h>

#include <cstdio>
#include <memory>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/export_writers.hpp"
#include "deepguide/vehicle/vehicle_params.hpp"

namespace deepguide::detail {
namespace {

const xmlChar* x(const char* s) { return reinterpret_cast<const xmlChar*>(s); }

void quiet(void*, const char*, ...) {}

void set(xmlNodePtr node, const char* name, const std::string& value) { xmlNewProp(node, x(name), x(value.c_str())); }

}  // namespace

void write_plan_rtz(const std::string& path, const ExportInput& in) {
  std::unique_ptr<xmlDoc, decltype(&xmlFreeDoc)> doc(xmlNewDoc(x("1.0")), &xmlFreeDoc);
  xmlNodePtr route = xmlNewNode(nullptr, x("route"));
  xmlDocSetRootElement(doc.get(), route);
  xmlNsPtr ns = xmlNewNs(route, x("http://www.cirm.org/RTZ/1/0"), nullptr);
  xmlSetNs(route, ns);
  set(route, "version", "1.0");
  xmlNodePtr info = xmlNewChild(route, ns, x("routeInfo"), nullptr);
  set(info, "routeName", in.mission.name);
  set(info, "routeAuthor", "deepguide");
  xmlNodePtr waypoints = xmlNewChild(route, ns, x("waypoints"), nullptr);
  for (std::size_t i = 0; i < in.waypoints.size(); ++i) {
    const ExportWaypoint& w = in.waypoints[i];
    xmlNodePtr wp = xmlNewChild(waypoints, ns, x("waypoint"), nullptr);
    set(wp, "id", std::to_string(i + 1));
    set(wp, "name", std::to_string(i + 1));
    xmlNodePtr pos = xmlNewChild(wp, ns, x("position"), nullptr);
    set(pos, "lat", fixed(w.lonlat.y(), 9));
    set(pos, "lon", fixed(w.lonlat.x(), 9));
    if (i > 0) {
      xmlNodePtr leg = xmlNewChild(wp, ns, x("leg"), nullptr);
      set(leg, "speedMax", fixed(w.speed_mps / kMetresPerSecondPerKnot, 3));
    }
    xmlNodePtr ext = xmlNewChild(xmlNewChild(wp, ns, x("extensions"), nullptr), ns, x("extension"), nullptr);
    set(ext, "manufacturer", "deepguide");
    set(ext, "name", "underwater");
    set(ext, "version", "1.0");
    xmlNewChild(ext, ns, x("depth_m"), x(fixed(w.depth_m, 3).c_str()));
    xmlNewChild(ext, ns, x("hold_s"), x(fixed(w.hold_s, 1).c_str()));
  }
  xmlSetGenericErrorFunc(nullptr, quiet);  // the failure is our one-line error, not libxml2's lines on stderr
  const int written = xmlSaveFormatFileEnc(path.c_str(), doc.get(), "UTF-8", 1);
  xmlSetGenericErrorFunc(nullptr, nullptr);
  if (written < 0) throw InputError(in.destination + ": could not write the RTZ file");
}

}  // namespace deepguide::detail
