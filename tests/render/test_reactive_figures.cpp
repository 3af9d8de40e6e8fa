// The reactive level's figures: round ticks, gradient lines against closed
// forms on a disc (the geometric method's shortest path, the dipole's
// stagnation point, the potential field's point of balance), lines that never
// enter a footprint, the PNG/SVG files with the methods' colours, and the
// CLI's one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "deepguide/core/error.hpp"
#include "deepguide/geometry/ellipse_segment.hpp"
#include "deepguide/render/field_figure.hpp"
#include "deepguide/render/gradient_lines.hpp"
#include "deepguide/render/identification_figure.hpp"
#include "deepguide/render/plot_furniture.hpp"
#include "deepguide/render/trajectory_figure.hpp"
#include "deepguide/render/turn_rate_plot.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "png_reader.hpp"
#include "test_support.hpp"

using namespace deepguide;
using deepguide::test::expect_one_line_error;
using deepguide::test::Png;
using deepguide::test::run_cli;
using deepguide::test::ScratchDir;
using deepguide::test::source_file;

namespace {

// A disc of radius 20 m at the origin with a 10 m margin: zone radius R = 30.
constexpr double kDisc = 20.0;
constexpr double kMargin = 10.0;
constexpr double kZone = kDisc + kMargin;

ReactiveParams disc_params() {
  ReactiveParams p;
  p.margin_m = kMargin;
  p.influence_m = 60.0;
  p.tuning["potential_gain"] = 1.0;
  return p;
}

const std::array<Ellipse, 1> kDiscObjects{Ellipse{Vec2(0.0, 0.0), kDisc, kDisc, 0.0}};

WorldBox box(double x0, double y0, double x1, double y1) {
  WorldBox b;
  b.extend(Vec2(x0, y0));
  b.extend(Vec2(x1, y1));
  return b;
}

double polyline_length(const std::vector<Vec2>& pts) {
  double s = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) s += (pts[i] - pts[i - 1]).norm();
  return s;
}

/// Pixels within `tol` of the colour on every channel.
int count_colour(const Png& png, const Rgba& c, int tol = 12) {
  const std::array<int, 3> want{static_cast<int>(std::lround(c.r * 255)), static_cast<int>(std::lround(c.g * 255)),
                                static_cast<int>(std::lround(c.b * 255))};
  int n = 0;
  for (int y = 0; y < png.height(); ++y) {
    for (int x = 0; x < png.width(); ++x) {
      const auto got = png.at(Vec2(x + 0.5, y + 0.5));
      if (std::abs(got[0] - want[0]) <= tol && std::abs(got[1] - want[1]) <= tol && std::abs(got[2] - want[2]) <= tol) {
        ++n;
      }
    }
  }
  return n;
}

Scenario one_obstacle() { return read_scenario_file(source_file("data/scenarios/one_obstacle.yaml")); }

}  // namespace

// ------------------------------------------------------------------ ticks

TEST(PlotTicks, StepsAreOneTwoFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(nice_tick_step(400.0, 10), 50.0);  // 400 / 9 = 44.4 -> 50
  EXPECT_DOUBLE_EQ(nice_tick_step(12.0, 9), 2.0);     // 12 / 8 = 1.5 -> 2
  EXPECT_DOUBLE_EQ(nice_tick_step(1.0, 11), 0.1);     // exactly 0.1: no step up by rounding
  EXPECT_DOUBLE_EQ(nice_tick_step(90.0, 10), 10.0);
  EXPECT_DOUBLE_EQ(nice_tick_step(0.003, 4), 0.001);
  const std::vector<double> t = nice_ticks(-200.0, 200.0, 10);
  ASSERT_EQ(t.size(), 9u);
  EXPECT_DOUBLE_EQ(t.front(), -200.0);
  EXPECT_DOUBLE_EQ(t[4], 0.0);
  EXPECT_FALSE(std::signbit(t[4]));                        // no "-0"
  const std::vector<double> r = nice_ticks(-6.9, 6.9, 9);  // step 2
  EXPECT_EQ(r, (std::vector<double>{-6, -4, -2, 0, 2, 4, 6}));
}

TEST(PlotTicks, LabelsCarryTheDecimalsOfTheStep) {
  EXPECT_EQ(format_tick(0.1 + 0.2, 0.1), "0.3");
  EXPECT_EQ(format_tick(-5.0, 1.0), "-5");
  EXPECT_EQ(format_tick(0.25, 0.05), "0.25");
  EXPECT_EQ(format_tick(5912300.0, 100.0), "5912300");  // a UTM northing, not 5.9e+06
}

