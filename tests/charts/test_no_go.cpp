// The no-go model: hand-made GeoTIFFs with hand-derived areas and outlines,
// then an independent cell-by-cell check (the test reads the raster itself
// with GDAL and transforms each no-go cell's centre and corners with its own
// OSR transformation) on synthetic and real rasters, plus the promises of the
// simplification: it covers the exact outline and stays within the tolerance.

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <boost/geometry.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <vector>

#include "deepguide/charts/no_go.hpp"
#include "deepguide/charts/no_go_export.hpp"
#include "deepguide/core/error.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

namespace bg = boost::geometry;
namespace fs = std::filesystem;

constexpr double kX0 = 500000, kY0 = 6000000, kCell = 10;  // UTM 32N, 10 m cells, north-up

using test::expect_one_line_error;

// Writes a Float32 GeoTIFF of DEPTHS (rows from north), 10 m cells at (kX0, kY0), EPSG:32632.
void write_depths(const std::string& path, int w, int h, const std::vector<double>& depth,
                  std::optional<double> nodata = std::nullopt, const char* crs = "EPSG:32632") {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
  GDALDatasetUniquePtr ds(drv->Create(path.c_str(), w, h, 1, GDT_Float32, nullptr));
  ASSERT_TRUE(ds);
  double gt[6] = {kX0, kCell, 0, kY0, 0, -kCell};
  ds->SetGeoTransform(gt);
  if (crs != nullptr && *crs != 0) {
    OGRSpatialReference srs;
    srs.SetFromUserInput(crs);
    ds->SetSpatialRef(&srs);
  }
  GDALRasterBand* band = ds->GetRasterBand(1);
  band->SetDescription("depth");
  if (nodata) band->SetNoDataValue(*nodata);
  std::vector<float> v(depth.begin(), depth.end());
  ASSERT_EQ(band->RasterIO(GF_Write, 0, 0, w, h, v.data(), w, h, GDT_Float32, 0, 0, nullptr), CE_None);
}

NoGoOptions at(double depth, double clearance, double tol) {
  NoGoOptions o;
  o.operating_depth_m = depth;
  o.vertical_clearance_m = clearance;
  o.simplify_tolerance_m = tol;
  return o;
}

BgMultiPolygon as_multi(const NoGoArea& a) {
  BgMultiPolygon mp;
  for (const auto& p : a.polygons) mp.push_back(p.footprint);
  return mp;
}

LocalFrame utm32() { return LocalFrame::from_user_crs("EPSG:32632"); }

