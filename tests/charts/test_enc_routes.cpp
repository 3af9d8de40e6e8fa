// Routes on real ENCs, checked by a reader and a geometry that share nothing
// with the library's no-go builder: the cell read here through OGR, the
// no-go kept as GEOS geometry (OGR's prepared geometries), and a raster of
// free water made with GDAL's rasterizer. For seeded start/goal pairs in free
// cells, every route the planner returns keeps the margin from every no-go
// feature, and none is refused while the raster connects start and goal.
//
// The charted rules checked are the ECDIS ones without zones of confidence
// (the library runs with zones of confidence off here, ZocPolicy::none; the zones only add
// no-go): depth and dredged areas with DRVAL1 < D, land, unsurveyed areas,
// structures, dangers and soundings shallower than D (dangers of unknown
// depth as no-go), and water outside the coverage.
//
// Pairs: DEEPGUIDE_ENC_PAIRS per chart and depth (default 15; the issue's
// 200-pair run is scripts/enc_routes.sh), a fifth under the sanitizers;
// DEEPGUIDE_ENC_SEED shifts the seeds.

#include <gdal_alg.h>
#include <gtest/gtest.h>
#include <ogr_api.h>
#include <ogr_geometry.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <memory>
#include <random>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/single_query.hpp"
#include "deepguide/world/enc_no_go.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

constexpr double kMargin = 5.0;
constexpr double kPointRadius = 10.0;  // the library's disc radius without zones of confidence
constexpr double kLineHalfWidth = 0.5;

int pairs_per_case() {
  const char* env = std::getenv("DEEPGUIDE_ENC_PAIRS");
  const int n = env != nullptr ? std::atoi(env) : 15;
  return std::max(1, test::cases(std::max(n, 5)));
}

using Geom = std::unique_ptr<OGRGeometry>;

// The cell's no-go at required depth D in UTM, read by this test alone.
struct OwnNoGo {
  std::unique_ptr<OGRSpatialReference> utm;
  std::vector<Geom> areas;            // no-go areas and strips, as charted (no margin)
  std::vector<std::string> area_ids;  // CELL:CLASS/RCID of each area, for what a failure says
  std::vector<Geom> points;           // point hazards and soundings (no radius)
  OGREnvelope extent;                 // of the coverage, in UTM
  Geom coverage;
  long scale = 0;  // DSPM_CSCL
};

bool drval_shallow(OGRFeature& f, double D) {
  const int i = f.GetFieldIndex("DRVAL1");
  return i < 0 || !f.IsFieldSetAndNotNull(i) || f.GetFieldAsDouble(i) < D;
}

OwnNoGo read_own(const std::string& path, double D, int utm_epsg) {
  OwnNoGo o;
  o.utm = std::make_unique<OGRSpatialReference>();
  o.utm->importFromEPSG(utm_epsg);
  o.utm->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  GDALAllRegister();
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  EXPECT_TRUE(ds);
  OGRSpatialReference wgs;
  wgs.SetWellKnownGeogCS("WGS84");
  wgs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&wgs, o.utm.get()));
  auto take = [&](OGRFeature& f, bool as_area_only) {
    Geom g(f.GetGeometryRef()->clone());
    g->transform(ct.get());
    const auto t = wkbFlatten(g->getGeometryType());
    if (t == wkbPoint || t == wkbMultiPoint) {
      if (!as_area_only) o.points.push_back(std::move(g));
    } else if (t == wkbLineString || t == wkbMultiLineString) {
      if (!as_area_only) {
        o.areas.emplace_back(g->Buffer(kLineHalfWidth, 8));
        o.area_ids.push_back(std::filesystem::path(path).stem().string() + ":" + f.GetDefnRef()->GetName() + "/" +
                             f.GetFieldAsString("RCID"));
      }
    } else {
      o.areas.push_back(std::move(g));
      o.area_ids.push_back(std::filesystem::path(path).stem().string() + ":" + f.GetDefnRef()->GetName() + "/" +
                           f.GetFieldAsString("RCID"));
    }
  };
  const std::vector<std::string> always = {"LNDARE", "UNSARE", "SLCONS", "PONTON", "HULKES", "FLODOC", "PILPNT",
                                           "PYLONS", "MORFAC", "OFSPLF", "CAUSWY", "DAMCON", "DRYDOC", "GATCON"};
  for (OGRLayer* layer : ds->GetLayers()) {
    const std::string cls = layer->GetName();
    for (auto& f : *layer) {
      if (cls == "DSID") o.scale = f->GetFieldAsInteger("DSPM_CSCL");  // a record without geometry
      if (f->GetGeometryRef() == nullptr || f->GetGeometryRef()->IsEmpty()) continue;
      if (cls == "M_COVR" && f->GetFieldAsInteger("CATCOV") == 1) {
        Geom g(f->GetGeometryRef()->clone());
        g->transform(ct.get());
        o.coverage = o.coverage ? Geom(o.coverage->Union(g.get())) : std::move(g);
      } else if (cls == "DEPARE" || cls == "DRGARE") {
        if (drval_shallow(*f, D)) take(*f, true);
      } else if (std::find(always.begin(), always.end(), cls) != always.end()) {
        take(*f, false);
      } else if (cls == "OBSTRN" || cls == "WRECKS" || cls == "UWTROC") {
        const int i = f->GetFieldIndex("VALSOU");
        const bool known = i >= 0 && f->IsFieldSetAndNotNull(i);
        // Unknown depth: no-go here (the library may tell it from WATLEV, CATWRK or EXPSOU: never less no-go).
        if (!known || f->GetFieldAsDouble(i) < D) take(*f, false);
      } else if (cls == "SOUNDG") {
        Geom g(f->GetGeometryRef()->clone());
        g->transform(ct.get());
        for (const OGRGeometry* p : *g->toGeometryCollection()) {
          if (p->toPoint()->getZ() < D) o.points.emplace_back(p->clone());
        }
      }
    }
  }
  o.coverage->getEnvelope(&o.extent);
  return o;
}

