// Bathymetry rasters: the real BAG, NetCDF/GMT and ESRI ASCII grids checked
// against the facts stated in ../shared/data/real/SOURCES.md (sections 2 and
// 3), the window-by-window scan against a whole-raster read of a synthetic
// GeoTIFF, the sign convention, and bad input (one-line errors).

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "deepguide/charts/bathymetry.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/currents/current_field.hpp"
#include "deepguide/world/raster_completeness.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

namespace fs = std::filesystem;

using test::real_file;
#define REAL_FILE_OR_SKIP(var, rel) DEEPGUIDE_REAL_FILE_OR_SKIP(var, rel)

using test::expect_one_line_error;

BathymetryOptions assumed(const std::string& crs) {
  BathymetryOptions o;
  o.assumed_crs = crs;
  return o;
}

// ---------------------------------------------------------------- damaged real files

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The netCDF library fills a classic file cut short with zeros: cut in half
// it read as "100.0 % valid" with a no-go area that is not there; cut within
// its last variable (9615 of 10628 bytes) the last rows read as 0 m.
TEST(BathymetryDamaged, ANetcdfGridCutShortIsRefused) {
  REAL_FILE_OR_SKIP(path, "bathy-gmt-cache/tut_bathy.nc");
  const std::string bytes = file_bytes(path);
  ASSERT_EQ(bytes.size(), 10628u);
  test::ScratchDir tmp;
  for (const std::size_t keep : {std::size_t{5314}, std::size_t{9615}, std::size_t{10625}}) {
    const std::string cut = tmp.write("cut.nc", bytes.substr(0, keep));
    expect_one_line_error([&] { inspect_bathymetry(cut); }, "the file is cut short");
    expect_one_line_error([&] { inspect_bathymetry(cut); }, "up to byte 10626");
  }
  // The 2 bytes of padding after the last variable may go: nothing is lost.
  const BathymetryInfo whole = inspect_bathymetry(tmp.write("cut.nc", bytes.substr(0, 10626)));
  EXPECT_DOUBLE_EQ(whole.min_depth_m, 89);
  EXPECT_DOUBLE_EQ(whole.max_depth_m, 5475);
}

// A flipped byte in the grid's numbers: -5475 .. -89 m is what the file says
// it holds (actual_range); a cell outside it is damage, not a 9457 m deep.
TEST(BathymetryDamaged, ACellOutsideTheFilesOwnRangeIsRefused) {
  REAL_FILE_OR_SKIP(path, "bathy-gmt-cache/tut_bathy.nc");
  std::string bytes = file_bytes(path);
  test::ScratchDir tmp;
  const std::size_t at = bytes.size() - 2 - 2 * 4453 + 2 * 100;  // the high byte of cell 100 of z (int16, big-endian)
  bytes[at] = static_cast<char>(static_cast<unsigned char>(bytes[at]) ^ 0x40);
  const std::string bad = tmp.write("bad.nc", bytes);
  expect_one_line_error([&] { inspect_bathymetry(bad); }, "outside the file's own actual_range -5475 .. -89");
}

// Appends a big-endian 32-bit number, as netCDF classic headers hold them.
void append_be32(std::string& bytes, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(static_cast<char>((v >> shift) & 0xff));
}

// A classic header whose counts are damaged: the netCDF library, handed a
// HYCOM file mutated so, allocated 12.8 GB and took 56 s to refuse it (found
// by fuzz/fuzz_current_nc). The header walk refuses before GDAL opens it.
TEST(BathymetryDamaged, ANetcdfHeaderWithAHugeCountIsRefusedBeforeGdalReadsIt) {
  std::string header("CDF\x01", 4);
  const auto u32 = [&](std::uint32_t v) { append_be32(header, v); };
  u32(0);                                       // numrecs
  u32(0), u32(0);                               // no dimensions
  u32(0x0C), u32(1);                            // one global attribute
  u32(1), header += std::string("a\0\0\0", 4);  // its name, padded to 4 bytes
  u32(2), u32(0x7fffffffu);                     // char, 2^31 - 1 of them (the file ends here)
  test::ScratchDir tmp;
  const std::string path = tmp.write("huge.nc", header);
  expect_one_line_error([&] { inspect_bathymetry(path); }, "expected a readable NetCDF classic header");
  expect_one_line_error([&] { load_current_field(path); }, "an attribute of 2147483647 values");
}

