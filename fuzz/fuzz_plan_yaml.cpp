// Fuzz harness: exported mission plans read back (YAML) (fuzz_support.hpp says how it runs).
#include "deepguide/mission/plan_export.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deepguide::fuzz::read_as(data, size, "plan.yaml",
                                  [](const std::string& path) { (void)deepguide::read_plan_yaml(path); });
}