// The independent check: every no-go cell of the raster (read here with GDAL,
// the rule applied here) has its centre and four corners inside the polygons.
// `to_depth` is the file's sign convention as the test knows it (+1: depth,
// -1: elevation). Returns the number of no-go cells it found.
std::size_t check_every_cell(const std::string& path, const LocalFrame& frame, const NoGoOptions& o,
                             const NoGoArea& area, double to_depth = 1.0, const std::string& assumed_crs = "") {
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  EXPECT_TRUE(ds);
  if (!ds) return 0;
  GDALRasterBand* band = ds->GetRasterBand(1);
  const int w = ds->GetRasterXSize(), h = ds->GetRasterYSize();
  std::vector<double> v(static_cast<std::size_t>(w) * h);
  EXPECT_EQ(band->RasterIO(GF_Read, 0, 0, w, h, v.data(), w, h, GDT_Float64, 0, 0, nullptr), CE_None);
  int has_nd = 0;
  const double nd = band->GetNoDataValue(&has_nd);
  double gt[6];
  ds->GetGeoTransform(gt);
  OGRSpatialReference src, dst;
  if (ds->GetSpatialRef() != nullptr && !ds->GetSpatialRef()->IsEmpty()) {
    src = *ds->GetSpatialRef();
  } else if (!assumed_crs.empty()) {
    src.SetFromUserInput(assumed_crs.c_str());
  } else {
    src.SetWellKnownGeogCS("WGS84");  // netCDF lon/lat axes
  }
  src.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  dst.importFromWkt(frame.wkt().c_str());
  dst.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&src, &dst));
  EXPECT_TRUE(ct);
  const double limit = o.operating_depth_m + o.vertical_clearance_m;

  const BgMultiPolygon mp = as_multi(area);
  std::size_t cells = 0, misses = 0;
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const double z = v[static_cast<std::size_t>(r) * w + c];
      const bool nodata = std::isnan(z) || (has_nd && static_cast<float>(z) == static_cast<float>(nd));
      const double d = z * to_depth;
      const bool no_go = nodata ? o.nodata_is_no_go : (d <= 0 || d < limit);
      if (!no_go) continue;
      ++cells;
      const double px[5] = {c + 0.5, c + 0.0, c + 1.0, c + 1.0, c + 0.0};
      const double py[5] = {r + 0.5, r + 0.0, r + 0.0, r + 1.0, r + 1.0};
      double x[5], y[5];
      for (int i = 0; i < 5; ++i) {
        x[i] = gt[0] + px[i] * gt[1];
        y[i] = gt[3] + py[i] * gt[5];
      }
      EXPECT_TRUE(ct->Transform(5, x, y));
      for (int i = 0; i < 5; ++i) {
        const BgPoint pt(x[i], y[i]);
        // Corners lie on the exact outline: allow the last bits of PROJ's arithmetic.
        if (!bg::covered_by(pt, mp) && bg::distance(pt, mp) > 1e-6) {
          if (++misses <= 5)
            ADD_FAILURE() << "no-go cell (col " << c << ", row " << r << ") point " << i << " at " << bg::wkt(pt)
                          << " lies outside the no-go polygons";
        }
      }
    }
  }
  EXPECT_EQ(misses, 0u);
  EXPECT_EQ(cells, area.no_go_cells);
  return cells;
}

// The simplified polygons cover the exact ones and lie within `tol` of them;
// the polygons returned are disjoint.
void check_simplified(const NoGoArea& exact, const NoGoArea& simple, double tol) {
  const BgMultiPolygon e = as_multi(exact), s = as_multi(simple);
  BgMultiPolygon lost;
  bg::difference(e, s, lost);
  EXPECT_LE(bg::area(lost), 1e-6) << "simplification removed no-go area";
  EXPECT_GE(bg::area(s), bg::area(e) - 1e-6);
  double worst = 0;
  for (const auto& p : s) {
    bg::for_each_point(p, [&](const BgPoint& pt) { worst = std::max(worst, bg::distance(pt, e)); });
  }
  EXPECT_LE(worst, tol + 1e-6) << "a simplified vertex lies beyond the tolerance";
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      if (!bg::intersects(bg::return_envelope<BgBox>(s[i]), bg::return_envelope<BgBox>(s[j]))) continue;
      BgMultiPolygon both;
      bg::intersection(s[i], s[j], both);
      EXPECT_LE(bg::area(both), 1e-6) << "polygons " << i << " and " << j << " overlap";
    }
  }
  EXPECT_LE(simple.vertices_after_simplify, simple.vertices_before_simplify + 4 * simple.polygons.size())
      << "simplification should not add many vertices";
}

// ---------------------------------------------------------------- hand-made rasters

