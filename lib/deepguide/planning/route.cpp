#include "deepguide/planning/route.hpp"

#include <algorithm>

namespace deepguide {

double Route::length() const {
  double sum = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) sum += (points[i] - points[i - 1]).norm();
  return sum;
}

Vec2 Route::point_at(double s) const {
  if (points.empty()) return Vec2(0.0, 0.0);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double len = (points[i + 1] - points[i]).norm();
    if (s <= len) return len > 0.0 ? Vec2(points[i] + (std::max(s, 0.0) / len) * (points[i + 1] - points[i])) : points[i];
    s -= len;
  }
  return points.back();
}

}  // namespace deepguide
