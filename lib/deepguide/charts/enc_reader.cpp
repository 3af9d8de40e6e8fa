#include "deepguide/charts/enc_reader.hpp"

#include <ogrsf_frmts.h>

#include <boost/geometry/algorithms/correct.hpp>
#include <boost/geometry/algorithms/union.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "deepguide/charts/s57_unknown_objects.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/world/frame_scale.hpp"
#include "deepguide/world/gdal_support.hpp"
#include "deepguide/world/plausible_depth.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string shown(const std::string& path) { return printable(path, 240); }

GDALDatasetUniquePtr open_cell(const std::string& path, bool apply_updates) {
  gdal::ensure_registered();
  const char* drivers[] = {"S57", nullptr};
  const char* open_options[] = {apply_updates ? "UPDATES=APPLY" : "UPDATES=IGNORE", "SPLIT_MULTIPOINT=OFF",
                                "ADD_SOUNDG_DEPTH=OFF", nullptr};
  GDALDatasetUniquePtr ds = gdal::open_dataset(path, GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers, open_options);
  if (!ds) {
    const std::string why = gdal::QuietErrors::last_message();
    throw InputError(shown(path) + ": expected an S-57 ENC cell GDAL's S57 driver can read" +
                     (why.empty() ? std::string(", got a file it does not recognise") : ", got: " + why));
  }
  return ds;
}

double real_field(const OGRFeature& f, const char* name) {
  const int i = f.GetFieldIndex(name);
  if (i < 0 || !f.IsFieldSetAndNotNull(i)) return kNaN;
  const double v = f.GetFieldAsDouble(i);
  return std::isfinite(v) ? v : kNaN;
}

int int_field(const OGRFeature& f, const char* name) {
  const int i = f.GetFieldIndex(name);
  return i >= 0 && f.IsFieldSetAndNotNull(i) ? f.GetFieldAsInteger(i) : 0;
}

std::string string_field(const OGRFeature& f, const char* name) {
  const int i = f.GetFieldIndex(name);
  return i >= 0 && f.IsFieldSetAndNotNull(i) ? f.GetFieldAsString(i) : std::string();
}

// S-57 list attributes come as a string list, or as "7,8" when the driver
// reads lists as strings.
std::vector<int> int_list_field(const OGRFeature& f, const char* name) {
  std::vector<int> out;
  const int i = f.GetFieldIndex(name);
  if (i < 0 || !f.IsFieldSetAndNotNull(i)) return out;
  auto add = [&](const char* text) {
    for (const char* p = text; *p != '\0';) {
      char* end = nullptr;
      const long v = std::strtol(p, &end, 10);
      if (end == p) {
        ++p;
        continue;
      }
      out.push_back(static_cast<int>(v));
      p = end;
    }
  };
  if (f.GetFieldDefnRef(i)->GetType() == OFTStringList) {
    for (char** s = f.GetFieldAsStringList(i); s != nullptr && *s != nullptr; ++s) add(*s);
  } else {
    add(f.GetFieldAsString(i));
  }
  return out;
}

// Reads geometries into the frame through one OSR transformation per cell.
class ToFrame {
 public:
  ToFrame(const LocalFrame& frame, std::string path)
      : path_(std::move(path)),
        srs_(gdal::srs_from_user_input(frame.wkt())),
        wgs84_(gdal::wgs84()),
        ct_(gdal::make_transform(*wgs84_, *srs_)),
        frame_id_(frame.id()) {
    if (!ct_) throw InputError(shown(path_) + ": no transformation from WGS 84 to " + frame_id_);
  }

