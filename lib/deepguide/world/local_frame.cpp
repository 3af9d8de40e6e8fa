#include "deepguide/world/local_frame.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <numbers>
#include <optional>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/world/frame_scale.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {

struct LocalFrame::Impl {
  std::unique_ptr<OGRSpatialReference> srs;
  gdal::TransformPtr to_local{nullptr, nullptr};
  gdal::TransformPtr to_geo{nullptr, nullptr};
  std::string id;
  std::string name;
  std::string wkt;
  // OGRCoordinateTransformation::Transform is not guaranteed thread-safe.
  mutable std::mutex mutex;
};

namespace {

// OSR reads a WKT whose projection method PROJ does not know (a typo such as
// "Transverse_Mercatorr") and makes a transformation that then fails on every
// point; the first position given blamed the data. The frame is tried at its
// own origin (the central meridian and latitude of origin) and at a few
// places a projection of any extent holds one of.
void require_projects_somewhere(const OGRSpatialReference& srs, OGRCoordinateTransformation& to_local,
                                const std::string& crs, const std::string& what) {
  const double lon0 =
      srs.GetNormProjParm(SRS_PP_CENTRAL_MERIDIAN, srs.GetNormProjParm(SRS_PP_LONGITUDE_OF_ORIGIN, 0.0));
  const double lat0 =
      srs.GetNormProjParm(SRS_PP_LATITUDE_OF_ORIGIN, srs.GetNormProjParm(SRS_PP_LATITUDE_OF_CENTER, 0.0));
  gdal::QuietErrors quiet;
  for (const auto& [lon, lat] :
       {std::pair{lon0, lat0}, {lon0, 0.0}, {lon0, 45.0}, {lon0, -45.0}, {lon0, 80.0}, {lon0, -80.0}, {0.0, 0.0}}) {
    double x = lon, y = lat;
    if (to_local.Transform(1, &x, &y) && std::isfinite(x) && std::isfinite(y)) return;
  }
  const char* method = srs.GetAttrValue("PROJECTION");
  const std::string why = gdal::QuietErrors::last_message();
  throw InputError(what + ": '" + printable(crs, 80) + "' projects no position" +
                   (method != nullptr ? " (projection method '" + printable(method) + "')" : std::string()) +
                   (why.empty() ? std::string() : ": " + printable(why, 120)) +
                   "; expected a CRS PROJ can project with, such as EPSG:32632");
}

}  // namespace

