// deepguide.generate_suite and deepguide.evaluate: `deepguide suite
// generate` and `deepguide evaluate`, from Python. The rows come as the
// rows.csv text (eval_row_csv), which the package's Python part reads into a
// structured array, so they are the file's to the digit; to_dict() is
// results.json.

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include <functional>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "deepguide/evaluation/eval_method.hpp"
#include "deepguide/evaluation/eval_rows.hpp"
#include "deepguide/evaluation/eval_summary.hpp"
#include "deepguide/evaluation/evaluate.hpp"
#include "deepguide/evaluation/suite.hpp"

namespace py = pybind11;

namespace deepguide::python {
namespace {

struct Evaluation {
  EvaluationRun run;
  bool timing = true;

  std::string rows_csv() const {
    std::string out = eval_rows_header();
    for (const EvalRow& r : run.rows) out += eval_row_csv(r, timing);
    return out;
  }
};

}  // namespace

void bind_evaluate(py::module_& m) {
  m.def(
      "generate_suite",
      [](const std::filesystem::path& directory, int scenarios, std::uint64_t seed, const std::string& name,
         int min_obstacles, int max_obstacles, double min_size, double max_size, double spread, double max_current,
         double sonar_noise, bool on_demand, bool overwrite) {
        MonteCarloParams p;
        p.scenarios = scenarios, p.seed = seed, p.min_obstacles = min_obstacles, p.max_obstacles = max_obstacles;
        p.min_size_m = min_size, p.max_size_m = max_size, p.cross_track_sigma_m = spread;
        p.max_current_mps = max_current, p.sonar_noise = sonar_noise;
        py::gil_scoped_release free;
        return write_suite(directory.string(), name, p, !on_demand, overwrite);
      },
      py::arg("directory"), py::kw_only(), py::arg("scenarios") = MonteCarloParams{}.scenarios,
      py::arg("seed") = MonteCarloParams{}.seed, py::arg("name") = "",
      py::arg("min_obstacles") = MonteCarloParams{}.min_obstacles,
      py::arg("max_obstacles") = MonteCarloParams{}.max_obstacles, py::arg("min_size") = MonteCarloParams{}.min_size_m,
      py::arg("max_size") = MonteCarloParams{}.max_size_m, py::arg("spread") = MonteCarloParams{}.cross_track_sigma_m,
      py::arg("max_current") = MonteCarloParams{}.max_current_mps,
      py::arg("sonar_noise") = MonteCarloParams{}.sonar_noise, py::arg("on_demand") = false,
      py::arg("overwrite") = false,
      R"(Writes a seeded random suite into `directory`, as `deepguide suite generate`; returns its name.)");

  py::class_<Evaluation>(m, "_Evaluation")
      .def("_rows_csv", &Evaluation::rows_csv)
      .def(
          "to_dict", [](const Evaluation& e) { return from_json(results_json(e.run, summarize(e.run)).dump()); },
          "What results.json holds: the summary per method, the seed's claims, every row.")
      .def(
          "summary_markdown", [](const Evaluation& e) { return summary_markdown(e.run, summarize(e.run)); },
          "The summary `deepguide evaluate` prints (summary.md).")
      .def_property_readonly("complete", [](const Evaluation& e) { return e.run.complete; })
      .def("_skipped_line", [](const Evaluation& e) { return skipped_line(e.run); });

  m.def(
      "_evaluate",
      [](const std::string& suite, const std::string& methods, const std::string& output, int threads, bool fresh,
         bool timing, bool report, std::optional<std::function<void(std::size_t, std::size_t)>> progress, bool html) {
        EvaluateOptions o;
        o.methods = parse_eval_methods(methods);
        o.threads = threads;
        o.fresh = fresh;
        o.timing = timing;
        o.report = report;
        o.maps = html;
        if (progress) {
          // Called on the calling thread (evaluate.hpp), which holds no GIL while it runs.
          o.progress = [f = *progress](std::size_t done, std::size_t total) {
            py::gil_scoped_acquire hold;
            f(done, total);
          };
        }
        Evaluation out;
        out.timing = timing;
        py::gil_scoped_release free;
        const Suite s = read_suite(suite);
        out.run = evaluate_suite(s, output, o);
        return out;
      },
      py::arg("suite"), py::arg("methods"), py::arg("output"), py::arg("threads") = 0, py::arg("fresh") = false,
      py::arg("timing") = true, py::arg("report") = false, py::arg("progress") = py::none(), py::arg("html") = false);
}

}  // namespace deepguide::python
