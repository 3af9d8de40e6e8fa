#include "deepguide/planning/route.hpp"

namespace deepguide {

double Route::length() const {
  double sum = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) sum += (points[i] - points[i - 1]).norm();
  return sum;
}

}  // namespace deepguide
