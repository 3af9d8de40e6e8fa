#pragma once
// The local metric frame in which all planning happens: x = easting (m),
// y = northing (m), z = depth (m, positive down). By default it is the UTM
// zone of the work area's centre; a user may name any projected CRS instead.
//
// Headings in files are clockwise from TRUE north, while the frame's y axis
// points to GRID north; they differ by the meridian convergence (up to a few
// degrees near the edge of a UTM zone). true_north_angle() gives the exact
// direction of true north at a point, so orientations stay right to the metre
// on long obstacles.

#include <Eigen/Core>
#include <memory>
#include <string>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

class LocalFrame {
 public:
  /// The UTM zone (WGS 84) containing the given longitude and latitude (degrees).
  static LocalFrame utm_for(double lon_deg, double lat_deg);
  /// A user-named CRS, e.g. "EPSG:32632", or anything OSR's SetFromUserInput
  /// accepts. It must be projected (metric). Throws InputError naming `what`
  /// (e.g. "`local_crs`") otherwise.
  static LocalFrame from_user_crs(const std::string& crs, const std::string& what = "`local_crs`");

  /// Geographic WGS 84 longitude/latitude (degrees) -> local (x, y) in metres.
  Eigen::Vector2d from_lonlat(double lon_deg, double lat_deg) const;
  Eigen::Vector2d from_lonlat(const Eigen::Vector2d& lonlat) const { return from_lonlat(lonlat.x(), lonlat.y()); }
  /// Local (x, y) in metres -> (longitude, latitude) in degrees.
  Eigen::Vector2d to_lonlat(const Eigen::Vector2d& xy) const;

  /// How many frame units one true metre (on the WGS 84 ellipsoid) becomes at
  /// a point (lon, lat in degrees), least and greatest over all directions:
  /// the semi-axes of Tissot's indicatrix. Equal in a conformal frame; (NaN,
  /// NaN) where the frame does not reach (outside the projection, a pole).
  struct Scale {
    double least;
    double greatest;
  };
  Scale scale_at(const Eigen::Vector2d& lonlat) const;

  /// Math angle (rad, ccw from the frame's x axis) of true north at a local point.
  double true_north_angle(const Eigen::Vector2d& xy) const;
  /// Nautical heading (deg, clockwise from true north) at xy -> local math angle (rad), and back.
  double heading_to_local(double heading_deg, const Eigen::Vector2d& xy) const;
  double local_to_heading(double math_rad, const Eigen::Vector2d& xy) const;

  /// "EPSG:32632" when the CRS has an EPSG code, otherwise its name.
  const std::string& id() const;
  /// Human-readable name, e.g. "WGS 84 / UTM zone 32N".
  const std::string& name() const;
  /// The CRS as WKT (for writers that need it).
  const std::string& wkt() const;

 private:
  struct Impl;
  explicit LocalFrame(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

/// Parses "lon,lat" in degrees given as `what` (e.g. "--from"); InputError
/// for anything else (not two numbers, NaN, beyond +-180, +-90).
Eigen::Vector2d parse_lonlat(const std::string& text, const std::string& what);

/// Parses a position "A,B" given on the command line as `what` (e.g. "--from"):
/// lon,lat in degrees, or, when `frame_coordinates`, x,y in the frame's CRS.
/// Throws InputError for anything else (not two numbers, NaN, lat beyond 90),
/// and, in a UTM frame, for a latitude beyond 80 S to 84 N or a longitude
/// more than a zone's width (6 degrees) from its central meridian.
Eigen::Vector2d parse_position(const std::string& text, const std::string& what, const LocalFrame& frame,
                               bool frame_coordinates);

/// EPSG code of the WGS 84 UTM zone containing the point (326zz north, 327zz south).
int utm_epsg_for(double lon_deg, double lat_deg);

}  // namespace deepguide
