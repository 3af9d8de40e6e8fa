#include "deepguide/render/turn_rate_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/render/reactive_map.hpp"  // method_color
#include "deepguide/simulation/scenario.hpp"

namespace deepguide {
namespace {

// Design units (at 1200 px wide).
constexpr double kTitleBand = 52.0;
constexpr double kAxisTitle = 22.0;
constexpr double kLabelLine = 24.0;
constexpr double kPanel = 170.0;
constexpr double kPanelGap = 12.0;
constexpr double kLeft = 80.0;
constexpr double kRight = 24.0;
constexpr double kTimeNumbers = 52.0;
constexpr double kBottom = 10.0;
constexpr int kLegendColumns = 3;
constexpr int kMaxTimeTicks = 12;

const Rgba kText = rgb_hex(0x212529);
const Rgba kFrame = rgb_hex(0x5c636a);
const Rgba kGrid = rgb_hex(0xe3e7ec);
const Rgba kReference = rgb_hex(0x343a40);
const Rgba kLimit = rgb_hex(0xc92a2a);

/// Nautical turning rate (deg/s, clockwise positive) of a math rate (rad/s).
double nautical_deg_s(double math_rad_s) { return -rad_to_deg(math_rad_s); }

Stroke rate_stroke(const ReactiveMethod& m, double u) { return {method_color(m), 2.4 * u, {}}; }
Stroke reference_stroke(double u) { return {kReference, 1.2 * u, {4.0 * u, 2.5 * u}}; }
Stroke limit_stroke(double u) { return {kLimit, 1.4 * u, {7.0 * u, 4.0 * u}}; }

std::string panel_label(const SimulationResult& run) {
  const SimulationStats& s = run.stats;
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "max |r_ref| %.1f \u00b0/s, max |r| %.1f \u00b0/s, RMS r %.2f \u00b0/s, %d heading reversal%s, %s",
                rad_to_deg(s.max_abs_rate_ref), rad_to_deg(s.max_abs_rate), rad_to_deg(s.rms_rate), s.heading_reversals,
                s.heading_reversals == 1 ? "" : "s", std::string(to_string(run.end)).c_str());
  return buf;
}

}  // namespace

TurnRatePlot turn_rate_plot_for(const Scenario& scenario, std::span<const ReactiveMethod> methods) {
  TurnRatePlot p;
  p.max_turn_rate = scenario.vehicle.max_turn_rate;
  p.title = "Turning rate of the reactive methods: " + scenario.name;
  for (const ReactiveMethod& m : methods) p.runs.push_back(simulate(scenario, m, {true}));
  return p;
}

TurnRateLayout turn_rate_layout(const TurnRatePlot& plot) {
  check_figure_width(plot.width_px);
  if (plot.runs.empty()) throw InputError("turn-rate plot: expected at least one run");
  if (!std::isfinite(plot.max_turn_rate)) throw InputError("turn-rate plot: expected a finite turn-rate limit");
  double t_end = 0.0;
  double peak = std::abs(rad_to_deg(plot.max_turn_rate));
  for (const SimulationResult& run : plot.runs) {
    if (run.trajectory.empty()) {
      throw InputError("turn-rate plot: expected a recorded trajectory for the " + std::string(to_string(run.method)) +
                       " method");
    }
    for (const TrajectorySample& s : run.trajectory) {
      if (!std::isfinite(s.time_s) || !std::isfinite(s.rate) || !std::isfinite(s.rate_ref)) {
        throw InputError("turn-rate plot: expected finite times and rates");
      }
      t_end = std::max(t_end, s.time_s);
      peak = std::max({peak, std::abs(rad_to_deg(s.rate)), std::abs(rad_to_deg(s.rate_ref))});
    }
  }
  TurnRateLayout l;
  l.width = plot.width_px;
  l.unit = plot.width_px / 1200.0;
  const double u = l.unit;
  l.rate_limit_deg_s = peak > 0.0 ? 1.15 * peak : 1.0;
  const double left = kLeft * u;
  const double width = plot.width_px - (kLeft + kRight) * u;
  double y = (kTitleBand + kAxisTitle) * u;
  for (std::size_t i = 0; i < plot.runs.size(); ++i) {
    y += kLabelLine * u;
    l.panels.push_back({left, y, width, kPanel * u});
    y += (kPanel + kPanelGap) * u;
  }
  y -= kPanelGap * u;
  // The time axis ends on a tick.
  const double t_step = nice_tick_step(t_end > 0.0 ? t_end : 1.0, kMaxTimeTicks);
  l.time = {0.0, std::max(1.0, std::ceil(t_end / t_step)) * t_step, left, left + width};
  l.legend = {left, y + kTimeNumbers * u, width, legend_height(3, kLegendColumns, u)};
  l.height = static_cast<int>(std::ceil(l.legend.y + l.legend.height + kBottom * u));
  return l;
}

