#include "deepguide/charts/prepared_chart.hpp"

#include <ogrsf_frmts.h>

#include <boost/geometry/algorithms/correct.hpp>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {
namespace fs = std::filesystem;

namespace {

constexpr const char* kFormat = "deepguide prepared chart 3";
// Format 2 kept no_go_features and the areas in lon/lat (format 3: in the
// frame it was prepared in); read the same way, through their layers' CRS.
constexpr const char* kFormat2 = "deepguide prepared chart 2";
// Format 1 had one zone_of_confidence flag (discs unclipped): read as strict or none.
constexpr const char* kFormat1 = "deepguide prepared chart 1";
constexpr const char* kMetaLayer = "deepguide_chart";
constexpr const char* kFeatureLayer = "no_go_features";
constexpr const char* kGraphLayer = "deepguide_graphs";
constexpr const char* kGraphColumns[] = {"graph", "key", "about"};

std::string shown(const std::string& path) { return printable(path, 240); }

[[noreturn]] void fail_write(const std::string& path, const std::string& what) {
  const std::string why = gdal::QuietErrors::last_message();
  throw InputError(shown(path) + ": could not " + what + (why.empty() ? std::string() : ": " + why));
}

// An area in the frame as an OGR multipolygon (in the frame: the layers
// carry its CRS), and back.
OGRMultiPolygon to_ogr(const BgMultiPolygon& area) {
  OGRMultiPolygon mp;
  for (const BgPolygon& poly : area) {
    OGRPolygon op;
    auto ring = [&](const auto& r) {
      OGRLinearRing lr;
      for (const BgPoint& q : r) lr.addPoint(q.x(), q.y());
      op.addRing(&lr);
    };
    ring(poly.outer());
    for (const auto& in : poly.inners()) ring(in);
    mp.addGeometry(&op);
  }
  return mp;
}

BgMultiPolygon from_frame_multipolygon(const OGRMultiPolygon& mp) {
  BgMultiPolygon out;
  for (const OGRPolygon* op : mp) {
    BgPolygon bp;
    auto ring = [](const OGRLinearRing& r, auto& dst) {
      for (int i = 0; i < r.getNumPoints(); ++i) dst.push_back(BgPoint(r.getX(i), r.getY(i)));
    };
    ring(*op->getExteriorRing(), bp.outer());
    for (int k = 0; k < op->getNumInteriorRings(); ++k) ring(*op->getInteriorRing(k), bp.inners().emplace_back());
    boost::geometry::correct(bp);
    out.push_back(std::move(bp));
  }
  return out;
}

// The areas a route's quality is measured on (EncNoGo::cell_areas, depth_areas, zones), one layer each.
constexpr const char* kAreaLayers[] = {"cell_areas", "depth_areas", "zones"};

void write_areas(GDALDataset& ds, const char* name, const std::vector<EncChartArea>& areas, const LocalFrame& frame,
                 const std::string& path) {
  const auto srs = gdal::srs_from_user_input(frame.wkt());
  OGRLayer* layer = ds.CreateLayer(name, srs.get(), wkbMultiPolygon, nullptr);
  if (layer == nullptr) fail_write(path, std::string("create the ") + name + " layer");
  for (const auto& [field, type] : std::initializer_list<std::pair<const char*, OGRFieldType>>{
           {"id", OFTString}, {"cell", OFTString}, {"depth_m", OFTReal}, {"catzoc", OFTInteger}}) {
    OGRFieldDefn fd(field, type);
    if (layer->CreateField(&fd) != OGRERR_NONE) fail_write(path, std::string("create field ") + field);
  }
  for (const EncChartArea& a : areas) {
    OGRFeature out(layer->GetLayerDefn());
    out.SetField("id", a.id.c_str());
    out.SetField("cell", a.cell.c_str());
    if (std::isfinite(a.depth_m)) out.SetField("depth_m", a.depth_m);
    out.SetField("catzoc", a.catzoc);
    OGRMultiPolygon mp = to_ogr(a.area);
    out.SetGeometry(&mp);
    if (layer->CreateFeature(&out) != OGRERR_NONE) fail_write(path, std::string("write a row of ") + name);
  }
}

// A layer's geometry into the frame: nothing to do when the layer is in the
// frame's CRS (what chart prepare writes, read in the frame it prepared in),
// else a transformation from the layer's CRS (lon/lat before format 3).
class IntoFrame {
 public:
  IntoFrame(OGRLayer& layer, const OGRSpatialReference& frame, const std::string& path) : ct_(nullptr, nullptr) {
    const OGRSpatialReference* from = layer.GetSpatialRef();
    if (from != nullptr && from->IsSame(&frame)) return;
    std::unique_ptr<OGRSpatialReference> geo;
    if (from == nullptr) geo = gdal::wgs84();
    ct_ = gdal::make_transform(from != nullptr ? *from : *geo, frame);
    if (!ct_) {
      throw InputError(shown(path) + ": layer " + layer.GetName() + ": no transformation from its CRS to the frame");
    }
  }
  bool apply(OGRGeometry& g) const { return !ct_ || g.transform(ct_.get()) == OGRERR_NONE; }

