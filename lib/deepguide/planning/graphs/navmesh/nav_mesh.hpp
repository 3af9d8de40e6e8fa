#pragma once
// A navigation mesh of the free water: the constrained Delaunay
// triangulation (CGAL) of a work area with the no-go polygons' rings as
// constraint edges, keeping the triangles that lie in the water.
//
// Faces are triangles with their corners anticlockwise and, across each
// edge, the face on the other side, or none where the edge bounds the water
// (a no-go ring or the area's edge). A vertex on such edges where the water
// is wider than a straight angle (an obstacle's convex corner) is a
// *corner*: the only places a shortest route can turn (a taut string bends
// only round an obstacle's convex corner), which is what Polyanya
// (polyanya.hpp) needs to know of it. Vertices within 1e-9 rad of straight,
// and those where the water touches itself (two wedges of water at one
// vertex), count as corners too: an extra corner costs search nodes, a
// missing one the shortest route.
//
// Which triangles are water: a flood from outside the area that flips at
// every constraint edge (outside the area, in it, in a no-go polygon, in a
// hole of one, ...): odd depths are water. The rings must not cross; merged
// zone polygons (zone_polygons.hpp) do not. The triangles are what is kept,
// saved and repaired; the search runs on them merged into convex cells
// (cells()), which it crosses in fewer steps.
//
// A no-go polygon found later (a sonar detection) goes in without
// triangulating the rest again (insert): the faces whose boxes meet its box
// are taken out, the region they cover is triangulated anew with its
// boundary and the polygon's rings as constraints, and the new faces are
// stitched to the old ones across the region's boundary. That boundary
// survives as it was: a face left in place has a box clear of the polygon's,
// so the polygon cannot cross an edge it shares with a face taken out.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/geometry/vec2.hpp"

namespace DEEPGUIDE_API deepguide {

struct ConvexCells;

class NavMesh {
 public:
  static constexpr std::int32_t kNone = -1;
  struct Face {
    std::array<std::uint32_t, 3> v;    ///< corners, anticlockwise
    std::array<std::int32_t, 3> next;  ///< the face across edge (v[k], v[k+1]); kNone: no water there
  };

  /// The box from area_min to area_max less the polygons of `no_go`, which
  /// must lie strictly inside it. Throws InputError for an empty or
  /// non-finite box.
  NavMesh(const BgMultiPolygon& no_go, const Vec2& area_min, const Vec2& area_max);
  /// A mesh kept earlier (nav_mesh_file.hpp), from its parts as the accessors
  /// give them; the corners are found again. Checks nothing: its reader has.
  NavMesh(std::vector<Vec2> vertices, std::vector<Face> faces, const Vec2& area_min, const Vec2& area_max);
  ~NavMesh();
  NavMesh(NavMesh&&) noexcept;
  NavMesh& operator=(NavMesh&&) noexcept;

  const std::vector<Vec2>& vertices() const { return vertices_; }
  const std::vector<Face>& faces() const { return faces_; }
  bool corner(std::uint32_t v) const { return corner_[v] != 0; }
  /// The triangles merged into convex cells (convex_cells.hpp): what
  /// Polyanya searches. Made again after every insert.
  const ConvexCells& cells() const { return *cells_; }
  Vec2 area_min() const { return area_min_; }
  Vec2 area_max() const { return area_max_; }

  /// The faces whose closed triangle holds p: one inside a face, two on an
  /// edge, all round a vertex; none outside the water.
  std::vector<std::int32_t> faces_at(const Vec2& p) const;
  /// Each edge between two water faces once, and each edge of the water's
  /// boundary: for drawings and the graph's size.
  std::vector<std::pair<Vec2, Vec2>> edges() const;
  /// edges().size(), without making them.
  std::size_t edge_count() const;
  /// The bounding box of face `id`.
  BgBox face_box(std::int32_t id) const;

  struct Repair {
    std::size_t removed = 0;  ///< faces taken out
    std::size_t added = 0;    ///< water faces made in their place
  };
  /// Takes the polygons (mesh coordinates; they may overlap the no-go the
  /// mesh was made round, or each other, and reach beyond the area) out of
  /// the water, re-triangulating only round them. The mesh is then what a
  /// mesh made round the union would be, up to the triangles' shapes: the
  /// same water, so the same shortest routes. Not safe while a search runs.
  Repair insert(const BgMultiPolygon& no_go);

 private:
  Repair insert(const BgPolygon& no_go);
  std::vector<Vec2> vertices_;
  std::vector<std::uint8_t> corner_;
  // Per vertex: the water's angle there (its faces' angles) and the boundary
  // edges that meet there; kept so insert can update them face by face.
  std::vector<double> angle_;
  std::vector<std::int32_t> boundary_;
  std::vector<Face> faces_;
  Vec2 area_min_, area_max_;
  struct Index;   // R-tree of the faces' boxes
  void finish();  // after the faces are made: corners, index, cells
  void index_faces();
  void find_corners();
  void count_face(std::size_t id, int sign);  // adds (sign 1) or takes back (-1) a face's angles and boundary edges
  void mark_corner(std::uint32_t v);
  // After an insert reused `reused` of the `taken` numbers (ascending): the
  // rest are filled by the last faces.
  void fill_freed(const std::vector<std::int32_t>& taken, std::size_t reused);
  std::unique_ptr<Index> index_;
  std::unique_ptr<ConvexCells> cells_;
};

}  // namespace deepguide
