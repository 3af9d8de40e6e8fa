#pragma once
// Small obstacles for planning tests: an axis-aligned box and a disc.
#include <boost/geometry.hpp>
#include <string>
#include <utility>

#include "deepguide/world/obstacle.hpp"

namespace deepguide::test {

inline PolygonObstacle box(double x0, double y0, double x1, double y1, std::string id = "") {
  PolygonObstacle p;
  p.id = std::move(id);
  p.footprint.outer() = {to_bg({x0, y0}), to_bg({x0, y1}), to_bg({x1, y1}), to_bg({x1, y0}), to_bg({x0, y0})};
  boost::geometry::correct(p.footprint);
  return p;
}

inline EllipticCylinder disc(double x, double y, double r, std::string id) {
  EllipticCylinder c;
  c.id = std::move(id);
  c.footprint = Ellipse{{x, y}, r, r, 0.0};
  return c;
}

}  // namespace deepguide::test
