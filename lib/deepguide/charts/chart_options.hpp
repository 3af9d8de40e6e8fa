#pragma once
// How S-57 charts are read, the same for every command that reads them
// (plan, mission check|plan|simulate, check route, chart info|nogo|prepare,
// render chart): one struct here, one set of flags in the CLI
// (apps/cli.cpp, add_chart_options), recorded in a prepared chart.
//
// Zones of confidence (M_QUAL CATZOC, IHO S-57 Appendix A; docs/CHARTS.md):
// a charted depth z is trusted to within the zone's depth uncertainty
// (a + b z), a charted position to within its position accuracy. The
// policies:
//  - clipped (default): depths less their zone's uncertainty; a point
//    hazard (a sounding, a rock, a wreck, an obstruction charted as a point)
//    is a disc of its zone's position accuracy, clipped to the water whose
//    zone is not better than its own (A1 > A2 > B > C > D > U; water without
//    M_QUAL counts as U): a better survey's own depths stand inside its zone.
//  - strict: the same depths, and the discs unclipped (they reach into any
//    zone, as far as the position accuracy says).
//  - none: charted depths and positions as exact (point hazards are discs of
//    EncNoGoOptions::point_radius_m).

#include <optional>
#include <string>
#include <string_view>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

enum class ZocPolicy { clipped, strict, none };

/// "clipped", "strict", "none".
const char* to_string(ZocPolicy policy);
/// The policy a name gives; "no" and "off" are none too. Nullopt for anything else.
std::optional<ZocPolicy> parse_zoc_policy(std::string_view name);

/// What a zone of confidence promises (IHO S-57 CATZOC): depths within
/// depth_fixed_m + depth_fraction * depth, positions within position_m.
struct ZocFigures {
  double depth_fixed_m = 0;
  double depth_fraction = 0;
  double position_m = 0;
};

struct ChartOptions {
  ZocPolicy zoc = ZocPolicy::clipped;
  /// Restricted areas (RESTRN 7 entry prohibited, 8 entry restricted, 14 area to be avoided) as no-go.
  bool restricted_areas = false;
  /// Figures for CATZOC D ("worse than C"), U (unassessed) and water without
  /// an M_QUAL area: by default C's, the best such a zone can be.
  ZocFigures unassessed{2.0, 0.05, 500.0};

  bool zones_of_confidence() const { return zoc != ZocPolicy::none; }
};

/// The first option in which `a` and `b` differ, in words, e.g. "zones of
/// confidence clipped, expected strict"; "" when they agree.
std::string chart_options_difference(const ChartOptions& prepared, const ChartOptions& asked);

/// Throws InputError naming the field for figures that are not finite, an
/// uncertainty outside [0, 1000] m, a fraction outside [0, 1) or a position
/// accuracy outside (0, 10000] m.
void check_chart_options(const ChartOptions& options);

}  // namespace deepguide
