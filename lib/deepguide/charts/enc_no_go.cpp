#include "deepguide/charts/enc_no_go.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <set>

#include "deepguide/charts/enc_cell_index.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"
#include "deepguide/geometry/polygon_locator.hpp"
#include "deepguide/geometry/polygon_ops.hpp"
#include "deepguide/world/no_go_union.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

using enc_detail::BoxItem;
using enc_detail::BoxTree;
using enc_detail::DepthAreas;
using enc_detail::envelope;
using enc_detail::ZocZones;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using enc_detail::BgLine;
using BgMultiLine = bg::model::multi_linestring<BgLine>;

const std::set<std::string> kDepthAreas = {"DEPARE", "DRGARE"};
const std::set<std::string> kAlways = {"LNDARE", "UNSARE", "SLCONS", "PONTON", "HULKES", "FLODOC", "PILPNT",
                                       "PYLONS", "MORFAC", "OFSPLF", "CAUSWY", "DAMCON", "DRYDOC", "GATCON"};
const std::set<std::string> kDangers = {"OBSTRN", "WRECKS", "UWTROC"};
// S-57's skin of the earth: areas of one cell that tile it, sharing their edges.
const std::set<std::string> kSkin = {"DEPARE", "DRGARE", "LNDARE", "UNSARE", "FLODOC", "HULKES", "PONTON"};
// RESTRN values that keep a vehicle out: entry prohibited, entry restricted, area to be avoided.
const std::set<int> kNoEntry = {7, 8, 14};
constexpr int kCirclePoints = 16;

void check_options(const EncNoGoOptions& o) {
  auto need = [](bool ok, const char* field, const char* expected, double got) {
    if (!ok) throw InputError(std::string(field) + ": expected " + expected + ", got " + general(got, 4));
  };
  need(std::isfinite(o.operating_depth_m) && o.operating_depth_m >= 0.0, "`operating_depth_m`",
       "the operating depth (m, >= 0) to tell too-shallow water in an S-57 chart", o.operating_depth_m);
  need(std::isfinite(o.vertical_clearance_m) && o.vertical_clearance_m >= 0.0, "`vertical_clearance_m`",
       "a clearance >= 0 m", o.vertical_clearance_m);
  need(std::isfinite(o.point_radius_m) && o.point_radius_m > 0.0, "point radius", "a radius > 0 m", o.point_radius_m);
  need(std::isfinite(o.line_half_width_m) && o.line_half_width_m > 0.0, "line half width", "a width > 0 m",
       o.line_half_width_m);
  need(std::isfinite(o.simplify_tolerance_m) && o.simplify_tolerance_m >= 0.0, "simplify tolerance",
       "a tolerance >= 0 m", o.simplify_tolerance_m);
  check_chart_options(o);
}

// Disc and strip polygons that enclose the true round shape: the chords of a
// regular n-gon at radius r / cos(pi / n) stay outside the circle of radius r.
BgMultiPolygon buffer_line(const std::vector<Vec2>& line, double half_width) {
  BgLine l;
  for (const Vec2& p : line) l.push_back(to_bg(p));
  BgMultiPolygon out;
  if (l.size() < 2) return out;
  const double d = half_width / std::cos(std::numbers::pi / kCirclePoints);
  bg::buffer(l, out, bg::strategy::buffer::distance_symmetric<double>(d), bg::strategy::buffer::side_straight(),
             bg::strategy::buffer::join_round(kCirclePoints), bg::strategy::buffer::end_round(kCirclePoints),
             bg::strategy::buffer::point_circle(kCirclePoints));
  return out;
}

// A point hazard's disc as a polygon enclosing it.
BgMultiPolygon disc_polygon(const Vec2& centre, double radius) {
  BgMultiPolygon out;
  const double d = radius / std::cos(std::numbers::pi / kCirclePoints);
  bg::buffer(to_bg(centre), out, bg::strategy::buffer::distance_symmetric<double>(d),
             bg::strategy::buffer::side_straight(), bg::strategy::buffer::join_round(kCirclePoints),
             bg::strategy::buffer::end_round(kCirclePoints), bg::strategy::buffer::point_circle(kCirclePoints));
  return out;
}

