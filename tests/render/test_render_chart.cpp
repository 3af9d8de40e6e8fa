// The sea chart figure: size, the colours at known places of the sample chart
// (land, deep water, no-go over the bank, no data), SVG output, and bad input
// through the library and the CLI (one-line errors, exit 1, no file left).
#include <cairo.h>
#include <gtest/gtest.h>

#include <array>
#include <boost/geometry.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "deepguide/charts/sample_chart.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/render/chart_scene.hpp"
#include "deepguide/render/enc_layer.hpp"
#include "deepguide/render/route_on_chart.hpp"
#include "deepguide/world/local_frame.hpp"
#include "png_reader.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::run_cli;
using deepguide::test::ScratchDir;
using deepguide::test::source_file;

namespace {

using test::Png;

::testing::AssertionResult same_colour(const std::array<int, 3>& got, const Rgba& want, int tol = 3) {
  const int w[3] = {static_cast<int>(std::lround(want.r * 255)), static_cast<int>(std::lround(want.g * 255)),
                    static_cast<int>(std::lround(want.b * 255))};
  for (int i = 0; i < 3; ++i) {
    if (std::abs(got[i] - w[i]) > tol) {
      return ::testing::AssertionFailure() << "got rgb(" << got[0] << "," << got[1] << "," << got[2] << "), want rgb("
                                           << w[0] << "," << w[1] << "," << w[2] << ")";
    }
  }
  return ::testing::AssertionSuccess();
}

Rgba blend(const Rgba& under, const Rgba& over, double alpha) {
  return {under.r + alpha * (over.r - under.r), under.g + alpha * (over.g - under.g),
          under.b + alpha * (over.b - under.b), 1.0};
}

ChartRenderOptions sample(int width = 800) {
  ChartRenderOptions o;
  o.charts = {source_file("charts/sample_chart.tif"), source_file("charts/sample_chart_hazards.gpkg")};
  o.width_px = width;
  return o;
}

// EPSG:32632 point of the sample chart's design point (metres from its south-west corner).
Vec2 design(double x, double y) {
  const SampleChartLayout& l = sample_chart_layout();
  return {l.west + x, l.north - l.height * l.cell_m + y};
}

std::size_t band_of(const ChartLayout& l, double depth) {
  std::size_t i = 0;
  while (i + 2 < l.band_edges.size() && depth >= l.band_edges[i + 1]) ++i;
  return i;
}

}  // namespace

TEST(RenderChart, SampleColoursAtKnownPlaces) {
  ScratchDir dir;
  const std::string out = dir.file("chart.png");
  const ChartLayout l = render_chart(sample(800), out);
  Png png(out);
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.width(), 800);
  EXPECT_EQ(png.height(), l.height);
  EXPECT_EQ(l.frame_id, "EPSG:32632");
  EXPECT_EQ(l.hazards, 9u);
  // The whole raster is shown: 2400 m x 2600 m, nothing more.
  EXPECT_NEAR(l.extent.width(), 2400.0, 1e-6);
  EXPECT_NEAR(l.extent.height(), 2600.0, 1e-6);
  // Depth bands of a round step over 0 .. 28.4 m: 0, 5, ..., 30.
  ASSERT_EQ(l.band_edges.size(), 7u);
  EXPECT_DOUBLE_EQ(l.band_edges.front(), 0.0);
  EXPECT_DOUBLE_EQ(l.band_edges.back(), 30.0);
  const ChartStyle style;
  // Land: the headland in the south-west.
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(design(60.0, 60.0))), style.land));
  // Open water in the north-west, 25-30 m deep: the deepest band.
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(design(40.0, 2560.0))), l.band_colors[band_of(l, 27.0)]));
  // The dredged channel (12 m) and the harbour basin (12 m): band 10-15.
  const SampleChartLayout& s = sample_chart_layout();
  const Vec2 on_bank = s.channel_start + 230.0 * (s.channel_end - s.channel_start).normalized();
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(on_bank)), l.band_colors[2]));
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(design(800.0, 200.0))), l.band_colors[2]));
  // The unsurveyed north-east corner.
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(design(2395.0, 2595.0))), style.nodata));
  // Title band and footer are white.
  EXPECT_TRUE(same_colour(png.at({3.0, 3.0}), style.background));
}

