#include "deepguide/core/error.hpp"

#include <cstdio>
#include <sstream>

namespace deepguide {

std::string InputLocation::describe() const {
  std::string s = file.empty() ? std::string("input") : file;
  if (!feature.empty()) s += ": " + feature;
  if (!field.empty()) s += ": field '" + field + "'";
  return s;
}

std::string printable(const std::string& text, std::size_t max_chars) {
  std::string out;
  for (unsigned char c : text) {
    if (out.size() >= max_chars) {
      out += "...";
      break;
    }
    if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

InputError input_error(const InputLocation& where, const std::string& expected,
                       const std::string& got) {
  std::string msg = where.describe() + ": expected " + expected;
  if (!got.empty()) msg += ", got " + got;
  return InputError(msg);
}

void require_param(bool ok, const char* group, const char* field, const char* expected, double got) {
  if (ok) return;
  std::ostringstream text;
  text << got;
  throw input_error({group, "", field}, expected, text.str());
}

}  // namespace deepguide
