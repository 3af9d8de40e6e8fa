#pragma once
// Polygons are Boost.Geometry models, so unions, buffers, within/intersects
// tests and R-trees come from the library. Orientation: Boost's default
// (clockwise outer rings, closed); bg::correct() fixes rings read from files.

#include <Eigen/Core>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/strategies/strategies.hpp>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

using BgPoint = boost::geometry::model::d2::point_xy<double>;
using BgPolygon = boost::geometry::model::polygon<BgPoint>;
using BgMultiPolygon = boost::geometry::model::multi_polygon<BgPolygon>;
using BgBox = boost::geometry::model::box<BgPoint>;

inline BgPoint to_bg(const Vec2& p) { return {p.x(), p.y()}; }
inline Vec2 to_eigen(const BgPoint& p) { return {p.x(), p.y()}; }

}  // namespace deepguide