// A zone's rank, best first: A1 1, A2 2, B 3, C 4, D 5; U, any other code and no zone 6.
int zoc_rank(int catzoc) { return catzoc >= 1 && catzoc <= 5 ? catzoc : 6; }

BgMultiPolygon clip_away(const BgMultiPolygon& area, const BgMultiPolygon& better) {
  if (better.empty() || !bg::intersects(envelope(area), envelope(better))) return area;
  BgMultiPolygon out;
  bg::difference(area, better, out);
  return out;
}

struct Builder {
  const EncNoGoOptions& o;
  EncNoGo& out;
  double D;
  bool several_cells;
  std::vector<std::size_t> tiles;        // features whose area is a whole, unclipped skin-of-the-earth area
  bool clipped = false;                  // the feature being read lost part of its area to a better cell
  const ZocZones* zones_here = nullptr;  // the zones of the cell being read

  std::string id_of(const EncCell& c, const EncFeature& f) const {
    return (several_cells ? c.name + ":" : std::string()) + f.cls + "/" + std::to_string(f.rcid);
  }

  double least(double z, const ZocFigures& f) const {
    return z - (f.depth_fixed_m + f.depth_fraction * std::max(z, 0.0));
  }
  bool too_shallow(double z, const ZocFigures& f) const {
    if (!(z >= 0.0)) return true;  // drying (or NaN: unknown)
    return (o.zones_of_confidence() ? least(z, f) : z) < D;
  }
  // Why a charted depth z is no-go; `catzoc` the (best) zone it fails in, -1 for none (unassessed).
  std::string depth_reason(const char* what, double z, int catzoc) const {
    if (std::isnan(z)) return std::string(what) + " unknown";
    std::string r = std::string(what) + " " + general(z, 4) + " m";
    if (z < 0.0) return r + " (dries)";
    if (z < D || !o.zones_of_confidence()) return r + " < " + general(D, 4) + " m";
    // Deep enough as charted: the zone of confidence decides.
    const ZocFigures f = zoc_figures(std::max(catzoc, 0), o);
    return r + ", least " + general(least(z, f), 4) + " m at CATZOC " +
           (catzoc <= 0 ? std::string("none (unassessed)") : zoc_name(catzoc)) + ", < " + general(D, 4) + " m";
  }

  EncNoGoFeature base(const EncCell& c, const EncFeature& f) const {
    EncNoGoFeature n;
    n.id = id_of(c, f);
    n.cell = c.name;
    n.cls = f.cls;
    n.rcid = f.rcid;
    return n;
  }

  static int zoc_min(const std::vector<std::size_t>& ks, const ZocZones& zones) {
    int m = 7;
    for (std::size_t k : ks) m = std::min(m, zones.catzoc[k]);
    return m;
  }

  // A point hazard's disc radius at p.
  double radius_at(const ZocZones& zones, const Vec2& p, double z) const {
    if (!o.zones_of_confidence()) return o.point_radius_m;
    const int k = zones.at(p, z, o);
    return zoc_figures(k < 0 ? 0 : zones.catzoc[static_cast<std::size_t>(k)], o).position_m;
  }