TEST(NoGo, SingleShallowCellIsOneSquare) {
  test::ScratchDir dir;
  const std::string path = dir.file("one.tif");
  std::vector<double> d(25, 50.0);
  d[2 * 5 + 3] = 5.0;  // row 2, column 3
  write_depths(path, 5, 5, d);
  const NoGoArea a = compute_no_go(path, utm32(), at(10, 2, 0));
  EXPECT_EQ(a.total_cells, 25u);
  EXPECT_EQ(a.no_go_cells, 1u);
  ASSERT_EQ(a.polygons.size(), 1u);
  EXPECT_EQ(a.polygons[0].id, "nogo/1");
  EXPECT_FALSE(a.polygons[0].height_m);  // the whole water column
  EXPECT_DOUBLE_EQ(a.area_m2, 100.0);
  EXPECT_DOUBLE_EQ(a.cell_area_m2, 100.0);
  EXPECT_EQ(a.vertices_before_simplify, 4u);
  EXPECT_EQ(a.vertices_after_simplify, 4u);
  const BgBox box = bg::return_envelope<BgBox>(a.polygons[0].footprint);
  EXPECT_DOUBLE_EQ(box.min_corner().x(), kX0 + 30);
  EXPECT_DOUBLE_EQ(box.max_corner().x(), kX0 + 40);
  EXPECT_DOUBLE_EQ(box.min_corner().y(), kY0 - 30);
  EXPECT_DOUBLE_EQ(box.max_corner().y(), kY0 - 20);
  EXPECT_TRUE(bg::is_valid(a.polygons[0].footprint));

  // Simplified: grows, but by at most the tolerance (5 m) on every side.
  const NoGoArea s = compute_no_go(path, utm32(), at(10, 2, 5));
  ASSERT_EQ(s.polygons.size(), 1u);
  EXPECT_GT(s.area_m2, 100.0);
  EXPECT_LT(s.area_m2, 20.0 * 20.0);
  check_simplified(a, s, 5.0);
  check_every_cell(path, utm32(), at(10, 2, 5), s);
}

TEST(NoGo, LShape) {
  test::ScratchDir dir;
  const std::string path = dir.file("l.tif");
  std::vector<double> d(36, 40.0);
  for (int r : {1, 2, 3}) d[r * 6 + 1] = 3.0;  // the stem, column 1
  d[3 * 6 + 2] = 3.0;                          // the foot
  d[3 * 6 + 3] = 3.0;
  write_depths(path, 6, 6, d);
  const NoGoArea a = compute_no_go(path, utm32(), at(10, 2, 0));
  EXPECT_EQ(a.no_go_cells, 5u);
  ASSERT_EQ(a.polygons.size(), 1u);
  EXPECT_DOUBLE_EQ(a.area_m2, 500.0);
  EXPECT_EQ(a.vertices_before_simplify, 6u);  // an L has six corners
  EXPECT_EQ(a.vertices_after_simplify, 6u);
  check_every_cell(path, utm32(), at(10, 2, 0), a);
  for (double tol : {1.0, 5.0, 12.0}) {
    const NoGoArea s = compute_no_go(path, utm32(), at(10, 2, tol));
    check_simplified(a, s, tol);
    check_every_cell(path, utm32(), at(10, 2, tol), s);
  }
}

TEST(NoGo, RingKeepsItsDeepHole) {
  test::ScratchDir dir;
  const std::string path = dir.file("ring.tif");
  std::vector<double> d(49, 60.0);
  for (int r = 1; r <= 5; ++r)
    for (int c = 1; c <= 5; ++c) d[r * 7 + c] = 8.0;  // a 5x5 shoal ...
  for (int r = 2; r <= 4; ++r)
    for (int c = 2; c <= 4; ++c) d[r * 7 + c] = 60.0;  // ... around a 3x3 deep pocket
  write_depths(path, 7, 7, d);
  const NoGoArea a = compute_no_go(path, utm32(), at(10, 2, 0));
  EXPECT_EQ(a.no_go_cells, 16u);
  ASSERT_EQ(a.polygons.size(), 1u);
  ASSERT_EQ(a.polygons[0].footprint.inners().size(), 1u);
  EXPECT_DOUBLE_EQ(a.area_m2, 1600.0);
  EXPECT_EQ(a.vertices_before_simplify, 8u);
  const BgPoint pocket(kX0 + 35, kY0 - 35);  // centre of the pocket
  EXPECT_FALSE(bg::covered_by(pocket, a.polygons[0].footprint));
  check_every_cell(path, utm32(), at(10, 2, 0), a);

  // 5 m tolerance: the 30 m pocket shrinks by at most 5 m a side and stays open.
  const NoGoArea s = compute_no_go(path, utm32(), at(10, 2, 5));
  ASSERT_EQ(s.polygons.size(), 1u);
  ASSERT_EQ(s.polygons[0].footprint.inners().size(), 1u);
  EXPECT_FALSE(bg::covered_by(pocket, s.polygons[0].footprint));
  const double hole = std::abs(bg::area(s.polygons[0].footprint.inners()[0]));
  EXPECT_LT(hole, 900.0);
  EXPECT_GT(hole, 20.0 * 20.0);
  check_simplified(a, s, 5.0);
  check_every_cell(path, utm32(), at(10, 2, 5), s);
}

