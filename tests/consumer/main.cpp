#include <deepguide/core/version.hpp>
#include <deepguide/geometry/ellipse_distance.hpp>
#include <iostream>

int main() {
  deepguide::Ellipse e;
  e.a = 2.0;
  e.b = 1.0;
  const double d = deepguide::signed_distance(e, {5.0, 0.0});
  std::cout << "deepguide " << deepguide::kVersion << " distance " << d << "\n";
  return d == 3.0 ? 0 : 1;
}
