#pragma once
// The no-go area of S-57 cells for a vehicle at an operating depth: what an
// ECDIS's route check flags, read for a submerged vehicle. docs/CHARTS.md
// lists every rule with the object class and attribute it reads; in short,
// with the required depth D = operating depth + vertical clearance:
//  - DEPARE, DRGARE: no-go where DRVAL1 (less the zone of confidence's depth
//    uncertainty) < D, or DRVAL1 is unknown; drying areas always.
//  - LNDARE, UNSARE and what a vehicle hits at any depth (SLCONS, PONTON,
//    HULKES, FLODOC, PILPNT, PYLONS, MORFAC, OFSPLF, CAUSWY, DAMCON, DRYDOC,
//    GATCON): always.
//  - OBSTRN, WRECKS, UWTROC: no-go where their depth (VALSOU, else from
//    WATLEV, CATWRK, EXPSOU: hazard_depth()) less the uncertainty < D; a
//    hazard whose depth cannot be told is no-go at every depth.
//  - SOUNDG: each sounding shallower than D (after the uncertainty).
//  - With restricted_areas: any area whose RESTRN holds 7 (entry
//    prohibited), 8 (entry restricted) or 14 (area to be avoided).
//  - Water outside every cell's coverage (M_COVR CATCOV 1) is unknown: no-go.
// Zones of confidence (M_QUAL CATZOC) give the depth uncertainty a + b z
// subtracted from a charted depth z, and the position accuracy that is the
// radius of a point hazard (points and lines have no area: a point becomes a
// disc of that radius, a line a strip of line_half_width_m; the planner's
// margin comes on top). An area lying in several zones is split where the
// verdict changes. By the default policy (ZocPolicy::clipped) a disc is
// clipped to the water whose zone is not better than the hazard's own, this
// cell's zones and those of the better cells read before it.
// Several cells: where coverages overlap, the cell of the larger compilation
// scale (smaller DSPM_CSCL; then the higher usage band) wins: every other
// cell's features are clipped to what no better cell covers.

#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "deepguide/charts/chart_options.hpp"
#include "deepguide/charts/enc_reader.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

/// How cells are read for a vehicle at an operating depth: the chart options
/// every command shares (chart_options.hpp: zones of confidence, restricted
/// areas, the unassessed figures), and what only callers in the library set.
struct EncNoGoOptions : ChartOptions {
  /// Operating depth (m, positive down). Required: finite, >= 0.
  double operating_depth_m = std::numeric_limits<double>::quiet_NaN();
  /// Water kept between the vehicle and the charted depth (m, >= 0).
  double vertical_clearance_m = 2.0;
  /// Radius of a point hazard without zones of confidence (m, > 0).
  double point_radius_m = 10.0;
  /// Half width of the strip a line feature becomes (m, > 0).
  double line_half_width_m = 0.5;
  bool apply_updates = true;
  /// How far the planners' polygons may lie outside the exact no-go (m, >= 0; 0 = exact).
  double simplify_tolerance_m = 1.0;
  /// Merge the features into the planners' obstacles (EncNoGo::obstacles); off for callers that
  /// only want the features (the sea floor, enc_sea_floor.hpp).
  bool planner_obstacles = true;
};

/// The options for a vehicle at `operating_depth_m` keeping `vertical_clearance_m`, with the
/// chart options a command was given and the library's defaults for the rest.
EncNoGoOptions enc_options(const ChartOptions& chart,
                           double operating_depth_m = std::numeric_limits<double>::quiet_NaN(),
                           double vertical_clearance_m = 2.0);