TEST(NoGo, LandAndNoData) {
  test::ScratchDir dir;
  const std::string path = dir.file("land.tif");
  // Row 0: land (-3), the waterline (0), a hair of water (0.5), NoData, water (30).
  std::vector<double> d(5 * 3, 30.0);
  d[0] = -3.0;
  d[1] = 0.0;
  d[2] = 0.5;
  d[3] = -9999.0;
  write_depths(path, 5, 3, d, -9999.0);
  // At the surface with no clearance only land and the waterline are no-go (and NoData).
  NoGoOptions o = at(0, 0, 0);
  const NoGoArea a = compute_no_go(path, utm32(), o);
  EXPECT_EQ(a.no_go_cells, 3u);
  ASSERT_EQ(a.polygons.size(), 2u);  // columns 0-1, and column 3 on its own
  EXPECT_DOUBLE_EQ(a.area_m2, 300.0);
  check_every_cell(path, utm32(), o, a);
  o.nodata_is_no_go = false;
  const NoGoArea b = compute_no_go(path, utm32(), o);
  EXPECT_EQ(b.no_go_cells, 2u);
  ASSERT_EQ(b.polygons.size(), 1u);
  EXPECT_DOUBLE_EQ(b.area_m2, 200.0);
  check_every_cell(path, utm32(), o, b);
  // Deeper: the 0.5 m cell joins (0.5 < 1 + 0), water at 30 m stays free.
  const NoGoArea c = compute_no_go(path, utm32(), at(1, 0, 0));
  EXPECT_EQ(c.no_go_cells, 4u);
  EXPECT_DOUBLE_EQ(c.area_m2, 400.0);
}

TEST(NoGo, DepthExactlyAtTheThresholdIsFree) {
  test::ScratchDir dir;
  const std::string path = dir.file("edge.tif");
  // 12 m of water: at 10 m with 2 m clearance the vehicle keeps exactly 2 m.
  std::vector<double> d = {12.0, 11.999, 12.001, 12.0};
  write_depths(path, 4, 1, d);
  const NoGoArea a = compute_no_go(path, utm32(), at(10, 2, 0));
  EXPECT_EQ(a.no_go_cells, 1u);
  ASSERT_EQ(a.polygons.size(), 1u);
  const BgBox box = bg::return_envelope<BgBox>(a.polygons[0].footprint);
  EXPECT_DOUBLE_EQ(box.min_corner().x(), kX0 + 10);  // the 11.999 m cell only
  EXPECT_DOUBLE_EQ(box.max_corner().x(), kX0 + 20);
  // A hair deeper and every cell but the deepest is no-go.
  EXPECT_EQ(compute_no_go(path, utm32(), at(10.0005, 2, 0)).no_go_cells, 3u);
}

