#include "deepguide/core/error.hpp"

namespace deepguide {

std::string InputLocation::describe() const {
  std::string s = file.empty() ? std::string("input") : file;
  if (!feature.empty()) s += ": " + feature;
  if (!field.empty()) s += ": field '" + field + "'";
  return s;
}

InputError input_error(const InputLocation& where, const std::string& expected,
                       const std::string& got) {
  std::string msg = where.describe() + ": expected " + expected;
  if (!got.empty()) msg += ", got " + got;
  return InputError(msg);
}

}  // namespace deepguide
