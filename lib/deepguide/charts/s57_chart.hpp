#pragma once
// S-57 electronic navigational charts (ENC cells, *.000 with updates *.001..)
// through OGR's S57 driver: a summary of what a cell holds (object counts,
// depth areas, soundings, extent), and its hazards as obstacles, read by the
// one S-57 reader the charts' no-go uses (enc_reader.hpp) with the rules below.
//
// Decisions (to be mirrored in docs/FORMATS.md):
// - Updates: GDAL applies the update files (.001, .002, ...) that sit beside
//   the base cell; S57Options::apply_updates = false reads the base cell only
//   (the driver's open option UPDATES=IGNORE, set per dataset, never global).
// - Hazards are the object classes OBSTRN (obstruction), WRECKS and UWTROC
//   (underwater/awash rock); land (LNDARE) is always an obstacle.
// - Point hazards carry no horizontal size in S-57: OBSTRN and WRECKS have
//   VERLEN (a vertical length) and HEIGHT (above the vertical datum, for
//   objects that stand above water) but no HORLEN/HORWID or radius, and
//   UWTROC has none either. A point hazard therefore becomes a circle of
//   S57Options::point_hazard_radius_m, default 10 m: an assumption, about the
//   size of a wreck or a rock plus the position uncertainty of a harbour- or
//   approach-scale chart, that the user overrides. The same holds for land
//   given as a point (an islet too small to draw at the cell's scale).
// - Area features (Polygon, MultiPolygon) become polygonal obstacles, one per
//   part. Line features (e.g. an OBSTRN drawn as a line) are skipped and
//   counted in S57Hazards::skipped_lines: they have no area and no width.
// - Vertically a hazard's top lies at its VALSOU (value of sounding, depth in
//   m, positive down); a VALSOU < 0 (the hazard dries) is taken as 0, the
//   surface. Without VALSOU the hazard fills the whole water column. With an
//   operating depth set, hazards whose VALSOU > operating depth + vertical
//   clearance are not obstacles (the vehicle passes above them).
// - Obstacle ids are "CLASS/RCID" (e.g. "WRECKS/87"), the S-57 record id;
//   further parts of a MultiPolygon get "#2", "#3", ... (counting the parts
//   the reader keeps: it drops a part of fewer than three distinct vertices).
// - The cell is read as the charts' no-go reads it (enc_reader.hpp), with its
//   checks: named *.000, its updates in sequence, a data set identification,
//   plausible depths, a frame true to scale over it, and a feature whose
//   point, line or area GDAL cannot assemble refused rather than skipped.

#include <cstddef>
#include <limits>
#include <map>
#include <string>

#include "deepguide/core/api.hpp"
#include "deepguide/world/extent.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/obstacle.hpp"

namespace DEEPGUIDE_API deepguide {

struct S57Options {
  /// Operating depth of the vehicle (m, positive down); NaN = no depth filter.
  double operating_depth_m = std::numeric_limits<double>::quiet_NaN();
  /// Vertical clearance kept above a hazard's top (m).
  double vertical_clearance_m = 2.0;
  /// Radius of the circle a point hazard becomes (m); S-57 gives points no size.
  double point_hazard_radius_m = 10.0;
  /// Apply the update files (.001, ...) beside the base cell.
  bool apply_updates = true;
  /// Local planning frame for s57_local_frame(): empty = UTM zone of the cell's centre.
  std::string local_crs;
};

struct S57Summary {
  /// Features per object class (OGR layer), as the cell stores them: SOUNDG
  /// counts multipoint features, not single soundings.
  std::map<std::string, std::size_t> layer_counts;
  std::string edition;         ///< DSID_EDTN
  int update_number = 0;       ///< DSID_UPDN after the updates read (0 = base cell only)
  std::string issue_date;      ///< DSID_ISDT, YYYYMMDD
  int usage_band = 0;          ///< DSID_INTU (1 overview .. 6 berthing)
  long compilation_scale = 0;  ///< DSPM_CSCL (the scale denominator)
  /// Depth areas: min DRVAL1 and max DRVAL2 (m; negative = drying). NaN without DEPARE.
  double depare_min_m = std::numeric_limits<double>::quiet_NaN();
  double depare_max_m = std::numeric_limits<double>::quiet_NaN();
  /// Single soundings (points of the SOUNDG multipoints) and their depth range (m).
  std::size_t soundings = 0;
  double sounding_min_m = std::numeric_limits<double>::quiet_NaN();
  double sounding_max_m = std::numeric_limits<double>::quiet_NaN();
  /// M_QUAL areas per zone of confidence (CATZOC: "A1", "A2", "B", "C", "D", "U", "unknown" when not given).
  std::map<std::string, std::size_t> zoc_areas;
  /// Envelope of the coverage features (M_COVR); of all features if the cell has none.
  LonLatExtent extent;
};

/// Reads the cell at `path`. Throws InputError (one line naming the file) for
/// a missing file or one the S57 driver cannot read (e.g. a truncated cell).
S57Summary summarize_s57(const std::string& path, bool apply_updates = true);

/// The local frame for a cell: options.local_crs if set, else the UTM zone of
/// the centre of summary.extent. Throws InputError for a bad local_crs.
LocalFrame s57_local_frame(const S57Summary& summary, const S57Options& options = {});

struct S57Hazards {
  ObstacleSet obstacles;
  /// Features read per object class (OBSTRN, WRECKS, UWTROC, LNDARE), before the depth filter.
  std::map<std::string, std::size_t> features_read;
  /// Line features skipped (no area): see the decisions above.
  std::size_t skipped_lines = 0;
  /// Features without any geometry (no spatial primitive), skipped.
  std::size_t skipped_empty = 0;
  /// Obstacles the depth filter removed (their top lies deeper than depth + clearance).
  std::size_t removed_by_depth = 0;
};

/// Hazards and land of the cell as obstacles in `frame`. Throws InputError
/// (one line naming the file, and the feature where one is to blame) for a
/// missing or unreadable cell, a position outside the frame, or a bad option.
S57Hazards s57_hazards(const std::string& path, const LocalFrame& frame, const S57Options& options = {});

}  // namespace deepguide