LocalFrame::LocalFrame(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

int utm_epsg_for(double lon_deg, double lat_deg) {
  const double lon = wrap_360(lon_deg + 180.0) - 180.0;
  int zone = static_cast<int>(std::floor((lon + 180.0) / 6.0)) + 1;
  zone = std::clamp(zone, 1, 60);
  return (lat_deg >= 0.0 ? 32600 : 32700) + zone;
}

namespace {

// UTM is defined from 80 S to 84 N; beyond, a polar projection is the frame.
void require_utm_latitude(double lon_deg, double lat_deg, const std::string& what) {
  if (lat_deg >= -80.0 && lat_deg <= 84.0) return;
  throw InputError(what + ": latitude " + fixed(lat_deg, 4) +
                   " lies beyond UTM's 80 S to 84 N; give `local_crs` with a projection of true scale there "
                   "(positions are then x,y in it), e.g. '" +
                   stereographic_crs_for({lon_deg, lon_deg, lat_deg, lat_deg}) + "'");
}

// The central meridian of a WGS 84 UTM frame (EPSG:326zz / 327zz); none for other frames.
std::optional<double> utm_central_meridian(const std::string& id) {
  if (id.size() != 10 || id.compare(0, 7, "EPSG:32") != 0 || (id[7] != '6' && id[7] != '7')) return std::nullopt;
  const int zone = std::atoi(id.c_str() + 8);
  if (zone < 1 || zone > 60) return std::nullopt;
  return -183.0 + 6.0 * zone;
}

}  // namespace

LocalFrame LocalFrame::utm_for(double lon_deg, double lat_deg) {
  require_utm_latitude(lon_deg, lat_deg, "UTM zone");
  return from_user_crs("EPSG:" + std::to_string(utm_epsg_for(lon_deg, lat_deg)), "UTM zone");
}

LocalFrame LocalFrame::from_user_crs(const std::string& crs, const std::string& what) {
  gdal::ensure_registered();
  auto impl = std::make_shared<Impl>();
  impl->srs = gdal::srs_from_user_input(crs);
  if (!impl->srs) {
    throw InputError(what + ": expected a known coordinate reference system such as EPSG:32632, got '" + crs + "'");
  }
  if (!impl->srs->IsProjected()) {
    throw InputError(what + ": expected a projected (metric) CRS for the local frame, got '" + crs +
                     "' which is not projected");
  }
  // Every length in deepguide is a metre: obstacle axes, margins, speeds. A frame in feet (a US
  // survey-foot UTM, a state plane) would take a 5 m margin as 5 ft and report feet as metres.
  const char* unit = nullptr;
  const double metres_per_unit = impl->srs->GetLinearUnits(&unit);
  if (std::abs(metres_per_unit - 1.0) > 1e-12) {
    throw InputError(what + ": expected a projected CRS in metres for the local frame, got '" + crs + "' in " +
                     (unit != nullptr ? std::string(unit) : std::string("another unit")) + " (" +
                     general(metres_per_unit, 10) + " m)");
  }
  const auto geo = gdal::wgs84();
  impl->to_local = gdal::make_transform(*geo, *impl->srs);
  impl->to_geo = gdal::make_transform(*impl->srs, *geo);
  if (!impl->to_local || !impl->to_geo) {
    throw InputError(what + ": no transformation between WGS 84 and '" + crs + "'");
  }
  require_projects_somewhere(*impl->srs, *impl->to_local, crs, what);
  // A CRS without an authority code is known by what the user gave, so that
  // the id made into a frame again (a prepared chart, a scenario) is the same frame.
  impl->id = impl->srs->GetAuthorityCode(nullptr) != nullptr ? gdal::srs_id(*impl->srs) : crs;
  const char* name = impl->srs->GetName();
  impl->name = name != nullptr ? name : impl->id;
  char* wkt = nullptr;
  impl->srs->exportToWkt(&wkt);
  impl->wkt = wkt != nullptr ? wkt : "";
  CPLFree(wkt);
  return LocalFrame(std::move(impl));
}

Eigen::Vector2d LocalFrame::from_lonlat(double lon_deg, double lat_deg) const {
  double x = lon_deg;
  double y = lat_deg;
  std::lock_guard lock(impl_->mutex);
  if (!std::isfinite(x) || !std::isfinite(y) || !impl_->to_local->Transform(1, &x, &y)) {
    return {std::nan(""), std::nan("")};
  }
  return {x, y};
}

Eigen::Vector2d LocalFrame::to_lonlat(const Eigen::Vector2d& xy) const {
  double x = xy.x();
  double y = xy.y();
  std::lock_guard lock(impl_->mutex);
  if (!std::isfinite(x) || !std::isfinite(y) || !impl_->to_geo->Transform(1, &x, &y)) {
    return {std::nan(""), std::nan("")};
  }
  return {x, y};
}

// Tissot's indicatrix by differences: the frame's Jacobian against true
// metres east and north on the WGS 84 ellipsoid (the datum every lon, lat
// here is on), whose singular values are the least and greatest scale. Not
// PROJ's proj_factors: it measures a projection against its own ellipsoid or
// sphere, and Web Mercator (a sphere on WGS 84's lon, lat) is 0.67 % longer
// north-south than it says at the equator.
LocalFrame::Scale LocalFrame::scale_at(const Eigen::Vector2d& lonlat) const {
  const double nan = std::nan("");
  if (!lonlat.allFinite() || std::abs(lonlat.y()) > 90.0) return {nan, nan};
  constexpr double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2.0 - f);
  const double phi = lonlat.y() * std::numbers::pi / 180.0;
  const double w = std::sqrt(1.0 - e2 * std::sin(phi) * std::sin(phi));
  const double meridian = a * (1.0 - e2) / (w * w * w);  // M: metres per radian north
  const double parallel = a / w * std::cos(phi);         // N cos(lat): metres per radian east
  // Steps of about 1 m (central differences: the error is of the step squared).
  constexpr double kStepM = 1.0;
  const double dlat = kStepM / meridian * 180.0 / std::numbers::pi;
  const double dlon = kStepM / std::max(parallel, 1e-3) * 180.0 / std::numbers::pi;
  if (std::abs(lonlat.y()) + dlat > 90.0) return {nan, nan};
  const Eigen::Vector2d e = (from_lonlat(lonlat.x() + dlon, lonlat.y()) - from_lonlat(lonlat.x() - dlon, lonlat.y())) /
                            (2.0 * dlon * std::numbers::pi / 180.0 * parallel);
  const Eigen::Vector2d n = (from_lonlat(lonlat.x(), lonlat.y() + dlat) - from_lonlat(lonlat.x(), lonlat.y() - dlat)) /
                            (2.0 * dlat * std::numbers::pi / 180.0 * meridian);
  if (!e.allFinite() || !n.allFinite()) return {nan, nan};
  // Singular values of [e n]: sqrt((s +- sqrt(s^2 - 4 det^2)) / 2).
  const double s = e.squaredNorm() + n.squaredNorm(), det = e.x() * n.y() - e.y() * n.x();
  const double root = std::sqrt(std::max(0.0, s * s - 4.0 * det * det));
  return {std::sqrt(std::max(0.0, 0.5 * (s - root))), std::sqrt(0.5 * (s + root))};
}