  // ZocPolicy::clipped: a point hazard's disc loses the water of better zones than its own, each
  // zone where its cell decides (out.zones: a worse cell's zone under a better cell says nothing
  // there), unless the hazard itself lies in one (zones that overlap). Its own zone is its cell's.
  void clip_disc(EncNoGoFeature& n) const {
    if (o.zoc != ZocPolicy::clipped || !n.point || zones_here == nullptr) return;
    const double z = std::isnan(n.charted_depth_m) ? 0.0 : n.charted_depth_m;
    const int k = zones_here->at(*n.point, z, o);
    const int own = k < 0 ? 0 : zones_here->catzoc[static_cast<std::size_t>(k)];
    const int rank = zoc_rank(own);
    if (rank <= 1) return;
    const BgMultiPolygon disc = disc_polygon(*n.point, n.radius_m);
    std::vector<const BgPolygon*> better;
    const BgBox disc_box = envelope(disc);
    for (const EncChartArea& zone : out.zones) {
      if (zoc_rank(zone.catzoc) >= rank || !bg::intersects(disc_box, envelope(zone.area))) continue;
      for (const BgPolygon& p : zone.area) {
        if (bg::intersects(p, disc)) better.push_back(&p);
      }
    }
    if (better.empty()) return;
    BgMultiPolygon cut = disc;
    for (const BgPolygon* b : better) {
      BgMultiPolygon next;
      bg::difference(cut, *b, next);
      cut = std::move(next);
    }
    // Where a chord of the disc crosses a zone's edge at a glancing angle, the difference leaves a
    // wedge a fraction of a millimetre wide (US4MD81M: 0.14 m2 over 400 m, 0.3 mm thick) that GEOS's
    // union of the planners' polygons snaps away. No route with a margin notices it; it is dropped
    // here (mean thickness 2 area / perimeter below the repair grid), so that the feature and the
    // planners' polygons agree.
    std::vector<const BgPolygon*> parts;
    for (const BgPolygon& p : cut) {
      if (2.0 * bg::area(p) >= kRepairGridM * bg::perimeter(p)) parts.push_back(&p);
    }
    BgMultiPolygon kept;
    for (BgPolygon& p : union_no_go({}, parts)) kept.push_back(std::move(p));
    if (kept.empty() || !bg::covered_by(to_bg(*n.point), kept)) return;
    n.area = std::move(kept);
    n.point.reset();
    n.reason += "; its " + general(n.radius_m, 4) + " m disc clipped to zones not better than CATZOC " +
                (k < 0 ? std::string("none (unassessed)") : zoc_name(own));
  }

  void add(EncNoGoFeature n, bool whole_area = false) {
    clip_disc(n);
    ++out.no_go_by_class[n.cls];
    if (whole_area && !clipped && kSkin.count(n.cls)) tiles.push_back(out.features.size());
    out.features.push_back(std::move(n));
  }

  // Areas and lines of a feature no-go whatever the depth, points as discs.
  void add_whole(const EncCell& c, const EncFeature& f, const ZocZones& zones, const std::string& reason,
                 double depth) {
    if (!f.areas.empty() || !f.lines.empty()) {
      EncNoGoFeature n = base(c, f);
      n.reason = reason;
      n.charted_depth_m = depth;
      n.area = f.areas;
      for (const auto& l : f.lines) {
        for (BgPolygon& p : buffer_line(l, o.line_half_width_m)) n.area.push_back(std::move(p));
      }
      if (!n.area.empty()) add(std::move(n), f.lines.empty());
    }
    for (std::size_t k = 0; k < f.points.size(); ++k) {
      EncNoGoFeature n = base(c, f);
      if (f.points.size() > 1) n.id += "#" + std::to_string(k + 1);
      n.reason = reason;
      n.charted_depth_m = depth;
      n.point = f.points[k];
      n.radius_m = radius_at(zones, f.points[k], std::isnan(depth) ? 0.0 : depth);
      add(std::move(n));
    }
  }

