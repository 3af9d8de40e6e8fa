#include "deepguide/core/format.hpp"

#include <cstdio>

namespace deepguide {

std::string fixed(double v, int digits) {
  char buf[384];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string general(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string point_text(double x, double y, int digits) { return "(" + fixed(x, digits) + ", " + fixed(y, digits) + ")"; }

}  // namespace deepguide
