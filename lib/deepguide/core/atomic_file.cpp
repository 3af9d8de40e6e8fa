#include "deepguide/core/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <string>
#include <system_error>

#include "deepguide/core/error.hpp"

namespace deepguide {
namespace fs = std::filesystem;

AtomicOutput::AtomicOutput(fs::path destination) : destination_(std::move(destination)) {
  fs::path dir = destination_.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw InputError(destination_.string() + ": expected an existing folder '" + dir.string() +
                     "' to write into");
  }
  if (fs::is_directory(destination_, ec)) {
    throw InputError(destination_.string() + ": expected a file path, got a folder");
  }
  static std::atomic<unsigned> counter{0};
  const std::string name = "." + destination_.stem().string() + ".tmp" + std::to_string(::getpid()) +
                           "-" + std::to_string(counter++) + destination_.extension().string();
  temp_ = dir / name;
  fs::remove_all(temp_, ec);
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(temp_, ec);
  }
}

void AtomicOutput::commit() {
  std::error_code ec;
  fs::rename(temp_, destination_, ec);
  if (ec) {
    throw InputError(destination_.string() + ": could not write the file (" + ec.message() + ")");
  }
  committed_ = true;
}

}  // namespace deepguide
