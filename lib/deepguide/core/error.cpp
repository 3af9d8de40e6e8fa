#include "deepguide/core/error.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>
#include <utility>

namespace deepguide {

std::string InputLocation::describe() const {
  std::string s = file.empty() ? std::string("input") : file;
  if (!feature.empty()) s += ": " + feature;
  if (!field.empty()) s += ": field '" + field + "'";
  return s;
}

namespace {

// The code point of the UTF-8 sequence at s[i] and its length; length 0 for
// bytes that are not valid UTF-8 (a stray continuation, a cut or overlong
// sequence, a surrogate).
std::pair<char32_t, std::size_t> decode_utf8(const std::string& s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t n = 0;
  char32_t cp = 0;
  if (c < 0x80) return {c, 1};
  if ((c & 0xe0) == 0xc0)
    n = 2, cp = c & 0x1f;
  else if ((c & 0xf0) == 0xe0)
    n = 3, cp = c & 0x0f;
  else if ((c & 0xf8) == 0xf0)
    n = 4, cp = c & 0x07;
  else
    return {0, 0};
  if (i + n > s.size()) return {0, 0};
  for (std::size_t k = 1; k < n; ++k) {
    if ((b(i + k) & 0xc0) != 0x80) return {0, 0};
    cp = (cp << 6) | (b(i + k) & 0x3f);
  }
  const char32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < least[n] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return {0, 0};
  return {cp, n};
}

// Characters that change how a terminal shows the rest of the line: C0 and
// C1 controls, and the invisible format and bidirectional controls that can
// reorder or hide text (U+202E shows what follows backwards).
bool hidden_or_control(char32_t cp) {
  return cp < 0x20 || (cp >= 0x7f && cp <= 0x9f) || cp == 0x061c || (cp >= 0x200b && cp <= 0x200f) ||
         (cp >= 0x2028 && cp <= 0x202e) || (cp >= 0x2060 && cp <= 0x2069) || cp == 0xfeff;
}

}  // namespace

std::string printable(const std::string& text, std::size_t max_chars) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (out.size() >= max_chars) {
      out += "...";
      break;
    }
    const auto [cp, n] = decode_utf8(text, i);
    char buf[16];
    if (n == 0) {
      std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(text[i]));
      out += buf;
      ++i;
    } else if (hidden_or_control(cp)) {
      if (cp < 0x100) {
        std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(cp));
      } else {
        std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(cp));
      }
      out += buf;
      i += n;
    } else {
      out.append(text, i, n);
      i += n;
    }
  }
  return out;
}

InputError input_error(const InputLocation& where, const std::string& expected, const std::string& got) {
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

std::string rename_parameters(std::string_view message,
                              const std::function<std::optional<std::string>(std::string_view)>& rename) {
  const auto is_name = [](std::string_view s) {
    if (s.empty() || !std::isalpha(static_cast<unsigned char>(s.front()))) return false;
    return std::all_of(s.begin(), s.end(),
                       [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; });
  };
  std::string out;
  std::size_t at = 0;
  while (at < message.size()) {
    const std::size_t open = message.find('`', at);
    const std::size_t close = open == std::string_view::npos ? open : message.find('`', open + 1);
    if (close == std::string_view::npos) break;
    const std::string_view name = message.substr(open + 1, close - open - 1);
    out.append(message.substr(at, open - at));
    if (!is_name(name)) {
      // Not a name, so its closing backquote may open one: "`a b` `c`".
      out.append(message.substr(open, close - open));
      at = close;
      continue;
    }
    const std::optional<std::string> renamed = rename(name);
    out += renamed ? *renamed : std::string(message.substr(open, close - open + 1));
    at = close + 1;
  }
  out.append(message.substr(at));
  return out;
}

}  // namespace deepguide
