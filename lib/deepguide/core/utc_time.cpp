#include "deepguide/core/utc_time.hpp"

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "deepguide/core/error.hpp"

namespace deepguide {
namespace {

// A cursor over the text: digits, one of some characters, blanks.
struct Reader {
  std::string_view s;
  std::size_t i = 0;

  bool done() const { return i == s.size(); }
  bool peek(std::string_view any_of) const { return i < s.size() && any_of.find(s[i]) != std::string_view::npos; }
  bool take(std::string_view any_of) {
    if (!peek(any_of)) return false;
    ++i;
    return true;
  }
  // 1 to `most` digits.
  bool number(int most, int& out) {
    std::size_t n = 0;
    while (i + n < s.size() && n < static_cast<std::size_t>(most) && s[i + n] >= '0' && s[i + n] <= '9') ++n;
    if (n == 0) return false;
    std::from_chars(s.data() + i, s.data() + i + n, out);
    i += n;
    return true;
  }
  void blanks() {
    while (peek(" \t")) ++i;
  }
  bool word(std::string_view w) {
    if (s.size() - i < w.size()) return false;
    for (std::size_t k = 0; k < w.size(); ++k) {
      if ((s[i + k] | 0x20) != w[k]) return false;
    }
    i += w.size();
    return true;
  }
};

}  // namespace

std::optional<double> parse_iso8601(std::string_view text, bool zone_required) {
  Reader r{text};
  r.blanks();
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, sec = 0;
  if (!r.number(4, y) || !r.take("-") || !r.number(2, mo) || !r.take("-") || !r.number(2, d)) return std::nullopt;
  double fraction = 0.0;
  const std::size_t before_clock = r.i;
  if (r.take("Tt ") && r.number(2, h)) {
    if (!r.take(":") || !r.number(2, mi)) return std::nullopt;
    if (r.take(":")) {
      if (!r.number(2, sec)) return std::nullopt;
      if (r.take(".,")) {
        const std::size_t start = r.i;
        while (r.peek("0123456789")) ++r.i;
        if (r.i == start) return std::nullopt;
        // from_chars, not stod: the C library's decimal point follows the locale.
        const std::string digits = "0." + std::string(text.substr(start, r.i - start));
        std::from_chars(digits.data(), digits.data() + digits.size(), fraction);
      }
    }
  } else {
    r.i = before_clock;  // a date alone (a blank before a zone is read below)
  }
  r.blanks();
  bool zoned = true;
  int offset_min = 0;
  if (r.take("Zz") || r.word("utc") || r.word("gmt")) {
  } else if (r.peek("+-")) {
    const int sign = r.s[r.i] == '-' ? -1 : 1;
    ++r.i;
    int oh = 0, om = 0;
    const std::size_t start = r.i;
    if (!r.number(2, oh)) return std::nullopt;
    const bool four = r.i - start == 2 && r.peek("0123456789");  // +hhmm
    if ((four || r.take(":")) && !r.number(2, om)) return std::nullopt;
    if (oh > 23 || om > 59) return std::nullopt;
    offset_min = sign * (oh * 60 + om);
  } else {
    zoned = false;
  }
  r.blanks();
  if (!r.done() || (zone_required && !zoned)) return std::nullopt;
  using namespace std::chrono;
  const year_month_day ymd{year{y}, month{static_cast<unsigned>(mo)}, day{static_cast<unsigned>(d)}};
  if (!ymd.ok() || h > 23 || mi > 59 || sec > 60) return std::nullopt;
  const double days = static_cast<double>(sys_days{ymd}.time_since_epoch().count());
  return days * 86400.0 + h * 3600.0 + (mi - offset_min) * 60.0 + sec + fraction;
}

double parse_utc(const std::string& text, const std::string& what) {
  const std::optional<double> t = parse_iso8601(text, false);
  if (!t) throw InputError(what + ": expected a UTC time such as 2019-03-07T15:00:00Z, got '" + printable(text) + "'");
  return *t;
}

std::string format_utc(double epoch_s, bool millis) {
  if (!std::isfinite(epoch_s)) return "?";
  using namespace std::chrono;
  const auto ms = static_cast<long long>(millis ? std::llround(epoch_s * 1000.0) : std::llround(epoch_s) * 1000);
  const sys_time<milliseconds> tp{milliseconds{ms}};
  const auto day = floor<days>(tp);
  const year_month_day ymd{day};
  const hh_mm_ss hms{tp - day};
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d-%02u-%02uT%02d:%02d:%02d", static_cast<int>(ymd.year()),
                static_cast<unsigned>(ymd.month()), static_cast<unsigned>(ymd.day()),
                static_cast<int>(hms.hours().count()), static_cast<int>(hms.minutes().count()),
                static_cast<int>(hms.seconds().count()));
  std::string out = buf;
  if (const auto sub = hms.subseconds().count(); sub != 0) {
    std::snprintf(buf, sizeof buf, ".%03d", static_cast<int>(sub));
    out += buf;
  }
  return out + "Z";
}

}  // namespace deepguide
