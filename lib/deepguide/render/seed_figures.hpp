#pragma once
// The seed paper's figures, reproduced from bundled data (`deepguide figures`).
// The paper's own figures are lost; its text says what each showed, and each
// is redrawn from one bundled input with the code that does the work:
//
//   Fig.  4  route by the two levels of control: a mission planned round its
//            known obstacles, an object nobody knew found by the sonar; the
//            reactive level reacts at point A, then the repaired plan is
//            sailed (data/missions/encounter.yaml + encounter_unknown.geojson)
//   Fig.  6  the visibility graph over the obstacle scenario's zone polygons,
//            every edge that cuts no zone, and its shortest route
//   Fig.  7  the quadtree graph over the same: free and occupied cells, the
//            edges between neighbouring free cells, its shortest route
//            (both data/scenarios/obstacle_field.yaml)
//   Fig.  8  gradient lines of the harmonic dipole potential
//   Fig. 10  gradient lines of the geometric construction
//            (both data/scenarios/one_obstacle.yaml)
//   Fig. 11  the paths of the dipole method and the geometric construction
//            through the obstacle scenario, simulated with vehicle and sonar
//   Fig. 12  their reference turning rate r_ref and the vehicle's r over time
//            (both data/scenarios/obstacle_field.yaml)
//
// Decisions:
// - Figs. 6 and 7 use the whole graph (no query focus), as the seed drew
//   them, with the scenario's margin. Fig. 6 is the full visibility graph (the
//   seed: "all possible lines between the vertices"), its zone polygons cut
//   at a 2 m tolerance so that a reader can count their corners; Fig. 7's raw
//   cell-centre route, unsmoothed: its shape is the seed's argument.
// - Figs. 11 and 12 show the two methods the seed compares; the potential
//   field is in `deepguide render simulation`.
// - Fig. 4's planner takes 30 s on the vehicle, so the reactive level's part
//   of the track is long enough to see.
// The numbers behind each figure (graph sizes, route lengths, turning rates)
// come back as facts, for the terminal and for tests.

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// One of the seed's figures, as this module redraws it.
struct SeedFigureSpec {
  int number = 0;
  std::string stem;                 ///< the file name without extension, e.g. "fig06_visibility_graph"
  std::string caption;              ///< what it shows, one line
  std::vector<std::string> inputs;  ///< bundled files it is drawn from, relative to the data root
};

/// The figures, in the seed's order (4, 6, 7, 8, 10, 11, 12).
const std::vector<SeedFigureSpec>& seed_figure_specs();

struct SeedFigureOptions {
  std::string data_root;          ///< the folder holding data/ (the project's root, or an installed share/deepguide)
  std::string output_dir;         ///< made when missing
  std::string extension = "png";  ///< png or svg
  int width_px = 1200;
  std::vector<int> only;  ///< figure numbers to draw; empty = all
};

struct WrittenSeedFigure {
  int number = 0;
  std::string path;
  std::string summary;                  ///< one line: the numbers the figure shows
  std::map<std::string, double> facts;  ///< the same as numbers, by name (e.g. "route_m", "geometric_max_r_ref_deg_s")
};

/// The first of `candidates` that holds every figure's inputs. Throws
/// InputError naming the candidates and the first input each one lacks.
std::string locate_seed_data(const std::vector<std::string>& candidates);

/// Draws the figures (options.only, or all) into options.output_dir, in the
/// seed's order, all or nothing: they are drawn into a staging folder inside
/// it and moved in when every one is done (then `on_written` is called for
/// each). Throws InputError for an unknown figure number (naming the known
/// ones), a bad extension or width, an output_dir that is a file or cannot be
/// made or written, and what the drawings throw for their inputs; then no
/// figure of this call is left, nor the output folder if the call made it.
std::vector<WrittenSeedFigure> write_seed_figures(const SeedFigureOptions& options,
                                                  const std::function<void(const WrittenSeedFigure&)>& on_written = {});

/// What `figures` prints of each figure: "Fig. N  PATH" and its summary below.
std::string to_text(const WrittenSeedFigure& figure);
/// {"data": data_root, "figures": [{figure, file, summary, facts}, ...]}.
nlohmann::json seed_figures_json(const std::string& data_root, const std::vector<WrittenSeedFigure>& figures);

}  // namespace deepguide
