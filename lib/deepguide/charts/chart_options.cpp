#include "deepguide/charts/chart_options.hpp"

#include <cmath>

#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {

const char* to_string(ZocPolicy policy) {
  switch (policy) {
    case ZocPolicy::clipped: return "clipped";
    case ZocPolicy::strict: return "strict";
    case ZocPolicy::none: return "none";
  }
  return "?";
}

std::optional<ZocPolicy> parse_zoc_policy(std::string_view name) {
  const std::string n = ascii_lower(std::string(name));
  if (n == "clipped") return ZocPolicy::clipped;
  if (n == "strict") return ZocPolicy::strict;
  if (n == "none" || n == "no" || n == "off") return ZocPolicy::none;
  return std::nullopt;
}

std::string chart_options_difference(const ChartOptions& prepared, const ChartOptions& asked) {
  if (prepared.zoc != asked.zoc) {
    return std::string("zones of confidence ") + to_string(prepared.zoc) + ", expected " + to_string(asked.zoc);
  }
  if (prepared.restricted_areas != asked.restricted_areas) {
    return std::string(prepared.restricted_areas ? "restricted areas as no-go" : "restricted areas passable") +
           ", expected " + (asked.restricted_areas ? "restricted areas as no-go" : "restricted areas passable");
  }
  const ZocFigures& p = prepared.unassessed;
  const ZocFigures& a = asked.unassessed;
  if (asked.zones_of_confidence() &&
      (p.depth_fixed_m != a.depth_fixed_m || p.depth_fraction != a.depth_fraction || p.position_m != a.position_m)) {
    auto text = [](const ZocFigures& f) {
      return general(f.depth_fixed_m, 6) + "," + general(f.depth_fraction, 6) + "," + general(f.position_m, 6);
    };
    return "unassessed zone figures " + text(p) + ", expected " + text(a);
  }
  return "";
}

void check_chart_options(const ChartOptions& o) {
  const ZocFigures& u = o.unassessed;
  auto need = [](bool ok, const char* expected, double got) {
    if (!ok) throw InputError(std::string("`unassessed`: expected ") + expected + ", got " + general(got, 4));
  };
  // Bounded too: a 1e308 m position accuracy would reach the discs' geometry as infinities.
  need(std::isfinite(u.depth_fixed_m) && u.depth_fixed_m >= 0.0 && u.depth_fixed_m <= 1000.0,
       "a depth uncertainty in [0, 1000] m for unassessed zones of confidence", u.depth_fixed_m);
  need(std::isfinite(u.depth_fraction) && u.depth_fraction >= 0.0 && u.depth_fraction < 1.0,
       "a depth fraction in [0, 1) for unassessed zones of confidence", u.depth_fraction);
  need(std::isfinite(u.position_m) && u.position_m > 0.0 && u.position_m <= 10000.0,
       "a position accuracy in (0, 10000] m for unassessed zones of confidence", u.position_m);
}

}  // namespace deepguide
