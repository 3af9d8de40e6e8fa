#include "deepguide/core/input_files.hpp"

#include <filesystem>
#include <system_error>

#include "deepguide/core/error.hpp"

namespace deepguide {

void refuse_special_file(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.rfind("/vsi", 0) == 0) return;
  std::error_code ec;
  const fs::file_type type = fs::status(path, ec).type();
  const char* got = type == fs::file_type::fifo                                        ? "a named pipe (FIFO)"
                    : type == fs::file_type::socket                                    ? "a socket"
                    : type == fs::file_type::character || type == fs::file_type::block ? "a device"
                                                                                       : nullptr;
  if (got != nullptr) throw InputError(printable(path) + ": expected a file, got " + got);
}

}  // namespace deepguide
