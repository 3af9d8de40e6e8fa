#include "deepguide/world/no_go_union.hpp"

#include <geos_c.h>
#include <ogr_geometry.h>

#include <algorithm>
#include <array>
#include <boost/geometry.hpp>
#include <boost/geometry/algorithms/point_on_surface.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "deepguide/geometry/polygon_locator.hpp"
#include "deepguide/world/gdal_support.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

using Segment = std::array<double, 4>;  // x0, y0, x1, y1 with (x0, y0) < (x1, y1)
using OgrPtr = std::unique_ptr<OGRGeometry, decltype(&OGRGeometryFactory::destroyGeometry)>;

OgrPtr owned(OGRGeometry* g) { return OgrPtr(g, &OGRGeometryFactory::destroyGeometry); }

template <class Ring>
void add_edges(const Ring& ring, std::vector<Segment>& out) {
  for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
    BgPoint a = ring[i], b = ring[i + 1];
    if (a.x() == b.x() && a.y() == b.y()) continue;
    if (std::make_pair(b.x(), b.y()) < std::make_pair(a.x(), a.y())) std::swap(a, b);
    out.push_back({a.x(), a.y(), b.x(), b.y()});
  }
}

OGRLinearRing to_ogr_ring(const BgPolygon::ring_type& ring) {
  OGRLinearRing r;
  r.setNumPoints(static_cast<int>(ring.size()), FALSE);
  for (std::size_t i = 0; i < ring.size(); ++i) r.setPoint(static_cast<int>(i), ring[i].x(), ring[i].y());
  return r;
}

OGRPolygon to_ogr(const BgPolygon& p) {
  OGRPolygon poly;
  OGRLinearRing outer = to_ogr_ring(p.outer());
  poly.addRing(&outer);
  for (const auto& in : p.inners()) {
    OGRLinearRing r = to_ogr_ring(in);
    poly.addRing(&r);
  }
  return poly;
}

// The polygonal parts of `g` into `mp` (a repair may return lines and points beside them).
void add_polygonal(OGRMultiPolygon& mp, const OGRGeometry& g) {
  switch (wkbFlatten(g.getGeometryType())) {
    case wkbPolygon: mp.addGeometry(&g); break;
    case wkbMultiPolygon:
    case wkbGeometryCollection:
      for (const OGRGeometry* part : *g.toGeometryCollection()) add_polygonal(mp, *part);
      break;
    default: break;
  }
}

// `p` as GEOS can join it: itself when valid, else what GEOS's MakeValid makes of it by its
// STRUCTURE method (shells joined, holes taken out: a ring that runs over itself keeps the water it
// covers twice, where the default LINEWORK method makes it a hole), LINEWORK where that fails.
void add_to(OGRMultiPolygon& mp, const BgPolygon& p) {
  OGRPolygon poly = to_ogr(p);
  if (poly.IsValid()) {
    mp.addGeometry(&poly);
    return;
  }
  const char* const structure[] = {"METHOD=STRUCTURE", nullptr};
  OgrPtr fixed = owned(poly.MakeValid(structure));
  if (!fixed) fixed = owned(poly.MakeValid());
  if (fixed) {
    add_polygonal(mp, *fixed);
  } else {
    mp.addGeometry(&poly);  // left to the snap-rounded union
  }
}

void from_ogr(const OGRGeometry& g, std::vector<BgPolygon>& out) {
  switch (wkbFlatten(g.getGeometryType())) {
    case wkbPolygon: {
      const OGRPolygon& poly = *g.toPolygon();
      if (poly.IsEmpty()) return;
      BgPolygon p;
      auto copy = [](const OGRLinearRing& r, auto& dst) {
        for (int i = 0; i < r.getNumPoints(); ++i) dst.push_back(BgPoint(r.getX(i), r.getY(i)));
      };
      copy(*poly.getExteriorRing(), p.outer());
      for (int k = 0; k < poly.getNumInteriorRings(); ++k) copy(*poly.getInteriorRing(k), p.inners().emplace_back());
      bg::correct(p);
      out.push_back(std::move(p));
      break;
    }
    case wkbMultiPolygon:
    case wkbGeometryCollection:
      for (const OGRGeometry* part : *g.toGeometryCollection()) from_ogr(*part, out);
      break;
    default: break;  // lines and points of a degenerate overlay carry no area
  }
}

