#include "deepguide/planning/graphs/navmesh/nav_mesh_file.hpp"

#include <bit>
#include <boost/geometry/algorithms/area.hpp>
#include <cmath>
#include <cstring>
#include <string>

#include "deepguide/core/error.hpp"

namespace deepguide {
namespace {

static_assert(std::endian::native == std::endian::little, "nav_mesh_file.hpp's format is little-endian");
constexpr char kMagic[8] = {'D', 'G', 'N', 'A', 'V', 'M', 'S', 'H'};
constexpr std::uint32_t kVersion = 1;

struct Writer {
  std::vector<std::uint8_t> out;
  template <class T>
  void put(const T& x) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&x);
    out.insert(out.end(), p, p + sizeof x);
  }
  void put(const Vec2& p) { put(p.x()), put(p.y()); }
  void count(std::size_t n) {
    if (n > 0xffffffffu)
      throw InputError("navigation mesh: expected at most 2^32 - 1 items to keep, got " + std::to_string(n));
    put(static_cast<std::uint32_t>(n));
  }
};

struct Reader {
  const std::vector<std::uint8_t>& in;
  std::size_t at = 0;

  [[noreturn]] void fail(const std::string& expected) const {
    throw InputError("navigation mesh, byte " + std::to_string(at) + ": expected " + expected);
  }
  template <class T>
  T get(const char* what) {
    if (in.size() - at < sizeof(T)) fail(std::string(what) + ", got the end of the data");
    T x;
    std::memcpy(&x, in.data() + at, sizeof x);
    at += sizeof x;
    return x;
  }
  double finite(const char* what) {
    const double x = get<double>(what);
    if (!std::isfinite(x)) fail(std::string(what) + " as a finite number");
    return x;
  }
  Vec2 point(const char* what) {
    const double x = finite(what);
    return {x, finite(what)};
  }
  // A count of items of `bytes_each` that the data left can hold.
  std::size_t count(const char* what, std::size_t bytes_each) {
    const std::uint32_t n = get<std::uint32_t>(what);
    if (static_cast<std::uint64_t>(n) * bytes_each > in.size() - at)
      fail(std::string(what) + " that the data left holds, got " + std::to_string(n));
    return n;
  }
};

}  // namespace

std::vector<std::uint8_t> write_nav_mesh(const BgMultiPolygon& zones, const Vec2& origin, const NavMesh& mesh) {
  Writer w;
  w.out.insert(w.out.end(), std::begin(kMagic), std::end(kMagic));
  w.put(kVersion);
  w.put(origin);
  w.count(zones.size());
  const auto ring = [&w](const BgPolygon::ring_type& r) {
    w.count(r.size());
    for (const BgPoint& p : r) w.put(p.x()), w.put(p.y());
  };
  for (const BgPolygon& poly : zones) {
    w.count(1 + poly.inners().size());
    ring(poly.outer());
    for (const auto& inner : poly.inners()) ring(inner);
  }
  w.put(mesh.area_min());
  w.put(mesh.area_max());
  w.count(mesh.vertices().size());
  for (const Vec2& p : mesh.vertices()) w.put(p);
  w.count(mesh.faces().size());
  for (const NavMesh::Face& f : mesh.faces()) {
    for (const std::uint32_t v : f.v) w.put(v);
    for (const std::int32_t n : f.next) w.put(n);
  }
  return std::move(w.out);
}

