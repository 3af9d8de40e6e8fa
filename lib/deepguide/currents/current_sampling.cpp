#include "deepguide/currents/current_sampling.hpp"

#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Index i of the node interval [a[i], a[i+1]] holding v, and the fraction in it; nullopt outside.
// The fraction is exactly 0 at a node, so the node's value comes back unchanged.
inline std::optional<std::pair<std::size_t, double>> locate(const std::vector<double>& a, double v) {
  const std::size_t n = a.size();
  if (n == 0 || !(v >= a.front() && v <= a.back())) return std::nullopt;
  if (n == 1) return std::make_pair(std::size_t{0}, 0.0);
  // Most axes are regular: guess from the mean step, then correct.
  const double step = (a.back() - a.front()) / static_cast<double>(n - 1);
  std::size_t i = std::min(static_cast<std::size_t>((v - a.front()) / step), n - 2);
  if (a[i] > v || a[i + 1] < v) {
    const auto it = std::upper_bound(a.begin(), a.end(), v);
    i = std::min(static_cast<std::size_t>(it - a.begin()) - 1, n - 2);
  }
  if (v == a[i + 1] && i + 2 < n) ++i;  // exactly on an inner node: start the interval there
  return std::make_pair(i, (v - a[i]) / (a[i + 1] - a[i]));
}

}  // namespace

std::optional<Eigen::Vector2d> sample_native(const CurrentField& f, const Eigen::Vector2d& p, double time_s) {
  if (f.constant) return f.constant_velocity;
  double px = p.x();
  if (f.geographic && !f.x.empty()) {
    if (px < f.x.front())
      px += 360.0;
    else if (px > f.x.back())
      px -= 360.0;
  }
  const auto lx = locate(f.x, px);
  const auto ly = locate(f.y, p.y());
  if (!lx || !ly) return std::nullopt;
  std::size_t k0 = 0;
  double wt = 0;
  if (!f.steady()) {
    const auto lt = locate(f.times_s, time_s);
    if (!lt) return std::nullopt;
    k0 = lt->first;
    wt = lt->second;
  }
  const std::size_t nx = f.nx(), ny = f.ny();
  // Plain names, not structured bindings: clang before 16 cannot capture those in the lambda.
  const std::size_t i = lx->first, j = ly->first;
  const double fx = lx->second, fy = ly->second;
  const std::size_t i1 = std::min(i + 1, nx - 1), j1 = std::min(j + 1, ny - 1);
  auto at = [&](const std::vector<double>& c, std::size_t k) -> double {
    const std::size_t b = k * ny * nx;
    const double v00 = c[b + j * nx + i], v10 = c[b + j * nx + i1];
    const double v01 = c[b + j1 * nx + i], v11 = c[b + j1 * nx + i1];
    // Weights exactly 1 and 0 at a node, so the node's value comes back bit for bit.
    return (1 - fy) * ((1 - fx) * v00 + fx * v10) + fy * ((1 - fx) * v01 + fx * v11);
  };
  double u = at(f.u, k0), v = at(f.v, k0);
  if (wt != 0.0) {
    const double u1 = at(f.u, k0 + 1), v1 = at(f.v, k0 + 1);
    u = (1 - wt) * u + wt * u1;
    v = (1 - wt) * v + wt * v1;
  }
  // 0 * NaN is NaN: an unknown node poisons the sample even with zero weight.
  if (std::isnan(u) || std::isnan(v)) return std::nullopt;
  return Eigen::Vector2d(u, v);
}

// Bilinear lattice over a local box: field coordinates and the rotation from field axes to local axes.
struct CurrentSampler::Lattice {
  Eigen::Vector2d origin{0, 0};
  double step_x = 1, step_y = 1;
  std::size_t nx = 0, ny = 0;
  // cos and sin of the rotation, not the angle: no trigonometry per sample. Across
  // a lattice cell the angle changes by ~1e-4 rad; the interpolated (c, s) is
  // renormalised (its length would be short by ~1e-9) and its direction is
  // right to ~1e-12 rad.
  std::vector<double> fx, fy, cos_rot, sin_rot;  // NaN where no transform

