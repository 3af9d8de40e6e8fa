// deepguide identify SCENARIO.yaml [--mode align|around] [-o TRAJ.csv] [--json]
// deepguide render identification SCENARIO.yaml [--mode align|around] [--width PX] [--title T] -o FIG.png|svg
// identify runs the scenario's identify section (simulation/
// identification_run.hpp) and prints its statistics and mode switches. Exit 0
// when the manoeuvre was done (held, laps_done); 3 when it could not be (a
// current stronger than the vehicle, the time limit), after printing and
// writing what there is; 1 for a bad scenario, an unknown mode or an
// unwritable output; 2 for usage. render identification draws whatever the
// run did (exit 0 with the figure, the outcome in its legend), 1 and 2 alike.

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/render/identification_figure.hpp"
#include "deepguide/render/route_scene.hpp"  // kMinImageWidth, kMaxImageWidth
#include "deepguide/simulation/identification_run.hpp"
#include "deepguide/simulation/scenario.hpp"
#include "deepguide/simulation/trajectory_io.hpp"

namespace deepguide::app {
namespace {

struct IdentifyOptions {
  std::string scenario, mode, output, title;
  bool json = false;
  int width = 1200;
};

// The scenario with its identify section, in the mode --mode names (or its own).
Scenario identify_scenario(const IdentifyOptions& o) {
  return read_identification_scenario(o.scenario, o.mode, "--mode");
}

}  // namespace

void register_identify(CLI::App& app) {
  auto o = std::make_shared<IdentifyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "identify", "Simulate an identification manoeuvre: aligning to an object in a current, or going around it");
  cmd->add_option("SCENARIO", o->scenario, "Scenario file with an identify section (see data/scenarios/)")->required();
  cmd->add_option("--mode", o->mode, "align or around (default: the scenario's identify.mode)");
  cmd->add_option("-o,--output", o->output, "Trajectory file to write (CSV)");
  cmd->add_flag("--json", o->json, "Print the statistics and mode switches as JSON");
  cmd->callback([o] {
    const Scenario scenario = identify_scenario(*o);
    const IdentifyResult result = simulate_identification(scenario, {!o->output.empty()});
    if (!o->output.empty()) write_identification_csv(o->output, result.trajectory);
    if (o->json) {
      std::cout << identification_json(scenario, result).dump(2) << "\n";
    } else {
      std::cout << identification_text(scenario, result) << std::flush;
    }
    if (!result.failure.empty()) throw ManoeuvreError(o->scenario + ": " + result.failure);
  });
}

void register_render_identification(CLI::App& render) {
  auto o = std::make_shared<IdentifyOptions>();
  CLI::App* cmd = render.add_subcommand(
      "identification", "Simulate an identification manoeuvre and draw the areas, the current and the track");
  cmd->add_option("SCENARIO", o->scenario, "Scenario file with an identify section (see data/scenarios/)")->required();
  cmd->add_option("-o,--output", o->output, "Image to write: .png or .svg")->required();
  cmd->add_option("--mode", o->mode, "align or around (default: the scenario's identify.mode)");
  cmd->add_option("--width", o->width, "Image width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(kMinImageWidth, kMaxImageWidth));
  cmd->add_option("--title", o->title, "Title line (default: the manoeuvre and the scenario's name)");
  cmd->callback([o] {
    image_format_for(o->output);  // fail fast, before simulating
    IdentificationFigure figure = identification_figure_for(identify_scenario(*o));
    figure.width_px = o->width;
    if (!o->title.empty()) figure.map.title = o->title;
    render_identification_figure(figure, o->output);
    std::printf("wrote            %s\n  %s\n", o->output.c_str(), identification_summary(figure.run).c_str());
    std::fflush(stdout);
    // The figure shows where it failed; the exit says so as identify's does.
    if (!figure.run.failure.empty()) throw ManoeuvreError(o->scenario + ": " + figure.run.failure);
  });
}

}  // namespace deepguide::app