  // An area with charted depth z: no-go where too shallow in its zones of confidence.
  void add_area_by_depth(const EncCell& c, const EncFeature& f, const BgMultiPolygon& area, double z, const char* what,
                         const ZocZones& zones) {
    if (area.empty()) return;
    EncNoGoFeature n = base(c, f);
    n.charted_depth_m = z;
    n.least_depth_m = z;
    const std::vector<std::size_t> met = o.zones_of_confidence() ? zones.meeting(area) : std::vector<std::size_t>{};
    if (o.zones_of_confidence() && std::isfinite(z) && z >= 0.0) {
      // The worst zone the area meets (water no zone covers counts as unassessed).
      double u = o.unassessed.depth_fixed_m + o.unassessed.depth_fraction * z;
      for (std::size_t k : met) {
        const ZocFigures f2 = zoc_figures(zones.catzoc[k], o);
        u = std::max(u, f2.depth_fixed_m + f2.depth_fraction * z);
      }
      n.least_depth_m = z - u;
    }
    if (std::isnan(z) || z < 0.0 || !o.zones_of_confidence()) {
      if (!too_shallow(z, {})) {
        ++out.passable_by_class[f.cls];
        return;
      }
      n.reason = depth_reason(what, z, -1);
      n.area = area;
      add(std::move(n), &area == &f.areas);
      return;
    }
    const bool unassessed_fails = too_shallow(z, o.unassessed);
    std::vector<std::size_t> failing, passing;
    for (std::size_t k : met) {
      (too_shallow(z, zoc_figures(zones.catzoc[k], o)) ? failing : passing).push_back(k);
    }
    if (passing.empty() && unassessed_fails) {
      // No-go in every zone it meets: the whole area, as charted.
      n.reason = depth_reason(what, z, failing.empty() ? -1 : zoc_min(failing, zones));
      n.area = area;
      add(std::move(n), &area == &f.areas);
      return;
    }
    BgMultiPolygon no_go;
    // The zone named: the best one the area fails in (the verdict's least favourable case is shown elsewhere).
    int shown_zoc = failing.empty() ? -1 : 7;
    for (std::size_t k : failing) shown_zoc = std::min(shown_zoc, zones.catzoc[k]);
    if (unassessed_fails) {
      no_go = area;
      for (std::size_t k : passing) {
        BgMultiPolygon next;
        bg::difference(no_go, zones.polys[k], next);
        no_go = std::move(next);
      }
    } else {
      for (std::size_t k : failing) {
        BgMultiPolygon part, next;
        bg::intersection(area, zones.polys[k], part);
        bg::union_(no_go, part, next);
        no_go = std::move(next);
      }
    }
    // Overlays of areas sharing edges with the zones are where Boost can go wrong: the no-go
    // must hold what it is made of (the area less the passing zones' parts, or the failing
    // zones' parts). Round-off of overlays along shared edges differs by a sliver (on US4MD81M
    // at 10 m, DEPARE/3863 less eleven A1 zones: 1.2 m2 along 148 km of edge, 8 microns wide),
    // so it may fall short by a sliver 0.1 mm wide along the area's edges (1 m2 at least); past
    // that GEOS's overlay is taken (no_go_union.hpp), and if that falls short too, the whole area.
    double expected = 0.0;
    if (unassessed_fails) {
      expected = bg::area(area);
      for (std::size_t k : passing) {
        BgMultiPolygon part;
        bg::intersection(area, zones.polys[k], part);
        expected -= bg::area(part);
      }
    } else {
      for (std::size_t k : failing) {
        BgMultiPolygon part;
        bg::intersection(area, zones.polys[k], part);
        expected += bg::area(part);
      }
    }
    const double slack = std::max(1.0, 1e-4 * static_cast<double>(bg::perimeter(area)));
    if (bg::area(no_go) < expected - slack) {
      std::vector<const BgPolygon*> cuts;
      for (std::size_t k : unassessed_fails ? passing : failing) cuts.push_back(&zones.polys[k]);
      std::vector<BgPolygon> again = overlay_no_go(area, cuts, !unassessed_fails);
      no_go.assign(std::make_move_iterator(again.begin()), std::make_move_iterator(again.end()));
      if (bg::area(no_go) < expected - slack) no_go = area;
    }
    if (no_go.empty() || bg::area(no_go) <= 0.0) {
      ++out.passable_by_class[f.cls];
      return;
    }
    n.reason = depth_reason(what, z, shown_zoc);
    n.area = std::move(no_go);
    add(std::move(n));
  }