TEST(PlotTicks, BadRangesAreOneLineErrors) {
  expect_one_line_error([] { nice_tick_step(0.0, 5); }, "positive finite range");
  expect_one_line_error([] { nice_tick_step(std::nan(""), 5); }, "positive finite range");
  expect_one_line_error([] { nice_tick_step(10.0, 1); }, "at least 2 ticks");
}

// ------------------------------------------------------------------ seeds and lines

TEST(GradientLines, SeedsLieAcrossTheWayThroughTheStart) {
  const std::vector<Vec2> s = upstream_seeds(box(-100, -100, 100, 100), Vec2(-50, 0), Vec2(50, 0), 10.0);
  ASSERT_EQ(s.size(), 21u);  // y = -100, -90, ..., 100
  for (const Vec2& p : s) EXPECT_DOUBLE_EQ(p.x(), -50.0);
  EXPECT_NEAR(s.front().y(), -100.0, 1e-12);
  EXPECT_NE(std::find(s.begin(), s.end(), Vec2(-50, 0)), s.end());
  // Diagonal: the seed line is perpendicular to start -> target.
  const std::vector<Vec2> d = upstream_seeds(box(-100, -100, 100, 100), Vec2(0, 0), Vec2(10, 10), 10.0);
  for (const Vec2& p : d) EXPECT_NEAR(p.x() + p.y(), 0.0, 1e-9);
  EXPECT_TRUE(upstream_seeds(box(-100, -100, 100, 100), Vec2(500, 0), Vec2(0, 0), 10.0).empty());
  expect_one_line_error([] { upstream_seeds(box(0, 0, 1, 1), Vec2(0, 0), Vec2(1, 1), 0.0); }, "seed spacing");
}

// From (-150, 15) to (150, 0) round the zone circle R = 30 over the top, the
// shortest path is tangent, arc, tangent:
//   L = sqrt(|P|^2 - R^2) + sqrt(|G|^2 - R^2) + R (angle(P, G) - acos(R/|P|) - acos(R/|G|)).
TEST(GradientLines, GeometricLineIsTheTangentArcTangentPath) {
  const Vec2 seed(-150.0, 15.0), target(150.0, 0.0);
  const GradientLine line = trace_gradient_line(ReactiveMethod::geometric, disc_params(), seed, target, kDiscObjects,
                                                box(-200, -100, 200, 100), {0.25, 20000});
  ASSERT_EQ(line.end, LineEnd::target);
  EXPECT_EQ(line.points.back(), target);
  const double p = seed.norm(), g = target.norm();
  const double angle = std::atan2(seed.y(), seed.x());  // target at angle 0
  const double exact = std::sqrt(p * p - kZone * kZone) + std::sqrt(g * g - kZone * kZone) +
                       kZone * (angle - std::acos(kZone / p) - std::acos(kZone / g));
  EXPECT_NEAR(exact, 303.76, 0.01);  // the hand value
  EXPECT_NEAR(polyline_length(line.points), exact, 0.3);
  for (const Vec2& q : line.points) EXPECT_GE(q.norm(), kZone - 0.01) << q.transpose();
  EXPECT_GT(line.points[line.points.size() / 2].y(), 0.0);  // over the top: the seed is north of the axis
}

// On the axis the dipole's line runs into the front stagnation point (-R, 0),
// the potential field's into its point of balance R + influence/2 in front of
// the zone (potential_field.hpp: m(rho0/2) = 1, the unit attraction). The
// seed's x is off the step grid, so no step lands exactly where the field is 0:
// the line must stop by the reversal rule.
TEST(GradientLines, AxisLinesStallWhereTheFieldVanishes) {
  const WorldBox area = box(-200, -100, 200, 100);
  const GradientLineOptions opt{0.25, 20000};
  const GradientLine dipole = trace_gradient_line(ReactiveMethod::dipole, disc_params(), Vec2(-150.1, 0), Vec2(150, 0),
                                                  kDiscObjects, area, opt);
  EXPECT_EQ(dipole.end, LineEnd::stalled);
  // Up to 2 m inside: at the stagnation point the dipole method's exit blend
  // starts from the flow just outside, which points into the zone, so the
  // field turns back only a little way in (1.9 m for R = 30).
  EXPECT_LE(dipole.points.back().x(), -kZone + 2.0);
  EXPECT_GE(dipole.points.back().x(), -kZone - opt.step_m);
  EXPECT_NEAR(dipole.points.back().y(), 0.0, 1e-9);
  const GradientLine potential = trace_gradient_line(ReactiveMethod::potential, disc_params(), Vec2(-150.1, 0),
                                                     Vec2(150, 0), kDiscObjects, area, opt);
  EXPECT_EQ(potential.end, LineEnd::stalled);
  EXPECT_NEAR(potential.points.back().x(), -(kZone + 30.0), opt.step_m);
}