 private:
  gdal::TransformPtr ct_;
};

std::vector<EncChartArea> read_areas(GDALDataset& ds, const char* name, const OGRSpatialReference& frame,
                                     const std::string& path) {
  std::vector<EncChartArea> out;
  OGRLayer* layer = ds.GetLayerByName(name);
  if (layer == nullptr) return out;  // a chart prepared before they were kept
  const IntoFrame into_frame(*layer, frame, path);
  for (auto& f : *layer) {
    EncChartArea a;
    a.id = f->GetFieldAsString("id");
    a.cell = f->GetFieldAsString("cell");
    const int di = f->GetFieldIndex("depth_m");
    a.depth_m = di >= 0 && f->IsFieldSetAndNotNull(di) ? f->GetFieldAsDouble(di) : std::nan("");
    a.catzoc = f->GetFieldAsInteger("catzoc");
    OGRGeometry* g = f->GetGeometryRef();
    if (g == nullptr || wkbFlatten(g->getGeometryType()) != wkbMultiPolygon || !into_frame.apply(*g)) {
      throw InputError(shown(path) + ": layer " + name + ", feature '" + printable(a.id) +
                       "': expected a multipolygon in the frame's area");
    }
    a.area = from_frame_multipolygon(*g->toMultiPolygon());
    out.push_back(std::move(a));
  }
  return out;
}

void write_features(GDALDataset& ds, const EncNoGo& no_go, const std::string& path) {
  const auto srs = gdal::srs_from_user_input(no_go.frame.wkt());
  OGRLayer* layer = ds.CreateLayer(kFeatureLayer, srs.get(), wkbUnknown, nullptr);
  if (layer == nullptr) fail_write(path, "create the no_go_features layer");
  for (const auto& [name, type] :
       std::initializer_list<std::pair<const char*, OGRFieldType>>{{"id", OFTString},
                                                                   {"cell", OFTString},
                                                                   {"class", OFTString},
                                                                   {"rcid", OFTInteger64},
                                                                   {"reason", OFTString},
                                                                   {"charted_depth_m", OFTReal},
                                                                   {"radius_m", OFTReal}}) {
    OGRFieldDefn fd(name, type);
    if (layer->CreateField(&fd) != OGRERR_NONE) fail_write(path, std::string("create field ") + name);
  }
  for (const EncNoGoFeature& f : no_go.features) {
    OGRFeature out(layer->GetLayerDefn());
    out.SetField("id", f.id.c_str());
    out.SetField("cell", f.cell.c_str());
    out.SetField("class", f.cls.c_str());
    out.SetField("rcid", static_cast<GIntBig>(f.rcid));
    out.SetField("reason", f.reason.c_str());
    if (std::isfinite(f.charted_depth_m)) out.SetField("charted_depth_m", f.charted_depth_m);
    if (f.point) {
      OGRPoint pt(f.point->x(), f.point->y());
      out.SetGeometry(&pt);
      out.SetField("radius_m", f.radius_m);
    } else {
      OGRMultiPolygon mp = to_ogr(f.area);
      out.SetGeometry(&mp);
    }
    if (layer->CreateFeature(&out) != OGRERR_NONE) fail_write(path, "write feature '" + f.id + "'");
  }
}

void write_meta(GDALDataset& ds, const EncNoGo& no_go, const EncNoGoOptions& o, const std::string& path) {
  OGRLayer* layer = ds.CreateLayer(kMetaLayer, nullptr, wkbNone, nullptr);
  if (layer == nullptr) fail_write(path, "create the deepguide_chart table");
  for (const auto& [name, type] :
       std::initializer_list<std::pair<const char*, OGRFieldType>>{{"format", OFTString},
                                                                   {"depth_m", OFTReal},
                                                                   {"vertical_clearance_m", OFTReal},
                                                                   {"required_depth_m", OFTReal},
                                                                   {"zone_of_confidence", OFTInteger},
                                                                   {"zoc", OFTString},
                                                                   {"unassessed_depth_fixed_m", OFTReal},
                                                                   {"unassessed_depth_fraction", OFTReal},
                                                                   {"unassessed_position_m", OFTReal},
                                                                   {"restricted_areas", OFTInteger},
                                                                   {"simplify_tolerance_m", OFTReal},
                                                                   {"local_crs", OFTString},
                                                                   {"cells", OFTString}}) {
    OGRFieldDefn fd(name, type);
    if (layer->CreateField(&fd) != OGRERR_NONE) fail_write(path, std::string("create field ") + name);
  }
  std::string cells;
  for (const EncCellSummary& c : no_go.cells) {
    cells += (cells.empty() ? "" : "; ") + c.name + " edition " + c.edition + " update " +
             std::to_string(c.update_number) + " (" + c.issue_date + ")";
  }
  OGRFeature f(layer->GetLayerDefn());
  f.SetField("format", kFormat);
  f.SetField("depth_m", o.operating_depth_m);
  f.SetField("vertical_clearance_m", o.vertical_clearance_m);
  f.SetField("required_depth_m", no_go.required_depth_m);
  f.SetField("zone_of_confidence", o.zones_of_confidence() ? 1 : 0);
  f.SetField("zoc", to_string(o.zoc));
  f.SetField("unassessed_depth_fixed_m", o.unassessed.depth_fixed_m);
  f.SetField("unassessed_depth_fraction", o.unassessed.depth_fraction);
  f.SetField("unassessed_position_m", o.unassessed.position_m);
  f.SetField("restricted_areas", o.restricted_areas ? 1 : 0);
  f.SetField("simplify_tolerance_m", o.simplify_tolerance_m);
  f.SetField("local_crs", no_go.frame.id().c_str());
  f.SetField("cells", cells.c_str());
  if (layer->CreateFeature(&f) != OGRERR_NONE) fail_write(path, "write the deepguide_chart row");
}

void write_graphs(GDALDataset& ds, const std::vector<PreparedGraphRecord>& graphs, const std::string& path) {
  OGRLayer* layer = ds.CreateLayer(kGraphLayer, nullptr, wkbNone, nullptr);
  if (layer == nullptr) fail_write(path, "create the deepguide_graphs table");
  for (const char* name : kGraphColumns) {
    OGRFieldDefn fd(name, OFTString);
    if (layer->CreateField(&fd) != OGRERR_NONE) fail_write(path, std::string("create field ") + name);
  }
  OGRFieldDefn blob("data", OFTBinary);
  if (layer->CreateField(&blob) != OGRERR_NONE) fail_write(path, "create field data");
  for (const PreparedGraphRecord& g : graphs) {
    OGRFeature f(layer->GetLayerDefn());
    f.SetField("graph", g.graph.c_str());
    f.SetField("key", g.key.c_str());
    f.SetField("about", g.about.c_str());
    if (g.data.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      fail_write(path, "store graph '" + g.graph + "' of " + std::to_string(g.data.size()) + " bytes (2 GiB at most)");
    f.SetField(layer->GetLayerDefn()->GetFieldIndex("data"), static_cast<int>(g.data.size()), g.data.data());
    if (layer->CreateFeature(&f) != OGRERR_NONE) fail_write(path, "write graph '" + g.graph + "'");
  }
}

GDALDatasetUniquePtr open_gpkg(const std::string& path) {
  gdal::ensure_registered();
  const char* drivers[] = {"GPKG", nullptr};
  return gdal::open_dataset(path, GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers);
}

}  // namespace

bool is_prepared_chart(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return false;
  // A GeoPackage is an SQLite file: anything else is told without GDAL.
  {
    std::ifstream in(path, std::ios::binary);
    char magic[16] = {};
    if (!in.read(magic, sizeof magic) || std::memcmp(magic, "SQLite format 3", 16) != 0) return false;
  }
  // One `plan` asks several times (the default graph, the chart reader, the
  // no-go); opening the GeoPackage costs tens of milliseconds each time. The
  // answer is kept per file, size and modification time.
  const auto size = fs::file_size(path, ec);
  const auto mtime = fs::last_write_time(path, ec).time_since_epoch().count();
  const std::string key = fs::absolute(path, ec).string() + '\n' + std::to_string(size) + '\n' + std::to_string(mtime);
  static std::mutex mutex;
  static std::map<std::string, bool> known;
  {
    const std::lock_guard lock(mutex);
    if (const auto it = known.find(key); it != known.end()) return it->second;
  }
  gdal::QuietErrors quiet;
  GDALDatasetUniquePtr ds = open_gpkg(path);
  const bool prepared = ds && ds->GetLayerByName(kMetaLayer) != nullptr;
  const std::lock_guard lock(mutex);
  known[key] = prepared;
  return prepared;
}

void write_prepared_chart(const std::string& path, const EncNoGo& no_go, const EncNoGoOptions& options, bool replace,
                          const PreparedGraphsMaker& graphs) {
  if (ascii_lower(fs::path(path).extension().string()) != ".gpkg") {
    throw InputError(shown(path) + ": expected a GeoPackage name (*.gpkg) for a prepared chart");
  }
  std::error_code ec;
  if (!replace && fs::exists(path, ec)) {
    throw InputError(shown(path) + ": exists; `overwrite` replaces it");
  }
  AtomicOutput out(path);
  write_obstacles(out.temp_path().string(), no_go.obstacles, no_go.frame);
  {
    gdal::QuietErrors quiet;
    GDALDatasetUniquePtr ds(GDALDataset::Open(out.temp_path().c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE));
    if (!ds) fail_write(path, "reopen the GeoPackage");
    if (ds->StartTransaction() != OGRERR_NONE) fail_write(path, "start a transaction");
    write_features(*ds, no_go, path);
    write_areas(*ds, kAreaLayers[0], no_go.cell_areas, no_go.frame, path);
    write_areas(*ds, kAreaLayers[1], no_go.depth_areas, no_go.frame, path);
    write_areas(*ds, kAreaLayers[2], no_go.zones, no_go.frame, path);
    write_meta(*ds, no_go, options, path);
    if (ds->CommitTransaction() != OGRERR_NONE) fail_write(path, "commit the GeoPackage");
    ds.reset();  // closes (flushes) before the rename
    if (!gdal::QuietErrors::last_message().empty()) fail_write(path, "finish the file");
  }
  if (graphs) {
    // The obstacles exactly as `plan --chart` will read them (a lon/lat round
    // trip changes their last bits): the graphs' key fingerprints them.
    const std::vector<PreparedGraphRecord> made =
        graphs(read_prepared_chart(out.temp_path().string(), no_go.frame, options.operating_depth_m,
                                   options.vertical_clearance_m)
                   .obstacles);
    gdal::QuietErrors quiet;
    GDALDatasetUniquePtr ds(GDALDataset::Open(out.temp_path().c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE));
    if (!ds) fail_write(path, "reopen the GeoPackage");
    if (ds->StartTransaction() != OGRERR_NONE) fail_write(path, "start a transaction");
    write_graphs(*ds, made, path);
    if (ds->CommitTransaction() != OGRERR_NONE) fail_write(path, "commit the GeoPackage");
    ds.reset();
    if (!gdal::QuietErrors::last_message().empty()) fail_write(path, "finish the file");
  }
  out.commit(replace);
}

namespace {

// The table that says what the file is, its one row checked for a format this reader knows.
std::unique_ptr<OGRFeature> prepared_row(GDALDataset* ds, const std::string& path) {
  OGRLayer* meta = ds ? ds->GetLayerByName(kMetaLayer) : nullptr;
  if (meta == nullptr) throw InputError(shown(path) + ": expected a prepared chart (chart prepare), got none");
  std::unique_ptr<OGRFeature> row(meta->GetNextFeature());
  const std::string format = row ? row->GetFieldAsString("format") : "";
  if (format != kFormat && format != kFormat2 && format != kFormat1) {
    throw InputError(shown(path) + ": table deepguide_chart: expected format '" + kFormat + "'");
  }
  return row;
}

}  // namespace

LocalFrame prepared_chart_frame(const std::string& path) {
  gdal::QuietErrors quiet;
  GDALDatasetUniquePtr ds = open_gpkg(path);
  return LocalFrame::from_user_crs(prepared_row(ds.get(), path)->GetFieldAsString("local_crs"), shown(path));
}

EncNoGo read_prepared_chart(const std::string& path, const std::optional<LocalFrame>& frame, double depth_m,
                            double vertical_clearance_m, PreparedChartInfo* info) {
  gdal::QuietErrors quiet;
  GDALDatasetUniquePtr ds = open_gpkg(path);
  const std::unique_ptr<OGRFeature> row = prepared_row(ds.get(), path);
  const std::string format = row->GetFieldAsString("format");
  PreparedChartInfo p;
  p.depth_m = row->GetFieldAsDouble("depth_m");
  p.vertical_clearance_m = row->GetFieldAsDouble("vertical_clearance_m");
  const bool zones = row->GetFieldAsInteger("zone_of_confidence") != 0;
  if (format == kFormat1) {
    p.chart.zoc = zones ? ZocPolicy::strict : ZocPolicy::none;
  } else {
    const std::optional<ZocPolicy> zoc = parse_zoc_policy(row->GetFieldAsString("zoc"));
    if (!zoc) {
      throw InputError(shown(path) + ": table deepguide_chart, field 'zoc': expected clipped, strict or none, got '" +
                       printable(row->GetFieldAsString("zoc")) + "'");
    }
    p.chart.zoc = *zoc;
    p.chart.unassessed = {row->GetFieldAsDouble("unassessed_depth_fixed_m"),
                          row->GetFieldAsDouble("unassessed_depth_fraction"),
                          row->GetFieldAsDouble("unassessed_position_m")};
  }
  p.chart.restricted_areas = row->GetFieldAsInteger("restricted_areas") != 0;
  p.simplify_tolerance_m = row->GetFieldAsDouble("simplify_tolerance_m");
  p.cells = row->GetFieldAsString("cells");
  if (info != nullptr) *info = p;
  if (std::abs(p.depth_m - depth_m) > 1e-9 || std::abs(p.vertical_clearance_m - vertical_clearance_m) > 1e-9) {
    throw InputError(shown(path) + ": prepared for depth " + general(p.depth_m) + " m and vertical clearance " +
                     general(p.vertical_clearance_m) + " m, expected depth " + general(depth_m) + " m and " +
                     general(vertical_clearance_m) + " m: prepare it again (chart prepare) for this depth");
  }
  const LocalFrame use = frame ? *frame : LocalFrame::from_user_crs(row->GetFieldAsString("local_crs"), shown(path));
  ObstacleReadOptions ro;
  ro.local_crs = use.id();
  ro.layers = {"obstacles"};
  ro.repair_polygons = true;
  EncNoGo out{use, depth_m + vertical_clearance_m, {}, {}, load_obstacles({path}, ro).obstacles, {}, {}, {}, 0, {}, {},
              {}};

  OGRLayer* features = ds->GetLayerByName(kFeatureLayer);
  if (features == nullptr) throw InputError(shown(path) + ": expected a no_go_features layer, found none");
  const auto srs = gdal::srs_from_user_input(use.wkt());
  const IntoFrame into_frame(*features, *srs, path);
  for (auto& f : *features) {
    EncNoGoFeature n;
    n.id = f->GetFieldAsString("id");
    n.cell = f->GetFieldAsString("cell");
    n.cls = f->GetFieldAsString("class");
    n.rcid = f->GetFieldAsInteger64("rcid");
    n.reason = f->GetFieldAsString("reason");
    const int di = f->GetFieldIndex("charted_depth_m");
    n.charted_depth_m = f->IsFieldSetAndNotNull(di) ? f->GetFieldAsDouble(di) : std::nan("");
    OGRGeometry* g = f->GetGeometryRef();
    if (g == nullptr || !into_frame.apply(*g)) {
      throw InputError(shown(path) + ": layer no_go_features, feature '" + printable(n.id) +
                       "': expected a geometry in the frame's area");
    }
    if (wkbFlatten(g->getGeometryType()) == wkbPoint) {
      n.point = Vec2(g->toPoint()->getX(), g->toPoint()->getY());
      n.radius_m = f->GetFieldAsDouble("radius_m");
    } else if (wkbFlatten(g->getGeometryType()) == wkbMultiPolygon) {
      n.area = from_frame_multipolygon(*g->toMultiPolygon());
    }
    if (n.cls != "M_COVR") ++out.no_go_by_class[n.cls];
    out.features.push_back(std::move(n));
  }
  out.cell_areas = read_areas(*ds, kAreaLayers[0], *srs, path);
  out.depth_areas = read_areas(*ds, kAreaLayers[1], *srs, path);
  out.zones = read_areas(*ds, kAreaLayers[2], *srs, path);
  if (const std::string why = gdal::QuietErrors::last_message(); !why.empty()) {
    throw InputError(shown(path) + ": expected a complete prepared chart, got: " + why);
  }
  return out;
}

std::vector<PreparedGraphRecord> read_prepared_graphs(const std::string& path) {
  gdal::QuietErrors quiet;
  GDALDatasetUniquePtr ds = open_gpkg(path);
  if (!ds) throw InputError(shown(path) + ": expected a prepared chart (chart prepare), got none");
  OGRLayer* layer = ds->GetLayerByName(kGraphLayer);
  std::vector<PreparedGraphRecord> out;
  if (layer == nullptr) return out;
  OGRFeatureDefn* defn = layer->GetLayerDefn();
  for (const char* name : kGraphColumns) {
    const int i = defn->GetFieldIndex(name);
    if (i < 0 || defn->GetFieldDefn(i)->GetType() != OFTString)
      throw InputError(shown(path) + ": table deepguide_graphs: expected a text field '" + name + "'");
  }
  const int data = defn->GetFieldIndex("data");
  if (data < 0 || defn->GetFieldDefn(data)->GetType() != OFTBinary)
    throw InputError(shown(path) + ": table deepguide_graphs: expected a BLOB field 'data'");
  for (auto& f : *layer) {
    PreparedGraphRecord r;
    r.graph = f->GetFieldAsString("graph");
    r.key = f->GetFieldAsString("key");
    r.about = f->GetFieldAsString("about");
    int n = 0;
    const GByte* bytes = f->GetFieldAsBinary(data, &n);
    if (bytes != nullptr && n > 0) r.data.assign(bytes, bytes + n);
    r.source = path;
    out.push_back(std::move(r));
  }
  if (const std::string why = gdal::QuietErrors::last_message(); !why.empty())
    throw InputError(shown(path) + ": table deepguide_graphs: expected rows as written, got: " + why);
  return out;
}

EncNoGo chart_no_go(const std::vector<std::string>& charts, const std::optional<LocalFrame>& frame,
                    const EncNoGoOptions& options) {
  std::size_t prepared = 0;
  for (const std::string& c : charts) prepared += is_prepared_chart(c);
  if (prepared == 0) return enc_no_go(charts, frame, options);
  if (charts.size() > 1) {
    throw InputError("`charts`: expected S-57 cells or one prepared chart, got " + std::to_string(prepared) +
                     " prepared chart(s) among " + std::to_string(charts.size()) + " charts");
  }
  if (!std::isfinite(options.operating_depth_m)) {
    throw InputError("`operating_depth_m`: expected the operating depth (m) the chart was prepared for");
  }
  PreparedChartInfo info;
  EncNoGo out =
      read_prepared_chart(charts.front(), frame, options.operating_depth_m, options.vertical_clearance_m, &info);
  if (const std::string differs = chart_options_difference(info.chart, options); !differs.empty()) {
    throw InputError(shown(charts.front()) + ": prepared with " + differs +
                     ": prepare it again (chart prepare) with the chart options of this run");
  }
  return out;
}

ChartPreparation prepare_chart(const std::vector<std::string>& charts, const std::string& local_crs,
                               const EncNoGoOptions& options, const std::string& output, bool overwrite,
                               const PreparedGraphsMaker& graphs) {
  const auto t0 = std::chrono::steady_clock::now();
  ChartPreparation p{
      output,
      enc_no_go(charts, local_crs.empty() ? std::nullopt : std::optional(LocalFrame::from_user_crs(local_crs)),
                options),
      options,
      {},
      0.0};
  PreparedGraphsMaker keep_summaries;
  if (graphs) {
    keep_summaries = [&](const ObstacleSet& as_read) {
      std::vector<PreparedGraphRecord> made = graphs(as_read);
      for (const PreparedGraphRecord& r : made) p.graphs.push_back({r.graph, r.key, r.about, {}, output});
      return made;
    };
  }
  write_prepared_chart(output, p.no_go, options, overwrite, keep_summaries);
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

nlohmann::json ChartPreparation::graphs_json() const {
  nlohmann::json out = nlohmann::json::array();
  for (const PreparedGraphRecord& g : graphs) out.push_back({{"graph", g.graph}, {"key", g.key}, {"about", g.about}});
  return out;
}

nlohmann::json ChartPreparation::to_json() const {
  return {{"output", output},
          {"cells", no_go.cells.size()},
          {"local_crs", no_go.frame.id()},
          {"required_depth_m", no_go.required_depth_m},
          {"zoc", to_string(options.zoc)},
          {"restricted_areas", options.restricted_areas},
          {"no_go_features", no_go.features.size()},
          {"polygons", no_go.obstacles.polygons.size()},
          {"discs", no_go.obstacles.ellipses.size()},
          {"vertices", no_go.vertices},
          {"graphs", graphs_json()},
          {"seconds", seconds}};
}

std::string ChartPreparation::to_text() const {
  std::string t;
  for (const EncCellSummary& c : no_go.cells) {
    t += printf_text("cell             %s  1:%ld, edition %s, update %d\n", c.name.c_str(), c.compilation_scale,
                     c.edition.c_str(), c.update_number);
  }
  t += printf_text("required depth   %.2f m (%.2f + %.2f clearance)%s\n", no_go.required_depth_m,
                   options.operating_depth_m, options.vertical_clearance_m,
                   options.zones_of_confidence() ? ", less each zone of confidence" : "");
  t += printf_text("zones            %s%s\n", to_string(options.zoc),
                   options.zoc == ZocPolicy::clipped ? " (point hazards' discs clipped to zones not better than theirs)"
                   : options.zoc == ZocPolicy::strict ? " (point hazards' discs unclipped)"
                                                      : " (charted depths and positions as exact)");
  t += printf_text("no-go            %zu features; for the planners %zu polygon(s), %zu corners, %zu disc(s)\n",
                   no_go.features.size(), no_go.obstacles.polygons.size(), no_go.vertices,
                   no_go.obstacles.ellipses.size());
  for (const PreparedGraphRecord& g : graphs)
    t += printf_text("graph            %s: %s\n", g.graph.c_str(), g.about.c_str());
  t += printf_text("time             %.2f s\n", seconds);
  t += printf_text("wrote            %s\n", output.c_str());
  return t;
}

}  // namespace deepguide
