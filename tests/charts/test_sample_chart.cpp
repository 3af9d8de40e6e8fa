// The bundled sample chart (charts/): the generator is deterministic, the
// committed files equal a fresh synth, the chart has the features it claims
// (channel, bank, land, hazards); `chart info` on it and on real charts, its
// JSON, and bad input through the CLI (one-line errors, exit 1).

#include <gtest/gtest.h>

#include <gdal_priv.h>
#include <algorithm>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "deepguide/charts/bathymetry.hpp"
#include "deepguide/charts/chart_info.hpp"
#include "deepguide/charts/s57_chart.hpp"
#include "deepguide/charts/sample_chart.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "test_support.hpp"

namespace deepguide {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::ScratchDir;
using test::source_file;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// All cells of band 1 of a raster, read back through GDAL.
std::vector<float> read_cells(const std::string& path, int& width, int& height) {
  GDALAllRegister();
  GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  EXPECT_TRUE(ds) << path;
  if (!ds) return {};
  width = ds->GetRasterXSize();
  height = ds->GetRasterYSize();
  std::vector<float> cells(static_cast<std::size_t>(width) * height);
  EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, width, height, cells.data(), width, height, GDT_Float32, 0, 0,
                                           nullptr),
            CE_None);
  return cells;
}

// Depth (m, positive down) of the cell holding EPSG:32632 point p.
double depth_at(const SampleChart& chart, const Vec2& p) {
  const SampleChartLayout& l = sample_chart_layout();
  const int col = static_cast<int>(std::floor((p.x() - l.west) / l.cell_m));
  const int row = static_cast<int>(std::floor((l.north - p.y()) / l.cell_m));
  return -static_cast<double>(chart.at(col, row));
}

void expect_one_line_exit_1(const test::RunResult& r, const std::string& needle) {
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

// ---------------------------------------------------------------- generator

TEST(SampleChart, SameSeedSameValuesOtherSeedOtherRoughness) {
  const SampleChart a = make_sample_chart();
  const SampleChart b = make_sample_chart();
  ASSERT_EQ(a.elevation.size(), 480u * 520u);
  EXPECT_EQ(a.elevation, b.elevation);
  SampleChartOptions other;
  other.seed = 2;
  const SampleChart c = make_sample_chart(other);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.elevation.size(); ++i) differ += a.elevation[i] != c.elevation[i];
  EXPECT_GT(differ, a.elevation.size() / 2) << "the seed drives the sea-floor roughness";
  // The dredged channel does not depend on the seed.
  const SampleChartLayout& l = sample_chart_layout();
  EXPECT_EQ(depth_at(a, l.channel_start), depth_at(c, l.channel_start));
}

TEST(SampleChart, ChannelIsTwelveMetresAlongItsAxis) {
  const SampleChart chart = make_sample_chart();
  const SampleChartLayout& l = sample_chart_layout();
  const Vec2 dir = (l.channel_end - l.channel_start).normalized();
  EXPECT_NEAR((l.channel_end - l.channel_start).norm(), 900.0, 1e-9);
  // Course 020: 20 degrees clockwise from grid north.
  EXPECT_NEAR(std::atan2(dir.x(), dir.y()) * 180.0 / 3.141592653589793, 20.0, 1e-9);
  const Vec2 side(dir.y(), -dir.x());
  for (double t = 0.0; t <= 900.0; t += 25.0) {
    for (const double off : {-40.0, 0.0, 40.0}) {
      const Vec2 p = l.channel_start + t * dir + off * side;
      EXPECT_GE(depth_at(chart, p), 12.0) << "t " << t << " m, offset " << off << " m";
    }
  }
  // Where the channel crosses the bank, the bank beside it is 6-8 m: the
  // channel is dredged, 12 m exactly (1/32 m steps represent 12 exactly).
  const Vec2 on_bank = l.channel_start + 230.0 * dir;
  EXPECT_EQ(depth_at(chart, on_bank), 12.0);
  const double beside = depth_at(chart, on_bank + 150.0 * side);
  EXPECT_GT(beside, 5.0);
  EXPECT_LT(beside, 9.5);
}