// The faces of the tiles' union, from the edges no two tiles share. Returns
// false when a face cannot be told inside or out (the caller then joins the
// tiles by a plain GEOS union).
bool tile_faces(const std::vector<const BgPolygon*>& tiles, OGRMultiPolygon& into) {
  std::vector<Segment> edges;
  for (const BgPolygon* t : tiles) {
    add_edges(t->outer(), edges);
    for (const auto& r : t->inners()) add_edges(r, edges);
  }
  std::sort(edges.begin(), edges.end());
  OGRMultiLineString boundary;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if ((j - i) % 2 == 1) {
      OGRLineString l;
      l.addPoint(edges[i][0], edges[i][1]);
      l.addPoint(edges[i][2], edges[i][3]);
      boundary.addGeometry(&l);
    }
    i = j;
  }
  if (boundary.IsEmpty()) return tiles.empty();
  // Node the edges (a tile corner lying on another tile's edge), then form
  // faces. A union with a part of itself nodes the whole (one with an empty
  // geometry may be returned as it is).
  OgrPtr noded = owned(boundary.Union(boundary.getGeometryRef(0)));
  if (!noded) return false;
  OgrPtr faces = owned(noded->Polygonize());
  if (!faces) return false;

  using Item = std::pair<BgBox, std::size_t>;
  std::vector<Item> boxes;
  for (std::size_t i = 0; i < tiles.size(); ++i) boxes.emplace_back(bg::return_envelope<BgBox>(*tiles[i]), i);
  const bgi::rtree<Item, bgi::rstar<16>> tree(boxes.begin(), boxes.end());
  for (const OGRGeometry* face : *faces->toGeometryCollection()) {
    std::vector<BgPolygon> as_bg;
    from_ogr(*face, as_bg);
    if (as_bg.size() != 1) return false;
    // (OGR's PointOnSurface fails on GEOS's polygonizer output here; Boost's works, but
    // may leave the point unset: it must land strictly inside the face.)
    BgPoint q(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
    try {
      bg::point_on_surface(as_bg.front(), q);
    } catch (const std::exception&) {
      return false;
    }
    if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !bg::within(q, as_bg.front())) return false;
    std::vector<Item> hits;
    tree.query(bgi::intersects(q), std::back_inserter(hits));
    const bool kept =
        std::any_of(hits.begin(), hits.end(), [&](const Item& h) { return bg::covered_by(q, *tiles[h.second]); });
    if (kept) into.addGeometry(face);
  }
  return true;
}

// Every tile lies in the union: a point inside each is covered by a polygon of it.
bool covers_every_tile(const std::vector<BgPolygon>& result, const std::vector<const BgPolygon*>& tiles) {
  std::vector<const BgPolygon*> ptrs;
  for (const BgPolygon& p : result) ptrs.push_back(&p);
  const PolygonLocator locator(ptrs);
  for (const BgPolygon* t : tiles) {
    BgPoint q(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
    try {
      bg::point_on_surface(*t, q);
    } catch (const std::exception&) {
      return false;
    }
    if (!std::isfinite(q.x())) continue;  // a tile without interior adds no area
    if (locator.covering(to_eigen(q)).empty()) return false;
  }
  return true;
}

struct GeosContext {
  GEOSContextHandle_t h = OGRGeometry::createGEOSContext();
  ~GeosContext() { OGRGeometry::freeGEOSContext(h); }
};

// GEOS's union of `all` snap-rounded to `grid` (OverlayNG at a fixed precision), or null.
OgrPtr snap_rounded(const OGRGeometry& all, double grid) {
  GeosContext ctx;
  GEOSGeometry* in = all.exportToGEOS(ctx.h);
  if (in == nullptr) return owned(nullptr);
  GEOSGeometry* out = GEOSUnaryUnionPrec_r(ctx.h, in, grid);
  GEOSGeom_destroy_r(ctx.h, in);
  if (out == nullptr) return owned(nullptr);
  OGRGeometry* g = OGRGeometryFactory::createFromGEOS(ctx.h, out);
  GEOSGeom_destroy_r(ctx.h, out);
  return owned(g);
}

// a less b (or a within b) snap-rounded to `grid`, or null.
OgrPtr snap_rounded_overlay(const OGRGeometry& a, const OGRGeometry& b, bool keep_inside, double grid) {
  GeosContext ctx;
  GEOSGeometry* ga = a.exportToGEOS(ctx.h);
  GEOSGeometry* gb = b.exportToGEOS(ctx.h);
  GEOSGeometry* out = nullptr;
  if (ga != nullptr && gb != nullptr) {
    out = keep_inside ? GEOSIntersectionPrec_r(ctx.h, ga, gb, grid) : GEOSDifferencePrec_r(ctx.h, ga, gb, grid);
  }
  if (ga != nullptr) GEOSGeom_destroy_r(ctx.h, ga);
  if (gb != nullptr) GEOSGeom_destroy_r(ctx.h, gb);
  if (out == nullptr) return owned(nullptr);
  OGRGeometry* g = OGRGeometryFactory::createFromGEOS(ctx.h, out);
  GEOSGeom_destroy_r(ctx.h, out);
  return owned(g);
}

// The union of `all`: GEOS's cascaded union (grid 0), else snap-rounded.
OgrPtr joined(const OGRMultiPolygon& all, double grid) {
  if (grid <= 0.0) {
    if (OgrPtr merged = owned(all.UnionCascaded())) return merged;
  }
  OgrPtr merged = snap_rounded(all, grid > 0.0 ? grid : kRepairGridM);
  if (!merged) throw std::runtime_error("GEOS could not join the no-go areas: " + gdal::QuietErrors::last_message());
  return merged;
}

bool all_valid(const std::vector<BgPolygon>& polys) {
  return std::all_of(polys.begin(), polys.end(), [](const BgPolygon& p) { return bg::is_valid(p); });
}

// Polygons Boost.Geometry finds invalid where GEOS did not: the whole set snap-rounded (so it stays disjoint).
void make_valid_for_boost(std::vector<BgPolygon>& out) {
  if (all_valid(out)) return;
  OGRMultiPolygon all;
  for (const BgPolygon& p : out) add_to(all, p);
  std::vector<BgPolygon> again;
  from_ogr(*joined(all, kRepairGridM), again);
  out = std::move(again);
}

}  // namespace

