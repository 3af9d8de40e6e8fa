// S-57 cells built from nothing but the geometry a test needs, written by
// GDAL's own S57 writer so that the bytes are what GDAL itself would produce
// and the library under test reads them through the same S57 reader as a
// real ENC. Checked against GDAL 3.6.2 (ogrs57datasource.cpp, s57writer.cpp).
//
// Topology: every area gets its own connected node (at its first vertex) and
// one edge that leaves and returns to that node. Shared boundaries are simply
// duplicated; the S57 reader rebuilds each polygon from its own edge, so
// neighbouring areas never depend on one another.
#pragma once

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <array>
#include <atomic>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace deepguide::test {

struct SyntheticArea {
  std::string cls;                          // object class acronym, e.g. "DEPARE"
  std::vector<std::array<double, 2>> ring;  // lon, lat; closed or not
  std::map<std::string, double> reals;      // e.g. DRVAL1, DRVAL2
  std::map<std::string, int> ints;          // e.g. CATZOC, CATCOV
};

struct SyntheticSounding {
  double lon, lat, depth_m;
};

// A point feature such as OBSTRN, UWTROC or WRECKS (VALSOU, WATLEV, CATWRK, EXPSOU).
struct SyntheticPoint {
  std::string cls;
  double lon, lat;
  std::map<std::string, double> reals;
  std::map<std::string, int> ints;
};

struct SyntheticCell {
  std::string name = "US5TEST1";   // DSID_DSNM stem
  long compilation_scale = 12000;  // DSPM_CSCL
  int usage_band = 5;              // DSID_INTU
  // DSPM_SOMF: the writer rounds depths to 1/SOMF m. Real cells use 10 (dm),
  // so a 5.25 m sounding comes back as 5.3 m unless this is raised.
  int sounding_factor = 10;
  std::vector<SyntheticArea> areas;          // M_COVR, DEPARE, DRGARE, M_QUAL, LNDARE, ...
  std::vector<SyntheticSounding> soundings;  // one SOUNDG multipoint, Z = depth
  std::vector<SyntheticPoint> points;        // point hazards
};

namespace synthetic_cell_detail {

// S-57 record name codes and the GRUP of classes drawn as the skin of the earth.
constexpr int kVI = 110, kVC = 120, kVE = 130;
constexpr int kAgency = 550;  // NOAA, as in US cells

inline bool skin_of_earth(const std::string& cls) {
  for (const char* c : {"DEPARE", "DRGARE", "LNDARE", "UNSARE", "FLODOC", "HULKES", "PONTON"}) {
    if (cls == c) return true;
  }
  return false;
}

[[noreturn]] inline void fail(const std::string& what) {
  const char* gdal = CPLGetLastErrorMsg();
  throw std::runtime_error("write_synthetic_cell: " + what + (gdal && *gdal ? std::string(": ") + gdal : ""));
}

inline OGRLayer* layer(GDALDataset& ds, const std::string& name) {
  OGRLayer* l = ds.GetLayerByName(name.c_str());
  if (l == nullptr) throw std::runtime_error("write_synthetic_cell: no S-57 object class " + name);
  return l;
}

inline void create(OGRLayer* l, OGRFeature& f, const std::string& what) {
  CPLErrorReset();
  if (l->CreateFeature(&f) != OGRERR_NONE) fail("writing " + what);
}

template <typename Attrs>
inline void set_attributes(OGRFeature& f, const std::string& cls, const Attrs& attrs) {
  for (const auto& [acronym, value] : attrs) {
    // The writer silently skips fields the class does not have; a typo in a test must not.
    const int i = f.GetFieldIndex(acronym.c_str());
    if (i < 0) throw std::runtime_error("write_synthetic_cell: " + cls + " has no attribute " + acronym);
    f.SetField(i, value);
  }
}

// The fields every feature record needs: RCID is unique per record, FOID
// (AGEN, FIDN, FIDS) gives the LNAM the reader reports. RVER 1 / RUIN insert
// are fixed by the writer itself.
inline void set_feature_record(OGRFeature& f, int rcid, int prim, const std::string& cls) {
  f.SetField("RCID", rcid);
  f.SetField("PRIM", prim);
  f.SetField("GRUP", skin_of_earth(cls) ? 1 : 2);
  f.SetField("AGEN", kAgency);
  f.SetField("FIDN", rcid);
  f.SetField("FIDS", 1);
}

inline void set_spatial_ref(OGRFeature& f, int rcnm, int rcid) {
  const int rcnms[] = {rcnm}, rcids[] = {rcid}, ornt[] = {1}, usag[] = {1}, mask[] = {255};
  f.SetField("NAME_RCNM", 1, rcnms);
  f.SetField("NAME_RCID", 1, rcids);
  f.SetField("ORNT", 1, ornt);  // forward: the ring comes back in the order given
  f.SetField("USAG", 1, usag);  // exterior boundary
  f.SetField("MASK", 1, mask);
}

}  // namespace synthetic_cell_detail

