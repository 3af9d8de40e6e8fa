#pragma once
// One S-57 cell read through OGR's S57 driver into plain records in the
// local frame: its identity and scale (DSID, DSPM), its coverage (M_COVR),
// and the features of the object classes asked for, with the attributes the
// no-go rules read (enc_no_go.hpp). The reader knows no rules.
//
// Decisions:
// - The cell is opened with the driver's open options, never process-wide
//   config: UPDATES=APPLY (or IGNORE), SPLIT_MULTIPOINT=OFF (a SOUNDG feature
//   stays one 3-D multipoint; z is the sounding's depth, m, positive down).
// - After GDAL applied the updates, DSID_UPDN must equal the last update file
//   found beside the cell (enc_cells.hpp); otherwise GDAL stopped early (a
//   damaged or foreign update) and the read is an error naming that file.
// - Positions are WGS 84 lon/lat (S-57 requires it); each geometry goes to
//   the frame through OSR. Polygons are corrected (Boost orientation).
// - Coverage is the union of the M_COVR areas with CATCOV = 1 (coverage
//   available); a cell without one covers the envelope of its features.
// - Attributes a feature does not carry stay NaN (reals) or 0 (enumerations):
//   "unknown", which the rules treat as such.

#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

struct EncFeature {
  std::string cls;                   ///< S-57 object class (the OGR layer), e.g. "DEPARE"
  long long rcid = 0;                ///< the feature record's id, RCID
  std::vector<Vec2> points;          ///< Point and MultiPoint parts
  std::vector<double> point_depths;  ///< SOUNDG: depth of each point (m, positive down); else empty
  std::vector<std::vector<Vec2>> lines;
  BgMultiPolygon areas;
  double drval1 = std::numeric_limits<double>::quiet_NaN();  ///< depth range value 1 (m)
  double drval2 = std::numeric_limits<double>::quiet_NaN();
  double valsou = std::numeric_limits<double>::quiet_NaN();  ///< value of sounding (m; < 0 dries)
  int watlev = 0;           ///< water level effect: 1 partly submerged at HW, 2 always dry, 3 always under water,
                            ///< 4 covers and uncovers, 5 awash, 6 subject to inundation, 7 floating
  int catwrk = 0;           ///< category of wreck: 1 non-dangerous, 2 dangerous, 3 distributed remains, ...
  int expsou = 0;           ///< exposition of sounding: 1 within the surrounding depth, 2 shoaler, 3 deeper
  int catzoc = 0;           ///< M_QUAL: zone of confidence 1 A1, 2 A2, 3 B, 4 C, 5 D, 6 U
  std::vector<int> restrn;  ///< restrictions (7 entry prohibited, 8 entry restricted, 14 area to be avoided, ...)
};

struct EncCell {
  std::string path;            ///< the base cell as given
  std::string name;            ///< DSID_DSNM without extension, e.g. "US4MD81M"
  int usage_band = 0;          ///< DSID_INTU: 1 overview .. 6 berthing
  long compilation_scale = 0;  ///< DSPM_CSCL: 1:n
  std::string edition;         ///< DSID_EDTN
  int update_number = 0;       ///< DSID_UPDN after the updates applied
  std::string issue_date;      ///< DSID_ISDT
  BgMultiPolygon coverage;     ///< M_COVR CATCOV = 1, in the frame
  std::vector<EncFeature> features;
  std::map<std::string, std::size_t> layer_counts;  ///< features per class in the whole cell
};

struct EncReadRequest {
  std::set<std::string> classes;   ///< object classes to read (M_QUAL included if asked)
  bool with_restrictions = false;  ///< also every area feature of any class that carries RESTRN
  bool apply_updates = true;
};

struct EncCells {
  LocalFrame frame;
  std::vector<EncCell> cells;  ///< in the order of the files given
};

/// Reads the cells into `frame`, or, without one, into the UTM zone of the
/// first cell's coverage centre. Throws InputError (one line naming the file,
/// and the layer and RCID where a feature is to blame) for a file the S57
/// driver cannot read, a damaged update sequence, or positions outside the
/// frame's area.
EncCells read_enc_cells(const std::vector<EncCellFiles>& files, const std::optional<LocalFrame>& frame,
                        const EncReadRequest& request);

}  // namespace deepguide