TEST(BathymetryDamaged, AHeaderStatingAGiantRasterIsRefusedBeforeGdalAllocatesIt) {
  // The fuzzing soak's find (fuzz/corpus/bathymetry_nc): 217 bytes that
  // GDAL's NGS geoid driver takes for a grid of 1 178 892 903 x 774 990 956
  // cells in blocks of one row, 4.7 GB, allocated on the first read.
  const std::string hex =
      "43ffffffffffffffffffffffffffffffffffffffffffffff43677269645f6365"
      "6c6c312e677a444601000000000000000a000000020000000178000000ff0000"
      "000000ffff43444601000000000000000a000000020000000178000000ff0044"
      "4341505f435245415445000000003d0049000000017900000000000000ffffff"
      "ffffffff7dffffffffffffffffff3d0049000000017900000000000000ffffff"
      "ffffffff7dffffffffffffffffffffffffffffffffffffffffffffffe1ffffff"
      "fffffffff6ffffffffffffffffffffffffffffe1ffffffffff";
  std::string bytes;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2)
    bytes += static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16));
  ASSERT_EQ(bytes.size(), 217u);
  test::ScratchDir tmp;
  const std::string path = tmp.write("giant.nc", bytes);
  expect_one_line_error([&] { inspect_bathymetry(path); }, "1178892903 x 774990956 cells in blocks of 4497 MiB");
}

