// deepguide render field SCENARIO.yaml --method dipole|geometric|potential [--width PX] [--title T] -o FIG.png|svg
// deepguide render simulation SCENARIO.yaml [--methods dipole,geometric,potential] [--width PX] [--title T] -o FIG
// deepguide render turn-rates SCENARIO.yaml [--methods ...] [--width PX] [--title T] -o FIG
// The reactive level's figures (the seed's Figs. 8/10, 11 and 12). An unknown
// method is bad input (exit 1, one line), as a bad scenario or extension.

#include <algorithm>
#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/render/field_figure.hpp"
#include "deepguide/render/route_scene.hpp"  // kMinImageWidth, kMaxImageWidth
#include "deepguide/render/trajectory_figure.hpp"
#include "deepguide/render/turn_rate_plot.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace deepguide::app {
namespace {

struct ReactiveFigureOptions {
  std::string scenario, output, title;
  std::string method;
  std::vector<std::string> methods = [] {
    std::vector<std::string> names;
    for (const ReactiveMethodEntry& e : reactive_method_entries()) names.push_back(e.name);
    return names;
  }();
  int width = 1200;
};

CLI::App* add_figure_command(CLI::App& render, const std::string& name, const std::string& help,
                             const std::shared_ptr<ReactiveFigureOptions>& o) {
  CLI::App* cmd = render.add_subcommand(name, help);
  cmd->add_option("SCENARIO", o->scenario, "Scenario file (YAML, see data/scenarios/one_obstacle.yaml)")->required();
  cmd->add_option("-o,--output", o->output, "Image to write: .png or .svg")->required();
  cmd->add_option("--width", o->width, "Image width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(kMinImageWidth, kMaxImageWidth));
  cmd->add_option("--title", o->title, "Title line (default: what the figure shows and the scenario's name)");
  return cmd;
}

void add_methods_option(CLI::App& cmd, ReactiveFigureOptions& o) {
  cmd.add_option("--methods", o.methods, "Methods to simulate, comma-separated")->delimiter(',')->capture_default_str();
}

}  // namespace

ReactiveMethod reactive_method_option(const std::string& option, const std::string& name) {
  return reactive_method_named(name, option);
}

void register_render_reactive(CLI::App& render) {
  {
    auto o = std::make_shared<ReactiveFigureOptions>();
    CLI::App* cmd = add_figure_command(
        render, "field", "Draw a reactive method's gradient lines around a scenario's obstacles (PNG or SVG)", o);
    cmd->add_option("--method", o->method, "Reactive method: " + reactive_method_names_text())->required();
    cmd->callback([o] {
      image_format_for(o->output);  // fail fast, before reading anything
      const ReactiveMethod method = reactive_method_option("--method", o->method);
      FieldFigure figure = field_figure_for(read_scenario_file(o->scenario), method);
      figure.width_px = o->width;
      if (!o->title.empty()) figure.map.title = o->title;
      const FieldFigureGeometry g = render_field_figure(figure, o->output);
      std::printf("wrote            %s (%zu gradient lines)\n", o->output.c_str(), g.lines.size());
    });
  }
  {
    auto o = std::make_shared<ReactiveFigureOptions>();
    CLI::App* cmd = add_figure_command(
        render, "simulation", "Simulate the reactive methods through a scenario and draw their trajectories", o);
    add_methods_option(*cmd, *o);
    cmd->callback([o] {
      image_format_for(o->output);
      const std::vector<ReactiveMethod> methods = reactive_methods_named(o->methods, "--methods");
      TrajectoryFigure figure = trajectory_figure_for(read_scenario_file(o->scenario), methods);
      figure.width_px = o->width;
      if (!o->title.empty()) figure.map.title = o->title;
      render_trajectory_figure(figure, o->output);
      std::printf("wrote            %s\n", o->output.c_str());
      for (const SimulationResult& run : figure.runs) std::printf("  %s\n", run_summary(run).c_str());
    });
  }
  {
    auto o = std::make_shared<ReactiveFigureOptions>();
    CLI::App* cmd = add_figure_command(render, "turn-rates",
                                       "Simulate the reactive methods and plot r_ref and r over time (deg/s)", o);
    add_methods_option(*cmd, *o);
    cmd->callback([o] {
      image_format_for(o->output);
      const std::vector<ReactiveMethod> methods = reactive_methods_named(o->methods, "--methods");
      TurnRatePlot plot = turn_rate_plot_for(read_scenario_file(o->scenario), methods);
      plot.width_px = o->width;
      if (!o->title.empty()) plot.title = o->title;
      render_turn_rate_plot(plot, o->output);
      std::printf("wrote            %s\n", o->output.c_str());
    });
  }
}

}  // namespace deepguide::app
