#pragma once
// A map an operator can zoom and click: one self-contained HTML page that
// works offline (no tile server, no network), its layers GeoJSON in lon/lat
// (WGS 84) drawn by Leaflet, which is inlined from Debian's libjs-leaflet
// when the page is written (docs/WEB_MAP.md).
//
// What the page does (render/web_map.js):
//  - each layer switchable, its name and feature count in the layer switcher,
//    a scale bar, the view fitted to `focus` (else to everything);
//  - a click on a feature of an `explained` layer (the chart's no-go) lists
//    every such feature under the click with its properties (why the
//    planner took it as no-go); other layers' features open their own
//    properties in a popup;
//  - a table beside the map (a route's waypoints);
//  - for tests and scripts, the URL's fragment: `#test` writes the layers'
//    feature counts and the table as JSON into <pre id="dg-test">,
//    `click=LON,LAT` clicks there, `zoom=Z` and `center=LON,LAT` set the view,
//    `show=ID,...` and `hide=ID,...` switch layers on and off.
// Coordinates are written to 1e-7 degrees (about a centimetre); lines and
// rings as integer steps of that (a third of the text), which the page
// decodes exactly.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/world/extent.hpp"
#include "deepguide/world/local_frame.hpp"

namespace DEEPGUIDE_API deepguide {

struct WebMapLayer {
  std::string id;    ///< a stable key ("no_go", "route"): what tests and the fragment's counts name it by
  std::string name;  ///< what the layer switcher shows
  /// Features: GeoJSON Feature objects in lon/lat; their properties are
  /// what a click shows (name -> value, in the order given).
  nlohmann::ordered_json features = nlohmann::ordered_json::array();
  std::string stroke = "#1c7ed6";
  std::string fill = "#1c7ed6";
  double fill_opacity = 0.2;
  double weight = 2.0;           ///< line width (px)
  std::string dash;              ///< SVG dash array, e.g. "6 4"; "" solid
  double point_radius_px = 4.0;  ///< points are drawn as circles this big
  bool shown = true;             ///< on when the page opens
  bool explained = false;        ///< a click lists every feature of it under the click
  bool hatched = false;          ///< areas filled with diagonal lines of `fill` (a chart's no-go)
  /// Drawn only from this zoom level in (Leaflet's: 0 the world, 18 streets;
  /// soundings thin out as a chart zooms out); 0: at every zoom.
  double min_zoom = 0.0;
};

/// A picture laid on the map between lon/lat bounds (a raster's depth
/// shading, render/raster_web_image.hpp), as Web Mercator cells.
struct WebMapImage {
  std::string id;
  std::string name;
  std::string png_base64;
  LonLatExtent bounds;
  double opacity = 0.85;
  bool shown = true;
};

struct WebMapTable {
  std::string title;
  std::vector<std::string> columns;
  std::vector<std::vector<nlohmann::ordered_json>> rows;
};

struct WebMap {
  std::string title;
  std::string subtitle;             ///< a second line: the frame, the depth, the graph
  std::vector<WebMapImage> images;  ///< drawn under the layers
  std::vector<WebMapLayer> layers;
  WebMapTable table;
  LonLatExtent focus;  ///< what the page shows first (NaN: every layer's extent)
  /// Positions are x, y metres of a local frame with no geographic anchor
  /// (drawn on a plain plane, Leaflet's CRS.Simple, with a metric scale);
  /// false: lon/lat.
  bool planar = false;
};

/// A feature for a layer: `geometry` a GeoJSON geometry in lon/lat;
/// `style` (e.g. {"fill": "#9ec5e8"}) overrides its layer's for it alone.
nlohmann::ordered_json web_map_feature(nlohmann::ordered_json geometry, nlohmann::ordered_json properties,
                                       nlohmann::ordered_json style = nullptr);

/// A lon/lat position as GeoJSON writes it, to 1e-7 degrees.
nlohmann::ordered_json web_map_position(double lon, double lat);

/// GeoJSON geometries of shapes in a local frame: in lon/lat, or, with no
/// frame (a scenario with no geographic anchor), as the frame's x, y metres
/// for a planar page (WebMap::planar).
struct WebMapGeometry {
  const LocalFrame* frame = nullptr;

  nlohmann::ordered_json position(const Vec2& p) const;
  nlohmann::ordered_json point(const Vec2& p) const;
  nlohmann::ordered_json line(const std::vector<Vec2>& points) const;
  /// A closed outline (closed here when it is not).
  nlohmann::ordered_json outline(const std::vector<Vec2>& ring) const;
  nlohmann::ordered_json polygon(const BgPolygon& p) const;
  nlohmann::ordered_json multipolygon(const BgMultiPolygon& m) const;
  /// A disc as a 48-gon.
  nlohmann::ordered_json disc(const Vec2& centre, double radius_m) const;
};

/// The planning frame's grid over the box [lo, hi] (frame metres): lines of
/// constant easting and northing at a round spacing (1, 2 or 5 x 10^k m,
/// about ten across), each with its value; off when the page opens.
WebMapLayer frame_grid_layer(const LocalFrame& frame, const Vec2& lo, const Vec2& hi);

/// The page. Throws InputError when Leaflet cannot be read (naming the
/// file and the Debian package).
std::string web_map_html(const WebMap& map);

/// Writes the page to `path` atomically (nothing written on failure).
/// Throws InputError for a path that is not .html or .htm, a missing folder,
/// or Leaflet missing.
void write_web_map(const WebMap& map, const std::string& path);

/// Throws InputError naming `option` (e.g. "--html") unless `path` ends in
/// .html or .htm and its folder exists: checked before the work that fills the page.
void check_web_map_path(const std::string& path, const std::string& option);

/// Where Leaflet is read from: $DEEPGUIDE_LEAFLET_DIR, else Debian's
/// /usr/share/javascript/leaflet (libjs-leaflet).
std::string leaflet_dir();

}  // namespace deepguide
