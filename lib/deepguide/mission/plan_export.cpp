#include "deepguide/mission/plan_export.hpp"

#include <cctype>
#include <algorithm>
#include <filesystem>
#include <regex>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
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
      {ExportFormat::yaml, "yaml", {".yaml", ".yml"}},  {ExportFormat::geojson, "geojson", {".geojson", ".json"}},
      {ExportFormat::gpx, "gpx", {".gpx"}},            {ExportFormat::kml, "kml", {".kml"}},
      {ExportFormat::csv, "csv", {".csv"}},            {ExportFormat::qgc_plan, "plan", {".plan"}},
      {ExportFormat::moos, "moos", {".bhv"}},          {ExportFormat::rtz, "rtz", {".rtz"}},
  };
  return f;
}

}  // namespace

ExportFormat parse_export_format(const std::string& name) {
  for (const FormatName& f : formats()) {
    if (name == f.name) return f.format;
  }
  throw InputError("--format: expected yaml, geojson, gpx, kml, csv, plan, moos or rtz, got '" + printable(name) + "'");
}

ExportFormat export_format_for(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const FormatName& f : formats()) {
    for (const char* e : f.extensions) {
      if (ext == e) return f.format;
    }
  }
  throw InputError(path + ": expected an extension that names the format (.yaml, .geojson, .gpx, .kml, .csv, .plan, "
                          ".bhv, .rtz), or --format");
}

std::string to_string(ExportFormat format) {
  for (const FormatName& f : formats()) {
    if (f.format == format) return f.name;
  }
  return "?";
}

const char* role_name(BasicManoeuvre::Role role) {
  switch (role) {
    case BasicManoeuvre::Role::evasion: return "evasion";
    case BasicManoeuvre::Role::identification: return "identification";
    case BasicManoeuvre::Role::mission: break;
  }
  return "mission";
}

std::vector<ExportWaypoint> export_waypoints(const Mission& mission, const MissionPlan& plan, double arc_tolerance_m) {
  std::vector<ExportWaypoint> out;
  const std::vector<TrackPoint> track = plan_polyline(plan, arc_tolerance_m);
  double time = 0.0;
  for (std::size_t k = 0; k < track.size(); ++k) {
    const TrackPoint& p = track[k];
    const BasicManoeuvre& b = plan.basics[p.basic];
    ExportWaypoint w;
    w.xy = p.xy;
    w.lonlat = mission.frame.to_lonlat(p.xy);
    w.depth_m = p.depth_m;
    w.speed_mps = b.speed_mps;
    w.along_m = p.along_m;
    if (k > 0) {
      const ExportWaypoint& before = out.back();
      time += before.hold_s + (b.speed_mps > 0.0 ? (p.along_m - track[k - 1].along_m) / b.speed_mps : 0.0);
      if (b.kind == BasicManoeuvre::Kind::point) w.hold_s = b.hold_s;
    }
    w.time_s = time;
    w.role = b.role;
    w.manoeuvre = b.source < mission.manoeuvres.size() ? mission.manoeuvres[b.source].name : std::string();
    out.push_back(std::move(w));
  }
  return out;
}

void export_plan(const Mission& mission, const MissionPlan& plan, const std::string& path, ExportFormat format,
                 const ExportOptions& options) {
  std::error_code ec;
  if (!options.overwrite && fs::exists(path, ec)) {
    throw InputError(path + ": expected a new file, got one that exists (give --overwrite to replace it)");
  }
  if (plan.basics.empty()) throw InputError(path + ": expected a plan with at least one manoeuvre to export");
  const std::vector<ExportWaypoint> waypoints = export_waypoints(mission, plan, options.arc_tolerance_m);
  AtomicOutput out(path);
  const detail::ExportInput in{path, mission, plan, waypoints};
  const std::string temp = out.temp_path().string();
  try {
    switch (format) {
      case ExportFormat::yaml: detail::write_plan_yaml(temp, in); break;
      case ExportFormat::geojson:
      case ExportFormat::gpx:
      case ExportFormat::kml:
      case ExportFormat::csv: detail::write_plan_ogr(temp, format, in); break;
      case ExportFormat::qgc_plan: detail::write_plan_qgc(temp, in); break;
      case ExportFormat::moos: detail::write_plan_moos(temp, in); break;
      case ExportFormat::rtz: detail::write_plan_rtz(temp, in); break;
    }
  } catch (const InputError& e) {
    // Name the user's file, not the temporary ones (GDAL's messages quote them), on one line.
    static const std::regex temporary(R"([^ :'"]*\.tmp[0-9]+-[0-9]+[^ :'"]*)");
    std::string what = std::regex_replace(e.what(), temporary, path);
    std::replace(what.begin(), what.end(), '\n', ' ');
    throw InputError(what);
  }
  out.commit(options.overwrite);
}

}  // namespace deepguide
