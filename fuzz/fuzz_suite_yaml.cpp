// Fuzz harness: suite files (suite.yaml) (fuzz_support.hpp says how it runs).
#include "deepguide/evaluation/suite.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return deepguide::fuzz::read_as(data, size, "suite.yaml",
                                  [](const std::string& path) { (void)deepguide::read_suite(path); });
}
