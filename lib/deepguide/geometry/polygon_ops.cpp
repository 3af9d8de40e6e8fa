#include "deepguide/geometry/polygon_ops.hpp"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <iterator>
#include <numeric>
#include <utility>

namespace deepguide {
namespace bg = boost::geometry;

namespace {
constexpr int kCirclePoints = 16;  // round joins of the outward buffer; the header's cos(pi/16)
}  // namespace

std::size_t distinct_vertices(const BgPolygon& p) {
  std::size_t n = p.outer().empty() ? 0 : p.outer().size() - 1;
  for (const auto& r : p.inners())
    if (!r.empty()) n += r.size() - 1;
  return n;
}

// The header says why this never shrinks `exact`.
BgMultiPolygon simplify_outward(const BgPolygon& exact, double tol) {
  const double grow = 0.5 * tol;
  BgMultiPolygon grown;
  bg::buffer(exact, grown, bg::strategy::buffer::distance_symmetric<double>(grow),
             bg::strategy::buffer::side_straight(), bg::strategy::buffer::join_round(kCirclePoints),
             bg::strategy::buffer::end_round(kCirclePoints), bg::strategy::buffer::point_circle(kCirclePoints));
  BgMultiPolygon simple;
  bg::simplify(grown, simple, 0.45 * tol);
  if (!simple.empty() && bg::is_valid(simple) && bg::covered_by(exact, simple)) return simple;
  // DP broke a ring (self-touching, collapsed): the buffer itself keeps both promises, when it is whole.
  if (!grown.empty() && bg::covered_by(exact, grown)) return grown;
  return BgMultiPolygon{exact};  // the overlay failed: the exact polygon, never less
}

std::vector<BgPolygon> merge_overlapping(std::vector<BgPolygon> polys) {
  namespace bgi = bg::index;
  using Entry = std::pair<BgBox, std::size_t>;
  std::vector<Entry> boxes;
  boxes.reserve(polys.size());
  for (std::size_t i = 0; i < polys.size(); ++i) boxes.emplace_back(bg::return_envelope<BgBox>(polys[i]), i);
  bgi::rtree<Entry, bgi::rstar<16>> tree(boxes.begin(), boxes.end());
  std::vector<std::size_t> parent(polys.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<Entry> hits;
  for (const auto& [box, i] : boxes) {
    hits.clear();
    tree.query(bgi::intersects(box), std::back_inserter(hits));
    for (const auto& h : hits) parent[find(h.second)] = find(i);
  }
  std::vector<std::vector<std::size_t>> groups(polys.size());
  for (std::size_t i = 0; i < polys.size(); ++i) groups[find(i)].push_back(i);

  std::vector<BgPolygon> out;
  for (auto& g : groups) {
    if (g.empty()) continue;
    if (g.size() == 1) {
      out.push_back(std::move(polys[g[0]]));
      continue;
    }
    std::vector<BgMultiPolygon> parts;
    for (std::size_t i : g) parts.push_back(BgMultiPolygon{std::move(polys[i])});
    while (parts.size() > 1) {  // pairwise, so each union stays balanced
      std::vector<BgMultiPolygon> next;
      for (std::size_t i = 0; i + 1 < parts.size(); i += 2) {
        BgMultiPolygon u;
        bg::union_(parts[i], parts[i + 1], u);
        next.push_back(std::move(u));
      }
      if (parts.size() % 2 == 1) next.push_back(std::move(parts.back()));
      parts = std::move(next);
    }
    for (auto& p : parts.front()) out.push_back(std::move(p));
  }
  return out;
}

}  // namespace deepguide