std::vector<BgPolygon> union_no_go(const std::vector<const BgPolygon*>& tiles,
                                   const std::vector<const BgPolygon*>& others, double grid_m) {
  if (!OGRGeometryFactory::haveGEOS()) throw std::runtime_error("GDAL was built without GEOS: no polygon union");
  gdal::QuietErrors quiet;
  std::vector<BgPolygon> out;
  OGRMultiPolygon all;
  const bool faces_ok = tile_faces(tiles, all);
  for (const BgPolygon* p : others) add_to(all, *p);
  if (faces_ok && !all.IsEmpty()) from_ogr(*joined(all, grid_m), out);
  if (!faces_ok || !covers_every_tile(out, tiles)) {
    // The edges did not tile cleanly (overlapping or duplicated tiles, a face of
    // doubtful side): every area through GEOS, slower and sure.
    OGRMultiPolygon plain;
    for (const BgPolygon* p : tiles) add_to(plain, *p);
    for (const BgPolygon* p : others) add_to(plain, *p);
    out.clear();
    if (!plain.IsEmpty()) from_ogr(*joined(plain, grid_m), out);
  }
  make_valid_for_boost(out);
  return out;
}

std::vector<BgPolygon> overlay_no_go(const BgMultiPolygon& area, const std::vector<const BgPolygon*>& cuts,
                                     bool keep_inside) {
  if (!OGRGeometryFactory::haveGEOS()) throw std::runtime_error("GDAL was built without GEOS: no polygon overlay");
  gdal::QuietErrors quiet;
  OGRMultiPolygon a, c;
  for (const BgPolygon& p : area) add_to(a, p);
  for (const BgPolygon* p : cuts) add_to(c, *p);
  std::vector<BgPolygon> out;
  if (a.IsEmpty()) return out;
  if (c.IsEmpty()) {
    if (!keep_inside) from_ogr(a, out);
    make_valid_for_boost(out);
    return out;
  }
  const OgrPtr cut = joined(c, 0.0);
  OgrPtr result = owned(keep_inside ? a.Intersection(cut.get()) : a.Difference(cut.get()));
  if (!result) result = snap_rounded_overlay(a, *cut, keep_inside, kRepairGridM);
  if (!result) throw std::runtime_error("GEOS could not overlay a no-go area: " + gdal::QuietErrors::last_message());
  from_ogr(*result, out);
  make_valid_for_boost(out);
  return out;
}

std::vector<BgPolygon> geos_buffer(const BgPolygon& polygon, double distance, int points_per_circle) {
  const OGRPolygon poly = to_ogr(polygon);
  // GEOS's quadrant segments: a quarter circle in at most this many steps.
  const int quadrant = std::max(2, (points_per_circle + 3) / 4);
  OgrPtr grown = owned(poly.Buffer(distance, quadrant));
  if (!grown || grown->IsEmpty()) {
    throw std::runtime_error("GEOS could not grow a polygon by " + std::to_string(distance) + " m");
  }
  std::vector<BgPolygon> out;
  from_ogr(*grown, out);
  return out;
}

}  // namespace deepguide
