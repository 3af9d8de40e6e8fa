#pragma once
// The ellipse: the footprint of the seed's elliptical-cylinder obstacle.
//
// Math on top: with R = R(theta) the rotation by the major-axis angle,
//   points  x = c + R diag(a, b) (cos t, sin t)            (parameter t)
//   inside  |diag(1/a, 1/b) R^T (x - c)| < 1              (the unit-circle frame)
//   support h(u) = u.c + sqrt(u^T A u),  A = R diag(a^2, b^2) R^T
// The map to the unit-circle frame is affine with positive determinant, so it
// keeps tangency, incidence and orientation (left stays left); several
// algorithms below work there and map back.

#include <Eigen/Core>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

struct Ellipse {
  Vec2 centre{0.0, 0.0};
  double a = 1.0;      ///< semi-major axis (m), a >= b > 0
  double b = 1.0;      ///< semi-minor axis (m)
  double theta = 0.0;  ///< direction of the major axis, math angle (rad, ccw from east)

  /// Unit vector along the major axis and along the minor axis (major rotated +90 deg).
  Vec2 major_dir() const;
  Vec2 minor_dir() const;

  /// Point of the boundary at parameter t.
  Vec2 point_at(double t) const;
  /// Outward unit normal of the boundary at parameter t.
  Vec2 normal_at(double t) const;

  /// World point -> unit-circle frame, and back.
  Vec2 to_unit(const Vec2& p) const;
  Vec2 from_unit(const Vec2& q) const;
  /// Point expressed in the ellipse's own frame (origin at centre, x along the major axis).
  Vec2 to_local(const Vec2& p) const;
  Vec2 from_local(const Vec2& q) const;

  /// Shape matrix A = R diag(a^2, b^2) R^T.
  Eigen::Matrix2d shape_matrix() const;
  /// Support function h(u) = max over the ellipse of u.x, for a unit vector u.
  double support(const Vec2& u) const;
  /// The boundary point whose outward normal is the unit vector u.
  Vec2 support_point(const Vec2& u) const;

  /// True for points strictly inside (boundary excluded, up to rounding).
  bool contains(const Vec2& p) const;
  /// (x'^2 + y'^2) in the unit-circle frame: < 1 inside, 1 on, > 1 outside.
  double implicit_value(const Vec2& p) const;

  double area() const;
};

}  // namespace deepguide