TEST(RenderChart, NoGoOverTheBankButNotInTheChannelOrOnLand) {
  ScratchDir dir;
  const std::string out = dir.file("nogo.png");
  ChartRenderOptions o = sample(800);
  o.depth_m = 10.0;
  o.clearance_m = 2.0;
  const ChartLayout l = render_chart(o, out);
  EXPECT_GE(l.no_go_polygons, 3u);
  Png png(out);
  ASSERT_TRUE(png.ok());
  const ChartStyle style;
  const SampleChartLayout& s = sample_chart_layout();
  const Vec2 dir_ = (s.channel_end - s.channel_start).normalized();
  const Vec2 side(dir_.y(), -dir_.x());
  // On the bank 150 m beside the channel: 5-10 m deep, under translucent red.
  const Vec2 bank = s.channel_start + 230.0 * dir_ + 150.0 * side;
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(bank)), blend(l.band_colors[1], style.no_go, 0.28), 4));
  // The channel itself is 12 m: deep enough for 10 + 2 m, no red.
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(s.channel_start + 230.0 * dir_)), l.band_colors[2]));
  // Land is no-go too, but stays beige.
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(design(60.0, 60.0))), style.land));
}

TEST(RenderChart, SvgAndObstacles) {
  ScratchDir dir;
  const std::string out = dir.file("chart.svg");
  ChartRenderOptions o = sample(600);
  o.obstacles = {source_file("data/sample_obstacles.geojson")};
  render_chart(o, out);
  std::ifstream in(out);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("width=\"600"), std::string::npos);
}

// The overlay's legend wraps instead of running off the image: each row it
// needs adds 24 design units to the footer, and every entry of a row ends
// inside the image (measured with the same text widths the drawing uses).
TEST(RenderChart, OverlayLegendWrapsIntoRowsThatFit) {
  ScratchDir dir;
  ChartRenderOptions o = sample(600);  // unit 0.5
  o.overlay_legend = {{rgb_hex(0x000000), 2.0, false, "short"}};
  const int one_row = render_chart(o, dir.file("one.png")).height;
  o.overlay_legend.clear();
  const std::string label = "an entry with a fairly long label, and longer still";
  for (int k = 0; k < 6; ++k) o.overlay_legend.push_back({rgb_hex(0x000000), 2.0, k % 2 == 0, label});
  const int many = render_chart(o, dir.file("many.png")).height;
  // Room for a row: 600 - (330 + 24) * 0.5 = 423 px; an entry: 46 * 0.5 + the label at 6.5 px.
  const double entry = 23.0 + measure_text_width(label, 6.5);
  ASSERT_GT(entry, 423.0 / 3.0) << "the label must be long enough for at most 2 entries a row";
  const int per_row = static_cast<int>((423.0 + 9.0) / entry);
  ASSERT_GE(per_row, 1);
  const int rows = (6 + per_row - 1) / per_row;
  EXPECT_NEAR(many - one_row, 12.0 * (rows - 1), 1.0) << per_row << " entries a row";
  EXPECT_GE(rows, 3);
}