TEST(NoGo, NearbyShoalsMergeIntoDisjointPolygons) {
  test::ScratchDir dir;
  const std::string path = dir.file("two.tif");
  std::vector<double> d(8 * 3, 50.0);
  d[1 * 8 + 2] = 4.0;  // two one-cell shoals 10 m apart
  d[1 * 8 + 4] = 4.0;
  write_depths(path, 8, 3, d);
  const NoGoArea exact = compute_no_go(path, utm32(), at(10, 2, 0));
  EXPECT_EQ(exact.polygons.size(), 2u);
  EXPECT_EQ(compute_no_go(path, utm32(), at(10, 2, 5)).polygons.size(), 2u);  // grow 2.5 m each: still apart
  const NoGoArea merged = compute_no_go(path, utm32(), at(10, 2, 30));
  EXPECT_EQ(merged.polygons.size(), 1u);  // grow 15 m each: one obstacle
  check_simplified(exact, merged, 30.0);
}

// A seabed with shoals, a channel and an island, 10 m cells; the windowed scan
// (one block per window) must give what the default windows give.
std::vector<double> synthetic_seabed(int w, int h) {
  std::vector<double> d(static_cast<std::size_t>(w) * h);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const double x = c / 7.0, y = r / 5.0;
      double z = 25 + 12 * std::sin(x) * std::cos(y) + 6 * std::sin(0.37 * c + 0.21 * r);
      const double ix = c - 0.7 * w, iy = r - 0.3 * h;
      z -= 40 * std::exp(-(ix * ix + iy * iy) / 30.0);  // an island
      d[static_cast<std::size_t>(r) * w + c] = z;
    }
  }
  return d;
}

TEST(NoGo, SyntheticSeabedCellByCell) {
  test::ScratchDir dir;
  const std::string path = dir.file("seabed.tif");
  const int w = 90, h = 70;
  write_depths(path, w, h, synthetic_seabed(w, h));
  NoGoOptions o = at(18, 2, 0);
  o.bathymetry.sense = VerticalSense::depth;
  const NoGoArea exact = compute_no_go(path, utm32(), o);
  EXPECT_GT(exact.no_go_cells, 600u);
  EXPECT_LT(exact.no_go_cells, static_cast<std::size_t>(w * h) - 600u);
  EXPECT_GT(exact.polygons.size(), 3u);
  EXPECT_NEAR(exact.area_m2, exact.no_go_cells * 100.0, 1e-6);  // exact outlines: area of the cells
  check_every_cell(path, utm32(), o, exact);

  o.bathymetry.max_window_cells = 1;  // one block per window
  const NoGoArea small_windows = compute_no_go(path, utm32(), o);
  EXPECT_EQ(small_windows.no_go_cells, exact.no_go_cells);
  EXPECT_EQ(small_windows.polygons.size(), exact.polygons.size());
  EXPECT_DOUBLE_EQ(small_windows.area_m2, exact.area_m2);

  for (double tol : {2.0, 5.0, 25.0}) {
    SCOPED_TRACE(tol);
    NoGoOptions s = o;
    s.simplify_tolerance_m = tol;
    const NoGoArea simple = compute_no_go(path, utm32(), s);
    EXPECT_EQ(simple.vertices_before_simplify, exact.vertices_before_simplify);
    // Below the cell size the 10 m stairs stay (DP cannot cut them without
    // leaving the tolerance); above it they go.
    if (tol > 10) {
      EXPECT_LT(simple.vertices_after_simplify, exact.vertices_after_simplify / 2);
    }
    check_simplified(exact, simple, tol);
    check_every_cell(path, utm32(), s, simple);
  }
}

TEST(NoGo, LocalFrameOfARasterIsItsUtmZone) {
  test::ScratchDir dir;
  const std::string path = dir.file("f.tif");
  write_depths(path, 3, 3, std::vector<double>(9, 20.0));
  EXPECT_EQ(raster_local_frame(path).id(), "EPSG:32632");
}

// ---------------------------------------------------------------- real rasters

