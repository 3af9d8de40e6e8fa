// Sea-current fields: the real HYCOM file against the facts in
// ../shared/data/real/SOURCES.md (section 4) and against GDAL's own reading of
// it, synthetic NetCDF and GeoTIFF fields written here through GDAL (linear in
// space and time, so bilinear/linear interpolation must reproduce them), the
// constant current's direction convention, the local-frame sampler against an
// exact per-point transform, coverage, and bad input (one-line errors).

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/utc_time.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/currents/current_sampling.hpp"
#include "deepguide/currents/current_summary.hpp"
#include "nc_writer.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

using test::ScratchDir;
constexpr const char* kHycom = "currents-hycom/hycom_glby_930_2019030712_t003_uv3z.nc";

using test::expect_one_line_error;
using test::NcSpec;
using test::write_attr;
using test::write_nc;

// ---------------------------------------------------------------- writers

// A two-band GeoTIFF in `epsg` with pixel centres at x0 + i*dx, y0 - j*dx.
void write_tiff(const std::string& path, int epsg, double x0, double y0, double dx, int w, int h,
                const std::function<double(double, double)>& u, const std::function<double(double, double)>& v) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
  GDALDatasetUniquePtr ds(drv->Create(path.c_str(), w, h, 2, GDT_Float64, nullptr));
  ASSERT_TRUE(ds);
  double gt[6] = {x0 - dx / 2, dx, 0, y0 + dx / 2, 0, -dx};
  ds->SetGeoTransform(gt);
  OGRSpatialReference srs;
  srs.importFromEPSG(epsg);
  ds->SetSpatialRef(&srs);
  for (int b = 1; b <= 2; ++b) {
    std::vector<double> buf;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const double x = x0 + i * dx, y = y0 - j * dx;
        const double val = b == 1 ? u(x, y) : v(x, y);
        buf.push_back(std::isnan(val) ? -9999.0 : val);
      }
    ds->GetRasterBand(b)->SetNoDataValue(-9999.0);
    ASSERT_EQ(ds->GetRasterBand(b)->RasterIO(GF_Write, 0, 0, w, h, buf.data(), w, h, GDT_Float64, 0, 0, nullptr),
              CE_None);
  }
}

// ---------------------------------------------------------------- real HYCOM

TEST(CurrentReal, HycomMatchesSources) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kHycom);
  const CurrentField f = load_current_field(path);
  EXPECT_EQ(f.driver, "netCDF");
  EXPECT_EQ(f.u_name, "water_u");  // by standard_name, not water_u_bottom
  EXPECT_EQ(f.v_name, "water_v");
  EXPECT_EQ(f.crs, "EPSG:4326");
  EXPECT_TRUE(f.geographic);
  EXPECT_EQ(f.nx(), 18u);
  EXPECT_EQ(f.ny(), 33u);
  // The file's axes carry float32 rounding (e.g. -75.5999755859375), hence 5e-5.
  EXPECT_NEAR(f.extent.west, -75.68, 5e-5);
  EXPECT_NEAR(f.extent.east, -74.32, 5e-5);
  EXPECT_NEAR(f.extent.south, 34.36, 5e-5);
  EXPECT_NEAR(f.extent.north, 35.64, 5e-5);
  EXPECT_NEAR(f.y[1] - f.y[0], 0.04, 5e-5);
  EXPECT_NEAR(f.x[1] - f.x[0], 0.08, 5e-5);
  // time = 168135 h since 2000-01-01 (946684800 s after the epoch).
  ASSERT_EQ(f.times_s.size(), 1u);
  EXPECT_DOUBLE_EQ(f.times_s[0], 946684800.0 + 168135.0 * 3600.0);
  EXPECT_EQ(format_utc(f.times_s[0]), "2019-03-07T15:00:00Z");
  EXPECT_TRUE(f.steady());
  EXPECT_EQ(f.depth_levels, "level 1 of 40 (0.0 m)");

  const CurrentSummary s = summarize_current(f);
  EXPECT_EQ(s.width, 18u);
  EXPECT_EQ(s.height, 33u);
  EXPECT_EQ(s.steps, 1u);
  EXPECT_NEAR(s.u_min, -0.230, 5e-4);
  EXPECT_NEAR(s.u_max, 0.996, 5e-4);
  EXPECT_NEAR(s.v_min, -0.161, 5e-4);
  EXPECT_NEAR(s.v_max, 1.387, 5e-4);
  EXPECT_EQ(s.valid_nodes + s.fill_nodes, 18u * 33u);
  EXPECT_GE(s.max_speed_mps, 1.387 - 5e-4);
  EXPECT_LE(s.max_speed_mps, std::hypot(0.996, 1.387) + 1e-3);
  EXPECT_GE(s.min_speed_mps, 0.0);
  // Fill values (-30000 * 0.001 = -30 m/s) must never show up as a speed.
  EXPECT_LT(s.max_speed_mps, 2.0);
}

