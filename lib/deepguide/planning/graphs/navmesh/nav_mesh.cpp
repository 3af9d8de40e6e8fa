#include "deepguide/planning/graphs/navmesh/nav_mesh.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <deque>
#include <unordered_map>

#include "deepguide/core/error.hpp"

namespace deepguide {
namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int depth = -1;  // constraint edges crossed from outside the area; -1: not reached yet
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::int64_t, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Each ring as closed constraint edges, its repeated closing point left out.
// All rings go to CGAL at once: insert_constraints sorts the points along a
// space-filling curve before inserting them, which locates each from the
// last instead of walking from afar (a third of the tight band's build).
struct Constraints {
  std::vector<K::Point_2> points;
  std::vector<std::pair<std::size_t, std::size_t>> edges;

  template <class Ring>
  void add_ring(const Ring& ring) {
    const std::size_t first = points.size();
    for (const BgPoint& p : ring) {
      const K::Point_2 q(p.x(), p.y());
      if (points.size() == first || points.back() != q) points.push_back(q);
    }
    while (points.size() > first + 1 && points[first] == points.back()) points.pop_back();
    const std::size_t n = points.size() - first;
    if (n < 3) {
      points.resize(first);
      return;
    }
    for (std::size_t i = 0; i < n; ++i) edges.emplace_back(first + i, first + (i + 1) % n);
  }
};

// The flood: faces reached without crossing a constraint share a depth; each
// constraint crossed adds one (CGAL's polygon-with-holes example, in breadth).
void mark_depths(Cdt& cdt) {
  std::deque<std::pair<Cdt::Face_handle, int>> border{{cdt.infinite_face(), 0}};
  while (!border.empty()) {
    const auto [start, depth] = border.front();
    border.pop_front();
    if (start->info().depth != -1) continue;
    std::deque<Cdt::Face_handle> flood{start};
    start->info().depth = depth;
    while (!flood.empty()) {
      const Cdt::Face_handle f = flood.front();
      flood.pop_front();
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle n = f->neighbor(i);
        if (n->info().depth != -1) continue;
        if (cdt.is_constrained({f, i})) {
          border.emplace_back(n, depth + 1);
        } else {
          n->info().depth = depth;
          flood.push_back(n);
        }
      }
    }
  }
}

bool water(const Cdt& cdt, Cdt::Face_handle f) { return !cdt.is_infinite(f) && f->info().depth % 2 == 1; }

}  // namespace

struct NavMesh::Index {
  using Item = std::pair<BgBox, std::int32_t>;
  bgi::rtree<Item, bgi::rstar<16>> faces;
};

NavMesh::NavMesh(const BgMultiPolygon& no_go, const Vec2& area_min, const Vec2& area_max)
    : area_min_(area_min), area_max_(area_max), index_(std::make_unique<Index>()) {
  if (!area_min.allFinite() || !area_max.allFinite() || !((area_max - area_min).minCoeff() > 0.0)) {
    throw InputError("navigation mesh: expected a work area with a positive, finite extent");
  }
  Cdt cdt;
  const std::vector<BgPoint> box{{area_min.x(), area_min.y()},
                                 {area_max.x(), area_min.y()},
                                 {area_max.x(), area_max.y()},
                                 {area_min.x(), area_max.y()}};
  Constraints constraints;
  constraints.add_ring(box);
  for (const BgPolygon& poly : no_go) {
    constraints.add_ring(poly.outer());
    for (const auto& inner : poly.inners()) constraints.add_ring(inner);
  }
  cdt.insert_constraints(constraints.points.begin(), constraints.points.end(), constraints.edges.begin(),
                         constraints.edges.end());
  mark_depths(cdt);

  // Number the water's faces and the vertices they use.
  std::unordered_map<const void*, std::int32_t> face_id;
  std::int64_t next_vertex = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) v->info() = -1;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!water(cdt, f)) continue;
    face_id.emplace(&*f, static_cast<std::int32_t>(face_id.size()));
    for (int i = 0; i < 3; ++i) {
      if (f->vertex(i)->info() == -1) {
        f->vertex(i)->info() = next_vertex++;
        vertices_.emplace_back(f->vertex(i)->point().x(), f->vertex(i)->point().y());
      }
    }
  }
  faces_.resize(face_id.size());
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!water(cdt, f)) continue;
    const std::int32_t id = face_id.at(&*f);
    Face& out = faces_[id];
    for (int k = 0; k < 3; ++k) out.v[k] = static_cast<std::uint32_t>(f->vertex(k)->info());
    for (int k = 0; k < 3; ++k) {
      // Edge (v[k], v[k+1]) lies opposite CGAL's vertex k + 2.
      const int opposite = (k + 2) % 3;
      const Cdt::Face_handle n = f->neighbor(opposite);
      const bool open = !cdt.is_constrained({f, opposite}) && water(cdt, n);
      out.next[k] = open ? face_id.at(&*n) : kNone;
    }
  }
  find_corners();
  index_faces();
}

