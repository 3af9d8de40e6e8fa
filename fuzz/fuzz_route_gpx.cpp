// Fuzz harness: route files in GPX (fuzz_support.hpp says how it runs).
#include "deepguide/planning/route_io.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deepguide::fuzz::read_as(data, size, "route.gpx",
                                  [](const std::string& path) { (void)deepguide::read_route_parts(path); });
}