TEST(SampleChart, LandOffshoreNoDataAndHazards) {
  const SampleChart chart = make_sample_chart();
  const SampleChartLayout& l = sample_chart_layout();
  // South-west corner: the headland (land, positive elevation).
  EXPECT_GT(chart.at(0, l.height - 1), 0.5f);
  EXPECT_GT(chart.at(l.width / 2, l.height - 1), 0.0f);  // the coast runs along the south
  // North-west: open water 20-30 m deep.
  EXPECT_GT(-chart.at(5, 5), 20.0f);
  EXPECT_LT(-chart.at(5, 5), 30.0f);
  // North-east corner: unsurveyed.
  EXPECT_EQ(chart.at(l.width - 1, 0), l.nodata);
  std::size_t land = 0, nodata = 0;
  float deepest = 0;
  for (float v : chart.elevation) {
    if (v == l.nodata) {
      ++nodata;
      continue;
    }
    land += v > 0.0f;
    deepest = std::min(deepest, v);
  }
  EXPECT_GT(land, chart.elevation.size() / 20);
  EXPECT_LT(land, chart.elevation.size() / 3);
  EXPECT_GT(nodata, 0u);
  EXPECT_GT(-deepest, 25.0f);
  EXPECT_LT(-deepest, 30.0f);

  std::map<std::string, int> kinds;
  for (const SampleHazard& h : chart.hazards) {
    ++kinds[h.kind];
    const double floor = depth_at(chart, h.position);
    EXPECT_GT(floor, 0.0) << h.id << " lies in water";
    EXPECT_LT(h.top_depth_m, floor) << h.id << ": its top stands above the sea floor";
    EXPECT_GT(h.top_depth_m, 0.0) << h.id;
  }
  EXPECT_EQ(chart.hazards.size(), 9u);
  EXPECT_EQ(kinds["wreck"], 3);
  EXPECT_EQ(kinds["rock"], 4);
  EXPECT_EQ(kinds["foul ground"] + kinds["spoil ground"], 2);
}

TEST(SampleChart, WritesTwiceTheSameAndReadsBack) {
  ScratchDir a, b;
  const SampleChartFiles fa = write_sample_chart(a.path().string());
  const SampleChartFiles fb = write_sample_chart(b.path().string());
  EXPECT_EQ(fs::path(fa.raster).filename(), "sample_chart.tif");
  EXPECT_EQ(fs::path(fa.hazards).filename(), "sample_chart_hazards.gpkg");
  EXPECT_EQ(slurp(fa.raster), slurp(fb.raster)) << "the GeoTIFF carries no timestamp";
  EXPECT_LT(fs::file_size(fa.raster), 300u * 1024u) << "small enough to commit";
  int w = 0, h = 0;
  EXPECT_EQ(read_cells(fa.raster, w, h), make_sample_chart().elevation);
  // Only the two files: no temporary or journal left behind.
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(a.path())) ++entries;
  EXPECT_EQ(entries, 2u);

  const LoadedObstacles loaded = load_obstacles({fa.hazards});
  EXPECT_EQ(loaded.frame.id(), "EPSG:32632");
  EXPECT_EQ(loaded.obstacles.ellipses.size(), 7u);
  EXPECT_EQ(loaded.obstacles.polygons.size(), 2u);
  const SampleChart chart = make_sample_chart();
  for (const EllipticCylinder& c : loaded.obstacles.ellipses) {
    const auto it =
        std::find_if(chart.hazards.begin(), chart.hazards.end(), [&](const auto& z) { return z.id == c.id; });
    ASSERT_NE(it, chart.hazards.end()) << c.id;
    EXPECT_NEAR((c.footprint.centre - it->position).norm(), 0.0, 1e-6) << c.id;
    EXPECT_DOUBLE_EQ(c.footprint.a, it->semi_major_m);
    ASSERT_TRUE(c.top_depth_m.has_value());
    EXPECT_DOUBLE_EQ(*c.top_depth_m, it->top_depth_m);
    // orientation_deg is from TRUE north; the frame turns it by the convergence.
    EXPECT_NEAR(loaded.frame.local_to_heading(c.footprint.theta, c.footprint.centre), it->orientation_deg, 1e-6);
  }
}

