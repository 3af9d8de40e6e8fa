// Fuzz harness: current fields (NetCDF u/v) opened and read (fuzz_support.hpp says how it runs).
#include "deepguide/currents/current_field.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deepguide::fuzz::read_as(data, size, "current.nc",
                                  [](const std::string& path) { (void)deepguide::load_current_field(path); });
}
