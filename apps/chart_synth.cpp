// deepguide chart synth -o DIR [--name NAME] [--seed N]

#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "deepguide/charts/sample_chart.hpp"

namespace deepguide::app {
namespace {

struct SynthOptions {
  std::string dir;
  SampleChartOptions chart;
};

}  // namespace

void register_chart_synth(CLI::App& chart) {
  auto o = std::make_shared<SynthOptions>();
  CLI::App* cmd = chart.add_subcommand(
      "synth", "Write the synthetic sample chart: DIR/NAME.tif (elevation) and DIR/NAME_hazards.gpkg");
  cmd->add_option("-o,--output", o->dir, "Existing folder to write into")->required();
  cmd->add_option("--name", o->chart.name, "File name stem")->capture_default_str();
  cmd->add_option("--seed", o->chart.seed, "Seed of the sea floor's small-scale roughness")->capture_default_str();
  cmd->callback([o] {
    const SampleChartFiles files = write_sample_chart(o->dir, o->chart);
    std::printf("wrote            %s\n", files.raster.c_str());
    std::printf("wrote            %s (%zu hazards)\n", files.hazards.c_str(), files.hazard_count);
  });
}

}  // namespace deepguide::app