// Every node read independently through GDAL's classic raster API
// (NETCDF:"file":water_u, band 1 = time 0, depth 0): sample_native at the node
// gives raw * scale exactly, and fill nodes give no value.
TEST(CurrentReal, HycomNodesEqualGdalsValuesExactly) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kHycom);
  const CurrentField f = load_current_field(path);
  GDALAllRegister();
  std::vector<std::vector<double>> comp(2);
  int w = 0, h = 0;
  double gt[6];
  for (int c = 0; c < 2; ++c) {
    const std::string sub = std::string("NETCDF:\"") + path + "\":" + (c == 0 ? "water_u" : "water_v");
    GDALDatasetUniquePtr ds(GDALDataset::Open(sub.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
    ASSERT_TRUE(ds);
    w = ds->GetRasterXSize();
    h = ds->GetRasterYSize();
    ASSERT_EQ(ds->GetRasterCount(), 40);  // 1 time x 40 depths
    ds->GetGeoTransform(gt);
    GDALRasterBand* b = ds->GetRasterBand(1);
    int ok = 0;
    const double scale = b->GetScale(&ok);
    ASSERT_TRUE(ok);
    int has = 0;
    const double nodata = b->GetNoDataValue(&has);
    ASSERT_TRUE(has);
    EXPECT_EQ(nodata, -30000.0);
    comp[c].resize(static_cast<std::size_t>(w * h));
    ASSERT_EQ(b->RasterIO(GF_Read, 0, 0, w, h, comp[c].data(), w, h, GDT_Float64, 0, 0, nullptr), CE_None);
    for (double& v : comp[c]) v = v == nodata ? NAN : v * scale;
  }
  ASSERT_EQ(w, 18);
  ASSERT_EQ(h, 33);
  int exact = 0, fill = 0;
  for (int r = 0; r < h; ++r)
    for (int col = 0; col < w; ++col) {
      const double lon = gt[0] + (col + 0.5) * gt[1];
      const double lat = gt[3] + (r + 0.5) * gt[5];
      // The loader's own node coordinates (GDAL's pixel centres agree to rounding).
      const std::size_t i = static_cast<std::size_t>(std::lround((lon - f.x[0]) / 0.08));
      const std::size_t j = static_cast<std::size_t>(std::lround((lat - f.y[0]) / 0.04));
      ASSERT_LT(i, f.nx());
      ASSERT_LT(j, f.ny());
      ASSERT_NEAR(f.x[i], lon, 1e-4);  // GDAL's regular geotransform vs the float32-rounded axis
      ASSERT_NEAR(f.y[j], lat, 1e-4);
      const double u = comp[0][static_cast<std::size_t>(r * w + col)];
      const double v = comp[1][static_cast<std::size_t>(r * w + col)];
      const auto got = sample_native(f, {f.x[i], f.y[j]}, 0.0);
      if (std::isnan(u) || std::isnan(v)) {
        EXPECT_FALSE(got.has_value()) << "fill node " << i << "," << j;
        ++fill;
        continue;
      }
      EXPECT_EQ(f.u[j * f.nx() + i], u);
      EXPECT_EQ(f.v[j * f.nx() + i], v);
      if (got) {  // a node next to land may have no value (its cell has a fill corner)
        EXPECT_EQ(got->x(), u) << i << "," << j;
        EXPECT_EQ(got->y(), v) << i << "," << j;
        ++exact;
      }
    }
  EXPECT_EQ(exact, 18 * 33);  // the surface has no fill node (land lies west of -75.68 here)
  const CurrentSummary s = summarize_current(f);
  EXPECT_EQ(static_cast<std::size_t>(fill), s.fill_nodes);
  std::printf("HYCOM surface: %d nodes exact, %d fill nodes\n", exact, fill);
}

TEST(CurrentReal, HycomSamplerInUtmMatchesTheExactTransform) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kHycom);
  auto f = std::make_shared<const CurrentField>(load_current_field(path));
  const LocalFrame frame = LocalFrame::utm_for(-75.0, 35.0);
  ASSERT_EQ(frame.id(), "EPSG:32618");
  const CurrentSampler sampler(f, frame);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> lon(-75.68, -74.32), lat(34.36, 35.64);
  double worst = 0;
  int compared = 0, lost = 0;
  for (int n = 0; n < 2000; ++n) {
    const Eigen::Vector2d xy = frame.from_lonlat(lon(rng), lat(rng));
    const auto fast = sampler.sample(xy, 0.0);
    const Eigen::Vector2d ll = frame.to_lonlat(xy);
    const auto ref = sample_native(*f, ll, 0.0);
    if (!ref) continue;
    if (!fast) {  // only within the lattice's error of a cell with a land corner
      ++lost;
      continue;
    }
    // Lon/lat components (true east/north) into grid axes: rotate by the convergence.
    const double rot = frame.true_north_angle(xy) - kPi / 2;
    const Eigen::Vector2d want(std::cos(rot) * ref->x() - std::sin(rot) * ref->y(),
                               std::sin(rot) * ref->x() + std::cos(rot) * ref->y());
    worst = std::max(worst, (*fast - want).norm());
    ++compared;
  }
  EXPECT_GT(compared, 1000);
  EXPECT_LE(lost, 2);
  EXPECT_LT(worst, 1e-5);  // m/s; the speeds are up to 1.7 m/s
  std::printf("HYCOM sampler vs exact transform: %d points, worst difference %.3g m/s\n", compared, worst);
  // Outside the field: no value.
  EXPECT_FALSE(sampler.sample(frame.from_lonlat(-76.0, 35.0), 0.0).has_value());
}