TEST(GradientLines, DividingLineIsFoundBetweenSeedsThatPassOnDifferentSides) {
  const WorldBox area = box(-200, -100, 200, 100);
  const GradientLineOptions opt{0.25, 20000};
  const std::vector<Vec2> seeds{Vec2(-150.1, -5), Vec2(-150.1, 5), Vec2(-150.1, 15)};
  const Vec2 target(150, 0);
  const auto lines = gradient_lines(ReactiveMethod::potential, disc_params(), seeds, target, kDiscObjects, area, opt);
  EXPECT_EQ(passing_sides(lines[0], target, kDiscObjects), std::vector<int>{-1});  // south of the axis
  EXPECT_EQ(passing_sides(lines[1], target, kDiscObjects), std::vector<int>{1});
  EXPECT_EQ(passing_sides(lines[2], target, kDiscObjects), std::vector<int>{1});
  const auto dividers =
      dividing_lines(ReactiveMethod::potential, disc_params(), seeds, lines, target, kDiscObjects, area, opt);
  ASSERT_EQ(dividers.size(), 1u);  // only between the first two
  EXPECT_EQ(dividers[0].end, LineEnd::stalled);
  EXPECT_NEAR(dividers[0].points.back().x(), -(kZone + 30.0), opt.step_m);  // the trap
}

TEST(GradientLines, BadInputIsAOneLineError) {
  const WorldBox area = box(-200, -100, 200, 100);
  expect_one_line_error(
      [&] {
        trace_gradient_line(ReactiveMethod::dipole, disc_params(), Vec2(0, 0), Vec2(1, 1), kDiscObjects, area,
                            {0.0, 10});
      },
      "positive step");
  expect_one_line_error(
      [&] {
        trace_gradient_line(ReactiveMethod::dipole, disc_params(), Vec2(900, 0), Vec2(1, 1), kDiscObjects, area,
                            {1.0, 10});
      },
      "seed inside the area");
  ReactiveParams bad = disc_params();
  bad.margin_m = -1.0;
  EXPECT_THROW(
      trace_gradient_line(ReactiveMethod::dipole, bad, Vec2(-150, 3), Vec2(150, 0), kDiscObjects, area, {1.0, 10}),
      InputError);
}

// ------------------------------------------------------------------ the field figure

// Every segment of every line of every method's figure keeps out of the true
// footprint, and every line of the dipole and geometric methods out of the
// security zone (to a hair: chords of an arc ridden along the boundary).
TEST(FieldFigure, NoLineEntersAFootprint) {
  const Scenario sc = one_obstacle();
  for (const ReactiveMethod& m : {ReactiveMethod::dipole, ReactiveMethod::geometric, ReactiveMethod::potential}) {
    FieldFigure f = field_figure_for(sc, m);
    f.width_px = 600;
    const FieldFigureGeometry g = field_figure_geometry(f);
    ASSERT_GE(g.lines.size(), 15u) << to_string(m);
    EXPECT_GE(g.dividing, 1u) << to_string(m);
    EXPECT_EQ((g.lines[g.start_line].points.front() - sc.start).norm(), 0.0);
    const Ellipse& foot = sc.obstacles.at(0).footprint;
    const Ellipse zone = security_ellipse(foot, sc.reactive.margin_m);
    std::size_t reached = 0;
    for (const GradientLine& line : g.lines) {
      reached += line.end == LineEnd::target ? 1 : 0;
      for (std::size_t i = 1; i < line.points.size(); ++i) {
        ASSERT_FALSE(segment_intersects(foot, line.points[i - 1], line.points[i]))
            << to_string(m) << ": segment " << i << " at " << line.points[i].transpose();
        ASSERT_TRUE(g.layout.area.min.x() <= line.points[i].x() && line.points[i].x() <= g.layout.area.max.x());
      }
      if (m == ReactiveMethod::potential) continue;
      for (const Vec2& p : line.points) ASSERT_GT(zone.implicit_value(p), 0.99) << to_string(m) << " " << p.transpose();
    }
    // All but the dividing line reach the target (the dipole's divider ends at a stagnation point).
    EXPECT_GE(reached + g.dividing, g.lines.size()) << to_string(m);
  }
}

