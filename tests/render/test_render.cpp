// The route chart: the world-to-pixel transform, what lands on which pixel,
// the PNG and SVG files, failures that must leave no file, and the CLI.
#include <cairo.h>
#include <gtest/gtest.h>

#include <boost/geometry/algorithms/correct.hpp>
#include <boost/geometry/io/wkt/read.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>

#include "deepguide/core/error.hpp"
#include "deepguide/render/canvas.hpp"
#include "deepguide/render/route_scene.hpp"
#include "png_reader.hpp"
#include "test_support.hpp"

using namespace deepguide;

// Under AddressSanitizer, fontconfig's caches (reached through Cairo's text)
// show up as leaks at exit; they are third-party, once per process, and freed
// only by FcFini(). These hooks, read by the sanitizer runtime and inert in
// other builds, suppress exactly those reports and keep stderr clean.
extern "C" const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
using deepguide::test::run_cli;
using deepguide::test::ScratchDir;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> folder_entries(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

using test::Png;

std::array<int, 3> rgb(const Rgba& c) {
  return {static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
          static_cast<int>(std::lround(c.b * 255))};
}

::testing::AssertionResult same_colour(const std::array<int, 3>& got, const Rgba& want, int tol = 3) {
  const auto w = rgb(want);
  for (int i = 0; i < 3; ++i) {
    if (std::abs(got[i] - w[i]) > tol) {
      return ::testing::AssertionFailure() << "got rgb(" << got[0] << "," << got[1] << "," << got[2] << "), want rgb("
                                           << w[0] << "," << w[1] << "," << w[2] << ")";
    }
  }
  return ::testing::AssertionSuccess();
}

/// Width from the PNG header: the IHDR chunk follows the 8-byte signature.
std::uint32_t png_header_width(const std::string& bytes) {
  if (bytes.size() < 24) return 0;
  std::uint32_t w = 0;
  for (int i = 16; i < 20; ++i) w = (w << 8) | static_cast<unsigned char>(bytes[static_cast<std::size_t>(i)]);
  return w;
}

/// An ellipse at the origin, a square polygon with a square hole, and a
/// two-leg route whose first leg runs along y = -200.
struct SmallScene {
  ObstacleSet obstacles;
  RouteScene scene;
  BgPolygon square;

  SmallScene() {
    EllipticCylinder e;
    e.id = "e1";
    e.footprint.centre = Vec2(0.0, 0.0);
    e.footprint.a = 40.0;
    e.footprint.b = 20.0;
    e.footprint.theta = 0.3;
    obstacles.ellipses.push_back(e);
    PolygonObstacle p;
    p.id = "p1";
    boost::geometry::read_wkt("POLYGON((200 0,200 100,300 100,300 0,200 0),(230 30,270 30,270 70,230 70,230 30))",
                              p.footprint);
    boost::geometry::correct(p.footprint);
    obstacles.polygons.push_back(p);
    scene.obstacles = &obstacles;
    scene.margin = 12.0;
    scene.route = {{-300.0, -200.0}, {-100.0, -200.0}, {100.0, 250.0}};
    scene.start = scene.route.front();
    scene.goal = scene.route.back();
    scene.title = "test scene";
  }
};

}  // namespace

// ---------------------------------------------------------------- formats, transform

TEST(RenderFormat, FromTheExtension) {
  EXPECT_EQ(image_format_for("a/b/route.png"), ImageFormat::png);
  EXPECT_EQ(image_format_for("ROUTE.SVG"), ImageFormat::svg);
  try {
    image_format_for("out/route.pdf");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("out/route.pdf"), std::string::npos) << m;
    EXPECT_NE(m.find(".png or .svg"), std::string::npos) << m;
  }
  EXPECT_THROW(image_format_for("route"), InputError);
}