TEST(NoGoReal, SmallCrmLonLatCellByCell) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, "bathy-usml-crm/small_crm.asc");
  BathymetryOptions b;
  b.assumed_crs = "EPSG:4326";  // no .prj (SOURCES.md)
  const LocalFrame frame = raster_local_frame(path, b);
  EXPECT_EQ(frame.id(), "EPSG:32617");  // -79.8 E: UTM 17N
  // Depths 622..771 m: 690 m and 740 m cut through the slope.
  for (double depth : {690.0, 740.0}) {
    SCOPED_TRACE(depth);
    NoGoOptions o = at(depth, 10, 0);
    o.bathymetry = b;
    const NoGoArea exact = compute_no_go(path, frame, o);
    EXPECT_GT(exact.no_go_cells, 2000u);
    EXPECT_LT(exact.no_go_cells, 241u * 241u - 2000u);
    // 3" cells at 29.5 N: about 80.6 m x 92.4 m.
    EXPECT_NEAR(exact.cell_area_m2, 80.6 * 92.4, 80.0);
    EXPECT_NEAR(exact.area_m2 / exact.no_go_cells, exact.cell_area_m2, 0.01 * exact.cell_area_m2);
    check_every_cell(path, frame, o, exact, -1.0, "EPSG:4326");
    o.simplify_tolerance_m = 20;
    const NoGoArea simple = compute_no_go(path, frame, o);
    check_simplified(exact, simple, 20.0);
    check_every_cell(path, frame, o, simple, -1.0, "EPSG:4326");
  }
}

TEST(NoGoReal, AzoresIslandsAreNoGo) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, "bathy-gmt-cache/bathy_1m.nc");
  BathymetryOptions b;
  b.assumed_crs = "EPSG:4326";  // plain x/y axes without units (SOURCES.md, test_bathymetry)
  const LocalFrame frame = raster_local_frame(path, b);
  EXPECT_EQ(frame.id(), "EPSG:32626");  // centre -28 E
  // -5158 .. +1117 m: at 500 m islands and their shelves are no-go, NaN cells too.
  NoGoOptions o = at(500, 10, 0);
  o.bathymetry = b;
  const NoGoArea exact = compute_no_go(path, frame, o);
  EXPECT_GT(exact.no_go_cells, 500u);
  EXPECT_GT(exact.polygons.size(), 5u);
  check_every_cell(path, frame, o, exact, -1.0, "EPSG:4326");
  o.simplify_tolerance_m = 100;
  const NoGoArea simple = compute_no_go(path, frame, o);
  check_simplified(exact, simple, 100.0);
  check_every_cell(path, frame, o, simple, -1.0, "EPSG:4326");
}

// ---------------------------------------------------------------- the sample chart

TEST(NoGoSample, SampleChartCellByCell) {
  const std::string path = test::source_file("charts/sample_chart.tif");
  if (!fs::is_regular_file(path)) GTEST_SKIP() << "charts/sample_chart.tif is absent (deepguide chart synth makes it)";
  const LocalFrame frame = raster_local_frame(path);
  EXPECT_EQ(frame.id(), "EPSG:32632");
  // Elevation; crests of 6-8 m, a 12 m channel, 20-28 m offshore, land, a NoData corner.
  for (double depth : {5.0, 10.0}) {
    SCOPED_TRACE(depth);
    NoGoOptions o = at(depth, 2, 0);
    const NoGoArea exact = compute_no_go(path, frame, o);
    EXPECT_GT(exact.no_go_cells, 1000u);
    EXPECT_LT(exact.no_go_cells, exact.total_cells - 1000u);
    EXPECT_NEAR(exact.area_m2, exact.no_go_cells * 25.0, 1e-6);  // 5 m cells, same CRS as the frame
    check_every_cell(path, frame, o, exact, -1.0);
    o.simplify_tolerance_m = 5;
    const NoGoArea simple = compute_no_go(path, frame, o);
    check_simplified(exact, simple, 5.0);
    check_every_cell(path, frame, o, simple, -1.0);
  }
}