  // Bilinear interpolation of the lattice at local xy: field x, field y, cos and sin of the rotation; false outside.
  bool at(const Eigen::Vector2d& xy, double& ox, double& oy, double& oc, double& os) const {
    const double gx = (xy.x() - origin.x()) / step_x, gy = (xy.y() - origin.y()) / step_y;
    if (!(gx >= 0 && gy >= 0 && gx <= static_cast<double>(nx - 1) && gy <= static_cast<double>(ny - 1))) return false;
    const std::size_t i = std::min(static_cast<std::size_t>(gx), nx - 2),
                      j = std::min(static_cast<std::size_t>(gy), ny - 2);
    const double tx = gx - static_cast<double>(i), ty = gy - static_cast<double>(j);
    auto bil = [&](const std::vector<double>& c) {
      const std::size_t b = j * nx + i;
      return (1 - ty) * ((1 - tx) * c[b] + tx * c[b + 1]) + ty * ((1 - tx) * c[b + nx] + tx * c[b + nx + 1]);
    };
    ox = bil(fx);
    oy = bil(fy);
    oc = bil(cos_rot);
    os = bil(sin_rot);
    const double len = std::sqrt(oc * oc + os * os);
    oc /= len;
    os /= len;
    return std::isfinite(ox) && std::isfinite(oy) && std::isfinite(oc) && std::isfinite(os);
  }
};

namespace {

// Exact (OSR) field coordinates and field-to-local rotation at a local point.
struct ExactMap {
  const CurrentField& field;
  const LocalFrame& frame;
  std::unique_ptr<OGRSpatialReference> srs;
  gdal::TransformPtr geo_to_field{nullptr, nullptr};
  double centre_lon = 0;

  ExactMap(const CurrentField& f, const LocalFrame& fr) : field(f), frame(fr) {
    if (!f.geographic) {
      srs = std::make_unique<OGRSpatialReference>();
      srs->importFromWkt(f.crs_wkt.c_str());
      srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
      geo_to_field = gdal::make_transform(*gdal::wgs84(), *srs);
    } else if (!f.x.empty()) {
      centre_lon = 0.5 * (f.x.front() + f.x.back());
    }
  }
  // lon/lat -> field coordinates (NaN if impossible).
  Eigen::Vector2d field_of(Eigen::Vector2d ll) const {
    if (!ll.allFinite()) return {kNaN, kNaN};
    if (field.geographic) {
      // Wrap into centre +- 180 so the lattice is continuous across the field.
      ll.x() = centre_lon + (wrap_360(ll.x() - centre_lon + 180.0) - 180.0);
      return ll;
    }
    if (!geo_to_field) return {kNaN, kNaN};
    double x = ll.x(), y = ll.y();
    if (!geo_to_field->Transform(1, &x, &y)) return {kNaN, kNaN};
    return {x, y};
  }
  // (field x, field y, rotation field axes -> local axes) at local xy.
  Eigen::Vector3d at(const Eigen::Vector2d& xy) const {
    const Eigen::Vector2d ll = frame.to_lonlat(xy);
    const Eigen::Vector2d p = field_of(ll);
    if (!p.allFinite()) return {kNaN, kNaN, kNaN};
    double field_north = kPi / 2;
    if (!field.geographic) {
      const double step = ll.y() > 89.0 ? -1e-5 : 1e-5;
      const Eigen::Vector2d q = field_of({ll.x(), ll.y() + step});
      if (!q.allFinite()) return {kNaN, kNaN, kNaN};
      field_north = math_angle(step > 0 ? Eigen::Vector2d(q - p) : Eigen::Vector2d(p - q));
    }
    return {p.x(), p.y(), wrap_pi(frame.true_north_angle(xy) - field_north)};
  }
};

bool same_crs(const CurrentField& f, const LocalFrame& frame) {
  if (f.constant || f.geographic) return false;
  OGRSpatialReference a, b;
  if (a.importFromWkt(f.crs_wkt.c_str()) != OGRERR_NONE || b.importFromWkt(frame.wkt().c_str()) != OGRERR_NONE)
    return false;
  return a.IsSame(&b) != 0;
}

// Local bounding box of the field's nodes (densified boundary through OSR).
std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> local_box_of(const CurrentField& f,
                                                                        const LocalFrame& frame) {
  std::unique_ptr<OGRSpatialReference> srs;
  gdal::TransformPtr to_geo{nullptr, nullptr};
  if (!f.geographic) {
    srs = std::make_unique<OGRSpatialReference>();
    srs->importFromWkt(f.crs_wkt.c_str());
    srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    to_geo = gdal::make_transform(*srs, *gdal::wgs84());
    if (!to_geo) return std::nullopt;
  }
  Eigen::Vector2d lo(kNaN, kNaN), hi(kNaN, kNaN);
  bool any = false;
  constexpr int kSteps = 64;
  const double x0 = f.x.front(), x1 = f.x.back(), y0 = f.y.front(), y1 = f.y.back();
  for (int e = 0; e < 4; ++e)
    for (int s = 0; s <= kSteps; ++s) {
      const double t = static_cast<double>(s) / kSteps;
      double x = e == 0 ? x0 + t * (x1 - x0) : e == 1 ? x1 : e == 2 ? x1 - t * (x1 - x0) : x0;
      double y = e == 0 ? y0 : e == 1 ? y0 + t * (y1 - y0) : e == 2 ? y1 : y1 - t * (y1 - y0);
      if (to_geo && !to_geo->Transform(1, &x, &y)) continue;
      const Eigen::Vector2d p = frame.from_lonlat(x, y);
      if (!p.allFinite()) continue;
      lo = any ? Eigen::Vector2d(lo.cwiseMin(p)) : p;
      hi = any ? Eigen::Vector2d(hi.cwiseMax(p)) : p;
      any = true;
    }
  if (!any) return std::nullopt;
  return std::make_pair(lo, hi);
}

}  // namespace

