#pragma once
// What every fuzz harness shares: the input goes to a file (our readers take
// paths, as the command line gives them), the reader runs, and InputError,
// the one-line refusal of bad input, is the expected end. Anything else that
// escapes (another exception, a crash, a sanitizer report, a hang past the
// fuzzer's -timeout) is a finding.
//
// Built two ways (fuzz/CMakeLists.txt): with clang's libFuzzer for the soak
// (scripts/fuzz.sh), and with replay_main.cpp for the short bounded run in
// CI, which replays the seed corpus and seeded mutations of it.

#include <unistd.h>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "deepguide/core/error.hpp"

namespace deepguide::fuzz {

// One scratch folder per process, removed at exit.
inline const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("deepguide-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(
          std::filesystem::temp_directory_path() / ("deepguide-fuzz-" + std::to_string(::getpid())), ec);
    });
    return d;
  }();
  return dir;
}

/// Writes the input to `name` in the scratch folder and calls read(path).
template <class Read>
int read_as(const std::uint8_t* data, std::size_t size, const char* name, Read read) {
  const std::filesystem::path path = scratch() / name;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    read(path.string());
  } catch (const InputError&) {
    // refused in one line: what bad input must get
  }
  return 0;
}

}  // namespace deepguide::fuzz