  void add_points_by_depth(const EncCell& c, const EncFeature& f, const std::vector<double>& depths, const char* what,
                           const ZocZones& zones) {
    for (std::size_t k = 0; k < f.points.size(); ++k) {
      const double z = depths[k];
      const int zi = o.zones_of_confidence() ? zones.at(f.points[k], std::isnan(z) ? 0.0 : z, o) : -1;
      const int catzoc = zi < 0 ? 0 : zones.catzoc[static_cast<std::size_t>(zi)];
      if (!too_shallow(z, zoc_figures(catzoc, o))) {
        ++out.passable_by_class[f.cls];
        continue;
      }
      EncNoGoFeature n = base(c, f);
      if (f.points.size() > 1) n.id += "#" + std::to_string(k + 1);
      n.charted_depth_m = z;
      n.least_depth_m = o.zones_of_confidence() ? least(z, zoc_figures(catzoc, o)) : z;
      n.reason = depth_reason(what, z, zi < 0 ? -1 : catzoc);
      n.point = f.points[k];
      n.radius_m = o.zones_of_confidence() ? zoc_figures(catzoc, o).position_m : o.point_radius_m;
      add(std::move(n));
    }
  }

  void cell(const EncCell& c, const BgMultiPolygon& better) {
    ZocZones zones;
    DepthAreas depth_areas;
    std::vector<EncFeature> features;  // clipped to what no better cell covers
    std::vector<bool> clipped_area;    // per feature: its area lost a part to a better cell
    for (const EncFeature& f : c.features) {
      EncFeature g = f;
      const bool near_better =
          !better.empty() && !f.areas.empty() && bg::intersects(envelope(f.areas), envelope(better));
      if (!better.empty()) {
        if (near_better) g.areas = clip_away(f.areas, better);
        g.points.clear();
        g.point_depths.clear();
        for (std::size_t k = 0; k < f.points.size(); ++k) {
          if (bg::covered_by(to_bg(f.points[k]), better)) continue;
          g.points.push_back(f.points[k]);
          if (k < f.point_depths.size()) g.point_depths.push_back(f.point_depths[k]);
        }
        g.lines.clear();
        for (const auto& l : f.lines) {
          BgLine bl;
          for (const Vec2& p : l) bl.push_back(to_bg(p));
          BgMultiLine kept;
          bg::difference(bl, better, kept);
          for (const BgLine& k : kept) {
            std::vector<Vec2> line;
            for (const BgPoint& p : k) line.push_back(to_eigen(p));
            g.lines.push_back(std::move(line));
          }
        }
      }
      if (f.cls == "M_QUAL") {
        // Zones of confidence are the cell's own, unclipped: they qualify its own features.
        ++out.zoc_areas[zoc_name(f.catzoc)];
        for (const BgPolygon& p : f.areas) {
          zones.polys.push_back(p);
          zones.catzoc.push_back(f.catzoc);
        }
        continue;
      }
      if (g.areas.empty() && g.points.empty() && g.lines.empty()) continue;
      features.push_back(std::move(g));
      clipped_area.push_back(near_better);
    }
    zones.build();
    zones_here = &zones;
    for (const EncFeature& f : features) {
      if (f.cls == "DEPARE" && !f.areas.empty()) depth_areas.areas.push_back(&f);
    }
    // What a route's quality is measured on: where this cell decides.
    const BgMultiPolygon decides = clip_away(c.coverage, better);
    if (!decides.empty()) out.cell_areas.push_back({c.name, c.name, decides, kNaN, 0});
    for (const EncFeature& f : features) {
      if (kDepthAreas.count(f.cls) && !f.areas.empty()) {
        out.depth_areas.push_back({id_of(c, f), c.name, f.areas, f.drval1, 0});
      }
    }
    for (std::size_t k = 0; k < zones.polys.size(); ++k) {
      BgMultiPolygon z{zones.polys[k]};
      z = clip_away(z, better);
      if (!z.empty()) out.zones.push_back({c.name + " M_QUAL", c.name, std::move(z), kNaN, zones.catzoc[k]});
    }
    depth_areas.build();

    for (std::size_t i = 0; i < features.size(); ++i) {
      const EncFeature& f = features[i];
      clipped = clipped_area[i];
      if (kDepthAreas.count(f.cls)) {
        add_area_by_depth(c, f, f.areas, f.drval1, "DRVAL1", zones);  // lines of a depth area bound nothing
      } else if (kAlways.count(f.cls)) {
        add_whole(c, f, zones,
                  f.cls == "UNSARE"   ? "unsurveyed"
                  : f.cls == "LNDARE" ? "land"
                                      : "hit at any depth",
                  kNaN);
      } else if (kDangers.count(f.cls)) {
        const std::optional<double> z = hazard_depth(f, depth_areas.least_drval1(f));
        if (!z) {
          add_whole(c, f, zones, "VALSOU unknown, depth not told by WATLEV, CATWRK or EXPSOU", kNaN);
          continue;
        }
        const char* what = std::isnan(f.valsou) ? "estimated depth" : "VALSOU";
        BgMultiPolygon strips = f.areas;
        for (const auto& l : f.lines) {
          for (BgPolygon& p : buffer_line(l, o.line_half_width_m)) strips.push_back(std::move(p));
        }
        add_area_by_depth(c, f, strips, *z, what, zones);
        add_points_by_depth(c, f, std::vector<double>(f.points.size(), *z), what, zones);
      } else if (f.cls == "SOUNDG") {
        add_points_by_depth(c, f, f.point_depths, "sounding", zones);
      } else if (o.restricted_areas && !f.areas.empty()) {
        const bool no_entry =
            std::any_of(f.restrn.begin(), f.restrn.end(), [](int r) { return kNoEntry.count(r) > 0; });
        if (no_entry) {
          EncNoGoFeature n = base(c, f);
          n.reason = "restricted (RESTRN entry prohibited, restricted or area to be avoided)";
          n.area = f.areas;
          add(std::move(n));
        }
      }
    }
    zones_here = nullptr;
  }
};