CurrentSampler::CurrentSampler(std::shared_ptr<const CurrentField> field, const LocalFrame& frame,
                               const std::optional<Eigen::Vector2d>& area_min,
                               const std::optional<Eigen::Vector2d>& area_max)
    : field_(std::move(field)), frame_(frame) {
  const CurrentField& f = *field_;
  if (same_crs(f, frame_)) return;
  std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> box;
  std::size_t n_x = 16, n_y = 16;
  if (f.constant) {
    if (!area_min || !area_max) return;  // exact path per sample
    box = std::make_pair(area_min->cwiseMin(*area_max), area_min->cwiseMax(*area_max));
  } else {
    if (f.x.empty() || f.y.empty()) return;
    box = local_box_of(f, frame_);
    n_x = std::clamp<std::size_t>(4 * f.nx(), 16, 256);
    n_y = std::clamp<std::size_t>(4 * f.ny(), 16, 256);
  }
  auto lat = std::make_shared<Lattice>();
  lat->nx = n_x;
  lat->ny = n_y;
  if (box) {
    Eigen::Vector2d lo = box->first, hi = box->second;
    // One lattice step of margin so points on the field's edge are inside.
    const Eigen::Vector2d size = (hi - lo).cwiseMax(Eigen::Vector2d(1.0, 1.0));
    const Eigen::Vector2d margin(size.x() / static_cast<double>(n_x - 3), size.y() / static_cast<double>(n_y - 3));
    lo -= margin;
    hi += margin;
    lat->origin = lo;
    lat->step_x = (hi.x() - lo.x()) / static_cast<double>(n_x - 1);
    lat->step_y = (hi.y() - lo.y()) / static_cast<double>(n_y - 1);
    const ExactMap exact(f, frame_);
    lat->fx.resize(n_x * n_y);
    lat->fy.resize(n_x * n_y);
    lat->cos_rot.resize(n_x * n_y);
    lat->sin_rot.resize(n_x * n_y);
    for (std::size_t j = 0; j < n_y; ++j)
      for (std::size_t i = 0; i < n_x; ++i) {
        const Eigen::Vector3d m =
            exact.at(lo + Eigen::Vector2d(static_cast<double>(i) * lat->step_x, static_cast<double>(j) * lat->step_y));
        lat->fx[j * n_x + i] = m.x();
        lat->fy[j * n_x + i] = m.y();
        lat->cos_rot[j * n_x + i] = std::cos(m.z());
        lat->sin_rot[j * n_x + i] = std::sin(m.z());
      }
  } else {
    lat->nx = lat->ny = 0;  // the field lies nowhere in this frame
  }
  lattice_ = std::move(lat);
}

std::optional<Eigen::Vector2d> CurrentSampler::sample(const Eigen::Vector2d& xy, double time_s) const {
  const CurrentField& f = *field_;
  if (!lattice_) {
    if (!f.constant) return sample_native(f, xy, time_s);
    // A constant current without a lattice: the exact rotation at this point.
    const double rot = frame_.true_north_angle(xy) - kPi / 2;
    if (!std::isfinite(rot)) return std::nullopt;
    return Eigen::Vector2d(std::cos(rot) * f.constant_velocity.x() - std::sin(rot) * f.constant_velocity.y(),
                           std::sin(rot) * f.constant_velocity.x() + std::cos(rot) * f.constant_velocity.y());
  }
  double fx = 0, fy = 0, c = 1, s = 0;
  if (lattice_->nx < 2 || !lattice_->at(xy, fx, fy, c, s)) {
    if (!f.constant) return std::nullopt;
    const double rot = frame_.true_north_angle(xy) - kPi / 2;
    if (!std::isfinite(rot)) return std::nullopt;
    c = std::cos(rot);
    s = std::sin(rot);
  }
  const auto v = sample_native(f, {fx, fy}, time_s);
  if (!v) return std::nullopt;
  return Eigen::Vector2d(c * v->x() - s * v->y(), s * v->x() + c * v->y());
}

