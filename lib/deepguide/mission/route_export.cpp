#include "deepguide/mission/route_export.hpp"

#include <algorithm>
#include <filesystem>
#include <regex>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/mission/basic_manoeuvres.hpp"
#include "deepguide/mission/export_writers.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace {

struct FormatName {
  ExportFormat format;
  const char* name;
  std::vector<const char*> extensions;
};

const std::vector<FormatName>& formats() {
  static const std::vector<FormatName> f = {
      {ExportFormat::yaml, "yaml", {".yaml", ".yml"}},
      {ExportFormat::geojson, "geojson", {".geojson", ".json"}},
      {ExportFormat::gpx, "gpx", {".gpx"}},
      {ExportFormat::kml, "kml", {".kml"}},
      {ExportFormat::csv, "csv", {".csv"}},
      {ExportFormat::qgc_plan, "plan", {".plan"}},
      {ExportFormat::moos, "moos", {".bhv"}},
      {ExportFormat::rtz, "rtz", {".rtz"}},
  };
  return f;
}

}  // namespace

ExportFormat parse_export_format(const std::string& name) {
  for (const FormatName& f : formats()) {
    if (name == f.name) return f.format;
  }
  throw InputError("`format`: expected yaml, geojson, gpx, kml, csv, plan, moos or rtz, got '" + printable(name) + "'");
}

ExportFormat export_format_for(const std::string& path) {
  const std::string ext = ascii_lower(fs::path(path).extension().string());
  for (const FormatName& f : formats()) {
    for (const char* e : f.extensions) {
      if (ext == e) return f.format;
    }
  }
  throw InputError(printable(path, 240) +
                   ": expected an extension that names the format (.yaml, .geojson, .gpx, "
                   ".kml, .csv, .plan, .bhv, .rtz), got '" +
                   printable(ext) + "'");
}

std::string to_string(ExportFormat format) {
  for (const FormatName& f : formats()) {
    if (f.format == format) return f.name;
  }
  return "?";
}

ExportFormat route_file_format(const std::string& path) {
  const ExportFormat format = export_format_for(path);
  if (format == ExportFormat::yaml) {
    throw InputError(printable(path, 240) +
                     ": expected a route file (.geojson, .gpx, .kml, .csv, .rtz, .plan or "
                     ".bhv); .yaml is a mission's plan of basic manoeuvres (mission export)");
  }
  return format;
}

std::string waypoint_name(std::size_t index, std::size_t count) {
  const int width = std::max<int>(3, static_cast<int>(std::to_string(count).size()));
  std::string n = std::to_string(index + 1);
  return std::string(static_cast<std::size_t>(std::max<int>(0, width - static_cast<int>(n.size()))), '0') + n;
}

ExportRoute export_route(const Route& route, const LocalFrame& frame, const VehicleParams& vehicle,
                         const RouteExportSettings& settings) {
  ExportRoute r{settings.name, frame};
  const std::size_t n = route.points.size();
  const auto speed = [&](std::size_t leg) {
    return leg < settings.leg_speeds_mps.size() ? settings.leg_speeds_mps[leg] : vehicle.cruise_speed_mps;
  };
  double along = 0.0, time = 0.0, fastest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    ExportWaypoint w;
    w.xy = route.points[i];
    w.lonlat = frame.to_lonlat(w.xy);
    w.name = waypoint_name(i, n);
    w.depth_m = i < route.depth_m.size() ? route.depth_m[i] : settings.depth_m;
    if (i > 0) {
      const double length = (route.points[i] - route.points[i - 1]).norm();
      along += length;
      time += i - 1 < settings.leg_times_s.size() ? settings.leg_times_s[i - 1]
                                                  : (speed(i - 1) > 0.0 ? length / speed(i - 1) : 0.0);
    }
    w.speed_mps = speed(i > 0 ? i - 1 : 0);
    fastest = std::max(fastest, w.speed_mps);
    w.along_m = along;
    w.time_s = time;
    r.waypoints.push_back(std::move(w));
  }
  r.length_m = route.length();
  r.turn_radius_m = settings.turn_radius_m > 0.0 ? settings.turn_radius_m : turn_radius(vehicle, fastest);
  r.vertical_speed_mps = vehicle.max_vertical_speed_mps;
  r.max_speed_mps = vehicle.max_speed_mps;
  r.xtd_m = settings.margin_m;
  r.safety_depth_m = settings.safety_depth_m;
  r.depart_utc_s = settings.depart_utc_s;
  return r;
}