TEST(RenderChart, BadInputLeavesNoFile) {
  ScratchDir dir;
  ChartRenderOptions o = sample(800);
  EXPECT_THROW(render_chart(o, dir.file("chart.jpg")), InputError);
  o.depth_m = -2.0;
  EXPECT_THROW(render_chart(o, dir.file("a.png")), InputError);
  o.depth_m = 5.0;
  o.width_px = 50;
  EXPECT_THROW(render_chart(o, dir.file("a.png")), InputError);
  o = sample(800);
  o.charts.push_back(dir.file("missing.tif"));
  EXPECT_THROW(render_chart(o, dir.file("a.png")), InputError);
  o.charts = {};
  EXPECT_THROW(render_chart(o, dir.file("a.png")), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(RenderChartCli, WritesPngOfTheRequestedWidth) {
  ScratchDir dir;
  const std::string out = dir.file("c.png");
  const auto r = run_cli("render chart '" + source_file("charts/sample_chart.tif") + "' '" +
                         source_file("charts/sample_chart_hazards.gpkg") + "' --depth 8 --width 640 -o '" + out + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Png png(out);
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.width(), 640);
  EXPECT_NE(r.out.find("no-go polygon"), std::string::npos) << r.out;
}

TEST(RenderChartCli, BadInputExitsOneWithOneLine) {
  ScratchDir dir;
  const std::string chart = "'" + source_file("charts/sample_chart.tif") + "'";
  auto one_line = [](const test::RunResult& r, const std::string& needle) {
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
  };
  one_line(run_cli("render chart '" + dir.file("none.tif") + "' -o '" + dir.file("a.png") + "'"), "none.tif");
  one_line(run_cli("render chart '" + dir.write("x.txt", "not a chart") + "' -o '" + dir.file("a.png") + "'"), "x.txt");
  one_line(run_cli("render chart " + chart + " --depth -1 -o '" + dir.file("a.png") + "'"), "--depth");
  one_line(run_cli("render chart " + chart + " -o '" + dir.file("a.gif") + "'"), "a.gif");
  one_line(run_cli("render chart " + chart + " -o '" + dir.file("no/dir/a.png") + "'"), "no/dir");
  EXPECT_FALSE(std::filesystem::exists(dir.file("a.png")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("a.gif")));
}

// A route over an S-57 cell: the route, its start and goal on top of the
// chart's tints and hatching, the map around the route's box.
TEST(RenderChart, RouteOverAnEncCell) {
  DEEPGUIDE_REAL_FILE_OR_SKIP(cell, "noaa-enc-US5FL4DQ/US5FL4DQ.000");
  ScratchDir dir;
  const std::string out = dir.file("route.png");
  RouteOnChart r;
  r.chart.charts = {cell};
  r.chart.depth_m = 1.0;
  r.chart.local_crs = "EPSG:32617";
  const LocalFrame frame = LocalFrame::from_user_crs(r.chart.local_crs);
  r.route = {frame.from_lonlat(-81.84, 24.59), frame.from_lonlat(-81.83, 24.55)};
  r.chart.width_px = 900;
  const ChartLayout l = render_route_on_chart(r, out);
  EXPECT_EQ(l.width, 900);
  // The map holds the route's box widened by a fifth of its size (at least 1 km).
  EXPECT_LE(l.extent.min.y(), r.route[1].y() - 1000.0 + 1e-6);
  EXPECT_GE(l.extent.max.y(), r.route[0].y() + 1000.0 - 1e-6);
  Png png(out);
  ASSERT_TRUE(png.ok());
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(0.5 * (r.route[0] + r.route[1]))), rgb_hex(0x1864d6), 12));
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(r.route[0])), rgb_hex(0x2f9e44), 12));
  EXPECT_TRUE(same_colour(png.at(l.view.to_pixel(r.route[1])), rgb_hex(0xc92a2a), 12));
  // Depth bands from the cell's depth areas (DRVAL2 up to 18.2 m).
  ASSERT_GE(l.band_edges.size(), 3u);
  EXPECT_GE(l.band_edges.back(), 18.2);
}

// An exchange set drawn as the planners read it: Homer's band-5 cell inside
// the band-4 cell round it. Where both cover, only the harbour cell's
// soundings are drawn (the approach cell's would pile up under them), each
// cell is outlined, and the command says how many no-go polygons and
// hazards it drew.
TEST(RenderChart, SeveralCellsAreDrawnAsThePlannersReadThem) {
  const std::string set = test::real_folder("noaa-enc-kachemak");
  if (set.empty()) GTEST_SKIP() << "../shared/data/real/noaa-enc-kachemak is absent";
  const std::string si = set + "/US5AK5SI_ENC_ROOT", ph = set + "/US4AK4PH_ENC_ROOT";
  const LocalFrame frame = LocalFrame::from_user_crs("EPSG:32605");
  const EncLayer harbour = read_enc_layer({si}, frame, NAN, 2.0);
  const EncLayer both = read_enc_layer({ph, si}, frame, NAN, 2.0);
  ASSERT_EQ(both.cells.size(), 2u);
  EXPECT_EQ(both.cells[0].name, "US5AK5SI");  // the better scale first, whatever the order given
  EXPECT_EQ(both.cells[1].usage_band, 4);
  EXPECT_TRUE(harbour.cells.empty());
  auto inside_harbour = [&](const EncLayer& l) {
    std::size_t n = 0;
    for (const EncLayer::Sounding& s : l.soundings) n += boost::geometry::covered_by(to_bg(s.at), harbour.coverage);
    return n;
  };
  EXPECT_GT(inside_harbour(harbour), 0u);
  EXPECT_EQ(inside_harbour(both), inside_harbour(harbour));
  EXPECT_GT(both.soundings.size(), harbour.soundings.size());  // the approach cell's, outside the harbour cell
  ScratchDir tmp;
  const test::RunResult r =
      run_cli("render chart '" + ph + "' '" + si + "' --depth 5 -o '" + tmp.file("two.png") + "' --width 600");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find(" 0 no-go polygon(s)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(" 0 hazard(s)"), std::string::npos) << r.out;
}