// Several cells read as an ECDIS reads them, by this test alone: where
// coverages overlap the larger compilation scale wins, so every other cell's
// areas are clipped to what no better cell covers and its points there are
// left out (points on a better cell's edge too).
OwnNoGo read_own_set(const std::vector<std::string>& paths, double D, int utm_epsg) {
  std::vector<OwnNoGo> cells;
  for (const std::string& p : paths) {
    cells.push_back(read_own(p, D, utm_epsg));
    EXPECT_TRUE(paths.size() == 1 || cells.back().scale > 0) << p << ": no DSPM_CSCL read";
  }
  std::stable_sort(cells.begin(), cells.end(), [](const OwnNoGo& a, const OwnNoGo& b) {
    return (a.scale > 0 ? a.scale : LONG_MAX) < (b.scale > 0 ? b.scale : LONG_MAX);
  });
  OwnNoGo out;
  out.utm = std::move(cells.front().utm);
  Geom better;
  for (OwnNoGo& c : cells) {
    for (std::size_t k = 0; k < c.areas.size(); ++k) {
      Geom& a = c.areas[k];
      Geom kept = better && a->Intersects(better.get()) ? Geom(a->Difference(better.get())) : std::move(a);
      if (kept && !kept->IsEmpty()) {
        out.areas.push_back(std::move(kept));
        out.area_ids.push_back(c.area_ids[k]);
      }
    }
    for (Geom& p : c.points) {
      if (!better || !p->Intersects(better.get())) out.points.push_back(std::move(p));
    }
    better = better ? Geom(better->Union(c.coverage.get())) : Geom(c.coverage->clone());
  }
  out.coverage = std::move(better);
  out.coverage->getEnvelope(&out.extent);
  return out;
}

// Free water on a grid of `cell` metres: no-go grown by the margin plus slack, all touched.
struct FreeRaster {
  double x0 = 0, y0 = 0, cell = 0;
  int w = 0, h = 0;
  std::vector<std::uint8_t> blocked;  // 1 = no-go
  std::vector<int> component;         // -1 for blocked cells

  Vec2 centre(int i, int j) const { return {x0 + (i + 0.5) * cell, y0 - (j + 0.5) * cell}; }
};