std::string corpus_file(const std::string& name) {
  std::ifstream in(std::string(DEEPGUIDE_SOURCE_DIR) + "/fuzz/corpus/" + name, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(BathymetryDamaged, TheSoaksFindsAreOneLineErrors) {
  test::ScratchDir tmp;
  // 1835 bytes with an NLAPS header on which GDAL 3.6's NDF driver
  // dereferenced a null list while probing: `chart info` and the current
  // reader crashed. The driver is no longer offered.
  const std::string ndf = corpus_file("current_nc/ndf-null-list");
  ASSERT_EQ(ndf.size(), 1835u);
  const std::string nc = tmp.write("ndf.nc", ndf);
  expect_one_line_error([&] { load_current_field(nc); }, "expected a current field GDAL can open");
  expect_one_line_error([&] { inspect_bathymetry(nc); }, "expected a raster GDAL can open");
  // 60 bytes GDAL's XYZ driver took for 51 117 053 x 2 cells (from the
  // spacing of two coordinates): 400 MB read, 10 s under the sanitizers.
  const std::string xyz = tmp.write("xyz.asc", corpus_file("bathymetry_asc/xyz-51-million-cells"));
  expect_one_line_error([&] { inspect_bathymetry(xyz); }, "51117053 x 2 cells, got 60 bytes");
  // 4540 bytes of NetCDF whose time axis states 2^32 - 1 values: the current
  // reader allocated 32 GiB for it before reading.
  const std::string axis = tmp.write("axis.nc", corpus_file("current_nc/axis-of-4-billion-values"));
  expect_one_line_error([&] { load_current_field(axis); }, "expected a coordinate axis of at most 10000000 values");
}

// The format's one unpadded case: a single record variable of shorts. Its
// records lie 2 bytes apart, so 10 records end 20 bytes after its start
// (the walk once asked for 4 bytes a record and refused such a file).
TEST(BathymetryDamaged, ASingleRecordVariableIsNotPadded) {
  std::string nc("CDF\x01", 4);
  const auto u32 = [&](std::uint32_t v) { append_be32(nc, v); };
  u32(10);                                          // numrecs
  u32(0x0A), u32(1), u32(4), nc += "time", u32(0);  // the record dimension
  u32(0), u32(0);                                   // no global attributes
  u32(0x0B), u32(1), u32(1), nc += std::string("x\0\0\0", 4);
  u32(1), u32(0);           // x(time)
  u32(0), u32(0);           // no attributes
  u32(3), u32(4), u32(80);  // short, vsize, begin
  ASSERT_EQ(nc.size(), 80u);
  nc += std::string(20, '\x01');  // 10 shorts
  test::ScratchDir tmp;
  EXPECT_NO_THROW(require_complete_netcdf(tmp.write("x.nc", nc)));
  expect_one_line_error([&] { require_complete_netcdf(tmp.write("x.nc", nc.substr(0, 99))); }, "up to byte 100");
}

// GDAL 3.6 rescans a cut ESRI ASCII grid for ever (more than 600 s for
// chart info); the count of numbers against ncols x nrows refuses it at once.
TEST(BathymetryDamaged, AnAsciiGridCutShortOrWithALetterIsRefused) {
  REAL_FILE_OR_SKIP(path, "bathy-usml-crm/small_crm.asc");
  const std::string bytes = file_bytes(path);
  test::ScratchDir tmp;
  for (const double part : {0.01, 0.5, 0.999}) {
    const std::string cut = tmp.write("cut.asc", bytes.substr(0, static_cast<std::size_t>(part * bytes.size())));
    // "expected 241 x 241 = 58081 numbers ..., got N", or, cut within a number, "line L: expected a number ..., got
    // '-'"
    const std::string msg = test::error_of([&] { inspect_bathymetry(cut, assumed("EPSG:4326")); });
    EXPECT_TRUE(msg.find("58081 numbers") != std::string::npos || msg.find(": expected a number") != std::string::npos)
        << msg;
    expect_one_line_error([&] { inspect_bathymetry(cut, assumed("EPSG:4326")); }, "cut.asc: ");
  }
  // A digit turned into a letter on line 10 (GDAL's reader would take "-7x2" as -7).
  std::size_t at = 0;
  for (int line = 1; line < 10; ++line) at = bytes.find('\n', at) + 1;
  std::string flipped = bytes;
  const std::size_t digit = flipped.find_first_of("0123456789", at + 1);
  ASSERT_LT(digit, flipped.find('\n', at));
  flipped[digit] = 'x';
  const std::string bad = tmp.write("bad.asc", flipped);
  expect_one_line_error([&] { inspect_bathymetry(bad, assumed("EPSG:4326")); }, "line 10: expected a number");
  // The untouched copy still reads (the check takes every number the real file holds).
  EXPECT_NEAR(inspect_bathymetry(tmp.write("ok.asc", bytes), assumed("EPSG:4326")).max_depth_m, 771, 1e-3);
}

// ---------------------------------------------------------------- BAG

TEST(BathymetryReal, JD211BagMatchesSources) {
  REAL_FILE_OR_SKIP(path, "bag-ons/JD211_public_Release_1-4_UTM.bag");
  const BathymetryInfo b = inspect_bathymetry(path);
  EXPECT_EQ(b.driver, "BAG");
  EXPECT_EQ(b.width, 1707);
  EXPECT_EQ(b.height, 1478);
  EXPECT_DOUBLE_EQ(b.pixel_x, 2.0);
  EXPECT_DOUBLE_EQ(b.pixel_y, -2.0);
  EXPECT_EQ(b.crs_source, "file");
  OGRSpatialReference srs;
  ASSERT_EQ(srs.importFromWkt(b.crs_wkt.c_str()), OGRERR_NONE);
  int north = 0;
  EXPECT_EQ(srs.GetUTMZone(&north), 2);
  EXPECT_TRUE(north);
  // Bering Strait, about 65.3 N 168.4 W.
  EXPECT_NEAR(0.5 * (b.extent.west + b.extent.east), -168.4, 0.05);
  EXPECT_NEAR(0.5 * (b.extent.south + b.extent.north), 65.3, 0.05);
  EXPECT_EQ(b.sense_used, VerticalSense::elevation);
  EXPECT_NE(b.sense_reason.find("BAG"), std::string::npos) << b.sense_reason;
  EXPECT_TRUE(b.has_nodata);
  EXPECT_DOUBLE_EQ(b.nodata, 1e6);
  // Elevation -52.957 .. -50.987 m -> depth 50.987 .. 52.957 m (float32 cells).
  EXPECT_NEAR(b.min_depth_m, 50.987, 5e-4);
  EXPECT_NEAR(b.max_depth_m, 52.957, 5e-4);
  EXPECT_NEAR(b.valid_fraction, 0.4587, 5e-4);
  EXPECT_GT(b.windows_read, 0u);
}

TEST(BathymetryReal, NominalOnlyBagHasNoCrs) {
  REAL_FILE_OR_SKIP(path, "bag-ons/nominal_only.bag");
  expect_one_line_error([&] { inspect_bathymetry(path); }, "give the CRS it uses (`src_crs`");
  // Its coordinates are synthetic; any projected CRS makes it readable.
  const BathymetryInfo b = inspect_bathymetry(path, assumed("EPSG:32631"));
  EXPECT_EQ(b.width, 10);
  EXPECT_EQ(b.height, 10);
  EXPECT_EQ(b.crs_source, "assumed (option)");
  // Elevation 10 .. 19.9 (positive: not real depth) -> depth -19.9 .. -10.
  EXPECT_NEAR(b.min_depth_m, -19.9, 1e-5);
  EXPECT_NEAR(b.max_depth_m, -10.0, 1e-5);
  EXPECT_DOUBLE_EQ(b.valid_fraction, 1.0);
}

TEST(BathymetryReal, VariableResolutionBag) {
  REAL_FILE_OR_SKIP(path, "bag-ons/test_vr.bag");
  // GDAL opens it as is: the low-resolution grid of 6x4 supergrids.
  const BathymetryInfo low = inspect_bathymetry(path);
  EXPECT_EQ(low.width, 6);
  EXPECT_EQ(low.height, 4);
  EXPECT_EQ(low.sense_used, VerticalSense::elevation);  // BAG, despite its "MLLW depth" vertical CRS
  BathymetryOptions o;
  o.open_options = {"MODE=RESAMPLED_GRID"};
  const BathymetryInfo grid = inspect_bathymetry(path, o);
  EXPECT_EQ(grid.width, 36);
  EXPECT_EQ(grid.height, 24);
  // NAD83 / UTM zone 10N.
  OGRSpatialReference srs;
  ASSERT_EQ(srs.importFromWkt(grid.crs_wkt.c_str()), OGRERR_NONE);
  int north = 0;
  EXPECT_EQ(srs.GetUTMZone(&north), 10);
}

// ---------------------------------------------------------------- NetCDF/GMT

TEST(BathymetryReal, TutBathyBermudaAllSea) {
  REAL_FILE_OR_SKIP(path, "bathy-gmt-cache/tut_bathy.nc");
  const BathymetryInfo b = inspect_bathymetry(path);
  EXPECT_EQ(b.driver, "netCDF");
  EXPECT_EQ(b.width, 73);
  EXPECT_EQ(b.height, 61);
  EXPECT_NE(b.crs_source.find("CF"), std::string::npos) << b.crs_source;  // x/y in degrees_east/north
  EXPECT_EQ(b.crs, "EPSG:4326");
  EXPECT_NEAR(b.pixel_x, 5.0 / 60.0, 1e-9);
  EXPECT_NEAR(b.extent.west, -66.04, 0.005);
  EXPECT_NEAR(b.extent.east, -59.96, 0.005);
  EXPECT_NEAR(b.extent.south, 29.96, 0.005);
  EXPECT_NEAR(b.extent.north, 35.04, 0.005);
  EXPECT_TRUE(b.has_nodata);
  EXPECT_DOUBLE_EQ(b.nodata, -32768);
  EXPECT_EQ(b.sense_used, VerticalSense::elevation);  // long_name Topography
  EXPECT_DOUBLE_EQ(b.min_depth_m, 89);
  EXPECT_DOUBLE_EQ(b.max_depth_m, 5475);
  EXPECT_GT(b.min_depth_m, 0) << "no land cell";
}

TEST(BathymetryReal, Bathy1mAzoresHasLand) {
  REAL_FILE_OR_SKIP(path, "bathy-gmt-cache/bathy_1m.nc");
  // Its axes are plain x/y without units: no CRS in the file.
  expect_one_line_error([&] { inspect_bathymetry(path); }, "give the CRS it uses (`src_crs`");
  const BathymetryInfo b = inspect_bathymetry(path, assumed("EPSG:4326"));
  EXPECT_EQ(b.width, 601);
  EXPECT_EQ(b.height, 451);
  EXPECT_NEAR(b.extent.west, -33.01, 0.005);
  EXPECT_NEAR(b.extent.east, -22.99, 0.005);
  EXPECT_NEAR(b.extent.south, 35.49, 0.005);
  EXPECT_NEAR(b.extent.north, 43.01, 0.005);
  EXPECT_EQ(b.sense_used, VerticalSense::elevation);  // GMT's z
  // Elevation -5158.4 .. +1116.7 m -> depth -1116.7 .. 5158.4 m: land present.
  EXPECT_NEAR(b.min_depth_m, -1116.7, 0.05);
  EXPECT_NEAR(b.max_depth_m, 5158.4, 0.05);
  EXPECT_LT(b.min_depth_m, 0) << "islands";
}

// ---------------------------------------------------------------- ESRI ASCII

TEST(BathymetryReal, SmallCrmNeedsTheCrs) {
  REAL_FILE_OR_SKIP(path, "bathy-usml-crm/small_crm.asc");
  expect_one_line_error([&] { inspect_bathymetry(path); }, path);
  const BathymetryInfo b = inspect_bathymetry(path, assumed("EPSG:4326"));
  EXPECT_EQ(b.driver, "AAIGrid");
  EXPECT_EQ(b.width, 241);
  EXPECT_EQ(b.height, 241);
  EXPECT_NEAR(b.pixel_x, 0.000833, 1e-6);
  EXPECT_NEAR(b.extent.west, -79.9004, 1e-4);
  EXPECT_NEAR(b.extent.east, -79.6996, 1e-4);
  EXPECT_NEAR(b.extent.south, 29.3996, 1e-4);
  EXPECT_NEAR(b.extent.north, 29.6004, 1e-4);
  EXPECT_TRUE(b.has_nodata);
  EXPECT_NEAR(b.nodata, 0.1, 1e-7);  // GDAL keeps it at float32 precision
  EXPECT_NE(b.sense_reason.find("assumed elevation"), std::string::npos) << b.sense_reason;
  EXPECT_NEAR(b.min_depth_m, 622, 1e-3);
  EXPECT_NEAR(b.max_depth_m, 771, 1e-3);
  // The user may say the file holds depths: then the signs flip.
  BathymetryOptions as_depth = assumed("EPSG:4326");
  as_depth.sense = VerticalSense::depth;
  const BathymetryInfo d = inspect_bathymetry(path, as_depth);
  EXPECT_NEAR(d.min_depth_m, -771, 1e-3);
  EXPECT_NEAR(d.max_depth_m, -622, 1e-3);
  EXPECT_EQ(d.sense_reason, "given as an option");
}

// ---------------------------------------------------------------- synthetic

constexpr double kNoData = -9999.0;

// A W x H Float32 GeoTIFF tiled in 16x16 blocks: cell (x, y) = -(10 + x + 0.5 y),
// every 7th cell NoData, one NaN; CRS EPSG:32632 unless `crs` is empty.
std::vector<float> write_geotiff(const std::string& path, int w, int h, const std::string& crs = "EPSG:32632",
                                 const char* description = nullptr) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
  const char* co[] = {"TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16", nullptr};
  GDALDatasetUniquePtr ds(drv->Create(path.c_str(), w, h, 1, GDT_Float32, const_cast<char**>(co)));
  EXPECT_TRUE(ds);
  double gt[6] = {500000, 10, 0, 6000000, 0, -10};
  ds->SetGeoTransform(gt);
  if (!crs.empty()) {
    OGRSpatialReference srs;
    srs.SetFromUserInput(crs.c_str());
    ds->SetSpatialRef(&srs);
  }
  std::vector<float> v(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      v[i] = (i % 7 == 3) ? static_cast<float>(kNoData) : static_cast<float>(-(10 + x + 0.5 * y));
    }
  v[5] = std::numeric_limits<float>::quiet_NaN();
  GDALRasterBand* band = ds->GetRasterBand(1);
  band->SetNoDataValue(kNoData);
  if (description != nullptr) band->SetDescription(description);
  EXPECT_EQ(band->RasterIO(GF_Write, 0, 0, w, h, v.data(), w, h, GDT_Float32, 0, 0, nullptr), CE_None);
  return v;
}

TEST(BathymetrySynthetic, WindowedScanEqualsWholeRead) {
  test::ScratchDir dir;
  const std::string path = dir.file("grid.tif");
  const int w = 100, h = 70;
  write_geotiff(path, w, h);

  // Independent whole-raster read through GDAL.
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(ds);
  std::vector<double> all(static_cast<std::size_t>(w) * h);
  ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, w, h, all.data(), w, h, GDT_Float64, 0, 0, nullptr), CE_None);
  ds.reset();
  double lo = 1e300, hi = -1e300;
  std::size_t valid = 0;
  for (double v : all) {
    if (std::isnan(v) || v == kNoData) continue;
    ++valid;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }

  for (std::size_t cells : {std::size_t{1}, std::size_t{256}, std::size_t{700}, std::size_t{1} << 22}) {
    BathymetryOptions o;
    o.max_window_cells = cells;
    const BathymetryInfo b = inspect_bathymetry(path, o);
    SCOPED_TRACE(cells);
    EXPECT_EQ(b.valid_cells, valid);
    EXPECT_DOUBLE_EQ(b.valid_fraction, static_cast<double>(valid) / (w * h));
    EXPECT_DOUBLE_EQ(b.min_depth_m, -hi);
    EXPECT_DOUBLE_EQ(b.max_depth_m, -lo);
    EXPECT_EQ(b.crs, "EPSG:32632");
    if (cells <= 256) {
      EXPECT_EQ(b.windows_read, 7u * 5u);  // one 16x16 block per window
    }
    if (cells == std::size_t{1} << 22) {
      EXPECT_EQ(b.windows_read, 1u);
    }
  }
}

