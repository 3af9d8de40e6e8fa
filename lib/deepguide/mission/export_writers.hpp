#pragma once
// Library-internal: one writer per export format (mission/route_export.hpp
// picks one, and makes the write atomic). Each writes `path` whole or throws.

#include <functional>
#include <string>

#include "deepguide/mission/plan_export.hpp"
#include "deepguide/mission/route_export.hpp"
#include "deepguide/world/local_frame.hpp"

namespace deepguide::detail {

struct ExportInput {
  std::string destination;  ///< the file the user named (messages; writers write the path they are given)
  const ExportRoute& route;
  std::string route_name;  ///< RTZ routeName (the destination's stem unless told)
};

void write_plan_yaml(const std::string& path, const std::string& destination, const Mission& mission,
                     const MissionPlan& plan);
void write_plan_ogr(const std::string& path, ExportFormat format, const ExportInput& in);  ///< geojson, gpx, kml, csv
void write_plan_qgc(const std::string& path, const ExportInput& in);
void write_plan_moos(const std::string& path, const ExportInput& in);
void write_plan_rtz(const std::string& path, const ExportInput& in);

/// Throws InputError "`path`: the `what` '...' holds ..." for a text no export
/// format carries whole: invalid UTF-8, a control character (U+0000 to U+001F,
/// U+007F to U+009F; XML 1.0 forbids most, a .bhv line ends at them) or "]]>"
/// (which ends the CDATA sections GDAL's KML driver writes). Refusing, not
/// mending, keeps every name the same in every format and on the way back.
void require_exportable_text(const std::string& text, const std::string& what, const std::string& path);

/// Runs `write(temp)` on a temporary file beside `path` and renames it onto
/// `path` (replacing an existing file only with `overwrite`). Messages name
/// `path`, never the temporary file, on one line.
void write_atomically(const std::string& path, bool overwrite, const std::function<void(const std::string&)>& write);

}  // namespace deepguide::detail