FreeRaster free_raster(const OwnNoGo& o, double cell, double grow) {
  FreeRaster r;
  r.cell = cell;
  r.x0 = o.extent.MinX;
  r.y0 = o.extent.MaxY;
  r.w = static_cast<int>(std::ceil((o.extent.MaxX - o.extent.MinX) / cell));
  r.h = static_cast<int>(std::ceil((o.extent.MaxY - o.extent.MinY) / cell));
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  GDALDatasetUniquePtr ds(mem->Create("", r.w, r.h, 1, GDT_Byte, nullptr));
  double gt[6] = {r.x0, cell, 0, r.y0, 0, -cell};
  ds->SetGeoTransform(gt);
  std::vector<OGRGeometryH> burn;
  std::vector<Geom> keep;
  for (const Geom& a : o.areas) keep.emplace_back(a->Buffer(grow, 4));
  for (const Geom& p : o.points) keep.emplace_back(p->Buffer(kPointRadius + grow, 8));
  // Outside the coverage: the envelope less the coverage, grown.
  OGRPolygon box;
  OGRLinearRing ring;
  ring.addPoint(o.extent.MinX - 100, o.extent.MinY - 100);
  ring.addPoint(o.extent.MinX - 100, o.extent.MaxY + 100);
  ring.addPoint(o.extent.MaxX + 100, o.extent.MaxY + 100);
  ring.addPoint(o.extent.MaxX + 100, o.extent.MinY - 100);
  ring.addPoint(o.extent.MinX - 100, o.extent.MinY - 100);
  box.addRing(&ring);
  Geom outside(box.Difference(o.coverage.get()));
  keep.emplace_back(outside->Buffer(grow, 4));
  for (const Geom& g : keep) burn.push_back(OGRGeometry::ToHandle(g.get()));
  int band = 1;
  double value = 1.0;
  std::vector<double> values(burn.size(), value);
  char* opts[] = {const_cast<char*>("ALL_TOUCHED=TRUE"), nullptr};
  EXPECT_EQ(GDALRasterizeGeometries(GDALDataset::ToHandle(ds.get()), 1, &band, static_cast<int>(burn.size()),
                                    burn.data(), nullptr, nullptr, values.data(), opts, nullptr, nullptr),
            CE_None);
  r.blocked.resize(static_cast<std::size_t>(r.w) * r.h);
  EXPECT_EQ(
      ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, r.w, r.h, r.blocked.data(), r.w, r.h, GDT_Byte, 0, 0, nullptr),
      CE_None);
  // 4-connected components of free cells.
  r.component.assign(r.blocked.size(), -1);
  int next = 0;
  std::deque<int> queue;
  for (int start = 0; start < r.w * r.h; ++start) {
    if (r.blocked[start] || r.component[start] >= 0) continue;
    r.component[start] = next;
    queue.push_back(start);
    while (!queue.empty()) {
      const int c = queue.front();
      queue.pop_front();
      const int i = c % r.w, j = c / r.w;
      const int nb[4][2] = {{i + 1, j}, {i - 1, j}, {i, j + 1}, {i, j - 1}};
      for (const auto& n : nb) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= r.w || n[1] >= r.h) continue;
        const int k = n[1] * r.w + n[0];
        if (r.blocked[k] || r.component[k] >= 0) continue;
        r.component[k] = next;
        queue.push_back(k);
      }
    }
    ++next;
  }
  return r;
}

// Every leg keeps the margin (less 1 cm) from every no-go area and point: no
// no-go geometry meets the leg grown by that much (GEOS, prepared).
struct OwnCheck {
  Geom all_areas;
  OGRPreparedGeometry* prepared_areas = nullptr;
  Geom all_points;
  OGRPreparedGeometry* prepared_points = nullptr;

