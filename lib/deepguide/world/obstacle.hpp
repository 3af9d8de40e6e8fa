#pragma once
// Obstacles in the local metric frame. The seed's Object Detection reports
// elliptical cylinders; charts add polygonal obstacles (land, hazard areas).
// Vertically an obstacle either stands `height_m` above the sea floor or has
// its top at `top_depth_m` (depth, positive down); with neither it is taken to
// fill the whole water column (the safe assumption for planning).

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/ellipse.hpp"
#include "deepguide/geometry/polygon.hpp"

namespace DEEPGUIDE_API deepguide {

struct EllipticCylinder {
  std::string id;
  Ellipse footprint;                  ///< local frame, metres; theta is a math angle
  std::optional<double> height_m;     ///< above the sea floor
  std::optional<double> top_depth_m;  ///< depth of the top, positive down
};

struct PolygonObstacle {
  std::string id;
  BgPolygon footprint;  ///< local frame, metres; corrected orientation
  std::optional<double> height_m;
  std::optional<double> top_depth_m;
};

struct ObstacleSet {
  std::vector<EllipticCylinder> ellipses;
  std::vector<PolygonObstacle> polygons;

  std::size_t size() const { return ellipses.size() + polygons.size(); }
  bool empty() const { return size() == 0; }
};

/// A box (min, max corners) around every footprint, an ellipse by the disc of
/// its semi-major axis; min > max for an empty set.
std::pair<Vec2, Vec2> footprint_box(const ObstacleSet& obstacles);

/// Removes the obstacles a vehicle at `depth_m` passes over: those whose top
/// lies deeper than depth_m + vertical_clearance_m. Obstacles given by their
/// height above the sea floor stay (their top depth needs a chart), as do
/// obstacles without vertical extent. Returns how many were removed; throws
/// InputError for a negative or non-finite depth or clearance.
std::size_t remove_passable(ObstacleSet& obstacles, double depth_m, double vertical_clearance_m);

/// The footprints' fingerprint ("fnv1a64:" and 16 hex digits), in order and
/// bit for bit: a graph prepared over these obstacles (prepared_graphs.hpp)
/// is taken only for the same obstacles read the same way.
std::string footprint_fingerprint(const ObstacleSet& obstacles);

/// The obstacles of `all` beyond those of `part` (footprints equal bit for
/// bit, each counted as often as it occurs), in `all`'s order; nullopt when
/// `part` is not wholly in `all`. What a graph kept for `part` must take in
/// to stand for `all` (prepared_graphs.hpp).
std::optional<ObstacleSet> obstacles_beyond(const ObstacleSet& all, const ObstacleSet& part);

}  // namespace deepguide
