#include "deepguide/render/enc_layer.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "deepguide/charts/enc_cells.hpp"
#include "deepguide/charts/enc_reader.hpp"
#include "deepguide/charts/prepared_chart.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/world/no_go_union.hpp"

namespace deepguide {

namespace {

const std::vector<std::string> kStructures = {"SLCONS", "PONTON", "HULKES", "FLODOC", "PILPNT", "PYLONS",
                                              "MORFAC", "OFSPLF", "CAUSWY", "DAMCON", "DRYDOC", "GATCON"};

std::vector<std::vector<Vec2>> rings_px(const BgPolygon& p, const ViewTransform& view) {
  std::vector<std::vector<Vec2>> rings;
  auto ring = [&](const auto& r) {
    std::vector<Vec2> out;
    out.reserve(r.size());
    for (const BgPoint& q : r) out.push_back(view.to_pixel(to_eigen(q)));
    rings.push_back(std::move(out));
  };
  ring(p.outer());
  for (const auto& in : p.inners()) ring(in);
  return rings;
}

// The discs of point hazards as one area: overlapping discs would darken where they pile up.
std::vector<BgPolygon> disc_union(const ObstacleSet& set) {
  std::vector<BgPolygon> discs;
  for (const EllipticCylinder& e : set.ellipses) {
    BgPolygon p;
    const int n = 48;
    for (int i = n; i >= 0; --i) {  // clockwise, closed
      const double a = 2.0 * std::numbers::pi * i / n;
      p.outer().push_back(to_bg(e.footprint.centre + e.footprint.a * Vec2(std::cos(a), std::sin(a))));
    }
    discs.push_back(std::move(p));
  }
  std::vector<const BgPolygon*> ptrs;
  for (const BgPolygon& p : discs) ptrs.push_back(&p);
  return union_no_go({}, ptrs);
}

std::string depth_text(double d) { return fixed(d, d < 10.0 ? 1 : 0); }

}  // namespace

WorldBox EncLayer::box() const {
  WorldBox b;
  for (const BgPolygon& p : coverage) {
    for (const BgPoint& q : p.outer()) b.extend(to_eigen(q));
  }
  return b;
}

bool LabelPlacer::place(const PixelRect& box) {
  if (boxes_.size() >= max_) return false;
  for (const PixelRect& r : boxes_) {
    if (box.x < r.x + r.width && r.x < box.x + box.width && box.y < r.y + r.height && r.y < box.y + box.height) {
      return false;
    }
  }
  boxes_.push_back(box);
  return true;
}

EncLayer read_enc_layer(const std::vector<std::string>& cells, const LocalFrame& frame, double depth_m,
                        double clearance_m, const ChartOptions& chart) {
  EncLayer layer;
  const bool prepared = cells.size() == 1 && is_prepared_chart(cells.front());
  if (std::isfinite(depth_m)) {
    layer.no_go = chart_no_go(cells, frame, enc_options(chart, depth_m, clearance_m));
  }
  if (prepared) {
    // Only the no-go was kept: its features stand for the chart.
    if (layer.no_go) {
      for (const EncNoGoFeature& f : layer.no_go->features) {
        if (f.cls == "M_COVR") continue;
        for (const BgPolygon& p : f.area) layer.coverage.push_back(p);
      }
    }
    return layer;
  }
  EncReadRequest request;
  request.classes = {"DEPARE", "DRGARE", "LNDARE", "UNSARE", "OBSTRN", "WRECKS", "UWTROC", "SOUNDG"};
  request.classes.insert(kStructures.begin(), kStructures.end());
  const EncCells read = read_enc_cells(find_enc_cells(cells), frame, request);
  // Several cells are drawn as the planners read them: best scale first, and each other cell only
  // where no better one covers (its areas clipped, its points and soundings there left out), so a
  // band-3 cell's symbols do not pile up under a harbour cell's.
  std::vector<const EncCell*> order;
  for (const EncCell& c : read.cells) order.push_back(&c);
  std::stable_sort(order.begin(), order.end(), [](const EncCell* a, const EncCell* b) {
    return decides_before(a->compilation_scale, a->usage_band, a->name, b->compilation_scale, b->usage_band, b->name);
  });
  BgMultiPolygon better;
  for (const EncCell* cp : order) {
    const EncCell& c = *cp;
    for (const BgPolygon& p : c.coverage) layer.coverage.push_back(p);
    if (read.cells.size() > 1) layer.cells.push_back({c.name, c.usage_band, c.compilation_scale, c.coverage});
    const BgBox better_box = better.empty() ? BgBox() : boost::geometry::return_envelope<BgBox>(better);
    auto hidden = [&](const Vec2& q) {
      return !better.empty() && boost::geometry::covered_by(to_bg(q), better_box) &&
             boost::geometry::covered_by(to_bg(q), better);
    };
    auto shown_area = [&](const BgMultiPolygon& a) {
      if (better.empty() || a.empty() ||
          !boost::geometry::intersects(boost::geometry::return_envelope<BgBox>(a), better_box)) {
        return a;
      }
      BgMultiPolygon out;
      boost::geometry::difference(a, better, out);
      return out;
    };
    for (const EncFeature& cell_feature : c.features) {
      EncFeature f = cell_feature;
      if (!better.empty()) {
        f.areas = shown_area(f.areas);
        std::vector<Vec2> points;
        std::vector<double> depths;
        for (std::size_t k = 0; k < f.points.size(); ++k) {
          if (hidden(f.points[k])) continue;
          points.push_back(f.points[k]);
          if (k < f.point_depths.size()) depths.push_back(f.point_depths[k]);
        }
        f.points = std::move(points);
        f.point_depths = std::move(depths);
        if (f.areas.empty() && f.points.empty() && f.lines.empty()) continue;
      }
      const std::string id = f.cls + "/" + std::to_string(f.rcid);
      if (f.cls == "DEPARE" || f.cls == "DRGARE") {
        if (!f.areas.empty()) layer.depth_areas.push_back({f.areas, f.drval1});
        if (std::isfinite(f.drval1)) layer.max_depth_m = std::max(layer.max_depth_m, f.drval1);
        if (std::isfinite(f.drval2)) layer.max_depth_m = std::max(layer.max_depth_m, f.drval2);
      } else if (f.cls == "LNDARE" || f.cls == "UNSARE") {
        for (const BgPolygon& p : f.areas) layer.land.push_back(p);
        for (const Vec2& p : f.points) layer.structure_points.push_back(p);
        for (const auto& l : f.lines) layer.structure_lines.push_back(l);
      } else if (f.cls == "SOUNDG") {
        for (std::size_t k = 0; k < f.points.size(); ++k) layer.soundings.push_back({f.points[k], f.point_depths[k]});
      } else if (f.cls == "OBSTRN" || f.cls == "WRECKS" || f.cls == "UWTROC") {
        layer.dangers.push_back({id, f.cls, f.points, f.areas, f.lines, f.valsou});
      } else {
        for (const BgPolygon& p : f.areas) layer.structure_areas.push_back(p);
        for (const Vec2& p : f.points) layer.structure_points.push_back(p);
        for (const auto& l : f.lines) layer.structure_lines.push_back(l);
      }
    }
    BgMultiPolygon next;
    boost::geometry::union_(better, c.coverage, next);
    better = std::move(next);
  }
  return layer;
}

void draw_enc_layer(Canvas& canvas, const ViewTransform& view, const EncLayer& layer, const EncStyle& style, double u,
                    const std::function<Rgba(double)>& depth_color, LabelPlacer& labels) {
  const double required = layer.no_go ? layer.no_go->required_depth_m : NAN;
  auto too_shallow = [&](double d) { return layer.no_go && (!(d >= 0.0) || d < required); };
  // Depth areas, then land over them.
  for (const EncLayer::DepthArea& a : layer.depth_areas) {
    const Rgba fill = std::isnan(a.drval1) ? Rgba{0.85, 0.85, 0.85, 1.0}
                      : a.drval1 < 0.0     ? style.drying
                                           : depth_color(a.drval1);
    for (const BgPolygon& p : a.area) canvas.fill_rings(rings_px(p, view), fill);
  }
  // The no-go, hatched once (the planners' merged polygons and the discs outside them: overlapping
  // features would darken where they pile up), land over it, then the no-go's edge: the safety
  // contour for the required depth with the dangers' rings.
  if (layer.no_go) {
    // A light wash under the hatching keeps it visible over the dark deep tints too.
    const Stroke hatch{{style.no_go.r, style.no_go.g, style.no_go.b, 0.7}, 0.8 * u, {}};
    const Rgba wash{style.no_go.r, style.no_go.g, style.no_go.b, 0.12};
    for (const PolygonObstacle& p : layer.no_go->obstacles.polygons) {
      const auto rings = rings_px(p.footprint, view);
      canvas.fill_rings(rings, wash);
      canvas.hatch_rings(rings, hatch, 6.0 * u);
    }
    for (const BgPolygon& d : disc_union(layer.no_go->obstacles)) {
      const auto rings = rings_px(d, view);
      canvas.fill_rings(rings, wash);
      canvas.hatch_rings(rings, hatch, 6.0 * u);
    }
  }
  for (const BgPolygon& p : layer.land) {
    const auto rings = rings_px(p, view);
    canvas.fill_rings(rings, style.land);
    for (const auto& r : rings) canvas.stroke_polyline(r, Stroke{style.land_edge, 0.8 * u, {}}, true);
  }
  if (layer.no_go) {
    const Stroke edge{style.no_go, 1.6 * u, {}};
    for (const PolygonObstacle& p : layer.no_go->obstacles.polygons) {
      for (const auto& r : rings_px(p.footprint, view)) canvas.stroke_polyline(r, edge, true);
    }
    for (const BgPolygon& d : disc_union(layer.no_go->obstacles)) {
      for (const auto& r : rings_px(d, view)) canvas.stroke_polyline(r, Stroke{style.no_go, 1.0 * u, {}}, true);
    }
  }
  // Several cells: each one's coverage outlined faintly, its name and usage band at its top left.
  for (const EncLayer::Cell& cell : layer.cells) {
    for (const BgPolygon& p : cell.coverage) {
      for (const auto& r : rings_px(p, view))
        canvas.stroke_polyline(r, Stroke{style.cell_edge, 0.9 * u, {4.0 * u, 3.0 * u}}, true);
    }
    if (cell.coverage.empty()) continue;
    const BgBox b = boost::geometry::return_envelope<BgBox>(cell.coverage);
    const Vec2 corner = view.to_pixel(Vec2(b.min_corner().x(), b.max_corner().y())) + Vec2(3.0 * u, 11.0 * u);
    const std::string t = cell.name + " (band " + std::to_string(cell.usage_band) + ")";
    const double w = canvas.text_width(t, 8.5 * u);
    if (labels.place({corner.x(), corner.y() - 9.0 * u, w, 10.0 * u})) {
      canvas.text_with_halo(corner, t, 8.5 * u, style.cell_edge, {1.0, 1.0, 1.0, 0.7}, 1.5 * u);
    }
  }
  // Structures.
  for (const BgPolygon& p : layer.structure_areas) canvas.fill_rings(rings_px(p, view), style.structure);
  for (const auto& l : layer.structure_lines) {
    std::vector<Vec2> px;
    for (const Vec2& q : l) px.push_back(view.to_pixel(q));
    canvas.stroke_polyline(px, Stroke{style.structure, 1.4 * u, {}});
  }
  for (const Vec2& q : layer.structure_points) canvas.circle(view.to_pixel(q), 1.8 * u, style.structure, std::nullopt);
  // Soundings: shallowest first, where their number fits.
  std::vector<const EncLayer::Sounding*> order;
  for (const EncLayer::Sounding& s : layer.soundings) order.push_back(&s);
  std::stable_sort(order.begin(), order.end(), [](auto* a, auto* b) { return a->depth < b->depth; });
  const double size = 9.5 * u;
  for (const EncLayer::Sounding* s : order) {
    const Vec2 c = view.to_pixel(s->at);
    const std::string t = depth_text(s->depth);
    const double w = canvas.text_width(t, size);
    if (!labels.place({c.x() - 0.5 * w, c.y() - size, w, size * 1.1})) continue;
    canvas.text(c + Vec2(0.0, 0.0), t, size, too_shallow(s->depth) ? style.no_go : style.sounding, TextAlign::centre);
  }
  // Dangers: a symbol by kind at each point, an outline round each area. At a regional scale
  // hundreds of them fall on a few pixels of coast: a point symbol is drawn where it overlaps no
  // symbol drawn before, the ones too shallow first.
  std::vector<const EncLayer::Danger*> dangers;
  for (const EncLayer::Danger& d : layer.dangers) dangers.push_back(&d);
  std::stable_sort(dangers.begin(), dangers.end(), [&](const EncLayer::Danger* a, const EncLayer::Danger* b) {
    return (too_shallow(a->depth) || std::isnan(a->depth)) > (too_shallow(b->depth) || std::isnan(b->depth));
  });
  LabelPlacer symbols(std::numeric_limits<std::size_t>::max());
  for (const EncLayer::Danger* dp : dangers) {
    const EncLayer::Danger& d = *dp;
    const Rgba c =
        too_shallow(d.depth) || std::isnan(d.depth) ? (layer.no_go ? style.no_go : style.danger) : style.danger;
    const Stroke line{c, 1.3 * u, {}};
    for (const BgPolygon& p : d.area) {
      for (const auto& r : rings_px(p, view)) canvas.stroke_polyline(r, Stroke{c, 1.2 * u, {1.5 * u, 2.0 * u}}, true);
    }
    for (const auto& l : d.lines) {
      std::vector<Vec2> px;
      for (const Vec2& q : l) px.push_back(view.to_pixel(q));
      canvas.stroke_polyline(px, Stroke{c, 1.2 * u, {1.5 * u, 2.0 * u}});
    }
    for (const Vec2& q : d.points) {
      const Vec2 p = view.to_pixel(q);
      const double r = 4.5 * u;
      if (!symbols.place({p.x() - r, p.y() - r, 2.0 * r, 2.0 * r})) continue;
      if (d.cls == "UWTROC") {  // a cross, the rock symbol
        canvas.stroke_segments({{p - Vec2(r, 0), p + Vec2(r, 0)}, {p - Vec2(0, r), p + Vec2(0, r)}}, line);
      } else if (d.cls == "WRECKS") {  // a hull with three masts
        canvas.stroke_segments({{p - Vec2(1.4 * r, 0), p + Vec2(1.4 * r, 0)},
                                {p - Vec2(0, r), p + Vec2(0, r)},
                                {p + Vec2(-0.7 * r, -0.6 * r), p + Vec2(-0.7 * r, 0.6 * r)},
                                {p + Vec2(0.7 * r, -0.6 * r), p + Vec2(0.7 * r, 0.6 * r)}},
                               line);
      } else {  // an obstruction: a dotted circle
        canvas.circle(p, r, std::nullopt, Stroke{c, 1.2 * u, {1.2 * u, 1.6 * u}});
      }
      const std::string t = std::isnan(d.depth) ? d.cls : depth_text(d.depth);
      const double w = canvas.text_width(t, 9.0 * u);
      if (labels.place({p.x() + r + 1.0 * u, p.y() - 9.0 * u, w, 10.0 * u})) {
        canvas.text_with_halo(p + Vec2(r + 1.0 * u, 0.0), t, 9.0 * u, c, {1.0, 1.0, 1.0, 0.8}, 2.0 * u);
      }
    }
  }
}

}  // namespace deepguide