  const OwnNoGo* own = nullptr;
  explicit OwnCheck(const OwnNoGo& o) : own(&o) {
    OGRMultiPolygon areas;
    for (const Geom& a : o.areas) {
      if (wkbFlatten(a->getGeometryType()) == wkbPolygon)
        areas.addGeometry(a.get());
      else if (wkbFlatten(a->getGeometryType()) == wkbMultiPolygon) {
        for (const OGRPolygon* p : *a->toMultiPolygon()) areas.addGeometry(p);
      }
    }
    all_areas.reset(areas.clone());
    prepared_areas = OGRCreatePreparedGeometry(OGRGeometry::ToHandle(all_areas.get()));
    // Points grown by their radius: the route keeps the margin from the disc's edge.
    OGRMultiPolygon discs;
    for (const Geom& p : o.points) {
      Geom d(p->Buffer(kPointRadius - 0.01, 16));
      discs.addGeometry(d.get());
    }
    all_points.reset(discs.clone());
    prepared_points = OGRCreatePreparedGeometry(OGRGeometry::ToHandle(all_points.get()));
  }
  ~OwnCheck() {
    OGRDestroyPreparedGeometry(prepared_areas);
    OGRDestroyPreparedGeometry(prepared_points);
  }
  // Why a leg is too near: the distance to the nearest area and disc, where.
  std::string why(const std::vector<Vec2>& route_utm, int k) const {
    OGRLineString leg;
    leg.addPoint(route_utm[k].x(), route_utm[k].y());
    leg.addPoint(route_utm[k + 1].x(), route_utm[k + 1].y());
    char buf[200];
    std::snprintf(buf, sizeof buf, "leg %d (%.1f, %.1f)-(%.1f, %.1f): %.3f m from the nearest area, %.3f m from a disc",
                  k, route_utm[k].x(), route_utm[k].y(), route_utm[k + 1].x(), route_utm[k + 1].y(),
                  leg.Distance(all_areas.get()), leg.Distance(all_points.get()));
    std::string near;
    for (std::size_t i = 0; i < own->areas.size(); ++i) {
      if (leg.Distance(own->areas[i].get()) < kMargin - 0.01) {
        char d[64];
        std::snprintf(d, sizeof d, " %.3f m", leg.Distance(own->areas[i].get()));
        near += "; " + own->area_ids[i] + d;
      }
    }
    return buf + near;
  }
  // The first leg that comes too near, or -1.
  int first_bad_leg(const std::vector<Vec2>& route_utm) const {
    for (std::size_t k = 0; k + 1 < route_utm.size(); ++k) {
      OGRLineString leg;
      leg.addPoint(route_utm[k].x(), route_utm[k].y());
      leg.addPoint(route_utm[k + 1].x(), route_utm[k + 1].y());
      Geom zone(leg.Buffer(kMargin - 0.01, 8));
      if (OGRPreparedGeometryIntersects(prepared_areas, OGRGeometry::ToHandle(zone.get())) ||
          OGRPreparedGeometryIntersects(prepared_points, OGRGeometry::ToHandle(zone.get()))) {
        return static_cast<int>(k);
      }
    }
    return -1;
  }
};

struct Case {
  const char* file;                   // a cell, or a folder of cells (an exchange set)
  double depth;                       // operating depth; D = depth + 2
  double cell_m;                      // the test raster's cells
  double min_km = 0.0, max_km = 1e9;  // how far apart the ends are
  int pairs = 0;                      // 0: pairs_per_case()
};

