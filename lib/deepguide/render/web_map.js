// The web map's page script (render/web_map.hpp says what the page does).
// It reads the layers from <script id="dg-data" type="application/json">,
// and is inlined into every page with Leaflet: no network.
(function () {
  "use strict";
  const data = JSON.parse(document.getElementById("dg-data").textContent);
  // Lines and rings come as steps of 1e-7 degrees ("q", web_map.cpp): decoded to GeoJSON positions.
  const positions = (q) => {
    const out = new Array(q.length / 2);
    let x = 0;
    let y = 0;
    for (let i = 0; i < q.length; i += 2) {
      x += q[i];
      y += q[i + 1];
      out[i / 2] = [x / 1e7, y / 1e7];
    }
    return out;
  };
  for (const layer of data.layers) {
    for (const f of layer.features) {
      const g = f.geometry;
      if (!g || !g.q) continue;
      if (g.type === "LineString") g.coordinates = positions(g.q);
      else if (g.type === "Polygon") g.coordinates = g.q.map(positions);
      else if (g.type === "MultiPolygon") g.coordinates = g.q.map((p) => p.map(positions));
      delete g.q;
    }
  }
  const esc = (s) => String(s).replace(/[&<>"']/g, (c) => ({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;"}[c]));
  const table = (props) =>
    "<table class=\"dg-props\">" +
    Object.entries(props).map(([k, v]) => "<tr><th>" + esc(k) + "</th><td>" + esc(v) + "</td></tr>").join("") +
    "</table>";

  // A frame with no geographic anchor is drawn on a plain plane, x east and y north in metres.
  const map = L.map("map", Object.assign({preferCanvas: true, zoomSnap: 0.25, attributionControl: false},
    data.planar ? {crs: L.CRS.Simple, minZoom: -10, maxZoom: 8} : {}));
  // The view first (web_map.cpp works it out): layers added after it are drawn once.
  const f = data.focus;
  if (f) map.fitBounds([[f.south, f.west], [f.north, f.east]], {padding: [20, 20], animate: false});
  else map.setView([0, 0], 2);

  // Pictures (a raster's depth shading) under the layers.
  const overlaysOfImages = {};
  for (const image of data.images || []) {
    const overlay = L.imageOverlay(image.url, [[image.south, image.west], [image.north, image.east]],
      {opacity: image.opacity, interactive: false});
    overlaysOfImages[esc(image.name)] = overlay;
    image.loaded = new Promise((resolve) => overlay.once("load", resolve));
    if (image.shown) overlay.addTo(map);
  }

  // A layer's features become Leaflet's when it is first shown (a hidden
  // layer costs nothing until then).
  const overlays = {};
  const built = {};
  const explained = [];
  // Diagonal lines in a colour, as a canvas pattern Leaflet's canvas renderer fills with.
  const hatch = (colour) => {
    const tile = document.createElement("canvas");
    tile.width = tile.height = 8;
    const c = tile.getContext("2d");
    c.strokeStyle = colour;
    c.lineWidth = 1.2;
    c.beginPath();
    c.moveTo(-2, 10);
    c.lineTo(10, -2);
    c.moveTo(-2, 2);
    c.lineTo(2, -2);
    c.moveTo(6, 10);
    c.lineTo(10, 6);
    c.stroke();
    return c.createPattern(tile, "repeat");
  };
  const build = (layer, group) => {
    if (built[layer.id]) return;
    const style = {
      color: layer.stroke, weight: layer.weight, fillColor: layer.hatched ? hatch(layer.fill) : layer.fill,
      fillOpacity: layer.fill_opacity, opacity: 1, dashArray: layer.dash || null, interactive: !layer.explained,
    };
    built[layer.id] = L.geoJSON({type: "FeatureCollection", features: layer.features}, {
      style: (f) => (f.style ? Object.assign({}, style, f.style) : style),
      pointToLayer: (f, ll) => L.circleMarker(ll, Object.assign({}, style, f.style || {}, {radius: layer.point_radius_px})),
      onEachFeature: (f, l) => {
        if (!layer.explained && f.properties && Object.keys(f.properties).length) l.bindPopup(table(f.properties));
      },
    });
    // A layer with a least zoom shows its features only from it in.
    const show = () => {
      const wanted = map.getZoom() >= (layer.min_zoom || 0);
      if (wanted && !group.hasLayer(built[layer.id])) group.addLayer(built[layer.id]);
      if (!wanted && group.hasLayer(built[layer.id])) group.removeLayer(built[layer.id]);
    };
    if (layer.min_zoom) map.on("zoomend", show);
    show();
  };
  for (const layer of data.layers) {
    const group = L.layerGroup();
    group.on("add", () => build(layer, group));
    if (layer.explained) explained.push({layer: layer, group: group});
    const swatch = "<span class=\"dg-swatch\" style=\"border-color:" + esc(layer.stroke) + ";background:" +
      esc(layer.fill) + "\"></span>";
    overlays[swatch + esc(layer.name) + " <span class=\"dg-count\">(" + layer.features.length + ")</span>"] = group;
    if (layer.shown) group.addTo(map);
    layer.group = group;
  }
  L.control.layers(null, Object.assign({}, overlaysOfImages, overlays), {collapsed: false}).addTo(map);
  L.control.scale({imperial: false, maxWidth: 160}).addTo(map);

  // Point in a GeoJSON (multi)polygon, even-odd over every ring (holes included).
  function inRing(ring, x, y) {
    let inside = false;
    for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
      const [xi, yi] = ring[i];
      const [xj, yj] = ring[j];
      if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
    }
    return inside;
  }
  function contains(geometry, x, y) {
    const polygons = geometry.type === "Polygon" ? [geometry.coordinates]
      : geometry.type === "MultiPolygon" ? geometry.coordinates : [];
    return polygons.some((rings) => rings.reduce((acc, ring) => acc !== inRing(ring, x, y), false));
  }
  // What a click tells: every feature of an explained layer under it (the
  // chart's no-go: overlapping features all listed, the planner's reason each).
  map.on("click", (e) => {
    const hits = [];
    for (const {layer, group} of explained) {
      if (!map.hasLayer(group)) continue;
      for (const feature of layer.features) {
        if (feature.geometry && contains(feature.geometry, e.latlng.lng, e.latlng.lat)) hits.push(feature.properties);
      }
    }
    if (hits.length) {
      L.popup({maxHeight: 320}).setLatLng(e.latlng)
        .setContent("<div class=\"dg-hits\">" + hits.map(table).join("<hr>") + "</div>").openOn(map);
    }
  });

  // The table beside the map (none: the map takes the page).
  const t = data.table;
  if (!t || !t.columns.length) document.getElementById("dg-table").style.display = "none";
  if (t && t.columns.length) {
    document.getElementById("dg-table").innerHTML =
      "<h2>" + esc(t.title) + "</h2><table class=\"dg-rows\"><thead><tr>" +
      t.columns.map((c) => "<th>" + esc(c) + "</th>").join("") + "</tr></thead><tbody>" +
      t.rows.map((r) => "<tr>" + r.map((v) => "<td>" + esc(v === null ? "" : v) + "</td>").join("") + "</tr>").join("") +
      "</tbody></table>";
  }

  const ready = Math.round(performance.now());  // the page as an operator gets it

  // The fragment: view, click and test output for scripts and tests.
  const args = {};
  for (const part of location.hash.replace(/^#/, "").split("&")) {
    const [k, v] = part.split("=");
    if (k) args[decodeURIComponent(k)] = v === undefined ? "" : decodeURIComponent(v);
  }
  // show=ID,... and hide=ID,...: switch layers on and off.
  for (const [key, on] of [["show", true], ["hide", false]]) {
    for (const id of (args[key] || "").split(",").filter(Boolean)) {
      const layer = data.layers.find((l) => l.id === id);
      if (layer && on) layer.group.addTo(map);
      if (layer && !on) map.removeLayer(layer.group);
    }
  }
  if (args.center || args.zoom) {
    const c = args.center ? args.center.split(",").map(Number) : [map.getCenter().lng, map.getCenter().lat];
    map.setView([c[1], c[0]], args.zoom ? Number(args.zoom) : map.getZoom(), {animate: false});
  }
  if (args.click) {
    const [lon, lat] = args.click.split(",").map(Number);
    map.fire("click", {latlng: L.latLng(lat, lon)});
  }
  if ("test" in args) {
    // Every layer built, hidden ones too, and counted as Leaflet made them.
    const counts = {};
    for (const layer of data.layers) {
      build(layer, layer.group);
      counts[layer.id] = built[layer.id].getLayers().length;
    }
    const out = document.createElement("pre");
    out.id = "dg-test";
    // Written once the pictures are decoded (shown ones load as the map draws them).
    const shown = (data.images || []).filter((image) => image.shown);
    Promise.all(shown.map((image) => image.loaded)).then(() => {
      const images = {};
      for (const image of data.images || []) {
        const el = overlaysOfImages[esc(image.name)].getElement();
        images[image.id] = el ? {width: el.naturalWidth, height: el.naturalHeight} : null;
      }
      out.textContent = JSON.stringify({
        layers: counts, images: images, table: t ? t.rows : [], zoom: map.getZoom(), ms: ready,
      });
      document.body.appendChild(out);
    });
  }
})();
