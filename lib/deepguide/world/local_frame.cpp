#include "deepguide/world/local_frame.hpp"

#include <charconv>
#include <cmath>
#include <mutex>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
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

LocalFrame::LocalFrame(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

int utm_epsg_for(double lon_deg, double lat_deg) {
  const double lon = wrap_360(lon_deg + 180.0) - 180.0;
  int zone = static_cast<int>(std::floor((lon + 180.0) / 6.0)) + 1;
  zone = std::clamp(zone, 1, 60);
  return (lat_deg >= 0.0 ? 32600 : 32700) + zone;
}

LocalFrame LocalFrame::utm_for(double lon_deg, double lat_deg) {
  return from_user_crs("EPSG:" + std::to_string(utm_epsg_for(lon_deg, lat_deg)), "UTM zone");
}

LocalFrame LocalFrame::from_user_crs(const std::string& crs, const std::string& what) {
  gdal::ensure_registered();
  auto impl = std::make_shared<Impl>();
  impl->srs = gdal::srs_from_user_input(crs);
  if (!impl->srs) {
    throw InputError(what + ": expected a known coordinate reference system such as EPSG:32632, got '" +
                     crs + "'");
  }
  if (!impl->srs->IsProjected()) {
    throw InputError(what + ": expected a projected (metric) CRS for the local frame, got '" + crs +
                     "' which is not projected");
  }
  const auto geo = gdal::wgs84();
  impl->to_local = gdal::make_transform(*geo, *impl->srs);
  impl->to_geo = gdal::make_transform(*impl->srs, *geo);
  if (!impl->to_local || !impl->to_geo) {
    throw InputError(what + ": no transformation between WGS 84 and '" + crs + "'");
  }
  impl->id = gdal::srs_id(*impl->srs);
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

Eigen::Vector2d parse_position(const std::string& text, const std::string& what, const LocalFrame& frame,
                               bool frame_coordinates) {
  const std::string expected = frame_coordinates ? "x,y in " + frame.id() + " metres" : "lon,lat in degrees";
  const auto comma = text.find(',');
  double v[2] = {0.0, 0.0};
  bool ok = comma != std::string::npos && text.find(',', comma + 1) == std::string::npos;
  for (int i = 0; ok && i < 2; ++i) {
    const std::string part = i == 0 ? text.substr(0, comma) : text.substr(comma + 1);
    const char* first = part.data();
    const char* last = part.data() + part.size();
    while (first < last && *first == ' ') ++first;
    if (first < last && *first == '+') ++first;
    auto [ptr, ec] = std::from_chars(first, last, v[i]);
    ok = ec == std::errc() && ptr == last && std::isfinite(v[i]);
  }
  if (!ok) throw InputError(what + ": expected " + expected + ", got '" + text + "'");
  if (frame_coordinates) return {v[0], v[1]};
  if (std::abs(v[1]) > 90.0 || std::abs(v[0]) > 180.0) {
    throw InputError(what + ": expected lon,lat in degrees within +-180,+-90, got '" + text +
                     "' (give --crs to use projected coordinates)");
  }
  const Eigen::Vector2d xy = frame.from_lonlat(v[0], v[1]);
  if (!xy.allFinite()) throw InputError(what + ": expected a position inside the local frame " + frame.id());
  return xy;
}

const std::string& LocalFrame::id() const { return impl_->id; }
const std::string& LocalFrame::name() const { return impl_->name; }
const std::string& LocalFrame::wkt() const { return impl_->wkt; }

}  // namespace deepguide
