// Fuzz harness: bathymetry grids in ESRI ASCII opened and scanned (fuzz_support.hpp says how it runs).
#include "deepguide/charts/bathymetry.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deepguide::fuzz::read_as(data, size, "bathymetry.asc", [](const std::string& path) {
    deepguide::BathymetryOptions o;
    o.assumed_crs = "EPSG:4326";  // a grid without a CRS is read, not refused at once
    (void)deepguide::inspect_bathymetry(path, o);
  });
}
