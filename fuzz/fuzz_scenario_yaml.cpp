// Fuzz harness: scenario files (YAML) (fuzz_support.hpp says how it runs).
#include "deepguide/simulation/scenario.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deepguide::fuzz::read_as(data, size, "scenario.yaml",
                                  [](const std::string& path) { (void)deepguide::read_scenario_file(path); });
}
