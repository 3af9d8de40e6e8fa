#include "deepguide/geometry/ellipse.hpp"

#include <cmath>
#include <numbers>

namespace deepguide {

Vec2 Ellipse::major_dir() const { return {std::cos(theta), std::sin(theta)}; }
Vec2 Ellipse::minor_dir() const { return {-std::sin(theta), std::cos(theta)}; }

Vec2 Ellipse::point_at(double t) const {
  return centre + a * std::cos(t) * major_dir() + b * std::sin(t) * minor_dir();
}

Vec2 Ellipse::normal_at(double t) const {
  // Gradient of the implicit function in the local frame: (cos t / a, sin t / b).
  const Vec2 n = std::cos(t) / a * major_dir() + std::sin(t) / b * minor_dir();
  return n.normalized();
}

// One cosine and one sine per call (not one pair per axis): reactive
// methods transform points into every zone's frame at each 10 Hz step.
Vec2 Ellipse::to_local(const Vec2& p) const {
  const Vec2 d = p - centre;
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}

Vec2 Ellipse::from_local(const Vec2& q) const {
  const double c = std::cos(theta), s = std::sin(theta);
  return centre + Vec2(c * q.x() - s * q.y(), s * q.x() + c * q.y());
}

Vec2 Ellipse::to_unit(const Vec2& p) const {
  const Vec2 l = to_local(p);
  return {l.x() / a, l.y() / b};
}

Vec2 Ellipse::from_unit(const Vec2& q) const { return from_local(Vec2(q.x() * a, q.y() * b)); }

Eigen::Matrix2d Ellipse::shape_matrix() const {
  Eigen::Matrix2d r;
  r.col(0) = major_dir();
  r.col(1) = minor_dir();
  return r * Eigen::Vector2d(a * a, b * b).asDiagonal() * r.transpose();
}

double Ellipse::support(const Vec2& u) const {
  const double ul = u.dot(major_dir());
  const double vl = u.dot(minor_dir());
  return u.dot(centre) + std::hypot(a * ul, b * vl);
}

Vec2 Ellipse::support_point(const Vec2& u) const {
  const double ul = u.dot(major_dir());
  const double vl = u.dot(minor_dir());
  const double h = std::hypot(a * ul, b * vl);
  return from_local(Vec2(a * a * ul / h, b * b * vl / h));
}

double Ellipse::implicit_value(const Vec2& p) const { return to_unit(p).squaredNorm(); }

bool Ellipse::contains(const Vec2& p) const { return implicit_value(p) < 1.0; }

double Ellipse::area() const { return std::numbers::pi * a * b; }

}  // namespace deepguide