TEST(BathymetrySynthetic, DepthDescriptionSetsTheSense) {
  test::ScratchDir dir;
  const std::string path = dir.file("depth.tif");
  write_geotiff(path, 20, 20, "EPSG:32632", "Depth below sea level");
  const BathymetryInfo b = inspect_bathymetry(path);
  EXPECT_EQ(b.sense_used, VerticalSense::depth);
  EXPECT_NE(b.sense_reason.find("depth"), std::string::npos) << b.sense_reason;
  EXPECT_LT(b.max_depth_m, 0);  // the cells are negative and taken as depths
}

// ---------------------------------------------------------------- bad input

TEST(BathymetryErrors, MissingFile) {
  test::ScratchDir dir;
  const std::string path = dir.file("nothing.tif");
  expect_one_line_error([&] { inspect_bathymetry(path); }, path);
}

TEST(BathymetryErrors, CorruptGeoTiff) {
  test::ScratchDir dir;
  const std::string good = dir.file("good.tif");
  write_geotiff(good, 64, 64);
  std::ifstream in(good, std::ios::binary);
  std::string head(200, '\0');
  in.read(head.data(), 200);
  std::string garbage(300, '\0');
  for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<char>((i * 37 + 11) & 0xff);
  const std::string bad = dir.write("corrupt.tif", head + garbage);
  expect_one_line_error([&] { inspect_bathymetry(bad); }, bad + ": expected a raster GDAL can");
}

TEST(BathymetryErrors, NotARaster) {
  test::ScratchDir dir;
  const std::string bad = dir.write("notes.tif", "this is not a raster\n");
  expect_one_line_error([&] { inspect_bathymetry(bad); }, "expected a raster GDAL can open");
}

TEST(BathymetryErrors, RasterWithoutCrs) {
  test::ScratchDir dir;
  const std::string path = dir.file("nocrs.tif");
  write_geotiff(path, 20, 20, "");
  expect_one_line_error([&] { inspect_bathymetry(path); }, path + ": expected a raster with a CRS");
  expect_one_line_error([&] { inspect_bathymetry(path, assumed("EPSG:nope")); }, "assumed CRS");
  EXPECT_EQ(inspect_bathymetry(path, assumed("EPSG:32632")).crs, "EPSG:32632");
}

TEST(BathymetryErrors, MissingBand) {
  test::ScratchDir dir;
  const std::string path = dir.file("one.tif");
  write_geotiff(path, 20, 20);
  BathymetryOptions o;
  o.band = 2;
  expect_one_line_error([&] { inspect_bathymetry(path, o); }, "expected band 2");
}

}  // namespace
}  // namespace deepguide