void run_case(const Case& c, unsigned seed) {
  const std::string path = test::real_file(c.file).empty() ? test::real_folder(c.file) : test::real_file(c.file);
  if (path.empty()) GTEST_SKIP() << "../shared/data/real/" << c.file << " is absent: skipping the test on real data";
  std::vector<std::string> cells;
  if (std::filesystem::is_directory(path)) {
    for (const auto& e : std::filesystem::recursive_directory_iterator(path)) {
      if (e.path().extension() == ".000") cells.push_back(e.path().string());
    }
  } else {
    cells.push_back(path);
  }
  const double D = c.depth + 2.0;
  EncNoGoOptions options;
  options.operating_depth_m = c.depth;
  options.vertical_clearance_m = 2.0;
  options.zoc = ZocPolicy::none;
  const EncNoGo no_go = enc_no_go({path}, std::nullopt, options);
  const std::string epsg = no_go.frame.id();
  ASSERT_EQ(epsg.rfind("EPSG:", 0), 0u);
  const OwnNoGo own = read_own_set(cells, D, std::stoi(epsg.substr(5)));
  // Cells grown by the margin, the planner's zone tolerance and simplification (1.5 m), and 1 m slack.
  const FreeRaster raster = free_raster(own, c.cell_m, kMargin + 2.5);
  const OwnCheck check(own);

  // DEEPGUIDE_ENC_SEED shifts every case's seed: a claim holds only if a fresh seed confirms it.
  const char* shift = std::getenv("DEEPGUIDE_ENC_SEED");
  std::mt19937 rng(seed + (shift != nullptr ? static_cast<unsigned>(std::atoi(shift)) : 0u));
  std::vector<int> free_cells;
  for (int k = 0; k < raster.w * raster.h; ++k) {
    if (!raster.blocked[k]) free_cells.push_back(k);
  }
  ASSERT_GT(free_cells.size(), 100u);
  std::uniform_int_distribution<std::size_t> pick(0, free_cells.size() - 1);
  PlannerOptions po;
  po.margin = kMargin;
  const int pairs = c.pairs > 0 ? c.pairs : pairs_per_case();
  auto apart_ok = [&](int a, int b) {
    const double km =
        (raster.centre(a % raster.w, a / raster.w) - raster.centre(b % raster.w, b / raster.w)).norm() / 1e3;
    return km >= c.min_km && km <= c.max_km;
  };
  int connected = 0, routes = 0, refused_disconnected = 0;
  for (int n = 0; n < pairs; ++n) {
    const int a = free_cells[pick(rng)];
    int b = free_cells[pick(rng)];
    for (int tries = 0; tries < 2000 && !apart_ok(a, b); ++tries) b = free_cells[pick(rng)];
    // Two in three pairs within one component (the interesting case).
    if (n % 3 != 2) {
      for (int tries = 0; tries < 2000 && (raster.component[b] != raster.component[a] || !apart_ok(a, b)); ++tries) {
        b = free_cells[pick(rng)];
      }
    }
    const Vec2 s = raster.centre(a % raster.w, a / raster.w), g = raster.centre(b % raster.w, b / raster.w);
    if ((g - s).norm() < 1.0) continue;
    const bool joined = raster.component[a] == raster.component[b];
    connected += joined;
    SCOPED_TRACE(::testing::Message() << c.file << " depth " << c.depth << " pair " << n << " from (" << s.x() << ", "
                                      << s.y() << ") to (" << g.x() << ", " << g.y() << ")");
    try {
      const SingleQueryPlan plan = plan_single_query(no_go.obstacles, {s, g, false}, po);
      if (!plan.outcome.result.found) {
        EXPECT_FALSE(joined) << "refused while the raster connects: " << plan.outcome.result.message;
        refused_disconnected += !joined;
        continue;
      }
      ++routes;
      EXPECT_TRUE(plan.outcome.check.safe) << plan.outcome.check.describe();
      const int bad = check.first_bad_leg(plan.outcome.result.route.points);
      EXPECT_EQ(bad, -1) << (bad >= 0 ? check.why(plan.outcome.result.route.points, bad) : std::string());
    } catch (const NoRouteError& e) {
      ADD_FAILURE() << "start or goal refused in a free raster cell: " << e.what();
    }
  }
  EXPECT_GT(connected, pairs / 2);
  EXPECT_GE(routes, connected);
  std::printf("%s at %.0f m: %d pairs, %d connected, %d routes, %d refused (raster disconnected)\n", c.file, c.depth,
              pairs, connected, routes, refused_disconnected);
}

TEST(EncRoutes, ChesapeakeAt3mIndependentlyChecked) { run_case({"noaa-enc-US4MD81M/US4MD81M.000", 1.0, 25.0}, 1); }
TEST(EncRoutes, ChesapeakeAt7mIndependentlyChecked) { run_case({"noaa-enc-US4MD81M/US4MD81M.000", 5.0, 25.0}, 2); }
TEST(EncRoutes, ChesapeakeAt10mIndependentlyChecked) { run_case({"noaa-enc-US4MD81M/US4MD81M.000", 8.0, 25.0}, 3); }
TEST(EncRoutes, KeyWestAt5mIndependentlyChecked) { run_case({"noaa-enc-US5FL4DQ/US5FL4DQ.000", 3.0, 10.0}, 4); }

// The 11-cell Kachemak exchange set (bands 3 to 5): transits 20 to 150 km,
// the better scale winning where coverages overlap (read_own_set). A query
// across the set takes seconds: DEEPGUIDE_KACHEMAK_PAIRS per depth (default
// 2; scripts/enc_routes.sh runs more), none under the sanitizers (a minute
// a query there; the Release build runs them).
int kachemak_pairs() {
  const char* env = std::getenv("DEEPGUIDE_KACHEMAK_PAIRS");
  return env != nullptr ? std::max(1, std::atoi(env)) : 2;
}
void run_kachemak(double depth, unsigned seed) {
#ifdef DEEPGUIDE_SANITIZED
  GTEST_SKIP() << "Kachemak transits run in the Release build";
#endif
  run_case({"noaa-enc-kachemak", depth, 50.0, 20.0, 150.0, kachemak_pairs()}, seed);
}
TEST(EncRoutes, KachemakAt5mIndependentlyChecked) { run_kachemak(3.0, 5); }
TEST(EncRoutes, KachemakAt7mIndependentlyChecked) { run_kachemak(5.0, 6); }
TEST(EncRoutes, KachemakAt12mIndependentlyChecked) { run_kachemak(10.0, 7); }

}  // namespace
}  // namespace deepguide