  // `g` in lon/lat -> feature geometry in the frame; `where` names the feature for errors.
  void read(const OGRGeometry& g, EncFeature& f, const std::string& where) const {
    switch (wkbFlatten(g.getGeometryType())) {
      case wkbPoint: {
        const OGRPoint& p = *g.toPoint();
        f.points.push_back(point(p.getX(), p.getY(), where));
        if (f.cls == "SOUNDG") {
          require_plausible_depth(p.getZ(), where + " (a sounding)");
          f.point_depths.push_back(p.getZ());
        }
        break;
      }
      case wkbLineString: f.lines.push_back(line(*g.toLineString(), where)); break;
      case wkbPolygon: add_polygon(*g.toPolygon(), f.areas, where); break;
      case wkbMultiPoint:
      case wkbMultiLineString:
      case wkbMultiPolygon:
      case wkbGeometryCollection:
        for (const OGRGeometry* part : *g.toGeometryCollection()) read(*part, f, where);
        break;
      default:
        throw InputError(where + ": expected a point, line or area geometry, got " +
                         OGRGeometryTypeToName(g.getGeometryType()));
    }
  }

  void add_polygon(const OGRPolygon& poly, BgMultiPolygon& out, const std::string& where) const {
    const OGRLinearRing* outer = poly.getExteriorRing();
    if (poly.IsEmpty() || outer == nullptr || outer->getNumPoints() < 4) return;  // degenerate: no area
    BgPolygon p;
    ring(*outer, p.outer(), where);
    for (int k = 0; k < poly.getNumInteriorRings(); ++k)
      ring(*poly.getInteriorRing(k), p.inners().emplace_back(), where);
    boost::geometry::correct(p);
    out.push_back(std::move(p));
  }

 private:
  Vec2 point(double lon, double lat, const std::string& where) const {
    double x = lon, y = lat;
    const bool inside = std::isfinite(lon) && std::isfinite(lat) && std::abs(lon) <= 180.0 && std::abs(lat) <= 90.0;
    if (!inside || !ct_->Transform(1, &x, &y) || !std::isfinite(x) || !std::isfinite(y)) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "lon %.7g, lat %.7g", lon, lat);
      throw InputError(where + ": expected a position inside the area of the local frame " + frame_id_ + ", got " +
                       buf);
    }
    return {x, y};
  }

  std::vector<Vec2> line(const OGRSimpleCurve& c, const std::string& where) const {
    std::vector<Vec2> out;
    out.reserve(static_cast<std::size_t>(c.getNumPoints()));
    for (int i = 0; i < c.getNumPoints(); ++i) out.push_back(point(c.getX(i), c.getY(i), where));
    return out;
  }

  template <class Ring>
  void ring(const OGRLinearRing& r, Ring& dst, const std::string& where) const {
    for (const Vec2& p : line(r, where)) dst.push_back(to_bg(p));
  }

  std::string path_;
  std::unique_ptr<OGRSpatialReference> srs_, wgs84_;
  gdal::TransformPtr ct_;
  std::string frame_id_;
};

struct OpenCell {
  EncCell cell;
  GDALDatasetUniquePtr ds;
};