// ---------------------------------------------------------------- bad input

TEST(NoGoErrors, BadOptions) {
  test::ScratchDir dir;
  const std::string path = dir.file("ok.tif");
  write_depths(path, 3, 3, std::vector<double>(9, 20.0));
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  expect_one_line_error([&] { compute_no_go(path, utm32(), NoGoOptions{}); }, "operating_depth_m");  // unset
  expect_one_line_error([&] { compute_no_go(path, utm32(), at(nan, 2, 5)); }, "'operating_depth_m': expected a finite");
  expect_one_line_error([&] { compute_no_go(path, utm32(), at(-1, 2, 5)); }, "got -1");
  expect_one_line_error([&] { compute_no_go(path, utm32(), at(10, -0.5, 5)); }, "vertical_clearance_m");
  expect_one_line_error([&] { compute_no_go(path, utm32(), at(10, inf, 5)); }, "got inf");
  expect_one_line_error([&] { compute_no_go(path, utm32(), at(10, 2, -5)); }, "simplify_tolerance_m");
  expect_one_line_error([&] { compute_no_go(path, utm32(), at(10, 2, nan)); }, "simplify_tolerance_m");
}

TEST(NoGoErrors, UnreadableRasters) {
  test::ScratchDir dir;
  expect_one_line_error([&] { compute_no_go(dir.file("missing.tif"), utm32(), at(10, 2, 5)); },
                        "expected an existing bathymetry raster");
  const std::string text = dir.write("notes.tif", "not a raster\n");
  expect_one_line_error([&] { compute_no_go(text, utm32(), at(10, 2, 5)); }, "expected a raster GDAL can open");

  const std::string good = dir.file("good.tif");
  write_depths(good, 64, 64, std::vector<double>(64 * 64, 5.0));
  std::ifstream in(good, std::ios::binary);
  std::string head(200, '\0');
  in.read(head.data(), 200);
  std::string garbage(300, '\0');
  for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<char>((i * 37 + 11) & 0xff);
  const std::string bad = dir.write("corrupt.tif", head + garbage);
  expect_one_line_error([&] { compute_no_go(bad, utm32(), at(10, 2, 5)); }, bad + ": expected a raster GDAL can");

  const std::string nocrs = dir.file("nocrs.tif");
  write_depths(nocrs, 4, 4, std::vector<double>(16, 5.0), std::nullopt, "");
  expect_one_line_error([&] { compute_no_go(nocrs, utm32(), at(10, 2, 5)); }, "expected a raster with a CRS");
  NoGoOptions o = at(10, 2, 0);
  o.bathymetry.assumed_crs = "EPSG:32632";
  EXPECT_EQ(compute_no_go(nocrs, utm32(), o).no_go_cells, 16u);
}

// ---------------------------------------------------------------- library call

// A 7 x 7 raster of 10 m cells: a 5 x 5 shoal (8 m) with a deep middle cell,
// in deep water (60 m).
void write_shoal_ring(const std::string& path) {
  std::vector<double> d(49, 60.0);
  for (int r = 1; r <= 5; ++r)
    for (int c = 1; c <= 5; ++c) d[r * 7 + c] = (r == 3 && c == 3) ? 60.0 : 8.0;
  write_depths(path, 7, 7, d);
}

