// Fuzz harness: obstacle files in GeoJSON through our OGR layer (fuzz_support.hpp says how it runs).
#include "deepguide/obstacle_files/obstacle_io.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deepguide::fuzz::read_as(data, size, "obstacles.geojson",
                                  [](const std::string& path) { (void)deepguide::load_obstacles({path}); });
}