TEST(SampleChart, CommittedFilesEqualAFreshSynth) {
  const std::string tif = source_file("charts/sample_chart.tif");
  const std::string gpkg = source_file("charts/sample_chart_hazards.gpkg");
  ASSERT_TRUE(fs::exists(tif)) << tif;
  ASSERT_TRUE(fs::exists(gpkg)) << gpkg;
  int w = 0, h = 0;
  const std::vector<float> committed = read_cells(tif, w, h);
  const SampleChart fresh = make_sample_chart();
  ASSERT_EQ(committed.size(), fresh.elevation.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < committed.size(); ++i) {
    // Another libm may round a cell to the neighbouring 1/32 m step.
    differ += std::abs(committed[i] - fresh.elevation[i]) > 0.04f;
  }
  EXPECT_EQ(differ, 0u) << "regenerate with: deepguide chart synth -o charts";
  const LoadedObstacles loaded = load_obstacles({gpkg});
  EXPECT_EQ(loaded.obstacles.size(), fresh.hazards.size());
}

TEST(SampleChart, BadFolderOrName) {
  ScratchDir dir;
  EXPECT_THROW(write_sample_chart(dir.file("missing")), InputError);
  SampleChartOptions bad;
  bad.name = "../escape";
  EXPECT_THROW(write_sample_chart(dir.path().string(), bad), InputError);
  bad.name = "";
  EXPECT_THROW(write_sample_chart(dir.path().string(), bad), InputError);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

// ---------------------------------------------------------------- chart info

TEST(ChartInfo, SampleRaster) {
  const ChartInfo c = chart_info(source_file("charts/sample_chart.tif"));
  EXPECT_EQ(c.kind, ChartKind::raster);
  EXPECT_EQ(c.driver, "GTiff");
  EXPECT_EQ(c.crs, "EPSG:32632");
  EXPECT_EQ(c.local_crs, "EPSG:32632");
  ASSERT_EQ(c.layers.size(), 1u);
  EXPECT_EQ(c.layers[0].features, 480u * 520u);
  EXPECT_DOUBLE_EQ(c.width_m, 2400.0);
  EXPECT_DOUBLE_EQ(c.height_m, 2600.0);
  EXPECT_EQ(c.hazards, 0u);
  EXPECT_FALSE(c.no_go.has_value());
  // Independent: the generator's own cells.
  const SampleChart fresh = make_sample_chart();
  double lo = INFINITY, hi = -INFINITY;
  std::size_t valid = 0;
  for (float v : fresh.elevation) {
    if (v == sample_chart_layout().nodata) continue;
    ++valid;
    lo = std::min(lo, -static_cast<double>(v));
    hi = std::max(hi, -static_cast<double>(v));
  }
  EXPECT_DOUBLE_EQ(c.min_depth_m, lo);
  EXPECT_DOUBLE_EQ(c.max_depth_m, hi);
  EXPECT_LT(c.min_depth_m, 0.0) << "land";
  EXPECT_NEAR(c.valid_fraction, static_cast<double>(valid) / fresh.elevation.size(), 1e-12);
  // Kiel Bight, lon 10.23-10.27, lat 54.44-54.46.
  EXPECT_NEAR(c.extent.west, 10.232, 0.002);
  EXPECT_NEAR(c.extent.north, 54.4627, 0.002);
  // What `chart info` prints says the same.
  const std::string text = to_text(c);
  EXPECT_EQ(text.rfind(c.path + "  [bathymetry raster, GTiff, EPSG:32632]\n", 0), 0u) << text;
  EXPECT_NE(text.find("raster           480 x 520 cells of 5 x 5, "), std::string::npos) << text;
  EXPECT_NE(text.find("depth range      " + printf_text("%.2f .. %.2f m", lo, hi) + "\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("no-go at"), std::string::npos) << "no depth was given: " << text;
}

TEST(ChartInfo, SampleRasterNoGoAtTenMetres) {
  ChartInfoOptions o;
  o.depth_m = 10.0;
  o.clearance_m = 2.0;
  const ChartInfo c = chart_info(source_file("charts/sample_chart.tif"), o);
  ASSERT_TRUE(c.no_go.has_value());
  // Independent count: NoData, land and water shallower than 10 + 2 m; the
  // 12 m channel is just deep enough.
  const SampleChart fresh = make_sample_chart();
  std::size_t expected = 0;
  for (float v : fresh.elevation) expected += v == sample_chart_layout().nodata || -v < 12.0f;
  EXPECT_EQ(c.no_go->no_go_cells, expected);
  EXPECT_EQ(c.no_go->total_cells, 480u * 520u);
  // The polygons cover every no-go cell (25 m2 each) and never shrink.
  EXPECT_GE(c.no_go->area_m2, 25.0 * static_cast<double>(expected) - 1.0);
  EXPECT_LT(c.no_go->area_m2, 25.0 * static_cast<double>(expected) * 1.1);
  EXPECT_GE(c.no_go->polygons, 3u);  // coast and bank, two shoals, the unsurveyed corner
}

TEST(ChartInfo, SampleHazards) {
  ChartInfoOptions o;
  o.depth_m = 10.0;
  const ChartInfo c = chart_info(source_file("charts/sample_chart_hazards.gpkg"), o);
  EXPECT_EQ(c.kind, ChartKind::vector);
  EXPECT_EQ(c.driver, "GPKG");
  ASSERT_EQ(c.layers.size(), 1u);
  EXPECT_EQ(c.layers[0].name, "hazards");
  EXPECT_EQ(c.layers[0].features, 9u);
  EXPECT_EQ(c.hazards, 9u);
  const SampleChart fresh = make_sample_chart();
  double lo = INFINITY, hi = -INFINITY;
  std::size_t passable = 0;
  for (const SampleHazard& h : fresh.hazards) {
    lo = std::min(lo, h.top_depth_m);
    hi = std::max(hi, h.top_depth_m);
    passable += h.top_depth_m > 12.0;
  }
  EXPECT_DOUBLE_EQ(c.min_depth_m, lo);
  EXPECT_DOUBLE_EQ(c.max_depth_m, hi);
  ASSERT_TRUE(c.no_go.has_value());
  EXPECT_EQ(c.no_go->hazards_passable, passable);
  EXPECT_EQ(c.no_go->polygons, 9u - passable);
  EXPECT_GT(c.no_go->area_m2, 0.0);
}

TEST(ChartInfo, RealS57Cell) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, "noaa-enc-US5FL4DQ/US5FL4DQ.000");
  const ChartInfo c = chart_info(path);
  EXPECT_EQ(c.kind, ChartKind::s57);
  EXPECT_EQ(c.driver, "S57");
  EXPECT_GT(c.layers.size(), 5u);
  EXPECT_GT(c.hazards, 0u);
  EXPECT_GT(c.land_features, 0u);
  // Key West, Florida.
  EXPECT_NEAR(0.5 * (c.extent.west + c.extent.east), -81.8, 0.3);
  EXPECT_NEAR(0.5 * (c.extent.south + c.extent.north), 24.5, 0.3);
  // Same numbers as the S-57 reader's own summary.
  const S57Summary s = summarize_s57(path);
  EXPECT_EQ(c.layers.size(), s.layer_counts.size());
}

TEST(ChartInfo, RealBag) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, "bag-ons/JD211_public_Release_1-4_UTM.bag");
  const ChartInfo c = chart_info(path);
  EXPECT_EQ(c.kind, ChartKind::raster);
  EXPECT_EQ(c.raster_width, 1707);
  EXPECT_EQ(c.raster_height, 1478);
  EXPECT_NEAR(c.min_depth_m, 50.987, 5e-4);
  EXPECT_NEAR(c.max_depth_m, 52.957, 5e-4);
  EXPECT_EQ(c.hazards, 0u);
}

