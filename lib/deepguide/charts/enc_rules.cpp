// The S-57 rules the no-go reading applies feature by feature, as free
// functions (enc_no_go.hpp states them): which cell decides where cells
// overlap, the zones of confidence's figures, and a hazard's depth.

#include <algorithm>
#include <cmath>
#include <limits>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {
namespace {

// S-52's depth for a non-dangerous wreck without VALSOU (deeper than 20 m).
constexpr double kNonDangerousWreckDepth = 20.1;

}  // namespace

bool decides_before(long scale_a, int band_a, const std::string& name_a, long scale_b, int band_b,
                    const std::string& name_b) {
  const long sa = scale_a > 0 ? scale_a : std::numeric_limits<long>::max();
  const long sb = scale_b > 0 ? scale_b : std::numeric_limits<long>::max();
  if (sa != sb) return sa < sb;
  if (band_a != band_b) return band_a > band_b;
  return name_a < name_b;
}

std::string zoc_name(int catzoc) {
  static const char* const names[] = {"A1", "A2", "B", "C", "D", "U"};
  return catzoc >= 1 && catzoc <= 6 ? names[catzoc - 1] : "unknown";
}

EncNoGoOptions enc_options(const ChartOptions& chart, double operating_depth_m, double vertical_clearance_m) {
  EncNoGoOptions o;
  static_cast<ChartOptions&>(o) = chart;
  o.operating_depth_m = operating_depth_m;
  o.vertical_clearance_m = vertical_clearance_m;
  return o;
}

ZocFigures zoc_figures(int catzoc, const ChartOptions& options) {
  switch (catzoc) {
    case 1: return {0.5, 0.01, 5.0};
    case 2: return {1.0, 0.02, 20.0};
    case 3: return {1.0, 0.02, 50.0};
    case 4: return {2.0, 0.05, 500.0};
    default: return options.unassessed;
  }
}

std::optional<double> hazard_depth(const EncFeature& h, double surrounding_drval1) {
  if (!std::isnan(h.valsou)) return h.valsou;
  switch (h.watlev) {
    case 1:
    case 2:
    case 4:
    case 5:
    case 6:
    case 7: return 0.0;
    default: break;
  }
  if (h.cls == "WRECKS" && h.catwrk == 1) return kNonDangerousWreckDepth;
  if ((h.expsou == 1 || h.expsou == 3) && !std::isnan(surrounding_drval1)) return surrounding_drval1;
  return std::nullopt;
}

}  // namespace deepguide