TEST(RenderTransform, NorthUpEqualScaleCentred) {
  WorldBox box;
  box.extend(Vec2(0.0, 0.0));
  box.extend(Vec2(100.0, 50.0));
  const ViewTransform v(box, PixelRect{10.0, 20.0, 200.0, 200.0});
  // Width limits: 2 px/m; the box's centre (50, 25) sits at the frame's centre (110, 120).
  EXPECT_DOUBLE_EQ(v.scale(), 2.0);
  EXPECT_NEAR(v.to_pixel({50.0, 25.0}).x(), 110.0, 1e-12);
  EXPECT_NEAR(v.to_pixel({50.0, 25.0}).y(), 120.0, 1e-12);
  EXPECT_NEAR(v.to_pixel({0.0, 0.0}).x(), 10.0, 1e-12);
  EXPECT_NEAR(v.to_pixel({0.0, 0.0}).y(), 170.0, 1e-12);
  EXPECT_NEAR(v.to_pixel({100.0, 50.0}).y(), 70.0, 1e-12);
  // North (larger y) is up (smaller row); east is right.
  EXPECT_LT(v.to_pixel({3.0, 40.0}).y(), v.to_pixel({3.0, 10.0}).y());
  EXPECT_GT(v.to_pixel({40.0, 3.0}).x(), v.to_pixel({10.0, 3.0}).x());
  // Equal scale: 10 m east and 10 m north are the same number of pixels.
  const Vec2 o = v.to_pixel({20.0, 20.0});
  EXPECT_NEAR((v.to_pixel({30.0, 20.0}) - o).norm(), (v.to_pixel({20.0, 30.0}) - o).norm(), 1e-12);
  const Vec2 w = v.to_world(v.to_pixel({12.5, -7.25}));
  EXPECT_NEAR(w.x(), 12.5, 1e-12);
  EXPECT_NEAR(w.y(), -7.25, 1e-12);
}

TEST(RenderTransform, TallBoxIsLimitedByHeight) {
  WorldBox box;
  box.extend(Vec2(0.0, 0.0));
  box.extend(Vec2(10.0, 400.0));
  const ViewTransform v(box, PixelRect{0.0, 0.0, 300.0, 200.0});
  EXPECT_DOUBLE_EQ(v.scale(), 0.5);
  EXPECT_NEAR(v.to_pixel({0.0, 400.0}).y(), 0.0, 1e-12);
  EXPECT_NEAR(v.to_pixel({0.0, 0.0}).y(), 200.0, 1e-12);
  EXPECT_THROW(ViewTransform(WorldBox{}, PixelRect{0.0, 0.0, 10.0, 10.0}), InputError);
}

TEST(RenderScaleBar, RoundLengths) {
  EXPECT_DOUBLE_EQ(nice_scale_length(396.0), 200.0);
  EXPECT_DOUBLE_EQ(nice_scale_length(1000.0), 1000.0);
  EXPECT_DOUBLE_EQ(nice_scale_length(999.9), 500.0);
  EXPECT_DOUBLE_EQ(nice_scale_length(100.0), 100.0);
  EXPECT_DOUBLE_EQ(nice_scale_length(4.99), 2.0);
  EXPECT_DOUBLE_EQ(nice_scale_length(0.73), 0.5);
  EXPECT_DOUBLE_EQ(nice_scale_length(1.9), 1.0);
  EXPECT_THROW(nice_scale_length(0.0), InputError);
  EXPECT_THROW(nice_scale_length(-5.0), InputError);
  EXPECT_THROW(nice_scale_length(std::nan("")), InputError);
}

