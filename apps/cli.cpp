// The deepguide command tree and its exit codes: 0 success, 1 bad input, 2
// usage, 3 no safe route, 4 done with some inputs skipped (evaluate: a broken
// scenario). apps/main.cpp runs it; tests run it in-process
// (tests/planning/test_toy_graph.cpp).

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <new>
#include <optional>

#include "commands.hpp"
#include "deepguide/charts/chart_options.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/version.hpp"

namespace deepguide::app {

void add_frame_options(CLI::App& cmd, FrameOptions& options) {
  cmd.add_option("--crs", options.crs,
                 "Local planning frame, a projected CRS in metres such as EPSG:32632 (default: UTM zone of the data)");
  cmd.add_option("--src-crs", options.src_crs,
                 "CRS of input files that carry none, e.g. a CSV in UTM (default: EPSG:4326 lon/lat)");
}

std::optional<double> finite_number(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

void require_finite_numbers(CLI::App& app) {
  // A value, or each comma-separated part of it, that reads as a number must
  // be a finite one; what is no number at all is left to the option's parser.
  // Refused as bad input (one line, exit 1) like every other bad value the
  // commands read, not as a usage error.
  for (CLI::Option* o : app.get_options()) {
    if (o->get_type_name().find("FLOAT") == std::string::npos) continue;
    const std::string flag = o->get_lnames().empty() ? o->get_name() : "--" + o->get_lnames().front();
    o->check(CLI::Validator(
        [flag](std::string& text) -> std::string {
          std::string_view rest = text;
          for (;;) {
            const std::size_t comma = rest.find(',');
            const std::string part(rest.substr(0, comma));
            char* end = nullptr;
            const double v = std::strtod(part.c_str(), &end);
            const char* stop = end;
            const bool all =
                stop != part.c_str() && std::all_of(stop, part.c_str() + part.size(), [](char c) { return c == ' '; });
            if (all && !std::isfinite(v)) {
              throw InputError(flag + ": expected a finite number, got '" + printable(text) + "'");
            }
            if (comma == std::string_view::npos) return std::string();
            rest.remove_prefix(comma + 1);
          }
        },
        ""));
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) require_finite_numbers(*sub);
}

void add_chart_options(CLI::App& cmd, ChartOptions& chart, double* vertical_clearance_m) {
  CLI::Option* zoc = cmd.add_option_function<std::string>(
      "--zoc",
      [&chart](const std::string& name) {
        const std::optional<ZocPolicy> p = parse_zoc_policy(name);
        if (!p) throw InputError("--zoc: expected clipped, strict or none, got '" + printable(name) + "'");
        chart.zoc = *p;
      },
      "Zones of confidence (M_QUAL CATZOC): clipped (default: depths less their uncertainty, a point hazard a disc "
      "of its zone's position accuracy clipped to water not surveyed better), strict (the discs unclipped), none "
      "(charted depths and positions as exact); docs/CHARTS.md");
  cmd.add_flag_callback(
         "--no-zoc", [&chart] { chart.zoc = ZocPolicy::none; }, "The same as --zoc none")
      ->excludes(zoc);
  cmd.add_flag("--restricted", chart.restricted_areas,
               "Restricted areas (RESTRN entry prohibited, entry restricted, area to be avoided) are no-go too");
  cmd.add_option_function<std::string>(
      "--unassessed-zoc",
      [&chart](const std::string& text) {
        double v[3];
        std::size_t at = 0;
        for (int k = 0; k < 3; ++k) {
          const std::size_t end = k < 2 ? text.find(',', at) : text.size();
          const std::string part = end == std::string::npos ? std::string() : text.substr(at, end - at);
          char* stop = nullptr;
          v[k] = part.empty() ? std::nan("") : std::strtod(part.c_str(), &stop);
          // The values' ranges (NaN and infinities out) are check_chart_options's.
          if (part.empty() || stop == nullptr || *stop != '\0' || (k == 2 && end != text.size())) {
            throw InputError("--unassessed-zoc: expected DEPTH_M,FRACTION,POSITION_M (e.g. 2,0.05,500), got '" +
                             printable(text) + "'");
          }
          at = end + 1;
        }
        chart.unassessed = {v[0], v[1], v[2]};
        check_chart_options(chart);
      },
      "Zones of confidence D, U and water without M_QUAL: depth uncertainty DEPTH_M + FRACTION x depth, position "
      "accuracy POSITION_M (default 2,0.05,500: CATZOC C's)");
  if (vertical_clearance_m != nullptr) {
    cmd.add_option("--vertical-clearance,--clearance", *vertical_clearance_m,
                   "Water kept between the vehicle and the charted depth, hazards and obstacle tops (m)")
        ->capture_default_str();
  }
}

namespace {

// The library's messages name the parameters its callers set (core/error.hpp);
// the command line's user set them as flags.
const std::map<std::string_view, std::string_view, std::less<>> kFlagOfParameter = {
    {"charts", "--chart"},
    {"clearance_m", "--clearance"},
    {"cost", "--cost"},
    {"data_root", "--data"},
    {"depart_s", "--depart"},
    {"depth_m", "--depth"},
    {"escape", "--escape"},
    {"format", "--format"},
    {"fresh", "--fresh"},
    {"goal", "--to"},
    {"goal_heading", "--to-heading"},
    {"graph", "--graph"},
    {"graphs", "--graphs"},
    {"local_crs", "--crs"},
    {"margin", "--margin"},
    {"margin_m", "--margin"},
    {"max_dive_deg", "--max-dive"},
    {"merge_distance_m", "--merge-distance"},
    {"method", "--method"},
    {"methods", "--methods"},
    {"min_cell_m", "--min-cell"},
    {"mode", "--mode"},
    {"name", "--name"},
    {"operating_depth_m", "--depth"},
    {"output", "--output"},
    {"overwrite", "--overwrite"},
    {"replan_events", "--replan-events"},
    {"search", "--search"},
    {"shard", "--shard"},
    {"smooth", "--smooth"},
    {"spacing_m", "--waypoint-grid"},
    {"speed", "--speed"},
    {"src_crs", "--src-crs"},
    {"start", "--from"},
    {"start_heading", "--from-heading"},
    {"tolerance", "--tolerance"},
    {"turn_radius_m", "--turn-radius"},
    {"unassessed", "--unassessed-zoc"},
    {"vehicle", "--vehicle"},
    {"vertical_clearance_m", "--vertical-clearance"},
    {"waypoint_grid", "--waypoint-grid"},
    {"width_px", "--width"},
    {"zone_tolerance", "--zone-tolerance"},
};

}  // namespace

std::optional<std::string> flag_of_parameter(std::string_view parameter) {
  const auto it = kFlagOfParameter.find(parameter);
  if (it == kFlagOfParameter.end()) return std::nullopt;
  return std::string(it->second);
}

void register_commands(CLI::App& app) {
  app.set_version_flag("--version", std::string("deepguide ") + kVersion);
  app.require_subcommand(1);

  CLI::App* obstacles = app.add_subcommand("obstacles", "Inspect and convert obstacle files");
  obstacles->require_subcommand(1);
  register_obstacles_info(*obstacles);
  register_obstacles_convert(*obstacles);
  register_obstacles_import(*obstacles);
  CLI::App* chart = app.add_subcommand("chart", "Sea charts: bathymetry, S-57 cells, no-go areas, the sample chart");
  chart->require_subcommand(1);
  register_chart_synth(*chart);
  register_chart_info(*chart);
  register_chart_nogo(*chart);
  register_chart_prepare(*chart);
  register_plan(app);
  register_mission(app);
  register_simulate(app);
  register_identify(app);
  register_suite(app);
  register_evaluate(app);
  register_figures(app);
  CLI::App* check = app.add_subcommand("check", "Check routes against obstacles");
  check->require_subcommand(1);
  register_check_route(*check);
  CLI::App* render = app.add_subcommand("render", "Draw charts as PNG or SVG");
  render->require_subcommand(1);
  register_render_route(*render);
  register_render_chart(*render);
  register_render_reactive(*render);
  register_render_identification(*render);
  register_render_mission(*render);
  require_finite_numbers(app);
}

int run(int argc, char** argv) {
  CLI::App app{"deepguide: plan and analyse how an AUV is guided around obstacles and objects"};
  register_commands(app);

  // Every message is one line a terminal shows as it is: what a file put in
  // an id or a name (a newline, an escape sequence, U+202E) is escaped here
  // whatever the message that carries it.
  const auto one_line = [](const char* what) { return printable(rename_parameters(what, flag_of_parameter), 4000); };
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const InputError& e) {
    std::cerr << "deepguide: error: " << one_line(e.what()) << "\n";
    return 1;
  } catch (const NoRouteError& e) {
    std::cerr << "deepguide: no safe route: " << one_line(e.what()) << "\n";
    return 3;
  } catch (const ManoeuvreError& e) {
    std::cerr << "deepguide: manoeuvre failed: " << one_line(e.what()) << "\n";
    return 3;
  } catch (const PartialError& e) {
    std::cerr << "deepguide: incomplete: " << one_line(e.what()) << "\n";
    return 4;
  } catch (const std::bad_alloc&) {
    std::cerr << "deepguide: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "deepguide: internal error: " << one_line(e.what()) << "\n";
    return 1;
  }
  return 0;
}

}  // namespace deepguide::app