// Writes `cell` to `path_000`. Throws std::runtime_error carrying GDAL's message.
// Lon/lat of a point `east_m`, `north_m` metres from a corner at 76.5 W,
// 38.8 N, by a flat-earth scale (the cells' own geometry and a planner's UTM
// frame differ from it by about 0.1 %), and a rectangle of four such corners.
inline constexpr double kSyntheticLon0 = -76.50, kSyntheticLat0 = 38.80;
inline std::array<double, 2> synthetic_lonlat(double east_m, double north_m) {
  const double per_deg_lat = 111320.0;
  const double per_deg_lon = per_deg_lat * std::cos(kSyntheticLat0 * 3.14159265358979323846 / 180.0);
  return {kSyntheticLon0 + east_m / per_deg_lon, kSyntheticLat0 + north_m / per_deg_lat};
}
inline std::vector<std::array<double, 2>> synthetic_box(double x0, double y0, double x1, double y1) {
  return {synthetic_lonlat(x0, y0), synthetic_lonlat(x1, y0), synthetic_lonlat(x1, y1), synthetic_lonlat(x0, y1)};
}

inline void write_synthetic_cell(const std::string& path_000, const SyntheticCell& cell) {
  namespace d = synthetic_cell_detail;
  if (GetGDALDriverManager()->GetDriverByName("S57") == nullptr) GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("S57");
  if (driver == nullptr) throw std::runtime_error("write_synthetic_cell: GDAL has no S57 driver");

  std::vector<std::vector<std::array<double, 2>>> rings;
  for (const SyntheticArea& a : cell.areas) {
    std::vector<std::array<double, 2>> r = a.ring;
    if (r.size() > 1 && r.front() == r.back()) r.pop_back();
    if (r.size() < 3) throw std::runtime_error("write_synthetic_cell: " + a.cls + " ring has fewer than 3 vertices");
    rings.push_back(std::move(r));
  }
  int meta = 0;
  for (const SyntheticArea& a : cell.areas) meta += a.cls.rfind("M_", 0) == 0;
  const int isolated = static_cast<int>(cell.points.size()) + (cell.soundings.empty() ? 0 : 1);
  const int features = static_cast<int>(cell.areas.size() + cell.points.size()) + (cell.soundings.empty() ? 0 : 1);

  // GDAL 3.6 has no S57_DSNM option: DSID_DSNM is the file name being
  // created. Write under the wanted name in memory, then copy to path_000.
  static std::atomic<int> serial{0};
  const std::string dir = "/vsimem/synthetic_cell_" + std::to_string(serial++);
  const std::string mem_path = dir + "/" + cell.name + ".000";
  const std::map<std::string, std::string> opts = {
      {"S57_INTU", std::to_string(cell.usage_band)},
      {"S57_CSCL", std::to_string(cell.compilation_scale)},
      {"S57_EDTN", "1"},
      {"S57_UPDN", "0"},
      {"S57_AGEN", std::to_string(d::kAgency)},
      {"S57_SOMF", std::to_string(cell.sounding_factor)},
      // DSSI record counts, so the header agrees with the records.
      {"S57_NOMR", std::to_string(meta)},
      {"S57_NOGR", std::to_string(features - meta)},
      {"S57_NOIN", std::to_string(isolated)},
      {"S57_NOCN", std::to_string(rings.size())},
      {"S57_NOED", std::to_string(rings.size())},
  };
  CPLStringList options;
  for (const auto& [k, v] : opts) options.SetNameValue(k.c_str(), v.c_str());
  {
    CPLErrorReset();
    GDALDatasetUniquePtr ds(driver->Create(mem_path.c_str(), 0, 0, 0, GDT_Unknown, options.List()));
    if (!ds) d::fail("creating " + mem_path);

    // Primitives first (ISO 8211 order of an ENC: vectors, then features).
    int rcid = 1;
    OGRLayer* vi = d::layer(*ds, "IsolatedNode");
    std::vector<int> point_node;
    for (const SyntheticPoint& p : cell.points) {
      OGRFeature f(vi->GetLayerDefn());
      f.SetField("RCNM", d::kVI);
      f.SetField("RCID", rcid);
      f.SetGeometryDirectly(new OGRPoint(p.lon, p.lat));  // 2-D: the writer emits SG2D when Z == 0
      d::create(vi, f, "isolated node for " + p.cls);
      point_node.push_back(rcid++);
    }
    const int sounding_node = rcid;
    if (!cell.soundings.empty()) {
      auto* mp = new OGRMultiPoint;
      for (const SyntheticSounding& s : cell.soundings) mp->addGeometryDirectly(new OGRPoint(s.lon, s.lat, s.depth_m));
      OGRFeature f(vi->GetLayerDefn());
      f.SetField("RCNM", d::kVI);
      f.SetField("RCID", rcid++);
      f.SetGeometryDirectly(mp);  // multipoints are always written as SG3D
      d::create(vi, f, "sounding node");
    }
    OGRLayer* vc = d::layer(*ds, "ConnectedNode");
    for (std::size_t i = 0; i < rings.size(); ++i) {
      OGRFeature f(vc->GetLayerDefn());
      f.SetField("RCNM", d::kVC);
      f.SetField("RCID", static_cast<int>(i + 1));
      f.SetGeometryDirectly(new OGRPoint(rings[i][0][0], rings[i][0][1]));
      d::create(vc, f, "connected node of " + cell.areas[i].cls);
    }
    OGRLayer* ve = d::layer(*ds, "Edge");
    for (std::size_t i = 0; i < rings.size(); ++i) {
      OGRFeature f(ve->GetLayerDefn());
      f.SetField("RCNM", d::kVE);
      f.SetField("RCID", static_cast<int>(i + 1));
      // SG2D holds only the inner vertices; the end points are the nodes (VRPT).
      auto* line = new OGRLineString;
      for (std::size_t k = 1; k < rings[i].size(); ++k) line->addPoint(rings[i][k][0], rings[i][k][1]);
      f.SetGeometryDirectly(line);
      for (const char* end : {"0", "1"}) {
        const std::string s = end;
        f.SetField(("NAME_RCNM_" + s).c_str(), d::kVC);
        f.SetField(("NAME_RCID_" + s).c_str(), static_cast<int>(i + 1));
        f.SetField(("ORNT_" + s).c_str(), 255);
        f.SetField(("USAG_" + s).c_str(), 255);
        f.SetField(("TOPI_" + s).c_str(), s == "0" ? 1 : 2);  // beginning node, end node
        f.SetField(("MASK_" + s).c_str(), 255);
      }
      d::create(ve, f, "edge of " + cell.areas[i].cls);
    }

    // Features: meta objects first, as in real cells.
    int frid = 1;
    for (const bool want_meta : {true, false}) {
      for (std::size_t i = 0; i < cell.areas.size(); ++i) {
        const SyntheticArea& a = cell.areas[i];
        if ((a.cls.rfind("M_", 0) == 0) != want_meta) continue;
        OGRLayer* l = d::layer(*ds, a.cls);
        OGRFeature f(l->GetLayerDefn());
        d::set_feature_record(f, frid++, 3, a.cls);
        d::set_attributes(f, a.cls, a.reals);
        d::set_attributes(f, a.cls, a.ints);
        d::set_spatial_ref(f, d::kVE, static_cast<int>(i + 1));
        d::create(l, f, a.cls);
      }
    }
    if (!cell.soundings.empty()) {
      OGRLayer* l = d::layer(*ds, "SOUNDG");
      OGRFeature f(l->GetLayerDefn());
      d::set_feature_record(f, frid++, 1, "SOUNDG");
      d::set_spatial_ref(f, d::kVI, sounding_node);
      d::create(l, f, "SOUNDG");
    }
    for (std::size_t i = 0; i < cell.points.size(); ++i) {
      const SyntheticPoint& p = cell.points[i];
      OGRLayer* l = d::layer(*ds, p.cls);
      OGRFeature f(l->GetLayerDefn());
      d::set_feature_record(f, frid++, 1, p.cls);
      d::set_attributes(f, p.cls, p.reals);
      d::set_attributes(f, p.cls, p.ints);
      d::set_spatial_ref(f, d::kVI, point_node[i]);
      d::create(l, f, p.cls);
    }
  }  // closing the dataset flushes the ISO 8211 file

  const int copied = CPLCopyFile(path_000.c_str(), mem_path.c_str());
  VSIUnlink(mem_path.c_str());
  VSIRmdir(dir.c_str());
  if (copied != 0) d::fail("copying to " + path_000);
}

}  // namespace deepguide::test