TEST(RenderLayout, ContentFitsTheMapWithEqualScale) {
  SmallScene s;
  const RouteLayout l = route_layout(s.scene, 900);
  EXPECT_EQ(l.width, 900);
  EXPECT_GT(l.height, l.map.y + l.map.height);
  // Everything drawn lies inside the map, not on its edge.
  for (const Vec2& p : {Vec2(-300.0, -200.0), Vec2(100.0, 250.0), Vec2(300.0 + 12.0, 100.0 + 12.0)}) {
    const Vec2 q = l.view.to_pixel(p);
    EXPECT_GT(q.x(), l.map.x + 5.0);
    EXPECT_LT(q.x(), l.map.x + l.map.width - 5.0);
    EXPECT_GT(q.y(), l.map.y + 5.0);
    EXPECT_LT(q.y(), l.map.y + l.map.height - 5.0);
  }
  EXPECT_THROW(route_layout(s.scene, 100), InputError);
  EXPECT_THROW(route_layout(s.scene, 100000), InputError);
}

// ---------------------------------------------------------------- pixels

TEST(RenderRoute, PngPixelsShowObstacleZoneRouteAndBackground) {
  ScratchDir dir;
  SmallScene s;
  const std::string out = dir.file("scene.png");
  render_route(s.scene, out, 900);
  const std::string bytes = slurp(out);
  ASSERT_GE(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png_header_width(bytes), 900u);

  const Png png(out);
  ASSERT_TRUE(png.ok());
  const RouteLayout l = route_layout(s.scene, 900);
  EXPECT_EQ(png.width(), 900);
  EXPECT_EQ(png.height(), l.height);
  const RouteStyle& st = s.scene.style;
  const auto px = [&](double x, double y) { return png.at(l.view.to_pixel({x, y})); };

  EXPECT_TRUE(same_colour(px(0.0, 0.0), st.obstacle)) << "ellipse centre";
  EXPECT_TRUE(same_colour(px(210.0, 10.0), st.obstacle)) << "inside the polygon";
  // The polygon's hole stays open: the sea shows through (the even-odd rule).
  EXPECT_TRUE(same_colour(px(250.0, 50.0), st.sea)) << "polygon hole";
  EXPECT_TRUE(same_colour(px(-200.0, -200.0), st.route)) << "middle of the first route leg";
  EXPECT_TRUE(same_colour(px(250.0, -180.0), st.sea)) << "open water far from everything";
  EXPECT_TRUE(same_colour(px(-300.0, -200.0), st.start)) << "start marker";
  EXPECT_TRUE(same_colour(px(100.0, 250.0), st.goal)) << "goal marker";
  EXPECT_TRUE(same_colour(png.at({2.0, 2.0}), st.background)) << "title band";

  // The dashed zone outline runs along the exact offset curve p(t) + d n(t):
  // most samples on it land on a reddish pixel, none just outside it does.
  const Ellipse& e = s.obstacles.ellipses[0].footprint;
  int on = 0, outside = 0;
  constexpr int kN = 200;
  for (int i = 0; i < kN; ++i) {
    const double t = 2.0 * std::numbers::pi * i / kN;
    const auto c = px((e.point_at(t) + 12.0 * e.normal_at(t)).x(), (e.point_at(t) + 12.0 * e.normal_at(t)).y());
    on += c[0] > c[1] + 60;
    const Vec2 far = e.point_at(t) + (12.0 + 6.0 / l.view.scale()) * e.normal_at(t);  // 6 px outside
    const auto f = px(far.x(), far.y());
    outside += f[0] > f[1] + 60;
  }
  EXPECT_GT(on, kN / 2) << "zone outline samples on a dash";
  EXPECT_EQ(outside, 0);
}

TEST(RenderRoute, GraphEdgesAreDrawnOnlyWhenGiven) {
  ScratchDir dir;
  SmallScene s;
  const std::string plain = dir.file("plain.png");
  render_route(s.scene, plain, 900);
  // A horizontal edge in open water; the extent does not change (it lies inside).
  s.scene.graph_edges = {{Vec2(-300.0, 150.0), Vec2(-100.0, 150.0)}};
  const std::string with = dir.file("graph.png");
  render_route(s.scene, with, 900);
  const RouteLayout l = route_layout(s.scene, 900);
  const Vec2 p = l.view.to_pixel({-200.0, 150.0});
  EXPECT_TRUE(same_colour(Png(with).at(p), s.scene.style.graph_edge));
  EXPECT_TRUE(same_colour(Png(plain).at(p), s.scene.style.sea));
}

