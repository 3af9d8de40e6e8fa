// The sea floor for planning in depth (world/sea_floor.hpp): bilinear depth
// against hand values, the pyramid's range against dense sampling, the exact
// lowest gap along a segment, the raster reader never deeper than the chart
// (the sample chart, and a pinnacle narrower than a node spacing), and bad input.
#include <gtest/gtest.h>

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "deepguide/charts/raster_sea_floor.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/world/local_frame.hpp"
#include "deepguide/world/sea_floor.hpp"
#include "test_support.hpp"

using namespace deepguide;

namespace {

// A bumpy floor on 40 x 30 nodes 5 m apart: 60 m deep, waves of +-15 m.
SeaFloor bumpy() {
  std::vector<double> d;
  for (int j = 0; j < 30; ++j) {
    for (int i = 0; i < 40; ++i)
      d.push_back(60.0 + 15.0 * std::sin(0.7 * i) * std::cos(0.45 * j) + 0.3 * ((i * 7 + j * 3) % 5));
  }
  return SeaFloor({100.0, 200.0}, 5.0, 40, 30, d);
}

}  // namespace

TEST(SeaFloor, BilinearDepthMatchesHandValues) {
  // Nodes 10 m apart: 10 20 / 30 60 (row j = 0 first).
  const SeaFloor floor({0.0, 0.0}, 10.0, 2, 2, {10.0, 20.0, 30.0, 60.0});
  EXPECT_DOUBLE_EQ(floor.depth_at({0.0, 0.0}), 10.0);
  EXPECT_DOUBLE_EQ(floor.depth_at({10.0, 10.0}), 60.0);
  EXPECT_DOUBLE_EQ(floor.depth_at({5.0, 5.0}), 30.0);  // the mean of the four
  EXPECT_DOUBLE_EQ(floor.depth_at({2.5, 0.0}), 12.5);
  EXPECT_DOUBLE_EQ(floor.depth_at({10.0, 5.0}), 40.0);
  EXPECT_DOUBLE_EQ(floor.depth_at({-0.1, 5.0}), 0.0);  // outside: no water to dive in
  EXPECT_DOUBLE_EQ(floor.max_depth(), 60.0);
  EXPECT_DOUBLE_EQ(floor.min_depth(), 10.0);
  const auto [lo, hi] = floor.depth_range({1.0, 1.0}, {9.0, 9.0});
  EXPECT_DOUBLE_EQ(lo, 10.0);
  EXPECT_DOUBLE_EQ(hi, 60.0);
  // No data is depth 0.
  const SeaFloor holes({0.0, 0.0}, 10.0, 2, 2, {10.0, std::nan(""), 30.0, 60.0});
  EXPECT_DOUBLE_EQ(holes.depth_at({10.0, 0.0}), 0.0);
  EXPECT_DOUBLE_EQ(holes.min_depth(), 0.0);
}

TEST(SeaFloor, RangeHoldsEverySampledDepth) {
  const SeaFloor floor = bumpy();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 300; ++k) {
    const Vec2 a(90.0 + 220.0 * u(rng), 190.0 + 160.0 * u(rng));
    const Vec2 b = a + Vec2(1.0 + 120.0 * u(rng) * u(rng), 1.0 + 90.0 * u(rng) * u(rng));
    const auto [lo, hi] = floor.depth_range(a, b);
    double seen_lo = std::numeric_limits<double>::infinity(), seen_hi = -seen_lo;
    for (int s = 0; s <= 40; ++s) {
      for (int t = 0; t <= 40; ++t) {
        const double d = floor.depth_at(a + Vec2((b - a).x() * s / 40.0, (b - a).y() * t / 40.0));
        seen_lo = std::min(seen_lo, d);
        seen_hi = std::max(seen_hi, d);
      }
    }
    ASSERT_LE(lo, seen_lo) << k;
    ASSERT_GE(hi, seen_hi) << k;
  }
  // Inside one grid cell the range is its four corners.
  const auto [lo, hi] = floor.depth_range({111.0, 211.0}, {114.0, 214.0});
  double corners_lo = 1e9, corners_hi = -1e9;
  for (double x : {110.0, 115.0}) {
    for (double y : {210.0, 215.0}) {
      corners_lo = std::min(corners_lo, floor.depth_at({x, y}));
      corners_hi = std::max(corners_hi, floor.depth_at({x, y}));
    }
  }
  EXPECT_DOUBLE_EQ(lo, corners_lo);
  EXPECT_DOUBLE_EQ(hi, corners_hi);
}