TEST(FieldFigure, WritesADecodablePngWithTheMethodsColour) {
  ScratchDir tmp;
  const std::string path = tmp.file("field.png");
  FieldFigure f = field_figure_for(one_obstacle(), ReactiveMethod::dipole);
  const FieldFigureGeometry g = render_field_figure(f, path);
  Png png(path);
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.width(), 1200);
  EXPECT_EQ(png.height(), g.layout.height);
  EXPECT_GT(count_colour(png, method_color(ReactiveMethod::dipole)), 500);
  EXPECT_EQ(count_colour(png, method_color(ReactiveMethod::geometric)), 0);
  // The footprint's centre is obstacle-dark, the target's pixel the marker's.
  EXPECT_GT(count_colour(png, ReactiveMapStyle{}.obstacle, 3), 1000);
  const auto centre = png.at(g.layout.view.to_pixel(Vec2(0.0, 0.0)));
  EXPECT_LT(centre[0], 80);
}

TEST(FieldFigure, WritesSvgAndRefusesOtherExtensionsWithoutAFile) {
  ScratchDir tmp;
  FieldFigure f = field_figure_for(one_obstacle(), ReactiveMethod::geometric);
  f.width_px = 600;
  render_field_figure(f, tmp.file("field.svg"));
  std::ifstream in(tmp.file("field.svg"));
  const std::string svg((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  expect_one_line_error([&] { render_field_figure(f, tmp.file("field.jpg")); }, ".png or .svg");
  f.width_px = 100;
  expect_one_line_error([&] { render_field_figure(f, tmp.file("small.png")); }, "image width");
  f.width_px = 600;
  f.map.margin_m = 5.0;  // zones drawn other than the method keeps
  expect_one_line_error([&] { render_field_figure(f, tmp.file("small.png")); }, "the method's (10 m), got 5 m");
  EXPECT_FALSE(std::filesystem::exists(tmp.file("field.jpg")));
  EXPECT_FALSE(std::filesystem::exists(tmp.file("small.png")));
}

// ------------------------------------------------------------------ trajectories and turning rates

TEST(TrajectoryFigure, DrawsEveryMethodsTrackInItsColour) {
  ScratchDir tmp;
  const std::string path = tmp.file("sim.png");
  const std::array<ReactiveMethod, 3> all{ReactiveMethod::dipole, ReactiveMethod::geometric, ReactiveMethod::potential};
  const TrajectoryFigure f = trajectory_figure_for(one_obstacle(), all);
  ASSERT_EQ(f.runs.size(), 3u);
  const ReactiveMapLayout l = render_trajectory_figure(f, path);
  Png png(path);
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.height(), l.height);
  for (const ReactiveMethod& m : all) EXPECT_GT(count_colour(png, method_color(m)), 300) << to_string(m);
  // Every track fits on the map.
  for (const SimulationResult& r : f.runs) {
    for (const TrajectorySample& s : r.trajectory) {
      const Vec2 p = l.view.to_pixel(s.position);
      ASSERT_TRUE(p.x() >= l.plot.x && p.x() <= l.plot.x + l.plot.width && p.y() >= l.plot.y &&
                  p.y() <= l.plot.y + l.plot.height);
    }
  }
  EXPECT_NE(run_summary(f.runs[1]).find("geometric: reached in"), std::string::npos);
  TrajectoryFigure empty = f;
  empty.runs.clear();
  expect_one_line_error([&] { render_trajectory_figure(empty, tmp.file("e.png")); }, "at least one run");
  empty.runs = {f.runs[0]};
  empty.runs[0].trajectory.clear();
  expect_one_line_error([&] { render_trajectory_figure(empty, tmp.file("e.png")); }, "recorded trajectory");
  EXPECT_FALSE(std::filesystem::exists(tmp.file("e.png")));
}

TEST(TurnRatePlot, PanelsShareASymmetricAxisWithTheLimitDashed) {
  ScratchDir tmp;
  const std::string path = tmp.file("rates.png");
  const std::array<ReactiveMethod, 2> two{ReactiveMethod::dipole, ReactiveMethod::geometric};
  const TurnRatePlot plot = turn_rate_plot_for(one_obstacle(), two);
  EXPECT_NEAR(plot.max_turn_rate, 6.0 * kPi / 180.0, 1e-12);  // the DeepC-like vehicle's r_max
  const TurnRateLayout l = render_turn_rate_plot(plot, path);
  ASSERT_EQ(l.panels.size(), 2u);
  EXPECT_GE(l.rate_limit_deg_s, 6.0 * 1.15 - 1e-9);  // the limit and a margin fit
  EXPECT_EQ(l.time.lo, 0.0);
  EXPECT_GE(l.time.hi, plot.runs[0].trajectory.back().time_s);
  const PlotAxis a = rate_axis(l, 0);
  EXPECT_NEAR(a.to_px(0.0), l.panels[0].y + 0.5 * l.panels[0].height, 1e-9);
  Png png(path);
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.height(), l.height);
  for (const ReactiveMethod& m : two) EXPECT_GT(count_colour(png, method_color(m)), 300) << to_string(m);
  // The dashed +6 deg/s line: red pixels along its row in the second panel.
  const double row = rate_axis(l, 1).to_px(6.0);
  int red = 0;
  for (double x = l.panels[1].x + 2.0; x < l.panels[1].x + l.panels[1].width - 2.0; x += 1.0) {
    const auto c = png.at(Vec2(x, row));
    red += (c[0] > 180 && c[1] < 110 && c[2] < 110) ? 1 : 0;
  }
  EXPECT_GT(red, 300);
  TurnRatePlot none = plot;
  none.runs.clear();
  expect_one_line_error([&] { render_turn_rate_plot(none, tmp.file("n.png")); }, "at least one run");
}