TEST(CurrentReal, HycomCoverage) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kHycom);
  const CurrentField f = load_current_field(path);
  const LocalFrame frame = LocalFrame::utm_for(-75.0, 35.0);
  // A box well inside: 0.2 deg around (-75.0, 35.0).
  const CurrentCoverage c =
      check_current_coverage(f, frame, frame.from_lonlat(-75.1, 34.9), frame.from_lonlat(-74.9, 35.1));
  // lon -75.1..-74.9 holds nodes -75.04, -74.96 (0.08 spacing from -75.68); lat 34.9..35.1 holds 5 nodes (0.04).
  EXPECT_GE(c.nodes, 2u * 5u);
  EXPECT_LE(c.nodes, 3u * 6u);
  // The steady field ignores the time interval.
  EXPECT_NO_THROW(
      check_current_coverage(f, frame, frame.from_lonlat(-75.1, 34.9), frame.from_lonlat(-74.9, 35.1), 0.0, 1.0));
  // At 1000 m the western (shelf) nodes lie below the sea floor: fill nodes are counted, not refused.
  CurrentOptions deep;
  deep.depth_m = 1000.0;
  const CurrentField fd = load_current_field(path, deep);
  const CurrentCoverage west =
      check_current_coverage(fd, frame, frame.from_lonlat(-75.6, 34.4), frame.from_lonlat(-75.0, 35.6));
  EXPECT_GT(west.nodes, 100u);
  EXPECT_GT(west.fill_nodes, 0u);
  EXPECT_LT(west.fill_nodes, west.nodes);
  std::printf("HYCOM at 1000 m, lon -75.6..-75.0: %zu nodes, %zu fill\n", west.nodes, west.fill_nodes);
  EXPECT_EQ(check_current_coverage(f, frame, frame.from_lonlat(-75.6, 34.4), frame.from_lonlat(-75.0, 35.6)).fill_nodes,
            0u);
  expect_one_line_error(
      [&] { check_current_coverage(f, frame, frame.from_lonlat(-75.5, 35.0), frame.from_lonlat(-73.9, 35.2)); },
      "the current field covers lon -75.6800 .. -74.3200, lat 34.3600 .. 35.6400 (times 2019-03-07T15:00:00Z, steady); "
      "the work area lon -75.5");
}

TEST(CurrentReal, HycomDepthLevels) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kHycom);
  CurrentOptions o;
  o.depth_m = 5000.0;
  const CurrentField deepest = load_current_field(path, o);
  EXPECT_EQ(deepest.depth_levels, "level 40 of 40 (5000.0 m)");
  // The sea floor lies above 5000 m everywhere here: every node is unknown, none is -30 m/s.
  const CurrentSummary s5000 = summarize_current(deepest);
  EXPECT_EQ(s5000.fill_nodes, 18u * 33u);
  EXPECT_EQ(s5000.valid_nodes, 0u);
  EXPECT_TRUE(std::isnan(s5000.max_speed_mps));
  // At 1000 m the shelf is land (fill), the slope water is not.
  o.depth_m = 1000.0;
  const CurrentField deep = load_current_field(path, o);
  const CurrentSummary ds = summarize_current(deep);
  EXPECT_GT(ds.fill_nodes, 0u);
  EXPECT_GT(ds.valid_nodes, 0u);
  EXPECT_EQ(summarize_current(load_current_field(path)).fill_nodes, 0u);
  // _FillValue -30000 (-30 m/s once scaled) must be unknown, never a value.
  EXPECT_GT(ds.u_min, -2.0);
  EXPECT_LT(ds.max_speed_mps, 2.0);
  for (double u : deep.u) EXPECT_TRUE(std::isnan(u) || std::abs(u) < 2.0);
  o.depth_m = 5001.0;
  expect_one_line_error([&] { load_current_field(path, o); },
                        "expected a depth within the field's levels (0.0 .. 5000.0 m)");
  // Between two levels: the linear blend of the two, node by node.
  CurrentOptions a, b, mid;
  a.depth_m = 0.0;
  b.depth_m = 2.0;
  mid.depth_m = 1.0;
  const CurrentField fa = load_current_field(path, a), fb = load_current_field(path, b),
                     fm = load_current_field(path, mid);
  EXPECT_NE(fb.depth_levels.find("level 2 of 40 (2.0 m)"), std::string::npos) << fb.depth_levels;
  EXPECT_NE(fm.depth_levels.find("between levels 1 and 2"), std::string::npos) << fm.depth_levels;
  for (std::size_t i = 0; i < fa.u.size(); ++i) {
    if (std::isnan(fa.u[i]) || std::isnan(fb.u[i])) {
      EXPECT_TRUE(std::isnan(fm.u[i]));
      continue;
    }
    EXPECT_NEAR(fm.u[i], 0.5 * (fa.u[i] + fb.u[i]), 1e-12);
  }
}