// Identity, scale and update check; the coverage in lon/lat envelope for the default frame.
OpenCell open_and_identify(const EncCellFiles& files, bool apply_updates, OGREnvelope& coverage_lonlat) {
  std::error_code ec;
  if (!fs::is_regular_file(files.base, ec)) {
    throw InputError(shown(files.base) + ": expected an S-57 cell file (*.000), found none");
  }
  OpenCell oc;
  try {
    oc.ds = open_cell(files.base, apply_updates);
  } catch (const InputError&) {
    if (!apply_updates || files.updates.empty()) throw;
    // GDAL reports a damaged update as a broken cell: tell the two apart.
    const std::string why = gdal::QuietErrors::last_message();
    open_cell(files.base, false);  // throws itself when the base cell is what is broken
    throw InputError(shown(files.updates.front()) +
                     (files.updates.size() > 1 ? " .. " + fs::path(files.updates.back()).extension().string() : "") +
                     ": expected update files GDAL's S57 driver can apply to " + shown(files.base) +
                     ", got a damaged update" + (why.empty() ? std::string() : " (" + why + ")"));
  }
  refuse_unknown_object_classes(*oc.ds, shown(files.base));
  EncCell& c = oc.cell;
  c.path = files.base;
  bool has_dsid = false;
  if (OGRLayer* dsid = oc.ds->GetLayerByName("DSID")) {
    for (auto& f : *dsid) {
      has_dsid = true;
      c.name = fs::path(string_field(*f, "DSID_DSNM")).stem().string();
      c.usage_band = int_field(*f, "DSID_INTU");
      c.compilation_scale = int_field(*f, "DSPM_CSCL");
      c.edition = string_field(*f, "DSID_EDTN");
      c.update_number = std::atoi(string_field(*f, "DSID_UPDN").c_str());
      c.issue_date = string_field(*f, "DSID_ISDT");
    }
  }
  if (const std::string why = gdal::QuietErrors::last_message(); !why.empty() || !has_dsid) {
    throw InputError(shown(files.base) + ": expected a complete S-57 cell, got " +
                     (has_dsid ? why : std::string("no data set identification (DSID)")));
  }
  if (c.name.empty()) c.name = fs::path(files.base).stem().string();
  const int wanted = apply_updates ? static_cast<int>(files.updates.size()) : 0;
  if (apply_updates && c.update_number != wanted) {
    const std::size_t next = static_cast<std::size_t>(std::max(c.update_number, 0));
    const std::string bad = next < files.updates.size() ? files.updates[next] : files.base;
    throw InputError(shown(bad) + ": expected update " + std::to_string(next + 1) + " of " + shown(files.base) +
                     " (edition " + c.edition +
                     ") that GDAL's S57 driver applies, got a sequence that stops at update " +
                     std::to_string(c.update_number) + " (damaged, or of another edition)");
  }
  if (OGRLayer* covr = oc.ds->GetLayerByName("M_COVR")) {
    for (auto& f : *covr) {
      const OGRGeometry* g = f->GetGeometryRef();
      if (int_field(*f, "CATCOV") != 1 || g == nullptr || g->IsEmpty()) continue;
      OGREnvelope e;
      g->getEnvelope(&e);
      coverage_lonlat.Merge(e);
    }
  }
  return oc;
}

std::string feature_where(const std::string& path, const std::string& cls, long long rcid) {
  return shown(path) + ": layer '" + cls + "', feature RCID " + std::to_string(rcid);
}

