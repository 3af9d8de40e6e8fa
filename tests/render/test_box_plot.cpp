// Box plots (render/box_plot.hpp), read back from the pixels at hand-derived
// places: at 1000 x 500 px (unit 1) the plot area is x 90 .. 970, y 70 .. 436;
// the values 1 .. 100 pad the axis by 5 % of their range (-3.95 .. 104.95),
// and nearest-rank quantiles put the box at 25 .. 75, the median at 50 and
// the whiskers at 5 and 95. One group fills the area: its centre is x 530,
// its box 110 px wide. The x axis is categorical: no tick at its corner.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "deepguide/core/error.hpp"
#include "deepguide/render/box_plot.hpp"
#include "png_reader.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::ScratchDir;

namespace {

constexpr double kBottom = 436.0, kHeight = 366.0, kLo = -3.95, kHi = 104.95;
double y_px(double v) { return kBottom - (v - kLo) / (kHi - kLo) * kHeight; }

Rgba over_white(const Rgba& c, double alpha) {
  return {1.0 + alpha * (c.r - 1.0), 1.0 + alpha * (c.g - 1.0), 1.0 + alpha * (c.b - 1.0), 1.0};
}

}  // namespace

TEST(BoxPlot, QuartilesMedianAndWhiskersWhereTheValuesSay) {
  BoxPlot plot;
  plot.title = "test";
  plot.width_px = 1000;
  plot.height_px = 500;
  const Rgba colour = rgb_hex(0x1864d6);
  BoxGroup g{"one", {}, colour};
  for (int v = 100; v >= 1; --v) g.values.push_back(v);  // unsorted on purpose
  plot.groups.push_back(g);
  ScratchDir dir;
  const std::string path = dir.file("box.png");
  render_box_plot(plot, path);
  const test::Png png(path);
  ASSERT_TRUE(png.ok());
  ASSERT_EQ(png.width(), 1000);
  ASSERT_EQ(png.height(), 500);
  const Rgba white = rgb_hex(0xffffff);
  const Rgba fill = over_white(colour, 0.25);
  const double inside = 530.0 + 30.0;  // in the box, off the whisker
  EXPECT_LE(test::colour_distance(png.at({inside, y_px(35.0)}), fill), 4) << "inside the box, 25 .. 75";
  EXPECT_LE(test::colour_distance(png.at({inside, y_px(65.0)}), fill), 4);
  EXPECT_LE(test::colour_distance(png.at({inside, y_px(50.0)}), colour), 20) << "the median line";
  EXPECT_LE(test::colour_distance(png.at({inside, y_px(22.0)}), white), 4) << "below the box";
  EXPECT_LE(test::colour_distance(png.at({inside, y_px(78.0)}), white), 4) << "above the box";
  EXPECT_LE(test::colour_distance(png.at({530.2, y_px(15.0)}), colour), 60) << "the lower whisker";
  EXPECT_LE(test::colour_distance(png.at({530.2, y_px(85.0)}), colour), 60) << "the upper whisker";
  EXPECT_LE(test::colour_distance(png.at({550.0, y_px(5.0)}), colour), 90) << "the whisker's cap at 5";
  EXPECT_LE(test::colour_distance(png.at({550.0, y_px(95.0)}), colour), 90) << "the whisker's cap at 95";
  EXPECT_LE(test::colour_distance(png.at({550.0, y_px(12.0)}), white), 4) << "between the cap and the box";
  EXPECT_LE(test::colour_distance(png.at({530.2, y_px(97.5)}), colour), 140) << "a dot beyond 95";
  EXPECT_LE(test::colour_distance(png.at({90.5, kBottom + 3.0}), white), 4) << "no tick under the corner";
}

TEST(BoxPlot, LogAxisLeavesOutWhatItCannotDrawAndBadInputIsRefused) {
  ScratchDir dir;
  BoxPlot plot;
  plot.log_y = true;
  plot.groups.push_back({"a", {0.0, -1.0, 10.0, 100.0}, rgb_hex(0x000000)});
  render_box_plot(plot, dir.file("log.png"));
  EXPECT_TRUE(test::Png(dir.file("log.png")).ok());

  plot.groups = {{"none", {0.0, -2.0, std::nan("")}, rgb_hex(0x000000)}};
  test::expect_error(test::error_of([&] { render_box_plot(plot, dir.file("none.png")); }), {"none.png", "values"});
  plot.groups.clear();
  test::expect_error(test::error_of([&] { render_box_plot(plot, dir.file("empty.png")); }), {"empty.png", "group"});
  plot.groups = {{"a", {1.0}, rgb_hex(0x000000)}};
  plot.width_px = 100;
  test::expect_error(test::error_of([&] { render_box_plot(plot, dir.file("small.png")); }), {"small.png", "size"});
  EXPECT_FALSE(std::filesystem::exists(dir.file("none.png")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("small.png")));
}
