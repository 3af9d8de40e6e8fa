#pragma once
// The gradient-line figure of one reactive method (the seed's Fig. 8 for the
// dipole method, Fig. 10 for the geometric construction): gradient lines from
// seeds across the way upstream (gradient_lines.hpp), the line from the start
// drawn bold, a light grid of arrows with the field's direction everywhere
// else, and a dot where a line ends because the field vanishes or reverses
// (a stagnation point, the potential field's trap). On the reactive map
// (reactive_map.hpp): footprints, security zones, start, target.
//
// Decisions:
// - Besides the evenly spaced lines, the dividing lines (gradient_lines.hpp):
//   the line into the dipole's stagnation point, into the potential field's
//   trap, which the figure exists to show.
// - Seeds every kSeedSpacing design units (about 22 px at 1200 px wide) on the
//   map: the lines' density is a property of the picture, not of the scene.
// - Integration step: half a pixel at the figure's scale, so the polylines are
//   smooth on screen and their chords cut at most a hair into a zone they
//   ride along; at most 4 times the area's perimeter in steps per line.
// - Arrows every 40 design units, skipped inside true footprints (a point
//   inside rock has no meaningful course); inside zones they show the exit.

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/render/gradient_lines.hpp"
#include "deepguide/render/reactive_map.hpp"

namespace DEEPGUIDE_API deepguide {

struct Scenario;

struct FieldFigure {
  ReactiveMethod method = ReactiveMethod::geometric;
  ReactiveParams params;
  ReactiveMap map;  ///< objects, start and target; map.margin_m must equal params.margin_m
  int width_px = 1200;
};

/// The figure for a scenario: its true obstacles, reactive params, start and
/// target, titled with the method and the scenario's name.
FieldFigure field_figure_for(const Scenario& scenario, ReactiveMethod method);

struct FieldFigureGeometry {
  ReactiveMapLayout layout;
  std::vector<GradientLine> lines;  ///< local frame (m): the seeds' lines, then the dividing lines
  std::size_t start_line = 0;       ///< index of the line from the start
  std::size_t dividing = 0;         ///< how many dividing lines end the list
  GradientLineOptions options;      ///< the step used
};

/// Layout and gradient lines, without drawing. Throws InputError for bad
/// params (validate), a map margin other than the params', a bad width or
/// non-finite positions.
FieldFigureGeometry field_figure_geometry(const FieldFigure& figure);

/// Draws the figure to `path` (.png or .svg), atomically; returns what it drew.
/// Errors are one line prefixed by the path.
FieldFigureGeometry render_field_figure(const FieldFigure& figure, const std::string& path);

}  // namespace deepguide