void read_features(OpenCell& oc, const ToFrame& to_frame, const EncReadRequest& request) {
  EncCell& c = oc.cell;
  OGREnvelope all;
  bool has_coverage = false;
  for (OGRLayer* layer : oc.ds->GetLayers()) {
    const std::string cls = layer->GetName();
    const bool coverage = cls == "M_COVR";
    const bool asked = request.classes.count(cls) > 0 ||
                       (request.with_restrictions && layer->GetLayerDefn()->GetFieldIndex("RESTRN") >= 0);
    std::size_t count = 0;
    for (auto& f : *layer) {
      ++count;
      const OGRGeometry* g = f->GetGeometryRef();
      if (g == nullptr || g->IsEmpty()) {
        // A feature whose record says it has a point, line or area (PRIM 1-3) that GDAL could not
        // assemble would vanish from the no-go: refuse the cell rather than plan on part of it.
        const int prim = int_field(*f, "PRIM");
        if (asked && prim >= 1 && prim <= 3) {
          throw InputError(feature_where(c.path, cls, int_field(*f, "RCID")) +
                           ": expected a geometry GDAL's S57 driver can assemble, got none");
        }
        continue;
      }
      OGREnvelope e;
      g->getEnvelope(&e);
      all.Merge(e);
      if (!asked && !coverage) continue;
      const int ri = f->GetFieldIndex("RCID");
      const long long rcid =
          ri >= 0 && f->IsFieldSetAndNotNull(ri) ? f->GetFieldAsInteger64(ri) : static_cast<long long>(f->GetFID());
      const std::string where = feature_where(c.path, cls, rcid);
      if (coverage) {
        if (int_field(*f, "CATCOV") != 1) continue;
        EncFeature tmp;
        to_frame.read(*g, tmp, where);
        for (auto& p : tmp.areas) c.coverage.push_back(std::move(p));
        has_coverage = true;
        if (!asked) continue;
      }
      if (!asked) continue;
      EncFeature ef;
      ef.cls = cls;
      ef.rcid = rcid;
      to_frame.read(*g, ef, where);
      if (request.with_restrictions && f->GetFieldIndex("RESTRN") >= 0) ef.restrn = int_list_field(*f, "RESTRN");
      if (request.classes.count(cls) == 0 && ef.restrn.empty()) continue;  // a RESTRN layer, none set here
      ef.drval1 = real_field(*f, "DRVAL1");
      ef.drval2 = real_field(*f, "DRVAL2");
      ef.valsou = real_field(*f, "VALSOU");
      for (const auto& [field, value] :
           {std::pair{"DRVAL1", ef.drval1}, {"DRVAL2", ef.drval2}, {"VALSOU", ef.valsou}}) {
        if (!std::isnan(value)) require_plausible_depth(value, where + " " + field);
      }
      ef.watlev = int_field(*f, "WATLEV");
      ef.catwrk = int_field(*f, "CATWRK");
      ef.expsou = int_field(*f, "EXPSOU");
      ef.catzoc = int_field(*f, "CATZOC");
      c.features.push_back(std::move(ef));
    }
    c.layer_counts[cls] = count;
  }
  if (const std::string why = gdal::QuietErrors::last_message(); !why.empty()) {
    throw InputError(shown(c.path) + ": expected a complete S-57 cell, got: " + why);
  }
  if (!has_coverage && all.IsInit()) {
    // No coverage record: the envelope of everything the cell holds.
    OGRPolygon box;
    OGRLinearRing ring;
    ring.addPoint(all.MinX, all.MinY);
    ring.addPoint(all.MinX, all.MaxY);
    ring.addPoint(all.MaxX, all.MaxY);
    ring.addPoint(all.MaxX, all.MinY);
    ring.addPoint(all.MinX, all.MinY);
    box.addRing(&ring);
    to_frame.add_polygon(box, c.coverage, shown(c.path) + ": the envelope of its features");
  }
  if (c.coverage.size() > 1) {
    // M_COVR areas of one cell may touch: one union, so clipping by it is clean.
    BgMultiPolygon merged;
    for (const BgPolygon& p : c.coverage) {
      BgMultiPolygon next;
      boost::geometry::union_(merged, p, next);
      merged = std::move(next);
    }
    c.coverage = std::move(merged);
  }
}

}  // namespace

EncCells read_enc_cells(const std::vector<EncCellFiles>& files, const std::optional<LocalFrame>& frame,
                        const EncReadRequest& request) {
  gdal::QuietErrors quiet;
  std::vector<OpenCell> open;
  std::optional<LocalFrame> use = frame;
  for (const EncCellFiles& f : files) {
    OGREnvelope coverage;
    open.push_back(open_and_identify(f, request.apply_updates, coverage));
    if (!use) {
      if (!coverage.IsInit()) {
        throw InputError(shown(f.base) +
                         ": expected a coverage area (M_COVR with CATCOV 1) to choose the local frame "
                         "by, found none; name one with `local_crs`");
      }
      use = default_frame_for({coverage.MinX, coverage.MaxX, coverage.MinY, coverage.MaxY});
    } else if (frame && coverage.IsInit()) {
      require_true_scale(*frame, {coverage.MinX, coverage.MaxX, coverage.MinY, coverage.MaxY}, shown(f.base));
    }
  }
  if (!use) throw InputError("charts: expected at least one S-57 cell, got none");
  EncCells out{*use, {}};
  for (OpenCell& oc : open) {
    read_features(oc, ToFrame(*use, oc.cell.path), request);
    oc.ds.reset();
    out.cells.push_back(std::move(oc.cell));
  }
  return out;
}

}  // namespace deepguide