/// One feature (or part of one) that is no-go, with why.
struct EncNoGoFeature {
  std::string id;    ///< "CLASS/RCID", prefixed "CELL:" when several cells are read
  std::string cell;  ///< the cell's name
  std::string cls;
  long long rcid = 0;
  std::string reason;  ///< e.g. "DRVAL1 3.6 m, least 2.5 m at CATZOC B, < 10 m"
  double charted_depth_m = std::numeric_limits<double>::quiet_NaN();  ///< DRVAL1, VALSOU or sounding; NaN if none
  /// The charted depth less the depth uncertainty of its zone of confidence
  /// (an area: the worst zone it meets); NaN for what is no-go at any depth.
  double least_depth_m = std::numeric_limits<double>::quiet_NaN();
  BgMultiPolygon area;        ///< areas, and line strips; empty for a point
  std::optional<Vec2> point;  ///< a point hazard: a disc of radius_m around it
  double radius_m = 0;
};

/// An area of one cell where that cell decides (what no better cell covers),
/// kept for what a route's quality is measured on (enc_route_quality.hpp).
struct EncChartArea {
  std::string id;  ///< as a feature's ("DEPARE/12", "CELL:" prefixed with several cells); a coverage: the cell's name
  std::string cell;
  BgMultiPolygon area;
  double depth_m = std::numeric_limits<double>::quiet_NaN();  ///< DEPARE, DRGARE: DRVAL1
  int catzoc = 0;                                             ///< M_QUAL: CATZOC
};

struct EncCellSummary {
  std::string path, name;
  int usage_band = 0;
  long compilation_scale = 0;
  std::string edition, issue_date;
  int update_number = 0;
  std::map<std::string, std::size_t> layer_counts;
};

struct EncNoGo {
  LocalFrame frame;
  double required_depth_m = 0;        ///< D = operating depth + vertical clearance
  std::vector<EncCellSummary> cells;  ///< best scale first (the order overlaps are decided in)
  std::vector<EncNoGoFeature> features;
  /// What the planners take: the no-go areas merged and simplified outward
  /// (ids "enc/N"), and point hazards as discs (their feature ids) where they
  /// reach outside those areas.
  ObstacleSet obstacles;
  std::map<std::string, std::size_t> no_go_by_class;     ///< features (points: soundings) per class
  std::map<std::string, std::size_t> passable_by_class;  ///< deep enough to pass over
  std::map<std::string, std::size_t> zoc_areas;          ///< M_QUAL areas per CATZOC letter ("A1", ..., "U", "none")
  std::size_t vertices = 0;                              ///< distinct polygon vertices of obstacles.polygons
  /// Where each cell decides, its depth and dredged areas there, and its
  /// zones of confidence there (a prepared chart of format 1 has none).
  std::vector<EncChartArea> cell_areas, depth_areas, zones;
};

/// The order overlaps are decided in: the larger compilation scale (smaller
/// DSPM_CSCL; none last), then the higher usage band, then the name.
bool decides_before(long scale_a, int band_a, const std::string& name_a, long scale_b, int band_b,
                    const std::string& name_b);

/// CATZOC code (1..6) -> "A1", "A2", "B", "C", "D", "U"; other -> "unknown".
std::string zoc_name(int catzoc);
/// The figures of a CATZOC code; D, U and anything else give options.unassessed.
ZocFigures zoc_figures(int catzoc, const ChartOptions& options);

/// The depth (m, positive down) an ECDIS would give the top of an OBSTRN,
/// WRECKS or UWTROC feature: VALSOU; else 0 when WATLEV says it dries, is
/// awash, floats or is subject to inundation; else 20.1 for a non-dangerous
/// wreck (CATWRK 1, as S-52 does); else the surrounding depth area's least
/// DRVAL1 when EXPSOU says it lies within (1) or below (3) the surrounding
/// depth; else nullopt: its depth is unknown.
std::optional<double> hazard_depth(const EncFeature& hazard, double surrounding_drval1);

/// Reads the cells (files or folders: enc_cells.hpp) and returns their no-go
/// in `frame` (or the UTM zone of the first cell's coverage). Throws
/// InputError (one line naming the file, and feature where one is to blame)
/// for unreadable cells, broken update sequences, a cell without depth areas
/// (DEPARE), or bad options.
EncNoGo enc_no_go(const std::vector<std::string>& charts, const std::optional<LocalFrame>& frame,
                  const EncNoGoOptions& options);

}  // namespace deepguide