TEST(NoGoExport, ReportsTheRingInTextAndJsonFromOneReport) {
  test::ScratchDir dir;
  // At 10 m depth the 24 shoal cells of the ring are no-go:
  // 24 of 49 cells (49.0 %), 100 m2 each, one polygon of 2400 m2 (with a hole).
  const std::string path = dir.file("ring.tif");
  write_shoal_ring(path);
  NoGoExportRequest request;
  request.charts = {path};
  request.output = dir.file("nogo.geojson");
  request.nogo = at(10, 2, 0);
  const NoGoExportReport report = export_no_go(request);
  EXPECT_FALSE(report.from_cells);
  const nlohmann::json j = report.to_json();
  EXPECT_EQ(j["no_go_cells"], 24);
  EXPECT_EQ(j["total_cells"], 49);
  EXPECT_EQ(j["polygons"], 1);
  EXPECT_DOUBLE_EQ(j["area_m2"].get<double>(), 2400.0);
  const std::string text = report.to_text();
  EXPECT_NE(text.find("no-go cells      24 of 49 (49.0%), 100.0 m2 each\n"), std::string::npos) << text;
  EXPECT_NE(text.find("polygons         1, area 2400.0 m2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("wrote            " + request.output + "\n"), std::string::npos) << text;
  EXPECT_TRUE(fs::exists(request.output));

  // A bad extension is refused before any work, and nothing is written.
  request.output = dir.file("nogo.txt");
  expect_one_line_error([&] { export_no_go(request); }, "nogo.txt");
  EXPECT_FALSE(fs::exists(request.output));
}

TEST(NoGoExport, CellsReportTheirClassesAndFrame) {
  test::ScratchDir dir;
  NoGoExportRequest request;
  request.charts = {test::real_file("noaa-enc-US5FL4DQ/US5FL4DQ.000")};
  request.output = dir.file("enc.gpkg");
  request.nogo.operating_depth_m = 3.0;
  const NoGoExportReport report = export_no_go(request);
  ASSERT_TRUE(report.from_cells);
  const nlohmann::json j = report.to_json();
  EXPECT_EQ(j["local_crs"], "EPSG:32617");
  EXPECT_DOUBLE_EQ(j["required_depth_m"].get<double>(), 5.0);  // 3 m operating + 2 m clearance
  EXPECT_GT(j["no_go_by_class"]["DEPARE"].get<int>(), 0);
  EXPECT_EQ(j["cells"][0]["name"], "US5FL4DQ");
  const std::string text = report.to_text();
  EXPECT_EQ(text.rfind("cell             US5FL4DQ  1:", 0), 0u) << text;
  EXPECT_NE(text.find("planners         " + std::to_string(report.polygons) + " polygon(s) with " +
                      std::to_string(report.vertices) + " corners"),
            std::string::npos)
      << text;
  EXPECT_TRUE(fs::exists(request.output));
}

// ---------------------------------------------------------------- CLI

TEST(NoGoCli, WritesObstaclePolygons) {
  test::ScratchDir dir;
  const std::string path = dir.file("ring.tif");
  write_shoal_ring(path);
  const std::string out = dir.file("nogo.geojson");
  const auto r = test::run_cli("chart nogo '" + path + "' --depth 10 --tolerance 0 -o '" + out + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"no_go_cells\": 24"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"area_m2\": 2400"), std::string::npos) << r.out;
  ASSERT_TRUE(fs::exists(out));
  GDALDatasetUniquePtr ds(GDALDataset::Open(out.c_str(), GDAL_OF_VECTOR));
  ASSERT_TRUE(ds);
  EXPECT_EQ(ds->GetLayer(0)->GetFeatureCount(), 1);

  const auto text = test::run_cli("chart nogo '" + path + "' --depth 10 -o '" + dir.file("n.gpkg") + "'");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("no-go cells"), std::string::npos) << text.out;
  EXPECT_TRUE(fs::exists(dir.file("n.gpkg")));

  const auto bad = test::run_cli("chart nogo '" + path + "' --depth -3 -o '" + dir.file("x.geojson") + "'");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("operating_depth_m"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir.file("x.geojson")));
  const auto missing = test::run_cli("chart nogo '" + dir.file("none.tif") + "' --depth 5 -o '" + out + "'");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(test::run_cli("chart nogo '" + path + "' -o '" + out + "'").exit_code, 2);  // --depth is required
}

}  // namespace
}  // namespace deepguide