PlotAxis rate_axis(const TurnRateLayout& l, std::size_t panel) {
  const PixelRect& r = l.panels.at(panel);
  return {-l.rate_limit_deg_s, l.rate_limit_deg_s, r.y + r.height, r.y};
}

TurnRateLayout render_turn_rate_plot(const TurnRatePlot& plot, const std::string& path) {
  image_format_for(path);
  TurnRateLayout l;
  try {
    l = turn_rate_layout(plot);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  const double u = l.unit;
  Canvas canvas(path, l.width, l.height);
  canvas.fill_rect({0.0, 0.0, static_cast<double>(l.width), static_cast<double>(l.height)}, rgb_hex(0xffffff));
  draw_figure_title(canvas, plot.title.empty() ? std::string("Turning rate") : plot.title, l.width, u, kText);
  canvas.text({l.panels.front().x, (kTitleBand + 14.0) * u}, "turning rate (\u00b0/s, + = to starboard)", 14.0 * u,
              kText);

  const double limit = std::abs(rad_to_deg(plot.max_turn_rate));
  for (std::size_t i = 0; i < plot.runs.size(); ++i) {
    const SimulationResult& run = plot.runs[i];
    const PixelRect& panel = l.panels[i];
    const PlotAxis rate = rate_axis(l, i);
    const bool last = i + 1 == plot.runs.size();
    canvas.text({panel.x, panel.y - 8.0 * u}, std::string(to_string(run.method)), 15.0 * u, method_color(run.method),
                TextAlign::left, true);
    canvas.text({panel.x + 95.0 * u, panel.y - 8.0 * u}, panel_label(run), 13.0 * u, kText);
    draw_axes(canvas, panel, l.time, rate, {"time (s)", "", kMaxTimeTicks, 9, last}, u, {kText, kFrame, kGrid});

    canvas.clip(panel);
    const double x0 = panel.x, x1 = panel.x + panel.width;
    canvas.stroke_polyline({{x0, rate.to_px(0.0)}, {x1, rate.to_px(0.0)}}, Stroke{kFrame, 1.0 * u, {}});
    if (limit > 0.0) {
      canvas.stroke_polyline({{x0, rate.to_px(limit)}, {x1, rate.to_px(limit)}}, limit_stroke(u));
      canvas.stroke_polyline({{x0, rate.to_px(-limit)}, {x1, rate.to_px(-limit)}}, limit_stroke(u));
    }
    std::vector<Vec2> r, r_ref;
    r.reserve(run.trajectory.size());
    r_ref.reserve(run.trajectory.size());
    for (const TrajectorySample& s : run.trajectory) {
      const double x = l.time.to_px(s.time_s);
      r.emplace_back(x, rate.to_px(nautical_deg_s(s.rate)));
      r_ref.emplace_back(x, rate.to_px(nautical_deg_s(s.rate_ref)));
    }
    // The thick r under the thin r_ref: both stay visible where they agree.
    canvas.stroke_polyline(r, rate_stroke(run.method, u));
    canvas.stroke_polyline(r_ref, reference_stroke(u));
    canvas.unclip();
  }

  const ReactiveMethod first = plot.runs.front().method;
  const std::vector<LegendEntry> legend{
      {"r, the vehicle's turning rate",
       [first, u](Canvas& c, const Vec2& m) {
         c.stroke_polyline({m - Vec2(15 * u, 0), m + Vec2(15 * u, 0)}, rate_stroke(first, u));
       }},
      {"r_ref, the autopilot's reference",
       [u](Canvas& c, const Vec2& m) {
         c.stroke_polyline({m - Vec2(15 * u, 0), m + Vec2(15 * u, 0)}, reference_stroke(u));
       }},
      {"\u00b1r_max = " + general(std::round(limit * 100.0) / 100.0) + " \u00b0/s, the vehicle's limit",
       [u](Canvas& c, const Vec2& m) {
         c.stroke_polyline({m - Vec2(15 * u, 0), m + Vec2(15 * u, 0)}, limit_stroke(u));
       }},
  };
  draw_legend(canvas, legend, l.legend, kLegendColumns, u, kText);
  canvas.finish();
  return l;
}

}  // namespace deepguide