TEST(CurrentReal, TruncatedHycomIsAOneLineError) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, kHycom);
  ScratchDir dir;
  std::ifstream in(path, std::ios::binary);
  std::string bytes(std::istreambuf_iterator<char>(in), {});
  // Cut in the data: the netCDF library would read zeros; the size check refuses it.
  const std::string cut = dir.write("cut.nc", bytes.substr(0, bytes.size() / 3));
  expect_one_line_error([&] { load_current_field(cut); }, "cut.nc: expected a complete NetCDF file");
  // The check is a lower bound (the variables' bytes, not the header's): 10 % short is caught.
  const std::string almost = dir.write("almost.nc", bytes.substr(0, bytes.size() * 9 / 10));
  expect_one_line_error([&] { load_current_field(almost); }, "the file is cut short");
  // Cut in the coordinates.
  const std::string head = dir.write("head.nc", bytes.substr(0, 3000));
  expect_one_line_error([&] { load_current_field(head); }, "head.nc: ");
  // The header's magic damaged.
  std::string bad = bytes;
  bad[0] = 'X';
  const std::string magic = dir.write("magic.nc", bad);
  expect_one_line_error([&] { load_current_field(magic); }, "magic.nc: expected a current field GDAL can open");
}

// ---------------------------------------------------------------- synthetic NetCDF

double lin_u(double lon, double lat, double t, double) {
  return 0.3 + 2.0 * (lon - 10.0) - 1.5 * (lat - 54.0) + 0.01 * t;
}
double lin_v(double lon, double lat, double t, double) {
  return -0.2 + 0.5 * (lon - 10.0) + 3.0 * (lat - 54.0) - 0.02 * t;
}

TEST(CurrentNetcdf, LinearFieldIsReproducedInSpaceAndTime) {
  ScratchDir dir;
  NcSpec s;
  s.time = {0.0, 6.0, 12.0, 30.0};  // hours since 2020-01-01; irregular steps
  s.u = lin_u;
  s.v = lin_v;
  const std::string path = dir.file("lin.nc");
  write_nc(path, s);
  const CurrentField f = load_current_field(path);
  EXPECT_EQ(f.nx(), 6u);
  EXPECT_EQ(f.ny(), 5u);
  EXPECT_EQ(f.y.front(), 54.2);  // stored ascending
  EXPECT_EQ(f.y.back(), 55.0);
  ASSERT_EQ(f.times_s.size(), 4u);
  const double t0 = 1577836800.0;  // 2020-01-01T00:00:00Z
  EXPECT_DOUBLE_EQ(f.times_s[0], t0);
  EXPECT_DOUBLE_EQ(f.times_s[3], t0 + 30 * 3600.0);
  EXPECT_FALSE(f.steady());
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> lon(10.0, 11.0), lat(54.2, 55.0), hours(0.0, 30.0);
  for (int n = 0; n < 500; ++n) {
    const double x = lon(rng), y = lat(rng), h = hours(rng);
    const auto got = sample_native(f, {x, y}, t0 + h * 3600.0);
    ASSERT_TRUE(got.has_value());
    EXPECT_NEAR(got->x(), lin_u(x, y, h, 0), 1e-12);
    EXPECT_NEAR(got->y(), lin_v(x, y, h, 0), 1e-12);
  }
  // At nodes and steps: exactly the stored value.
  const auto node = sample_native(f, {10.35, 54.6}, t0 + 12 * 3600.0);
  ASSERT_TRUE(node.has_value());
  EXPECT_EQ(node->x(), f.u[(2 * 5 + 2) * 6 + 3]);
  // Outside the time axis (not clamped) and outside the nodes: no value.
  EXPECT_FALSE(sample_native(f, {10.5, 54.5}, t0 - 1.0).has_value());
  EXPECT_FALSE(sample_native(f, {10.5, 54.5}, t0 + 30 * 3600.0 + 1.0).has_value());
  EXPECT_FALSE(sample_native(f, {10.5, 54.5}, NAN).has_value());
  EXPECT_FALSE(sample_native(f, {9.99, 54.5}, t0).has_value());
  EXPECT_FALSE(sample_native(f, {10.5, 55.01}, t0).has_value());
  // Longitudes wrap by 360 degrees.
  const auto wrapped = sample_native(f, {10.5 - 360.0, 54.5}, t0);
  ASSERT_TRUE(wrapped.has_value());
  EXPECT_NEAR(wrapped->x(), lin_u(10.5, 54.5, 0, 0), 1e-9);
}