namespace detail {

void require_exportable_text(const std::string& text, const std::string& what, const std::string& path) {
  const auto refuse = [&](const std::string& holds) {
    throw InputError(printable(path) + ": the " + what + " '" + printable(text) + "' holds " + holds +
                     ", which not every route format carries; expected a name without control characters or ']]>'");
  };
  if (text.find("]]>") != std::string::npos) refuse("']]>'");
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    // The length of the UTF-8 sequence this byte starts, and its code point.
    const int n = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
    if (n == 0 || i + static_cast<std::size_t>(n) > text.size()) refuse("bytes that are not UTF-8");
    char32_t cp = n == 1 ? c : c & (0x7F >> n);
    for (int k = 1; k < n; ++k) {
      const auto b = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
      if ((b & 0xC0) != 0x80) refuse("bytes that are not UTF-8");
      cp = (cp << 6) | (b & 0x3F);
    }
    const bool overlong = (n == 2 && cp < 0x80) || (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
    if (overlong || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF) || cp == 0xFFFE || cp == 0xFFFF) {
      refuse("bytes that are not UTF-8");
    }
    if (cp < 0x20 || (cp >= 0x7F && cp <= 0x9F)) refuse("a control character");
    i += static_cast<std::size_t>(n);
  }
}

void write_atomically(const std::string& path, bool overwrite, const std::function<void(const std::string&)>& write) {
  std::error_code ec;
  if (!overwrite && fs::exists(path, ec)) {
    throw InputError(path + ": expected a new file, got one that exists (`overwrite` replaces it)");
  }
  AtomicOutput out(path);
  try {
    write(out.temp_path().string());
  } catch (const InputError& e) {
    // Name the user's file, not the temporary ones (GDAL's messages quote them), on one line.
    static const std::regex temporary(R"([^ :'"]*\.tmp[0-9]+-[0-9]+[^ :'"]*)");
    std::string what = std::regex_replace(e.what(), temporary, path);
    std::replace(what.begin(), what.end(), '\n', ' ');
    throw InputError(what);
  }
  out.commit(overwrite);
}

}  // namespace detail

void write_route_file(const ExportRoute& route, const std::string& path, ExportFormat format,
                      const ExportOptions& options) {
  if (format == ExportFormat::yaml) route_file_format(path);  // throws: not a route format
  if (route.waypoints.size() < 2) throw InputError(path + ": expected a route with at least two waypoints to write");
  const std::string name = options.route_name.empty() ? fs::path(path).stem().string() : options.route_name;
  detail::require_exportable_text(route.name, "route name", path);
  detail::require_exportable_text(name, options.route_name.empty() ? "file name" : "route name", path);
  for (const ExportWaypoint& w : route.waypoints) {
    detail::require_exportable_text(w.name, "waypoint name", path);
    detail::require_exportable_text(w.manoeuvre, "manoeuvre name", path);
  }
  const detail::ExportInput in{path, route, name};
  detail::write_atomically(path, options.overwrite, [&](const std::string& temp) {
    switch (format) {
      case ExportFormat::geojson:
      case ExportFormat::gpx:
      case ExportFormat::kml:
      case ExportFormat::csv: detail::write_plan_ogr(temp, format, in); break;
      case ExportFormat::qgc_plan: detail::write_plan_qgc(temp, in); break;
      case ExportFormat::moos: detail::write_plan_moos(temp, in); break;
      case ExportFormat::rtz: detail::write_plan_rtz(temp, in); break;
      case ExportFormat::yaml: break;
    }
  });
}

}  // namespace deepguide
