#include "deepguide/evaluation/eval_report.hpp"

#include <cmath>
#include <filesystem>
#include <functional>
#include <sstream>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/evaluation/eval_summary.hpp"
#include "deepguide/render/box_plot.hpp"

namespace deepguide {

namespace {

// Okabe-Ito colours, the reactive methods' own first (render/reactive_map.cpp).
Rgba colour(const std::string& method, std::size_t i) {
  if (method == "dipole") return rgb_hex(0x0072b2);
  if (method == "geometric") return rgb_hex(0xd55e00);
  if (method == "potential") return rgb_hex(0x009e73);
  static const unsigned others[] = {0xe69f00, 0xcc79a7, 0x56b4e9, 0x000000, 0xf0e442};
  return rgb_hex(others[i % 5]);
}

struct Figure {
  const char* file;
  const char* title;
  const char* y_title;
  bool log_y;
  bool planners_only;
  std::function<double(const MethodRun&)> value;  // NaN: not drawn
};

}  // namespace

std::vector<std::string> write_report(const std::string& dir, const EvaluationRun& run,
                                      const std::vector<EvaluationMap>& maps) {
  const double nan = std::nan("");
  const std::vector<Figure> figures = {
      {"fig_path_length.png", "Path sailed", "path over ground (m)", false, false,
       [nan](const MethodRun& r) { return r.end == "no_route" ? nan : r.path_length_m; }},
      {"fig_energy.png", "Energy", "energy (kJ)", false, false,
       [nan](const MethodRun& r) { return r.end == "no_route" ? nan : r.energy_j / 1000.0; }},
      {"fig_time.png", "Time", "time (s)", false, false,
       [nan](const MethodRun& r) { return r.end == "no_route" ? nan : r.time_s; }},
      {"fig_min_clearance.png", "Least clearance to a true obstacle", "clearance (m)", false, false,
       [nan](const MethodRun& r) { return r.end == "no_route" ? nan : r.min_clearance_m; }},
      {"fig_max_rate_ref.png", "Largest reference turning rate (the seed's Fig. 12 over the suite)",
       "max |r_ref| (\u00b0/s)", false, false,
       [nan](const MethodRun& r) { return r.end == "no_route" ? nan : rad_to_deg(r.max_rate_ref); }},
      {"fig_rms_rate_ref.png", "RMS reference turning rate", "rms r_ref (\u00b0/s)", false, false,
       [nan](const MethodRun& r) { return r.end == "no_route" ? nan : rad_to_deg(r.rms_rate_ref); }},
      {"fig_compute_ms.png", "Compute time (planners: graph and search; reactive: guidance over the run)",
       "compute time (ms)", true, false, [](const MethodRun& r) { return r.compute_ms; }},
      {"fig_graph_size.png", "Graph size (vertices + edges)", "vertices + edges", true, true,
       [](const MethodRun& r) { return static_cast<double>(r.graph_vertices + r.graph_edges); }},
  };
  const std::filesystem::path d(dir);
  std::vector<std::string> written;
  std::vector<std::string> planners;
  for (const std::string& m : run.manifest.methods) {
    if (parse_eval_method(m).is_planner()) planners.push_back(m);
  }
  for (const Figure& f : figures) {
    if (std::string(f.file) == "fig_compute_ms.png" && !run.manifest.timing) continue;
    BoxPlot plot;
    plot.title = f.title;
    plot.y_title = f.y_title;
    plot.log_y = f.log_y;
    const std::vector<std::string>& methods = f.planners_only ? planners : run.manifest.methods;
    for (std::size_t i = 0; i < methods.size(); ++i) {
      BoxGroup g;
      g.label = methods[i];
      g.color = colour(methods[i], i);
      for (const EvalRow& r : run.rows) {
        if (r.method != methods[i]) continue;
        const double v = f.value(r.run);
        if (!std::isnan(v)) g.values.push_back(v);
      }
      plot.groups.push_back(std::move(g));
    }
    bool any = false;
    for (const BoxGroup& g : plot.groups) {
      for (double v : g.values) any = any || (std::isfinite(v) && (!f.log_y || v > 0.0));
    }
    if (!any) continue;
    render_box_plot(plot, (d / f.file).string());
    written.push_back(f.file);
  }

  const EvaluationSummary s = summarize(run);
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>deepguide evaluation: "
    << html_text(run.manifest.suite) << "</title>\n<style>\n"
    << "body{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#212529;padding:0 1em}\n"
    << "table{border-collapse:collapse;font-size:0.9em}td,th{border:1px solid #ced4da;padding:0.3em 0.5em;"
       "text-align:right}td:first-child,th:first-child{text-align:left}\n"
    << ".holds{color:#2b8a3e}.fails{color:#c92a2a}img{max-width:100%;border:1px solid #e3e7ec;margin:0.5em 0}\n"
    << "</style>\n</head>\n<body>\n";
  o << "<h1>Evaluation of suite " << html_text(run.manifest.suite) << "</h1>\n";
  o << "<p>" << run.rows.size() << " runs of " << run.manifest.methods.size() << " methods"
    << (run.manifest.skipped.empty() ? "" : ", " + std::to_string(run.manifest.skipped.size()) + " skipped")
    << ". Each cell: median / 95th percentile. Path, energy, time, clearance and turning rates are the vehicle's, "
       "simulated; a planner's route, within the vehicle's turning radius, is sailed by path following "
       "(docs/EVALUATION.md).</p>\n";
  o << "<h2>The seed's claims</h2>\n<ul>\n";
  for (const ClaimCheck& c : s.claims) {
    const char* cls = c.verdict == "holds" ? "holds" : c.verdict == "does not hold" ? "fails" : "";
    o << "<li><b>" << html_text(c.claim) << "</b>: <span class=\"" << cls << "\">" << html_text(c.verdict)
      << "</span><ul>\n";
    for (const std::string& e : c.evidence) o << "<li>" << html_text(e) << "</li>\n";
    o << "</ul></li>\n";
  }
  o << "</ul>\n<h2>Methods</h2>\n<table>\n<tr>";
  const std::vector<MethodColumn> columns = method_columns(run.manifest);
  for (const MethodColumn& c : columns) o << "<th>" << html_text(c.header) << "</th>";
  o << "</tr>\n";
  for (const MethodStats& m : s.methods) {
    o << "<tr>";
    for (const MethodColumn& c : columns) o << "<td>" << html_text(c.cell(m)) << "</td>";
    o << "</tr>\n";
  }
  o << "</table>\n<h2>Figures</h2>\n";
  for (const std::string& f : written) o << "<p><img src=\"" << f << "\" alt=\"" << f << "\"></p>\n";
  if (!maps.empty()) {
    o << "<h2>Scenarios as maps</h2>\n<p>Where the methods came closest to an obstacle, and where they collided: "
         "each method's track over the obstacles, to zoom and click (one page each, offline).</p>\n<ul>\n";
    for (const EvaluationMap& m : maps) {
      o << "<li><a href=\"" << html_text(m.file) << "\">" << html_text(m.scenario) << "</a>: " << html_text(m.why)
        << "</li>\n";
    }
    o << "</ul>\n";
  }
  if (!run.manifest.skipped.empty()) {
    o << "<h2>Skipped</h2>\n<ul>\n";
    for (const SkippedRun& k : run.manifest.skipped) {
      o << "<li>" << html_text(k.scenario) << (k.method.empty() ? "" : " with " + html_text(k.method)) << ": "
        << html_text(k.error) << "</li>\n";
    }
    o << "</ul>\n";
  }
  o << "<p>Rows: <a href=\"rows.csv\">rows.csv</a>, <a href=\"results.json\">results.json</a>.</p>\n</body>\n</html>\n";
  write_text_file(d / "report.html", o.str(), "report");
  return written;
}

}  // namespace deepguide
