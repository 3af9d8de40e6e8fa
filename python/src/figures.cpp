// The drawings of `deepguide render field|simulation|turn-rates|
// identification|mission` and `deepguide figures`, each drawn to a path by
// the library call the command makes. The package's Python part gives them
// `path=None`: the drawing's bytes (PNG or SVG), for a notebook or a web page.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/reactive/reactive_registry.hpp"
#include "deepguide/render/canvas.hpp"
#include "deepguide/render/field_figure.hpp"
#include "deepguide/render/identification_figure.hpp"
#include "deepguide/render/mission_figure.hpp"
#include "deepguide/render/route_scene.hpp"  // kMinImageWidth, kMaxImageWidth
#include "deepguide/render/seed_figures.hpp"
#include "deepguide/render/trajectory_figure.hpp"
#include "deepguide/render/turn_rate_plot.hpp"
#include "deepguide/simulation/identification_run.hpp"
#include "deepguide/simulation/mission_run_report.hpp"
#include "deepguide/simulation/scenario.hpp"

namespace py = pybind11;

namespace deepguide::python {
namespace {

// Checked before anything is read or simulated, as the CLI's option is.
void check_figure(const std::filesystem::path& path, int width) {
  image_format_for(path.string());
  if (width < kMinImageWidth || width > kMaxImageWidth) {
    throw InputError("`width`: expected " + std::to_string(kMinImageWidth) + " to " + std::to_string(kMaxImageWidth) +
                     " pixels, got " + std::to_string(width));
  }
}

// Where the bundled data may be, as `deepguide figures` looks: `data`, else
// $DEEPGUIDE_DATA, the current folder, the source tree built from, the
// installed share/deepguide.
std::vector<std::string> data_candidates(const std::string& given) {
  if (!given.empty()) return {given};
  std::vector<std::string> out;
  if (const char* env = std::getenv("DEEPGUIDE_DATA")) out.emplace_back(env);
  out.emplace_back(".");
  out.emplace_back(DEEPGUIDE_SOURCE_DIR);
  out.emplace_back(DEEPGUIDE_INSTALL_DATA);
  return out;
}

}  // namespace

void bind_figures(py::module_& m) {
  m.def(
      "_render_field",
      [](const std::filesystem::path& scenario, const std::string& method, const std::filesystem::path& path, int width,
         const std::string& title) {
        const ReactiveMethod parsed = reactive_method_named(method, "`method`");
        check_figure(path, width);
        py::gil_scoped_release free;
        FieldFigure figure = field_figure_for(read_scenario_file(scenario.string()), parsed);
        figure.width_px = width;
        if (!title.empty()) figure.map.title = title;
        render_field_figure(figure, path.string());
      },
      py::arg("scenario"), py::arg("method"), py::arg("path"), py::arg("width"), py::arg("title"));
  m.def(
      "_render_simulation",
      [](const std::filesystem::path& scenario, const std::vector<std::string>& methods,
         const std::filesystem::path& path, int width, const std::string& title) {
        const std::vector<ReactiveMethod> parsed = reactive_methods_named(methods, "`methods`");
        check_figure(path, width);
        py::gil_scoped_release free;
        TrajectoryFigure figure = trajectory_figure_for(read_scenario_file(scenario.string()), parsed);
        figure.width_px = width;
        if (!title.empty()) figure.map.title = title;
        render_trajectory_figure(figure, path.string());
      },
      py::arg("scenario"), py::arg("methods"), py::arg("path"), py::arg("width"), py::arg("title"));
  m.def(
      "_render_turn_rates",
      [](const std::filesystem::path& scenario, const std::vector<std::string>& methods,
         const std::filesystem::path& path, int width, const std::string& title) {
        const std::vector<ReactiveMethod> parsed = reactive_methods_named(methods, "`methods`");
        check_figure(path, width);
        py::gil_scoped_release free;
        TurnRatePlot plot = turn_rate_plot_for(read_scenario_file(scenario.string()), parsed);
        plot.width_px = width;
        if (!title.empty()) plot.title = title;
        render_turn_rate_plot(plot, path.string());
      },
      py::arg("scenario"), py::arg("methods"), py::arg("path"), py::arg("width"), py::arg("title"));
  m.def(
      "_render_identification",
      [](const std::filesystem::path& scenario, const std::string& mode, const std::filesystem::path& path, int width,
         const std::string& title) {
        check_figure(path, width);
        py::gil_scoped_release free;
        IdentificationFigure figure = identification_figure_for(read_identification_scenario(scenario.string(), mode));
        figure.width_px = width;
        if (!title.empty()) figure.map.title = title;
        render_identification_figure(figure, path.string());
      },
      py::arg("scenario"), py::arg("mode"), py::arg("path"), py::arg("width"), py::arg("title"));
  m.def(
      "_render_mission",
      [](const std::filesystem::path& mission, const std::filesystem::path& path, int width, const std::string& title,
         bool as_written) {
        check_figure(path, width);
        py::gil_scoped_release free;
        render_mission_file(mission.string(), path.string(), {title, width, as_written});
      },
      py::arg("mission"), py::arg("path"), py::arg("width"), py::arg("title"), py::arg("as_written"));
  // A simulated mission's drawing, from the run in hand (not simulated again).
  py::type::of<MissionRunReport>().attr("_render") = py::cpp_function(
      [](const MissionRunReport& r, const std::filesystem::path& path, double zoom, int width,
         const std::string& title) {
        check_figure(path, width);
        py::gil_scoped_release free;
        const LoadedMission& l = r.loaded;
        MissionFigure figure = simulated_mission_figure(l.mission, l.plan, r.planned, r.run, zoom);
        figure.width_px = width;
        if (!title.empty()) figure.title = title;
        render_mission(figure, path.string());
      },
      py::is_method(py::type::of<MissionRunReport>()), py::arg("path"), py::arg("zoom"), py::arg("width"),
      py::arg("title"));
  m.def(
      "_seed_figures",
      [](const std::filesystem::path& output, const std::vector<int>& only, const std::string& format, int width,
         const std::string& data) {
        std::string json;
        {
          py::gil_scoped_release free;
          SeedFigureOptions o;
          o.data_root = locate_seed_data(data_candidates(data));
          o.output_dir = output.string();
          o.extension = format;
          o.width_px = width;
          o.only = only;
          json = seed_figures_json(o.data_root, write_seed_figures(o))
                     .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
        }
        return from_json(json);
      },
      py::arg("output"), py::arg("only"), py::arg("format"), py::arg("width"), py::arg("data"));
}

}  // namespace deepguide::python