KeptNavMesh read_nav_mesh(const std::vector<std::uint8_t>& bytes) {
  Reader r{bytes};
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    r.fail("the mark DGNAVMSH of a kept navigation mesh");
  r.at = sizeof kMagic;
  if (const auto version = r.get<std::uint32_t>("the format version"); version != kVersion)
    r.fail("format version 1, got " + std::to_string(version) + " (prepare the chart again)");
  KeptNavMesh out;
  out.origin = r.point("the origin");
  const std::size_t polygons = r.count("the number of zone polygons", 4);
  out.zones.resize(polygons);
  for (BgPolygon& poly : out.zones) {
    const std::size_t rings = r.count("the number of a polygon's rings", 4);
    if (rings == 0) r.fail("a polygon with an outer ring, got none");
    poly.inners().resize(rings - 1);
    for (std::size_t k = 0; k < rings; ++k) {
      auto& ring = k == 0 ? poly.outer() : poly.inners()[k - 1];
      const std::size_t n = r.count("the number of a ring's points", 16);
      if (n < 4) r.fail("a closed ring of at least 4 points, got " + std::to_string(n));
      ring.reserve(n);
      for (std::size_t i = 0; i < n; ++i) ring.push_back(to_bg(r.point("a zone point")));
    }
  }
  const Vec2 lo = r.point("the work area's corner"), hi = r.point("the work area's corner");
  if (!((hi - lo).minCoeff() > 0.0)) r.fail("a work area of positive extent");
  const std::size_t nv = r.count("the number of vertices", 16);
  std::vector<Vec2> vertices(nv);
  for (Vec2& p : vertices) p = r.point("a vertex");
  const std::size_t nf = r.count("the number of faces", 24);
  std::vector<NavMesh::Face> faces(nf);
  for (NavMesh::Face& f : faces) {
    for (std::uint32_t& v : f.v) {
      v = r.get<std::uint32_t>("a face's vertex");
      if (v >= nv) r.fail("a vertex below " + std::to_string(nv) + ", got " + std::to_string(v));
    }
    for (std::int32_t& n : f.next) {
      n = r.get<std::int32_t>("a face's neighbour");
      if (n != NavMesh::kNone && (n < 0 || static_cast<std::size_t>(n) >= nf))
        r.fail("a neighbour below " + std::to_string(nf) + " or -1, got " + std::to_string(n));
    }
  }
  if (r.at != bytes.size()) r.fail("the end of the data, got " + std::to_string(bytes.size() - r.at) + " more bytes");
  // The mesh as a whole: what the search relies on.
  for (std::size_t id = 0; id < nf; ++id) {
    const NavMesh::Face& f = faces[id];
    const std::string face = "face " + std::to_string(id);
    const Vec2 ab = vertices[f.v[1]] - vertices[f.v[0]], ac = vertices[f.v[2]] - vertices[f.v[0]];
    if (!(cross(ab, ac) > 0.0)) throw InputError("navigation mesh, " + face + ": expected an anticlockwise triangle");
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = f.v[k], b = f.v[(k + 1) % 3];
      if (f.next[k] == NavMesh::kNone) continue;
      const NavMesh::Face& g = faces[static_cast<std::size_t>(f.next[k])];
      bool back = false;
      for (int j = 0; j < 3; ++j)
        back = back || (g.v[j] == b && g.v[(j + 1) % 3] == a && g.next[j] == static_cast<std::int32_t>(id));
      if (!back)
        throw InputError("navigation mesh, " + face + ": expected face " + std::to_string(f.next[k]) +
                         " to name it back across their shared edge");
    }
  }
  // Faces that overlap (or leave a gap) would keep every test above; their
  // areas would not add up to the water's: the box less the zones.
  double faces_area = 0.0;
  for (const NavMesh::Face& f : faces)
    faces_area += 0.5 * cross(vertices[f.v[1]] - vertices[f.v[0]], vertices[f.v[2]] - vertices[f.v[0]]);
  const double box_area = (hi - lo).prod();
  const double water = box_area - boost::geometry::area(out.zones);
  if (!(std::abs(faces_area - water) <= 1e-8 * box_area)) {
    throw InputError("navigation mesh: expected faces covering the water's " + std::to_string(water) +
                     " m2 once, got " + std::to_string(faces_area) + " m2");
  }
  out.mesh = std::make_unique<NavMesh>(std::move(vertices), std::move(faces), lo, hi);
  return out;
}

}  // namespace deepguide