TEST(CurrentNetcdf, ReversingTideIsLinearBetweenSteps) {
  // A tidal stream: +1 m/s east at 0 h, -1 m/s at 6 h (the ebb), +1 m/s at 12 h.
  ScratchDir dir;
  NcSpec s;
  s.time = {0.0, 6.0, 12.0};
  s.time_units = "minutes since 2021-06-01T00:00:00Z";  // here the times are minutes
  s.time = {0.0, 360.0, 720.0};
  s.u = [](double, double, double t, double) { return t == 360.0 ? -1.0 : 1.0; };
  s.v = [](double, double, double, double) { return 0.0; };
  const std::string path = dir.file("tide.nc");
  write_nc(path, s);
  const CurrentField f = load_current_field(path);
  const double t0 = 1622505600.0;  // 2021-06-01T00:00:00Z
  EXPECT_EQ(format_utc(f.times_s[0]), "2021-06-01T00:00:00Z");
  EXPECT_EQ(format_utc(f.times_s[2]), "2021-06-01T12:00:00Z");
  auto u_at = [&](double hours) { return sample_native(f, {10.5, 54.5}, t0 + hours * 3600.0)->x(); };
  EXPECT_DOUBLE_EQ(u_at(0.0), 1.0);
  EXPECT_DOUBLE_EQ(u_at(1.5), 0.5);
  EXPECT_DOUBLE_EQ(u_at(3.0), 0.0);  // slack water
  EXPECT_DOUBLE_EQ(u_at(4.5), -0.5);
  EXPECT_DOUBLE_EQ(u_at(6.0), -1.0);
  EXPECT_DOUBLE_EQ(u_at(9.0), 0.0);
  EXPECT_DOUBLE_EQ(u_at(12.0), 1.0);
  // Coverage of a time interval.
  const LocalFrame frame = LocalFrame::utm_for(10.5, 54.5);
  const Eigen::Vector2d a = frame.from_lonlat(10.4, 54.4), b = frame.from_lonlat(10.6, 54.6);
  EXPECT_NO_THROW(check_current_coverage(f, frame, a, b, t0, t0 + 12 * 3600.0));
  expect_one_line_error([&] { check_current_coverage(f, frame, a, b, t0, t0 + 13 * 3600.0); },
                        "(times 2021-06-01T00:00:00Z .. 2021-06-01T12:00:00Z); the work area lon 10.4");
}

TEST(CurrentNetcdf, DepthIsInterpolatedLinearly) {
  ScratchDir dir;
  NcSpec s;
  s.depth = {0.0, 10.0, 30.0};
  s.u = [](double, double, double, double z) { return 1.0 - 0.02 * z; };
  s.v = [](double, double, double, double z) { return z > 20.0 ? NAN : 0.1; };  // below 20 m: sea floor
  const std::string path = dir.file("depth.nc");
  write_nc(path, s);
  CurrentOptions o;
  o.depth_m = 20.0;
  const CurrentField f = load_current_field(path, o);
  EXPECT_EQ(f.depth_levels, "between levels 2 and 3 of 3 (10.0 and 30.0 m)");
  EXPECT_TRUE(f.steady());
  EXPECT_NEAR(f.u[0], 0.6, 1e-12);
  EXPECT_TRUE(std::isnan(f.v[0]));  // unknown at 30 m -> unknown at 20 m
  EXPECT_FALSE(sample_native(f, {10.5, 54.5}, 0.0).has_value());
  o.depth_m = 5.0;
  const CurrentField g = load_current_field(path, o);
  const auto at5 = sample_native(g, {10.5, 54.5}, 0.0);
  ASSERT_TRUE(at5.has_value());
  EXPECT_NEAR(at5->x(), 0.9, 1e-12);
  EXPECT_NEAR(at5->y(), 0.1, 1e-12);
  o.depth_m = -1.0;
  expect_one_line_error([&] { load_current_field(path, o); }, "expected a depth >= 0 m");
}

