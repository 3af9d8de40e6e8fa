// Fuzz harness: mission files (YAML) (fuzz_support.hpp says how it runs).
#include "deepguide/mission/mission.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deepguide::fuzz::read_as(data, size, "mission.yaml",
                                  [](const std::string& path) { (void)deepguide::read_mission(path); });
}