TEST(RenderRoute, CurrentArrowsAndLegLabelsAreDrawnOnlyWhenGiven) {
  ScratchDir dir;
  SmallScene s;
  // Pixels of the map in the arrows' colour; the map's top row of arrows
  // lies above the route, in open water.
  const auto arrow_pixels = [&](const std::string& path) {
    const Png png(path);
    const RouteLayout l = route_layout(s.scene, 900);
    int n = 0;
    for (double y = l.map.y + 1; y < l.map.y + 0.2 * l.map.height; y += 1.0) {
      for (double x = l.map.x + 1; x < l.map.x + l.map.width - 1; x += 1.0) {
        n += same_colour(png.at({x, y}), s.scene.style.current, 8) ? 1 : 0;
      }
    }
    return n;
  };
  const std::string plain = dir.file("plain.png");
  render_route(s.scene, plain, 900);
  EXPECT_EQ(arrow_pixels(plain), 0);
  // 1 m/s setting east in the northern half, nothing known in the south.
  s.scene.current = [](const Vec2& p) -> std::optional<Vec2> {
    if (p.y() < 0.0) return std::nullopt;
    return Vec2(1.0, 0.0);
  };
  s.scene.current_label = "current, 1 m/s";
  s.scene.leg_labels = {"2.06 m/s, 0:01:37, 200 kJ", "x"};
  const std::string with = dir.file("current.png");
  render_route(s.scene, with, 900);
  EXPECT_GT(arrow_pixels(with), 200);
  // No arrow where the field has no value: the open water south-west of the route.
  const RouteLayout l = route_layout(s.scene, 900);
  const Vec2 south = l.view.to_pixel({-220.0, -80.0});
  int near_south = 0;
  const Png png(with);
  for (double dy = -25; dy <= 25; ++dy) {
    for (double dx = -25; dx <= 25; ++dx)
      near_south += same_colour(png.at(south + Vec2(dx, dy)), s.scene.style.current, 8);
  }
  EXPECT_EQ(near_south, 0);
  // The first leg's label sits above it (left of eastbound travel), in the route's colour.
  const Vec2 a = l.view.to_pixel({-300.0, -200.0}), b = l.view.to_pixel({-100.0, -200.0});
  const auto bluish = [&](const Png& image) {
    int n = 0;
    for (double y = a.y() - 18; y < a.y() - 3; ++y) {
      for (double x = a.x() + 10; x < b.x() - 10; ++x) n += same_colour(image.at({x, y}), s.scene.style.route, 60);
    }
    return n;
  };
  EXPECT_EQ(bluish(Png(plain)), 0);
  EXPECT_GT(bluish(png), 8);
}

TEST(RenderRoute, SvgIsWritten) {
  ScratchDir dir;
  SmallScene s;
  const std::string out = dir.file("scene.svg");
  render_route(s.scene, out, 700);
  const std::string text = slurp(out);
  EXPECT_EQ(text.rfind("<?xml", 0), 0u) << text.substr(0, 80);
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("width=\"700"), std::string::npos) << text.substr(0, 300);
  EXPECT_EQ(folder_entries(dir.path()).size(), 1u) << "no temporary file left behind";
}

// ---------------------------------------------------------------- failures

