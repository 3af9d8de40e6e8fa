#pragma once
// S-57 charts as a web map (render/web_map.hpp): `render chart --html`.
//
// Layers, each switchable, from the cells' no-go at an operating depth
// (enc_no_go.hpp), so what is drawn is what the planners read:
//  - cells: where each cell decides, with its name, usage band, scale,
//    edition and update;
//  - depth areas (DEPARE, DRGARE where their cell decides), shaded by
//    DRVAL1, each with its record id;
//  - land (LNDARE);
//  - no_go: every no-go feature with the planner's reason; a click lists
//    every one under it;
//  - hazards: point hazards (rocks, wrecks, obstructions, piles) by kind;
//  - soundings that are no-go (off at first);
//  - zones of confidence (M_QUAL CATZOC, off at first).

#include <string>

#include "deepguide/charts/enc_no_go.hpp"
#include "deepguide/core/api.hpp"
#include "deepguide/render/chart_scene.hpp"
#include "deepguide/render/web_map.hpp"

namespace DEEPGUIDE_API deepguide {

/// The no-go layer alone, every feature with the planner's reason (`plan
/// --html` draws it under a route).
WebMapLayer enc_no_go_layer(const EncNoGo& enc, double operating_depth_m);

/// The map of `enc`, read for `operating_depth_m`; `title` heads the page.
WebMap chart_web_map(const EncNoGo& enc, double operating_depth_m, const std::string& title);

/// `render chart --html`: the charts read as `render chart` reads them
/// (their frame, depth, clearance and chart options; the title, when given)
/// and the page written to `path`: S-57 charts as above, a bathymetry
/// raster's depth shading (render/raster_web_image.hpp), and the rasters' and
/// hazard files' no-go at the depth. Throws InputError naming `--html` for a
/// missing depth, before reading anything.
void write_chart_web_map(const ChartRenderOptions& options, const std::string& path);

}  // namespace deepguide