TEST(SeaFloor, LowestGapIsTheExactMinimumAlongTheSegment) {
  // A tilted plane: depth 100 + 0.1 x, a level leg at 50 m: the gap is least at x = 0.
  const SeaFloor plane({0.0, 0.0}, 10.0, 21, 3, [] {
    std::vector<double> d;
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 21; ++i) d.push_back(100.0 + i);
    }
    return d;
  }());
  const SeaFloor::Gap g = plane.lowest_gap({0.0, 10.0, 50.0}, {200.0, 10.0, 50.0});
  EXPECT_NEAR(g.gap_m, 50.0, 1e-12);
  EXPECT_NEAR(g.where.x(), 0.0, 1e-12);
  // Diving at 1 in 5 down the same slope of 1 in 10: least at the far end, 100 + 20 - 90 = 30.
  EXPECT_NEAR(plane.lowest_gap({0.0, 10.0, 50.0}, {200.0, 10.0, 90.0}).gap_m, 30.0, 1e-12);

  // A bumpy floor against 20 000 samples: never above the sampled minimum, and
  // close to it (samples 1.2 cm apart on slopes up to 2.5 miss at most 3 cm).
  const SeaFloor floor = bumpy();
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 100; ++k) {
    const Vec3 a(100.0 + 195.0 * u(rng), 200.0 + 145.0 * u(rng), 30.0 * u(rng));
    const Vec3 b(100.0 + 195.0 * u(rng), 200.0 + 145.0 * u(rng), 30.0 * u(rng));
    double sampled = std::numeric_limits<double>::infinity();
    for (int s = 0; s <= 20000; ++s) {
      const Vec3 p = a + (s / 20000.0) * (b - a);
      sampled = std::min(sampled, floor.depth_at(p.head<2>()) - p.z());
    }
    const SeaFloor::Gap g = floor.lowest_gap(a, b);
    ASSERT_LE(g.gap_m, sampled + 1e-9) << k;
    ASSERT_GE(g.gap_m, sampled - 0.03) << k;
    ASSERT_NEAR(floor.depth_at(g.where.head<2>()) - g.where.z(), g.gap_m, 1e-9);
  }
}

TEST(SeaFloor, FromRasterIsNeverDeeperThanTheChart) {
  // The sample chart (UTM 32N, 5 m cells, elevation) at 8 m nodes, the CLI's
  // default: at every chart cell centre in the area the floor is no deeper
  // than the chart, and no shallower than the shallowest chart cell within
  // three node spacings and a chart cell (how far the conservative rule
  // reaches: a node's neighbours, their cells, the cells they touch).
  const std::string path = std::string(DEEPGUIDE_SOURCE_DIR) + "/charts/sample_chart.tif";
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  const Vec2 lo(580400.0, 6033400.0), hi(581000.0, 6033900.0);
  const double spacing = 8.0;
  const SeaFloor floor = raster_sea_floor(path, frame, lo, hi, spacing);
  GDALAllRegister();
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(ds);
  double gt[6];
  ds->GetGeoTransform(gt);
  const int c0 = static_cast<int>((lo.x() - gt[0]) / gt[1]) - 4, r0 = static_cast<int>((hi.y() - gt[3]) / gt[5]) - 4;
  const int cols = static_cast<int>((hi.x() - lo.x()) / gt[1]) + 8,
            rows = static_cast<int>((hi.y() - lo.y()) / -gt[5]) + 8;
  std::vector<float> chart(static_cast<std::size_t>(cols * rows));
  ASSERT_EQ(
      ds->GetRasterBand(1)->RasterIO(GF_Read, c0, r0, cols, rows, chart.data(), cols, rows, GDT_Float32, 0, 0, nullptr),
      CE_None);
  const auto centre = [&](int c, int r) {
    return Vec2(gt[0] + (c0 + c + 0.5) * gt[1], gt[3] + (r0 + r + 0.5) * gt[5]);
  };
  int checked = 0;
  double widest = 0.0;
  for (int r = 4; r < rows - 4; ++r) {
    for (int c = 4; c < cols - 4; ++c) {
      const Vec2 p = centre(c, r);
      if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
      const double chart_depth = -chart[static_cast<std::size_t>(r * cols + c)];
      ASSERT_LE(floor.depth_at(p), chart_depth + 1e-4) << p.transpose();
      double shallowest = chart_depth;
      const int reach = static_cast<int>(std::ceil((3.0 * spacing + 5.0) / gt[1]));  // in chart cells
      for (int rr = std::max(0, r - reach); rr <= std::min(rows - 1, r + reach); ++rr) {
        for (int cc = std::max(0, c - reach); cc <= std::min(cols - 1, c + reach); ++cc) {
          shallowest = std::min(shallowest, -static_cast<double>(chart[static_cast<std::size_t>(rr * cols + cc)]));
        }
      }
      ASSERT_GE(floor.depth_at(p), shallowest - 1e-4) << p.transpose();
      widest = std::max(widest, chart_depth - floor.depth_at(p));
      ++checked;
    }
  }
  EXPECT_GT(checked, 10000);
  EXPECT_GT(widest, 0.0);  // the rule does make the floor shallower somewhere
}