TEST(ChartInfo, BadInput) {
  ScratchDir dir;
  EXPECT_THROW(chart_info(dir.file("none.tif")), InputError);
  EXPECT_THROW(chart_info(dir.path().string()), InputError);
  EXPECT_THROW(chart_info(dir.write("junk.bin", std::string("\x01\x02garbage\xff", 11))), InputError);
  ChartInfoOptions o;
  o.depth_m = -1.0;
  EXPECT_THROW(chart_info(source_file("charts/sample_chart.tif"), o), InputError);
  o.depth_m = INFINITY;
  EXPECT_THROW(chart_info(source_file("charts/sample_chart.tif"), o), InputError);
  o.depth_m = 5.0;
  o.clearance_m = -0.5;
  EXPECT_THROW(chart_info(source_file("charts/sample_chart.tif"), o), InputError);
}

// ---------------------------------------------------------------- CLI

TEST(ChartCli, InfoJson) {
  const auto r = run_cli("chart info --json --depth 10 '" + source_file("charts/sample_chart.tif") + "' '" +
                         source_file("charts/sample_chart_hazards.gpkg") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j[0]["kind"], "bathymetry raster");
  EXPECT_EQ(j[0]["crs"], "EPSG:32632");
  EXPECT_EQ(j[0]["raster"]["width"], 480);
  EXPECT_EQ(j[0]["hazards"], 0);
  EXPECT_GT(j[0]["no_go"]["area_m2"].get<double>(), 0.0);
  EXPECT_EQ(j[0]["no_go"]["depth_m"], 10.0);
  EXPECT_EQ(j[1]["kind"], "hazard file");
  EXPECT_EQ(j[1]["hazards"], 9);
  EXPECT_EQ(j[1]["layers"][0]["name"], "hazards");
  EXPECT_TRUE(j[1]["extent"]["west"].is_number());
}

