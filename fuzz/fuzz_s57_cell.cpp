// Fuzz harness: S-57 cells: structure check and summary (chart info) (fuzz_support.hpp says how it runs).
#include "deepguide/charts/chart_info.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deepguide::fuzz::read_as(data, size, "CELL.000",
                                  [](const std::string& path) { (void)deepguide::chart_info(path); });
}
