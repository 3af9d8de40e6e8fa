#include "deepguide/core/format.hpp"

#include <cstdarg>
#include <cstdio>

namespace deepguide {

std::string fixed(double v, int digits) {
  char buf[384];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string general(double v, int significant) {
  char buf[400];
  std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  return buf;
}

std::string printf_text(const char* format, ...) {
  va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, format, again);
  va_end(again);
  return out;
}

std::string point_text(double x, double y, int digits) {
  return "(" + fixed(x, digits) + ", " + fixed(y, digits) + ")";
}

std::string clock_text(double seconds) {
  if (!(seconds >= 0.0 && seconds < 1e15)) return "-";  // NaN, negative, or beyond any mission
  char buf[48];
  const long long s = static_cast<long long>(seconds + 0.5);
  std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

std::string report_line(const std::string& label, const std::string& value) {
  return label + std::string(label.size() < 17 ? 17 - label.size() : 1, ' ') + value + "\n";
}

std::string ascii_lower(std::string s) {
  for (char& c : s) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return s;
}

std::string html_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace deepguide