CurrentCoverage check_current_coverage(const CurrentField& f, const LocalFrame& frame, const Eigen::Vector2d& area_min,
                                       const Eigen::Vector2d& area_max, double time_first_s, double time_last_s) {
  CurrentCoverage cov;
  if (f.constant) return cov;
  const ExactMap exact(f, frame);
  const Eigen::Vector2d lo = area_min.cwiseMin(area_max), hi = area_min.cwiseMax(area_max);
  double fx0 = kNaN, fx1 = kNaN, fy0 = kNaN, fy1 = kNaN;
  double lon0 = kNaN, lon1 = kNaN, lat0 = kNaN, lat1 = kNaN;
  bool inside = !f.x.empty() && !f.y.empty();
  constexpr int kSteps = 32;
  for (int e = 0; e < 4; ++e)
    for (int s = 0; s <= kSteps; ++s) {
      const double t = static_cast<double>(s) / kSteps;
      const Eigen::Vector2d p(e == 0   ? lo.x() + t * (hi.x() - lo.x())
                              : e == 1 ? hi.x()
                              : e == 2 ? hi.x() - t * (hi.x() - lo.x())
                                       : lo.x(),
                              e == 0   ? lo.y()
                              : e == 1 ? lo.y() + t * (hi.y() - lo.y())
                              : e == 2 ? hi.y()
                                       : hi.y() - t * (hi.y() - lo.y()));
      const Eigen::Vector2d ll = frame.to_lonlat(p);
      lon0 = std::fmin(lon0, ll.x());
      lon1 = std::fmax(lon1, ll.x());
      lat0 = std::fmin(lat0, ll.y());
      lat1 = std::fmax(lat1, ll.y());
      Eigen::Vector2d q = exact.field_of(ll);
      if (f.geographic && q.allFinite()) {
        if (q.x() < f.x.front())
          q.x() += 360.0;
        else if (q.x() > f.x.back())
          q.x() -= 360.0;
      }
      if (!q.allFinite() || !inside || q.x() < f.x.front() || q.x() > f.x.back() || q.y() < f.y.front() ||
          q.y() > f.y.back()) {
        inside = false;
        continue;
      }
      fx0 = std::fmin(fx0, q.x());
      fx1 = std::fmax(fx1, q.x());
      fy0 = std::fmin(fy0, q.y());
      fy1 = std::fmax(fy1, q.y());
    }
  const bool timed = !f.steady() && (std::isfinite(time_first_s) || std::isfinite(time_last_s));
  bool time_ok = true;
  if (timed) {
    const double a = std::isfinite(time_first_s) ? time_first_s : time_last_s;
    const double b = std::isfinite(time_last_s) ? time_last_s : time_first_s;
    time_ok = std::min(a, b) >= f.times_s.front() && std::max(a, b) <= f.times_s.back();
  }
  if (!inside || !time_ok) {
    std::string times;
    if (!f.times_s.empty()) {
      times = " (times " + format_utc(f.times_s.front()) +
              (f.steady() ? std::string(", steady") : " .. " + format_utc(f.times_s.back())) + ")";
    }
    std::string work =
        "lon " + fixed(lon0, 4) + " .. " + fixed(lon1, 4) + ", lat " + fixed(lat0, 4) + " .. " + fixed(lat1, 4);
    if (timed) {
      work += ", times " + format_utc(std::isfinite(time_first_s) ? time_first_s : time_last_s) + " .. " +
              format_utc(std::isfinite(time_last_s) ? time_last_s : time_first_s);
    }
    throw InputError(f.source + ": the current field covers lon " + fixed(f.extent.west, 4) + " .. " +
                     fixed(f.extent.east, 4) + ", lat " + fixed(f.extent.south, 4) + " .. " + fixed(f.extent.north, 4) +
                     times + "; the work area " + work + " is " + (inside ? "outside its time axis" : "outside"));
  }
  const std::size_t nx = f.nx(), ny = f.ny(), steps = f.steps();
  for (std::size_t j = 0; j < ny; ++j) {
    if (f.y[j] < fy0 || f.y[j] > fy1) continue;
    for (std::size_t i = 0; i < nx; ++i) {
      if (f.x[i] < fx0 || f.x[i] > fx1) continue;
      ++cov.nodes;
      for (std::size_t k = 0; k < steps; ++k) {
        const std::size_t idx = (k * ny + j) * nx + i;
        if (std::isnan(f.u[idx]) || std::isnan(f.v[idx])) {
          ++cov.fill_nodes;
          break;
        }
      }
    }
  }
  return cov;
}

}  // namespace deepguide