// The planners' obstacles: every no-go area merged and simplified outward,
// discs kept where they reach outside the merged areas.
void planning_obstacles(EncNoGo& out, const std::vector<std::size_t>& tiles, double tol) {
  std::vector<bool> is_tile(out.features.size(), false);
  for (std::size_t i : tiles) is_tile[i] = true;
  std::vector<const BgPolygon*> tile_areas, other_areas;
  for (std::size_t i = 0; i < out.features.size(); ++i) {
    for (const BgPolygon& p : out.features[i].area) (is_tile[i] ? tile_areas : other_areas).push_back(&p);
  }
  std::vector<BgPolygon> merged = union_no_go(tile_areas, other_areas);
  std::vector<BgPolygon> simple;
  for (BgPolygon& p : merged) {
    if (tol <= 0.0) {
      simple.push_back(std::move(p));
      continue;
    }
    for (BgPolygon& q : simplify_outward(p, tol)) simple.push_back(std::move(q));
  }
  if (tol > 0.0) {
    // Grown outward, neighbours may overlap now: join them again, snap-rounded, so the planners and
    // a prepared chart's round trip through lon/lat get polygons no round-off makes cross themselves
    // (the 0.7 mm a snap may move an edge is well inside the growth of tol / 2).
    std::vector<const BgPolygon*> grown;
    for (const BgPolygon& p : simple) grown.push_back(&p);
    simple = union_no_go({}, grown, kRepairGridM);
  }
  std::vector<const BgPolygon*> ptrs;
  for (std::size_t i = 0; i < simple.size(); ++i) {
    PolygonObstacle p;
    p.id = "enc/" + std::to_string(i + 1);
    out.vertices += distinct_vertices(simple[i]);
    p.footprint = std::move(simple[i]);
    out.obstacles.polygons.push_back(std::move(p));
  }
  for (const PolygonObstacle& p : out.obstacles.polygons) ptrs.push_back(&p.footprint);
  const PolygonLocator locator(ptrs);
  for (const EncNoGoFeature& f : out.features) {
    if (!f.point) continue;
    // A disc inside the polygons adds nothing: its centre is covered and no edge is nearer than its radius.
    if (!locator.covering(*f.point).empty() && locator.distance_to_edges(*f.point) >= f.radius_m) continue;
    EllipticCylinder e;
    e.id = f.id;
    e.footprint.centre = *f.point;
    e.footprint.a = e.footprint.b = f.radius_m;
    e.footprint.theta = 0.0;
    out.obstacles.ellipses.push_back(std::move(e));
  }
}

}  // namespace