TEST(SeaFloor, APinnacleNarrowerThanANodeSpacingStays) {
  // A 1 m GeoTIFF 50 m deep with a 3 m x 3 m pinnacle up to 5 m, read at 4 m
  // nodes: a level leg at 20 m over the pinnacle must run into the floor.
  deepguide::test::ScratchDir dir;
  const std::string path = dir.file("pinnacle.tif");
  GDALAllRegister();
  {
    GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
    GDALDatasetUniquePtr ds(gtiff->Create(path.c_str(), 200, 200, 1, GDT_Float32, nullptr));
    double gt[6] = {500000.0, 1.0, 0.0, 6000200.0, 0.0, -1.0};
    ds->SetGeoTransform(gt);
    OGRSpatialReference srs;
    srs.importFromEPSG(32632);
    ds->SetSpatialRef(&srs);
    std::vector<float> v(200 * 200, -50.0f);
    for (int r = 98; r <= 100; ++r) {
      for (int c = 101; c <= 103; ++c) v[static_cast<std::size_t>(r * 200 + c)] = -5.0f;
    }
    ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, 200, 200, v.data(), 200, 200, GDT_Float32, 0, 0, nullptr),
              CE_None);
  }
  const SeaFloor floor = raster_sea_floor(path, LocalFrame::from_user_crs("EPSG:32632"), {500010.0, 6000010.0},
                                          {500190.0, 6000190.0}, 4.0);
  EXPECT_LE(floor.min_depth(), 5.0 + 1e-9);
  EXPECT_LE(floor.depth_at({500102.5, 6000100.5}), 5.0 + 1e-9);
  EXPECT_LT(floor.lowest_gap({500020.0, 6000100.5, 20.0}, {500180.0, 6000100.5, 20.0}).gap_m, 0.0);
  EXPECT_NEAR(floor.depth_at({500030.0, 6000030.0}), 50.0, 1e-9);  // far from it, the chart's depth
}

TEST(SeaFloor, BadInputIsRefusedWithAClearError) {
  EXPECT_THROW(SeaFloor({0.0, 0.0}, 0.0, 2, 2, {1, 2, 3, 4}), InputError);
  EXPECT_THROW(SeaFloor({0.0, 0.0}, 1.0, 1, 4, {1, 2, 3, 4}), InputError);
  EXPECT_THROW(SeaFloor({0.0, 0.0}, 1.0, 2, 2, {1, 2, 3}), InputError);
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  try {
    raster_sea_floor("/nonexistent/floor.tif", frame, {0.0, 0.0}, {10.0, 10.0}, 1.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/floor.tif"), std::string::npos) << e.what();
  }
  // An area the chart does not reach.
  const std::string path = std::string(DEEPGUIDE_SOURCE_DIR) + "/charts/sample_chart.tif";
  try {
    raster_sea_floor(path, frame, {100000.0, 100000.0}, {100100.0, 100100.0}, 5.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not reach"), std::string::npos) << e.what();
  }
}