double LocalFrame::true_north_angle(const Eigen::Vector2d& xy) const {
  // Step a short way north along the meridian through the point (towards the
  // equator near the poles, then reverse) and read the direction in the frame.
  const Eigen::Vector2d ll = to_lonlat(xy);
  const double step = ll.y() > 89.0 ? -1e-5 : 1e-5;
  const Eigen::Vector2d other = from_lonlat(ll.x(), ll.y() + step);
  const Eigen::Vector2d here = from_lonlat(ll.x(), ll.y());
  const Eigen::Vector2d d = step > 0 ? Eigen::Vector2d(other - here) : Eigen::Vector2d(here - other);
  return math_angle(d);
}

double LocalFrame::heading_to_local(double heading_deg, const Eigen::Vector2d& xy) const {
  return wrap_pi(true_north_angle(xy) - deg_to_rad(heading_deg));
}

double LocalFrame::local_to_heading(double math_rad, const Eigen::Vector2d& xy) const {
  return wrap_360(rad_to_deg(true_north_angle(xy) - math_rad));
}

namespace {

// "A,B": two finite numbers, or nothing.
std::optional<Eigen::Vector2d> number_pair(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) return std::nullopt;
  double v[2] = {0.0, 0.0};
  for (int i = 0; i < 2; ++i) {
    const std::string part = i == 0 ? text.substr(0, comma) : text.substr(comma + 1);
    const char* first = part.data();
    const char* last = part.data() + part.size();
    while (first < last && *first == ' ') ++first;
    if (first < last && *first == '+') ++first;
    auto [ptr, ec] = std::from_chars(first, last, v[i]);
    if (ec != std::errc() || ptr != last || !std::isfinite(v[i])) return std::nullopt;
  }
  return Eigen::Vector2d(v[0], v[1]);
}

}  // namespace

Eigen::Vector2d parse_lonlat(const std::string& text, const std::string& what) {
  const std::optional<Eigen::Vector2d> v = number_pair(text);
  if (!v) throw InputError(what + ": expected lon,lat in degrees, got '" + text + "'");
  if (std::abs(v->y()) > 90.0 || std::abs(v->x()) > 180.0) {
    throw InputError(what + ": expected lon,lat in degrees within +-180,+-90, got '" + text +
                     "' (give `local_crs` to use projected coordinates)");
  }
  return *v;
}

Eigen::Vector2d parse_position(const std::string& text, const std::string& what, const LocalFrame& frame,
                               bool frame_coordinates) {
  if (frame_coordinates) {
    const std::optional<Eigen::Vector2d> v = number_pair(text);
    if (!v) throw InputError(what + ": expected x,y in " + frame.id() + " metres, got '" + text + "'");
    const Eigen::Vector2d ll = frame.to_lonlat(*v);
    if (!ll.allFinite()) throw InputError(what + ": expected a position inside the local frame " + frame.id());
    require_true_scale(frame, std::vector<Eigen::Vector2d>{ll}, what);
    return *v;
  }
  const Eigen::Vector2d ll = parse_lonlat(text, what);
  const double v[2] = {ll.x(), ll.y()};
  // In a UTM frame: within its latitudes, and within a zone's width (6 deg)
  // of its central meridian, where its scale is off by at most 0.55 %.
  if (const std::optional<double> cm = utm_central_meridian(frame.id())) {
    require_utm_latitude(v[0], v[1], what);
    const double off = std::abs(std::remainder(v[0] - *cm, 360.0));
    if (off > 6.0) {
      const double b = std::cos(v[1] * std::numbers::pi / 180.0) * std::sin(off * std::numbers::pi / 180.0);
      const double scale = 0.9996 / std::sqrt(std::max(1.0 - b * b, 1e-12)) - 1.0;
      throw InputError(what + ": " + fixed(off, 2) + " degrees of longitude from the central meridian (" +
                       fixed(*cm, 0) + ") of the local frame " + frame.id() +
                       ", more than a UTM zone's width (6 degrees), where its distances are off by " +
                       (scale < 1.0 ? fixed(100.0 * scale, 1) + " %" : std::string("more than 100 %")) +
                       "; plan in shorter parts, or give `local_crs` with a projection that covers the whole route "
                       "(`start` and `goal` are then x,y in it)");
    }
  }
  const Eigen::Vector2d xy = frame.from_lonlat(v[0], v[1]);
  if (!xy.allFinite()) throw InputError(what + ": expected a position inside the local frame " + frame.id());
  require_true_scale(frame, std::vector<Eigen::Vector2d>{ll}, what);
  return xy;
}

const std::string& LocalFrame::id() const { return impl_->id; }
const std::string& LocalFrame::name() const { return impl_->name; }
const std::string& LocalFrame::wkt() const { return impl_->wkt; }

}  // namespace deepguide