TEST(CurrentNetcdf, FindsVariablesByStandardNameAndOption) {
  ScratchDir dir;
  NcSpec s;
  s.u_name = "east_speed";
  s.v_name = "north_speed";
  s.u_standard = "surface_eastward_sea_water_velocity";
  s.v_standard = "surface_northward_sea_water_velocity";
  s.u = lin_u;
  s.v = lin_v;
  const std::string path = dir.file("sn.nc");
  write_nc(path, s);
  const CurrentField f = load_current_field(path);
  EXPECT_EQ(f.u_name, "east_speed");
  EXPECT_EQ(f.v_name, "north_speed");
  EXPECT_TRUE(f.steady());
  EXPECT_EQ(f.depth_levels, "no depth axis");

  NcSpec t = s;
  t.u_name = "a1";
  t.v_name = "a2";
  t.u_standard = t.v_standard = "";
  const std::string other = dir.file("named.nc");
  write_nc(other, t);
  CurrentOptions o;
  o.u_variable = "a1";
  o.v_variable = "a2";
  EXPECT_EQ(load_current_field(other, o).u_name, "a1");
  o.v_variable = "nope";
  expect_one_line_error([&] { load_current_field(other, o); }, "asked for 'a1'/'nope'");
}

// ---------------------------------------------------------------- two-band raster

TEST(CurrentRaster, GeoTiffInTheFrameCrsIsExactAndLinear) {
  ScratchDir dir;
  const std::string path = dir.file("uv.tif");
  auto u = [](double x, double y) { return 0.1 + 1e-4 * (x - 580000.0) + 2e-4 * (y - 6030000.0); };
  auto v = [](double x, double y) { return x < 580050.0 && y > 6034900.0 ? NAN : -0.3 + 3e-4 * (x - 580000.0); };
  write_tiff(path, 32632, 580000.0, 6035000.0, 100.0, 40, 50, u, v);
  auto f = std::make_shared<const CurrentField>(load_current_field(path));
  EXPECT_EQ(f->driver, "GTiff");
  EXPECT_EQ(f->crs, "EPSG:32632");
  EXPECT_FALSE(f->geographic);
  EXPECT_EQ(f->nx(), 40u);
  EXPECT_EQ(f->ny(), 50u);
  EXPECT_EQ(f->x.front(), 580000.0);  // pixel centres
  EXPECT_EQ(f->y.back(), 6035000.0);
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  const CurrentSampler sampler(f, frame);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> xs(580100.0, 583900.0), ys(6030100.0, 6034800.0);
  for (int n = 0; n < 300; ++n) {
    const Eigen::Vector2d p(xs(rng), ys(rng));
    const auto got = sampler.sample(p, 123.0);
    ASSERT_TRUE(got.has_value());
    EXPECT_NEAR(got->x(), u(p.x(), p.y()), 1e-12);
    EXPECT_NEAR(got->y(), v(p.x(), p.y()), 1e-12);
  }
  const auto node = sampler.sample({581200.0, 6033000.0}, 0.0);
  ASSERT_TRUE(node.has_value());
  EXPECT_EQ(node->x(), u(581200.0, 6033000.0));
  // NoData corner (the north-west pixel): no value in its cells, never zero.
  EXPECT_FALSE(sampler.sample({580030.0, 6034950.0}, 0.0).has_value());
  EXPECT_FALSE(sampler.sample({579990.0, 6032000.0}, 0.0).has_value());  // west of the first pixel centre
  EXPECT_EQ(summarize_current(*f).fill_nodes, 1u);                       // only the pixel centred at (580000, 6035000)
}

TEST(CurrentRaster, UtmFieldInAnotherZoneIsRotatedByTheConvergence) {
  // A field in UTM 33N sampled in a UTM 32N frame at 12 E: grid north differs by
  // the difference of the two convergences, about (12-9 - (12-15)) * sin(54.5) = 4.9 deg.
  ScratchDir dir;
  const std::string path = dir.file("uv33.tif");
  const LocalFrame f33 = LocalFrame::from_user_crs("EPSG:32633");
  const Eigen::Vector2d c33 = f33.from_lonlat(12.0, 54.5);
  const double x0 = std::round(c33.x()) - 2000.0, y0 = std::round(c33.y()) + 2000.0;
  write_tiff(
      path, 32633, x0, y0, 200.0, 21, 21, [](double, double) { return 0.0; },
      [](double, double) { return 1.0; });  // 1 m/s towards grid north of zone 33
  auto f = std::make_shared<const CurrentField>(load_current_field(path));
  const LocalFrame f32 = LocalFrame::from_user_crs("EPSG:32632");
  const CurrentSampler sampler(f, f32);
  const Eigen::Vector2d p = f32.from_lonlat(12.0, 54.5);
  const auto got = sampler.sample(p, 0.0);
  ASSERT_TRUE(got.has_value());
  EXPECT_NEAR(got->norm(), 1.0, 1e-9);
  const double want = f32.true_north_angle(p) - f33.true_north_angle(c33) + kPi / 2;
  EXPECT_NEAR(math_angle(*got), want, 1e-6);
  // Independent: the convergence gamma = atan(tan(lon - lon0) sin(lat)) in each zone.
  auto gamma = [](double dlon) { return std::atan(std::tan(deg_to_rad(dlon)) * std::sin(deg_to_rad(54.5))); };
  EXPECT_NEAR(rad_to_deg(math_angle(*got) - kPi / 2), rad_to_deg(gamma(12.0 - 9.0) - gamma(12.0 - 15.0)), 0.01);
}