TEST(ChartCli, ACutShortBagIsOneLineWithoutHdf5sDiagnostics) {
  // HDF5 printed its error stack (11-20 lines) before our message.
  DEEPGUIDE_REAL_FILE_OR_SKIP(path, "bag-ons/JD211_public_Release_1-4_UTM.bag");
  ScratchDir dir;
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.resize(100000);
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  const std::string cut = dir.write("cut.bag", bytes);
  for (const std::string& cmd :
       {"chart info '" + cut + "'", "plan --chart '" + cut + "' --depth 5 --from 0,0 --to 0.01,0.01"}) {
    const auto r = run_cli(cmd);
    EXPECT_EQ(r.exit_code, 1) << cmd << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << cmd << ": " << r.err;
    EXPECT_EQ(r.err.find("HDF5"), std::string::npos) << cmd << ": " << r.err;
    EXPECT_EQ(r.err.rfind("deepguide: error: ", 0), 0u) << cmd << ": " << r.err;
  }
}

TEST(ChartCli, InfoText) {
  const auto r = run_cli("chart info --depth 10 '" + source_file("charts/sample_chart.tif") + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2400.0 m x 2600.0 m"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no-go at 10 m"), std::string::npos) << r.out;
}

TEST(ChartCli, SynthWritesBothFiles) {
  ScratchDir dir;
  const auto r = run_cli("chart synth -o '" + dir.path().string() + "' --name approach");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.file("approach.tif")));
  EXPECT_TRUE(fs::exists(dir.file("approach_hazards.gpkg")));
}

TEST(ChartCli, BadInputExitsOne) {
  ScratchDir dir;
  expect_one_line_exit_1(run_cli("chart info '" + dir.file("missing.tif") + "'"), "missing.tif");
  expect_one_line_exit_1(run_cli("chart info '" + dir.write("notes.txt", "hello\n") + "'"), "notes.txt");
  expect_one_line_exit_1(run_cli("chart info --depth -3 '" + source_file("charts/sample_chart.tif") + "'"), "--depth");
  expect_one_line_exit_1(run_cli("chart info --depth nan '" + source_file("charts/sample_chart.tif") + "'"), "--depth");
  expect_one_line_exit_1(run_cli("chart synth -o '" + dir.file("no/such/dir") + "'"), "no/such/dir");
  EXPECT_EQ(run_cli("chart info").exit_code, 2);  // usage
}

}  // namespace
}  // namespace deepguide
