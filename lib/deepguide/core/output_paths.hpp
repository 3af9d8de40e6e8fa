#pragma once
// Outputs never destroy inputs: a command refuses an output file that is one
// of its inputs (the same file by device and inode, so another name, a hard
// link or a symbolic link is seen through) or that another of its outputs
// names too (`-o x.png --render x.png` would keep only one of them).

#include <string>
#include <vector>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

struct NamedPath {
  std::string option;  ///< e.g. "-o", "--render", "--obstacles"
  std::string path;    ///< empty: not given (skipped)
};

/// Throws InputError naming both options and the path otherwise.
void check_outputs_apart(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

}  // namespace deepguide