// ---------------------------------------------------------------- constant current

TEST(CurrentConstant, DirectionIsWhereItSetsTowardsClockwiseFromNorth) {
  auto vel = [](const std::string& t) { return parse_constant_current(t, "--current").constant_velocity; };
  EXPECT_EQ(vel("1,90"), Eigen::Vector2d(1.0, 0.0));    // sets towards east
  EXPECT_EQ(vel("2,180"), Eigen::Vector2d(0.0, -2.0));  // towards south
  EXPECT_EQ(vel("0.5,0"), Eigen::Vector2d(0.0, 0.5));
  EXPECT_EQ(vel("1, 270"), Eigen::Vector2d(-1.0, 0.0));
  EXPECT_EQ(vel("0,45"), Eigen::Vector2d(0.0, 0.0));
  const Eigen::Vector2d ne = vel("+1.5,45");
  EXPECT_NEAR(ne.x(), 1.5 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(ne.y(), 1.5 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(course_deg_of(vel("0.7,301")), 301.0, 1e-12);

  const CurrentField c = parse_constant_current("1,90", "--current");
  EXPECT_TRUE(c.constant);
  EXPECT_EQ(*sample_native(c, {1e9, -1e9}, NAN), Eigen::Vector2d(1.0, 0.0));
  const CurrentSummary s = summarize_current(c);
  EXPECT_DOUBLE_EQ(s.max_speed_mps, 1.0);
  EXPECT_EQ(s.steps, 0u);
}

TEST(CurrentConstant, TrueNorthBecomesGridNorthInTheFrame) {
  // "1,0" flows to TRUE north; at 12 E in UTM 32N true north lies west of grid north by
  // gamma = atan(tan(3 deg) sin(54.5 deg)) = 2.44 deg, so the local vector points there.
  auto c = std::make_shared<const CurrentField>(parse_constant_current("1,0", "--current"));
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32632");
  const Eigen::Vector2d p = frame.from_lonlat(12.0, 54.5);
  const double gamma = std::atan(std::tan(deg_to_rad(3.0)) * std::sin(deg_to_rad(54.5)));
  const CurrentSampler exact(c, frame);
  const CurrentSampler fast(c, frame, p - Eigen::Vector2d(5000, 5000), p + Eigen::Vector2d(5000, 5000));
  for (const CurrentSampler* s : {&exact, &fast}) {
    const auto got = s->sample(p, 0.0);
    ASSERT_TRUE(got.has_value());
    EXPECT_NEAR(got->norm(), 1.0, 1e-12);
    EXPECT_NEAR(math_angle(*got), kPi / 2 + gamma, 2e-5);
  }
  EXPECT_NEAR(
      (*fast.sample(p + Eigen::Vector2d(1234, -987), 0.0) - *exact.sample(p + Eigen::Vector2d(1234, -987), 0.0)).norm(),
      0.0, 1e-9);
  // A constant field covers any work area.
  EXPECT_NO_THROW(check_current_coverage(*c, frame, p, p + Eigen::Vector2d(1e5, 1e5)));
}

TEST(CurrentConstant, MalformedTextIsAOneLineError) {
  for (const char* bad : {"1", "a,b", "nan,0", "-1,0", "1,0,0", "", ",", "1,", "inf,0", "1,nan", "1e999,0", "1 0",
                          "1;90", "0x1,0", "1,90\n2"}) {
    SCOPED_TRACE(bad);
    expect_one_line_error([&] { parse_constant_current(bad, "--current"); }, "--current: expected ");
  }
}

// ---------------------------------------------------------------- bad input

TEST(CurrentErrors, NetcdfWithoutUvListsItsVariables) {
  ScratchDir dir;
  NcSpec s;
  s.u_name = "temperature";
  s.v_name = "salinity";
  s.u = s.v = [](double, double, double, double) { return 1.0; };
  const std::string path = dir.file("ts.nc");
  write_nc(path, s);
  expect_one_line_error([&] { load_current_field(path); }, "expected current variables u and v");
  expect_one_line_error([&] { load_current_field(path); }, "got variables: lat, lon, temperature, salinity");
  // Only u present.
  NcSpec only_u;
  only_u.v_name = "";
  only_u.u = lin_u;
  const std::string p2 = dir.file("u.nc");
  write_nc(p2, only_u);
  expect_one_line_error([&] { load_current_field(p2); }, "expected current variables v ");
}

TEST(CurrentErrors, MissingCorruptAndForeignFiles) {
  ScratchDir dir;
  expect_one_line_error([&] { load_current_field(dir.file("none.nc")); },
                        "none.nc: expected an existing current field file");
  expect_one_line_error([&] { load_current_field(dir.path().string()); }, "got a folder");
  const std::string junk = dir.write("junk.nc", std::string("CDF\x01") + std::string(300, '\x07') + "\nmore\n");
  // The CDF magic and garbage after it: the header walk refuses it before GDAL reads it.
  expect_one_line_error([&] { load_current_field(junk); }, "junk.nc: expected a readable NetCDF classic header");
  const std::string text = dir.write("notes.txt", "water_u,water_v\n1,2\n");
  expect_one_line_error([&] { load_current_field(text); }, "notes.txt: expected ");
  // A one-band raster is not a current field.
  GDALAllRegister();
  const std::string one = dir.file("one.tif");
  {
    GDALDatasetUniquePtr ds(
        GetGDALDriverManager()->GetDriverByName("GTiff")->Create(one.c_str(), 4, 4, 1, GDT_Float32, nullptr));
    double gt[6] = {0, 1, 0, 4, 0, -1};
    ds->SetGeoTransform(gt);
    OGRSpatialReference srs;
    srs.importFromEPSG(32632);
    ds->SetSpatialRef(&srs);
  }
  expect_one_line_error([&] { load_current_field(one); }, "expected a two-band raster (band 1 u east, band 2 v north");
}

TEST(CurrentErrors, ShapesCrsTimeUnitsAndSize) {
  ScratchDir dir;
  NcSpec shapes;
  shapes.u = lin_u;
  shapes.v = lin_v;
  shapes.v_missing_row = true;
  const std::string p1 = dir.file("shapes.nc");
  write_nc(p1, shapes);
  expect_one_line_error([&] { load_current_field(p1); }, "expected the same shape, got 5 x 6 and 4 x 6");

  NcSpec nocrs;
  nocrs.u = lin_u;
  nocrs.v = lin_v;
  nocrs.lon_units = nocrs.lat_units = "";
  const std::string p2 = dir.file("nocrs.nc");
  write_nc(p2, nocrs);
  expect_one_line_error([&] { load_current_field(p2); }, "nocrs.nc: expected lon/lat axes");
  CurrentOptions assume;
  assume.assumed_crs = "EPSG:4326";
  EXPECT_EQ(load_current_field(p2, assume).crs_source, "assumed (option)");

  NcSpec badtime;
  badtime.u = lin_u;
  badtime.v = lin_v;
  badtime.time = {0.0, 1.0};
  badtime.time_units = "fortnights since 2020-01-01";
  const std::string p3 = dir.file("badtime.nc");
  write_nc(p3, badtime);
  expect_one_line_error([&] { load_current_field(p3); },
                        "badtime.nc: variable 'time': field 'units': expected 'UNITS since YYYY-MM-DD hh:mm:ss'");
  badtime.time_units = "hours since yesterday";
  write_nc(p3, badtime);
  expect_one_line_error([&] { load_current_field(p3); }, "got 'hours since yesterday'");

  NcSpec big;
  big.u = lin_u;
  big.v = lin_v;
  big.time = {0.0, 1.0, 2.0};
  const std::string p4 = dir.file("big.nc");
  write_nc(p4, big);
  CurrentOptions small;
  small.max_cells_per_step = 29;
  expect_one_line_error([&] { load_current_field(p4, small); },
                        "expected a current field of at most 29 nodes per time step");
  CurrentOptions total;
  total.max_total_cells = 89;
  expect_one_line_error([&] { load_current_field(p4, total); }, "got 6 x 5 nodes x 3 step(s)");
  total.max_total_cells = 90;
  EXPECT_NO_THROW(load_current_field(p4, total));
}

TEST(CurrentErrors, WorkAreaOutsideTheField) {
  ScratchDir dir;
  NcSpec s;
  s.u = lin_u;
  s.v = lin_v;
  const std::string path = dir.file("lin.nc");
  write_nc(path, s);
  const CurrentField f = load_current_field(path);
  const LocalFrame frame = LocalFrame::utm_for(10.5, 54.5);
  const CurrentCoverage ok =
      check_current_coverage(f, frame, frame.from_lonlat(10.05, 54.25), frame.from_lonlat(10.95, 54.95));
  EXPECT_EQ(ok.nodes, 4u * 3u);  // lon 10.1, 10.3, 10.35, 10.6 and lat 54.4, 54.6, 54.8 lie inside
  EXPECT_EQ(ok.fill_nodes, 0u);
  // Partly outside (east of 11 E), and wholly elsewhere.
  expect_one_line_error(
      [&] { check_current_coverage(f, frame, frame.from_lonlat(10.5, 54.5), frame.from_lonlat(11.2, 54.7)); },
      "lin.nc: the current field covers lon 10.0000 .. 11.0000, lat 54.2000 .. 55.0000; the work area lon 10.5");
  expect_one_line_error(
      [&] { check_current_coverage(f, frame, frame.from_lonlat(12.0, 56.0), frame.from_lonlat(12.1, 56.1)); },
      "is outside");
}

}  // namespace
}  // namespace deepguide