NavMesh::NavMesh(std::vector<Vec2> vertices, std::vector<Face> faces, const Vec2& area_min, const Vec2& area_max)
    : vertices_(std::move(vertices)),
      faces_(std::move(faces)),
      area_min_(area_min),
      area_max_(area_max),
      index_(std::make_unique<Index>()) {
  find_corners();
  index_faces();
}

void NavMesh::find_corners() {
  // Per vertex: the water's angle (its faces' angles there) and the
  // boundary edges that meet there (two where one wedge of water ends, more
  // where the water touches itself).
  std::vector<double> angle(vertices_.size(), 0.0);
  std::vector<std::uint32_t> boundary(vertices_.size(), 0);
  for (const Face& f : faces_) {
    for (int k = 0; k < 3; ++k) {
      const Vec2& p = vertices_[f.v[k]];
      const Vec2 a = vertices_[f.v[(k + 1) % 3]] - p, b = vertices_[f.v[(k + 2) % 3]] - p;
      angle[f.v[k]] += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      if (f.next[k] == kNone) ++boundary[f.v[k]], ++boundary[f.v[(k + 1) % 3]];
    }
  }
  constexpr double kStraight = 3.14159265358979323846 - 1e-9;
  corner_.assign(vertices_.size(), 0);
  for (std::size_t v = 0; v < vertices_.size(); ++v) {
    corner_[v] = boundary[v] > 2 || (boundary[v] == 2 && angle[v] > kStraight) ? 1 : 0;
  }
}

void NavMesh::index_faces() {
  std::vector<Index::Item> boxes;
  boxes.reserve(faces_.size());
  for (std::size_t id = 0; id < faces_.size(); ++id) {
    BgBox b;
    bg::assign_inverse(b);
    for (const std::uint32_t v : faces_[id].v) bg::expand(b, to_bg(vertices_[v]));
    boxes.emplace_back(b, static_cast<std::int32_t>(id));
  }
  index_->faces = bgi::rtree<Index::Item, bgi::rstar<16>>(boxes.begin(), boxes.end());
}

NavMesh::~NavMesh() = default;
NavMesh::NavMesh(NavMesh&&) noexcept = default;
NavMesh& NavMesh::operator=(NavMesh&&) noexcept = default;

std::vector<std::int32_t> NavMesh::faces_at(const Vec2& p) const {
  // A point on an edge counts as in the face up to a nanometre: a start
  // stepped onto a zone polygon's boundary (the band round a zone) comes out
  // within rounding of the edge, on either side of it.
  constexpr double kOn = 1e-9;
  std::vector<Index::Item> near;
  const BgBox around(to_bg(p - Vec2::Constant(kOn)), to_bg(p + Vec2::Constant(kOn)));
  index_->faces.query(bgi::intersects(around), std::back_inserter(near));
  std::vector<std::int32_t> out;
  for (const auto& [box, id] : near) {
    const Face& f = faces_[id];
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const Vec2& a = vertices_[f.v[k]];
      const Vec2& b = vertices_[f.v[(k + 1) % 3]];
      const Vec2 ab = b - a, ap = p - a;
      inside = ab.x() * ap.y() - ab.y() * ap.x() >= -kOn * ab.norm();  // signed distance times |ab|
    }
    if (inside) out.push_back(id);
  }
  return out;
}

std::vector<std::pair<Vec2, Vec2>> NavMesh::edges() const {
  std::vector<std::pair<Vec2, Vec2>> out;
  for (std::size_t id = 0; id < faces_.size(); ++id) {
    const Face& f = faces_[id];
    for (int k = 0; k < 3; ++k) {
      if (f.next[k] != kNone && static_cast<std::size_t>(f.next[k]) < id) continue;  // the other face has it
      out.emplace_back(vertices_[f.v[k]], vertices_[f.v[(k + 1) % 3]]);
    }
  }
  return out;
}

std::size_t NavMesh::edge_count() const {
  // An edge shared by two faces is counted by one of them; a boundary edge by its only face.
  std::size_t count = 0;
  for (std::size_t id = 0; id < faces_.size(); ++id) {
    for (const std::int32_t n : faces_[id].next) count += n == kNone || static_cast<std::size_t>(n) > id ? 1 : 0;
  }
  return count;
}

}  // namespace deepguide