// ------------------------------------------------------------------ CLI

TEST(RenderReactiveCli, WritesTheFiguresAndRefusesBadInputInOneLine) {
  ScratchDir tmp;
  const std::string sc = "'" + source_file("data/scenarios/one_obstacle.yaml") + "'";
  const auto ok = run_cli("render field " + sc + " --method potential --width 600 -o '" + tmp.file("f.png") + "'");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(Png(tmp.file("f.png")).ok());
  const auto sim =
      run_cli("render simulation " + sc + " --methods geometric --width 600 -o '" + tmp.file("s.svg") + "'");
  EXPECT_EQ(sim.exit_code, 0) << sim.err;
  EXPECT_NE(sim.out.find("geometric: reached"), std::string::npos) << sim.out;

  auto expect_bad = [&](const std::string& args, const std::string& needle, const std::string& out) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << out;
  };
  expect_bad("render field " + sc + " --method dipol -o '" + tmp.file("a.png") + "'",
             "--method: expected dipole, geometric or potential, got 'dipol'", tmp.file("a.png"));
  expect_bad("render field " + sc + " --method dipole -o '" + tmp.file("a.jpg") + "'", ".png or .svg",
             tmp.file("a.jpg"));
  expect_bad("render simulation " + sc + " --methods dipole,magnet -o '" + tmp.file("b.png") + "'",
             "--methods: expected dipole, geometric or potential, got 'magnet'", tmp.file("b.png"));
  expect_bad("render turn-rates " + sc + " --methods dipole,dipole -o '" + tmp.file("c.png") + "'", "twice",
             tmp.file("c.png"));
  expect_bad("render turn-rates '" + tmp.file("missing.yaml") + "' -o '" + tmp.file("d.png") + "'", "missing.yaml",
             tmp.file("d.png"));
  // A usage error (no output) is exit 2.
  EXPECT_EQ(run_cli("render field " + sc + " --method dipole").exit_code, 2);
}