EncNoGo enc_no_go(const std::vector<std::string>& charts, const std::optional<LocalFrame>& frame,
                  const EncNoGoOptions& options) {
  check_options(options);
  const std::vector<EncCellFiles> files = find_enc_cells(charts);
  EncReadRequest request;
  request.classes.insert(kDepthAreas.begin(), kDepthAreas.end());
  request.classes.insert(kAlways.begin(), kAlways.end());
  request.classes.insert(kDangers.begin(), kDangers.end());
  request.classes.insert({"SOUNDG", "M_QUAL"});
  request.with_restrictions = options.restricted_areas;
  request.apply_updates = options.apply_updates;
  EncCells read = read_enc_cells(files, frame, request);
  for (const EncCell& c : read.cells) {
    const auto it = c.layer_counts.find("DEPARE");
    if (it == c.layer_counts.end() || it->second == 0) {
      throw InputError(printable(c.path, 240) +
                       ": expected depth areas (DEPARE) to tell deep water from shallow, "
                       "found none (not a navigational ENC?)");
    }
  }
  // One cell twice (two editions, or copies in two folders) would have one clip the other.
  for (std::size_t i = 0; i < read.cells.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (read.cells[i].name == read.cells[j].name) {
        throw InputError(printable(read.cells[i].path, 240) + ": expected each cell once, got " + read.cells[i].name +
                         " (edition " + read.cells[i].edition + ") and " + printable(read.cells[j].path, 240) +
                         " (edition " + read.cells[j].edition + "): give one of them");
      }
    }
  }
  // Best scale first: a smaller DSPM_CSCL, then a higher usage band, then the name.
  std::vector<const EncCell*> order;
  for (const EncCell& c : read.cells) order.push_back(&c);
  std::stable_sort(order.begin(), order.end(), [](const EncCell* a, const EncCell* b) {
    return decides_before(a->compilation_scale, a->usage_band, a->name, b->compilation_scale, b->usage_band, b->name);
  });

  EncNoGo out{read.frame, options.operating_depth_m + options.vertical_clearance_m, {}, {}, {}, {}, {}, {}, 0, {}, {},
              {}};
  Builder builder{options, out, out.required_depth_m, order.size() > 1, {}, false, nullptr};
  BgMultiPolygon covered;  // by the cells done so far
  for (const EncCell* c : order) {
    out.cells.push_back({c->path, c->name, c->usage_band, c->compilation_scale, c->edition, c->issue_date,
                         c->update_number, c->layer_counts});
    builder.cell(*c, covered);
    BgMultiPolygon next;
    bg::union_(covered, c->coverage, next);
    covered = std::move(next);
  }
  // Water no cell covers is unknown: a ring from the coverage out to a box
  // well beyond it (5 km or a tenth of its size), so no route leaves the charts.
  BgMultiPolygon unknown_water;
  if (!covered.empty()) {
    BgBox box = envelope(covered);
    const double pad = std::max(5000.0, 0.1 * std::max(box.max_corner().x() - box.min_corner().x(),
                                                       box.max_corner().y() - box.min_corner().y()));
    BgPolygon outer;
    bg::convert(BgBox(BgPoint(box.min_corner().x() - pad, box.min_corner().y() - pad),
                      BgPoint(box.max_corner().x() + pad, box.max_corner().y() + pad)),
                outer);
    bg::correct(outer);
    bg::difference(outer, covered, unknown_water);
    EncNoGoFeature n;
    n.id = "M_COVR/outside";
    n.cls = "M_COVR";
    n.reason = "outside every cell's coverage: unknown water";
    n.area = unknown_water;
    out.features.push_back(std::move(n));
  }
  if (options.planner_obstacles) planning_obstacles(out, builder.tiles, options.simplify_tolerance_m);
  return out;
}

}  // namespace deepguide
