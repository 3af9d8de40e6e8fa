#pragma once
// The navigation mesh's water triangles merged into convex cells, the
// polygons Polyanya (polyanya.hpp) searches: fewer, larger faces, so an
// interval crosses fewer edges on its way and the search expands fewer nodes
// (the Kachemak set at 5 m: 43,098 triangles, 23,128 cells; the search's
// 99th percentile a third lower, docs/PERFORMANCE.md).
//
// The merge is Hertel and Mehlhorn's: an edge between two cells is taken out
// when the cell it leaves is still strictly convex at both of its ends, the
// edges taken in the triangles' order (longest first gave 3-5 % fewer cells
// and no faster search, for a third more merge time: the sort scatters the
// memory it touches). Every cell is a union of whole triangles, so the
// water, its boundary and its corners are the triangles' own, and a route
// inside one cell is a straight line.
//
// A repair (NavMesh::insert) changes a few triangles: the cells they lay in
// are dissolved and their triangles, old and new, merged again, while every
// other cell keeps its number and corners (a full merge of the Kachemak
// set takes 7 ms, a repair's under one).

#include <cstdint>
#include <vector>

#include "deepguide/core/api.hpp"
#include "deepguide/geometry/vec2.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh.hpp"

namespace DEEPGUIDE_API deepguide {

struct ConvexCells {
  static constexpr std::int32_t kNone = -1;
  /// Cell k's corners are corner[begin[k]] .. corner[begin[k] + count[k] - 1];
  /// count 0: a number freed by a repair, which no link leads to.
  std::vector<std::uint32_t> begin, count;
  std::vector<std::uint32_t> corner;  ///< mesh vertices, anticlockwise round each cell
  /// Per corner i: the cell across the edge from corner i to the next one
  /// round its cell, or kNone where the edge bounds the water.
  std::vector<std::int32_t> across;
  /// Per corner i with a cell across: the same edge's place in that cell
  /// (its first corner's offset from that cell's begin).
  std::vector<std::uint32_t> back;
  /// The cell each triangle lies in; kNone for a triangle not merged yet.
  std::vector<std::int32_t> cell_of;
  std::size_t live = 0;     ///< cells with corners
  std::size_t garbage = 0;  ///< entries of `corner` that no cell uses
};

/// Merges a mesh's triangles into convex cells.
ConvexCells merge_into_cells(const std::vector<Vec2>& vertices, const std::vector<NavMesh::Face>& faces);

/// After a repair: the cells `dissolved` are taken out, and their triangles
/// together with every triangle whose cell_of is kNone (the new ones) are
/// merged into new cells, linked to the cells round them. `cells.cell_of`
/// must follow the triangles' numbers (one entry per face).
void merge_again(ConvexCells& cells, const std::vector<Vec2>& vertices, const std::vector<NavMesh::Face>& faces,
                 const std::vector<std::int32_t>& dissolved);

}  // namespace deepguide