// The identification figures: the shade, the track's modes and the path in
// their colours, every sample on the map, and the CLI with its bad input.
TEST(IdentificationFigure, DrawsTheShadeTheModesAndThePath) {
  ScratchDir tmp;
  const IdentificationFigure align =
      identification_figure_for(read_scenario_file(source_file("data/scenarios/align_in_current.yaml")));
  const ReactiveMapLayout l = render_identification_figure(align, tmp.file("align.png"));
  Png png(tmp.file("align.png"));
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.height(), l.height);
  EXPECT_GT(count_colour(png, phase_color(IdentifyPhase::evasive)), 300);
  EXPECT_GT(count_colour(png, phase_color(IdentifyPhase::positioning)), 300);
  // The shade (sky blue at 18 % over the sea) 30 m past the held point, down the axis.
  const Vec2 shade = l.view.to_pixel(align.run.goal + 30.0 * align.scenario.current.normalized());
  const auto got = png.at(shade + Vec2(0.0, 12.0));  // beside the track, not on it
  EXPECT_LT(got[0], 232);                            // the sea is (243, 246, 249); the tint takes red away
  EXPECT_GT(got[2], 235);
  for (const IdentifySample& x : align.run.trajectory) {
    const Vec2 p = l.view.to_pixel(x.vehicle.position);
    ASSERT_TRUE(p.x() >= l.plot.x && p.x() <= l.plot.x + l.plot.width && p.y() >= l.plot.y &&
                p.y() <= l.plot.y + l.plot.height);
  }
  EXPECT_NE(identification_summary(align.run).find("held 300 s from"), std::string::npos);

  const IdentificationFigure around =
      identification_figure_for(read_scenario_file(source_file("data/scenarios/around_object.yaml")));
  render_identification_figure(around, tmp.file("around.svg"));
  EXPECT_TRUE(std::filesystem::exists(tmp.file("around.svg")));
  EXPECT_NE(identification_summary(around.run).find("2.0 laps in"), std::string::npos);

  IdentificationFigure empty = around;
  empty.run.trajectory.clear();
  expect_one_line_error([&] { render_identification_figure(empty, tmp.file("e.png")); }, "recorded run");
  EXPECT_FALSE(std::filesystem::exists(tmp.file("e.png")));
}

TEST(RenderIdentificationCli, WritesTheFigureAndRefusesBadInputInOneLine) {
  ScratchDir tmp;
  const std::string sc = "'" + source_file("data/scenarios/around_object.yaml") + "'";
  const auto ok = run_cli("render identification " + sc + " --width 600 -o '" + tmp.file("a.png") + "'");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("laps in"), std::string::npos) << ok.out;
  Png png(tmp.file("a.png"));
  ASSERT_TRUE(png.ok());
  EXPECT_EQ(png.width(), 600);
  const auto bad_ext = run_cli("render identification " + sc + " -o '" + tmp.file("a.jpg") + "'");
  EXPECT_EQ(bad_ext.exit_code, 1);
  EXPECT_NE(bad_ext.err.find(".png or .svg"), std::string::npos) << bad_ext.err;
  const auto bad_mode = run_cli("render identification " + sc + " --mode spin -o '" + tmp.file("b.png") + "'");
  EXPECT_EQ(bad_mode.exit_code, 1);
  EXPECT_NE(bad_mode.err.find("--mode: expected align or around, got 'spin'"), std::string::npos) << bad_mode.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("b.png")));
  // A manoeuvre identify calls failed (a 3.5 m/s current, the vehicle's top
  // speed 3.09 m/s) is drawn, and the exit and the line say so as identify's do.
  std::ifstream in(source_file("data/scenarios/align_in_current.yaml"));
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const std::size_t at = text.find("current: \"1.0,100\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, std::string("current: \"1.0,100\"").size(), "current: \"3.5,100\"");
  const std::size_t vehicle = text.find("../vehicles/deepc.yaml");  // relative to the scenario's folder
  ASSERT_NE(vehicle, std::string::npos);
  text.replace(vehicle, std::string("../vehicles/deepc.yaml").size(), source_file("data/vehicles/deepc.yaml"));
  const std::string strong = tmp.write("strong.yaml", text);
  const auto identify = run_cli("identify '" + strong + "'");
  const auto drawn = run_cli("render identification '" + strong + "' -o '" + tmp.file("s.png") + "'");
  EXPECT_EQ(identify.exit_code, 3) << identify.err;
  EXPECT_EQ(drawn.exit_code, identify.exit_code) << drawn.err;
  EXPECT_EQ(drawn.err, identify.err);
  EXPECT_NE(drawn.err.find("top speed (3.09 m/s)"), std::string::npos) << drawn.err;
  EXPECT_TRUE(std::filesystem::exists(tmp.file("s.png")));
}
