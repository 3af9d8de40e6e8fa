#include "deepguide/core/output_paths.hpp"

#include <sys/stat.h>

#include <filesystem>

#include "deepguide/core/error.hpp"

namespace deepguide {
namespace {

bool same_file(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

// For files that may not exist yet: the absolute path with dots and links in its folders resolved.
std::string resolved(const std::string& p) {
  std::error_code ec;
  const std::filesystem::path r = std::filesystem::weakly_canonical(std::filesystem::absolute(p, ec), ec);
  return ec ? std::filesystem::absolute(p).lexically_normal().string() : r.string();
}

}  // namespace

void check_outputs_apart(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& out = outputs[i];
    if (out.path.empty()) continue;
    for (const NamedPath& in : inputs) {
      if (!in.path.empty() && same_file(out.path, in.path)) {
        throw InputError(out.option + ": expected a file that is not an input, got " + printable(out.path, 200) +
                         ", which is the " + in.option + " file " + printable(in.path, 200) +
                         " (writing it would destroy it)");
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      const NamedPath& other = outputs[j];
      if (!other.path.empty() && (same_file(out.path, other.path) || resolved(out.path) == resolved(other.path))) {
        throw InputError(out.option + ": expected a file apart from " + other.option + "'s, got the same file " +
                         printable(out.path, 200));
      }
    }
  }
}

}  // namespace deepguide
