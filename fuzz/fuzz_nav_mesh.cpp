// Fuzz harness: a kept navigation mesh (nav_mesh_file.hpp) read from bytes,
// and when it is accepted, searched: a mesh the reader lets through must not
// crash or hang Polyanya (the search runs on a budget here; an accepted mesh
// that spends it is a finding for the reader's checks).
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "deepguide/core/error.hpp"
#include "deepguide/planning/graphs/navmesh/nav_mesh_file.hpp"
#include "deepguide/planning/graphs/navmesh/polyanya.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace deepguide;
  try {
    const KeptNavMesh kept = read_nav_mesh(std::vector<std::uint8_t>(data, data + size));
    const NavMesh& mesh = *kept.mesh;
    SearchBudget budget;
    budget.max_expansions = 200000;
    const Vec2 lo = mesh.area_min(), hi = mesh.area_max();
    const PolyanyaResult r = polyanya(mesh, lo + 0.01 * (hi - lo), hi - 0.02 * (hi - lo), budget);
    if (r.stopped == SearchStop::budget) {
      std::fprintf(stderr, "an accepted mesh of %zu faces spent 200000 expansions\n", mesh.faces().size());
      std::abort();
    }
  } catch (const InputError&) {
    // refused in one line: what bad input must get
  }
  return 0;
}
