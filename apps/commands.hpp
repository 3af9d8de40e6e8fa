#pragma once
// Each subcommand registers itself on its parent from its own file.

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>

namespace deepguide {
struct ChartOptions;
class LocalFrame;
struct Route;
struct ReactiveMethod;
}  // namespace deepguide

namespace deepguide::app {

/// Parses the command line, runs the command and returns the exit code
/// (apps/cli.cpp): what `main` does, callable in-process.
int run(int argc, char** argv);

/// Every command and its options under `app` (run's tree), each number an
/// option takes checked finite (require_finite_numbers).
void register_commands(CLI::App& app);

/// Adds, to every option under `app` whose values are numbers (CLI11's FLOAT
/// type), a check that refuses NaN and infinities (InputError naming the flag), also inside lists such as
/// TOP,BOTTOM: NaN passes every range check (each comparison with it is
/// false) and stands for "not given" in many of the library's requests.
void require_finite_numbers(CLI::App& app);

/// The number `text` spells, if it is one and finite (no NaN, no infinity);
/// a leading '+' and surrounding blanks are allowed. For options read as text.
std::optional<double> finite_number(std::string_view text);

/// The flag that sets a parameter a library message names ("min_cell_m" ->
/// "--min-cell"); nothing for a parameter no flag sets.
std::optional<std::string> flag_of_parameter(std::string_view parameter);

/// Options every command that reads obstacles or charts shares.
struct FrameOptions {
  std::string crs;      ///< --crs: local planning frame
  std::string src_crs;  ///< --src-crs: CRS of inputs that carry none
};
void add_frame_options(CLI::App& cmd, FrameOptions& options);

/// The chart options of every command that reads S-57 charts, with the same
/// names and meaning everywhere (charts/chart_options.hpp): --zoc
/// clipped|strict|none (--no-zoc for none), --restricted, --unassessed-zoc
/// A,B,R, and --vertical-clearance (also --clearance) where the command
/// keeps one (`vertical_clearance_m` not null).
void add_chart_options(CLI::App& cmd, ChartOptions& chart, double* vertical_clearance_m);

void register_obstacles_info(CLI::App& obstacles);
void register_obstacles_convert(CLI::App& obstacles);
void register_obstacles_import(CLI::App& obstacles);
void register_plan(CLI::App& app);
void register_mission(CLI::App& app);
void register_render_mission(CLI::App& render);
void register_check_route(CLI::App& check);
void register_render_route(CLI::App& render);
void register_chart_synth(CLI::App& chart);
void register_chart_info(CLI::App& chart);
void register_render_chart(CLI::App& render);
void register_render_reactive(CLI::App& render);
void register_chart_nogo(CLI::App& chart);
void register_chart_prepare(CLI::App& chart);
void register_simulate(CLI::App& app);
void register_identify(CLI::App& app);
void register_suite(CLI::App& app);
void register_evaluate(CLI::App& app);
void register_figures(CLI::App& app);
void register_render_identification(CLI::App& render);

/// A reactive method named on the command line (simulate, render field): an
/// unknown name is bad input (exit 1), as --graph's is for plan.
ReactiveMethod reactive_method_option(const std::string& option, const std::string& name);

}  // namespace deepguide::app
