#pragma once
// The navigation-mesh graph kept as bytes (a prepared chart's
// "deepguide_graphs" table, prepared_graphs.hpp): the zone polygons it was
// made round and its mesh, so that a prepared chart plans without
// triangulating. Little-endian, as the machines we build for:
//
//   "DGNAVMSH"  u32 version (1)
//   f64 origin x, y                       the mesh's coordinates are about it
//   u32 polygons; each: u32 rings (the outer first); each: u32 points, then
//       points x f64 (x, y)               the zones, planning frame, closed
//   f64 area_min x, y, area_max x, y      the mesh's work area (mesh coordinates)
//   u32 vertices; vertices x f64 (x, y)
//   u32 faces; faces x (u32 v0, v1, v2; i32 next0, next1, next2)
//
// Reading checks all of it: sizes against the bytes left, every number
// finite, every index in range, every triangle anticlockwise, every
// neighbour naming the face back across the same edge, the triangles'
// areas adding up to the water's, and nothing left over. The corners are
// found again from the triangles (NavMesh), not trusted to the bytes. What fails is an InputError saying what was
// expected and where; a damaged table never reaches the search.

#include <cstdint>
#include <memory>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/polygon.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh.hpp"

namespace DEEPGUIDE_API deepguide {

struct KeptNavMesh {
  BgMultiPolygon zones;  ///< planning frame
  Vec2 origin{0.0, 0.0};
  std::unique_ptr<NavMesh> mesh;
};

std::vector<std::uint8_t> write_nav_mesh(const BgMultiPolygon& zones, const Vec2& origin, const NavMesh& mesh);
KeptNavMesh read_nav_mesh(const std::vector<std::uint8_t>& bytes);

}  // namespace deepguide