TEST(RenderRoute, UnknownExtensionIsAnInputErrorAndWritesNothing) {
  ScratchDir dir;
  SmallScene s;
  const std::string out = dir.file("scene.jpg");
  try {
    render_route(s.scene, out);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(out), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(".png or .svg"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(folder_entries(dir.path()).empty());
}

TEST(RenderRoute, MissingFolderIsAnInputError) {
  ScratchDir dir;
  SmallScene s;
  const std::string out = dir.file("no/such/folder/scene.png");
  try {
    render_route(s.scene, out);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(out), std::string::npos) << e.what();
  }
  EXPECT_TRUE(folder_entries(dir.path()).empty());
}

TEST(RenderRoute, FailureKeepsTheOldFileAndLeavesNoTemporary) {
  ScratchDir dir;
  const std::string out = dir.write("scene.png", "old");
  SmallScene s;
  s.scene.route.push_back({std::numeric_limits<double>::quiet_NaN(), 0.0});
  try {
    render_route(s.scene, out);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(out), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("route"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(out), "old");
  EXPECT_EQ(folder_entries(dir.path()), std::vector<std::string>{"scene.png"});
  // Nothing to draw at all.
  EXPECT_THROW(render_route(RouteScene{}, out), InputError);
  EXPECT_EQ(slurp(out), "old");
}

TEST(RenderCanvas, AbandonedCanvasLeavesNoFile) {
  ScratchDir dir;
  {
    Canvas c(dir.file("a.png"), 50, 40);
    c.fill_rect({0, 0, 50, 40}, rgb_hex(0x336699));
    Canvas d(dir.file("b.svg"), 50, 40);
    d.circle({25, 20}, 10, rgb_hex(0xff0000), std::nullopt);
    // Destroyed without finish(): a drawing that failed half-way.
  }
  EXPECT_TRUE(folder_entries(dir.path()).empty());
  Canvas c(dir.file("a.png"), 50, 40);
  c.fill_rect({0, 0, 50, 40}, rgb_hex(0x336699));
  c.finish();
  const Png png(dir.file("a.png"));
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.width(), 50);
  EXPECT_TRUE(same_colour(png.at({10.5, 10.5}), rgb_hex(0x336699), 0));
  EXPECT_THROW(Canvas(dir.file("big.png"), 40000, 10), InputError);
  EXPECT_THROW(Canvas(dir.file("zero.svg"), 0, 10), InputError);
}

// ---------------------------------------------------------------- CLI

TEST(RenderCli, RenderRouteAndPlanRender) {
  ScratchDir dir;
  const std::string sample = deepguide::test::source_file("data/sample_obstacles.geojson");
  const std::string route = dir.file("route.geojson");
  const auto plan = run_cli("plan --obstacles '" + sample + "' --from 10.240,54.440 --to 10.265,54.462 -o '" + route +
                            "' --render '" + dir.file("plan.svg") + "' --render-graph");
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_NE(slurp(dir.file("plan.svg")).find("<svg"), std::string::npos);

  const std::string png = dir.file("chart.png");
  const auto ok = run_cli("render route --obstacles '" + sample + "' --route '" + route +
                          "' --graph visibility --width 700 -o '" + png + "'");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const std::string bytes = slurp(png);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png_header_width(bytes), 700u);

  const auto bad =
      run_cli("render route --obstacles '" + sample + "' --route '" + route + "' -o '" + dir.file("chart.jpg") + "'");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find(".png or .svg"), std::string::npos) << bad.err;
  const auto bad_graph = run_cli("render route --obstacles '" + sample + "' --route '" + route +
                                 "' --graph octree -o '" + dir.file("g.png") + "'");
  EXPECT_EQ(bad_graph.exit_code, 1);
  EXPECT_NE(bad_graph.err.find("expected none, "), std::string::npos) << bad_graph.err;
  // plan checks --render before planning, so a bad name writes no route either.
  const std::string route2 = dir.file("route2.geojson");
  const auto bad_plan = run_cli("plan --obstacles '" + sample + "' --from 10.240,54.440 --to 10.265,54.462 -o '" +
                                route2 + "' --render '" + dir.file("plan.gif") + "'");
  EXPECT_EQ(bad_plan.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(route2));
  EXPECT_FALSE(std::filesystem::exists(dir.file("chart.jpg")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("g.png")));
}
