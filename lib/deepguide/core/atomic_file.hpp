#pragma once
// Never leave a half-written output file: writers produce a temporary file in
// the destination's folder (same file system, so the final rename is atomic)
// and rename it over the destination only when everything has been written.

#include <filesystem>
#include <string>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

class AtomicOutput {
 public:
  /// Reserves a temporary path next to `destination` that keeps its extension
  /// (GDAL drivers look at it). Throws InputError if the folder does not exist.
  explicit AtomicOutput(std::filesystem::path destination);
  ~AtomicOutput();  ///< removes the temporary file unless commit() succeeded
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::filesystem::path& temp_path() const { return temp_; }
  const std::filesystem::path& destination() const { return destination_; }

  /// Renames the temporary file onto the destination. With replace false an
  /// existing destination is never replaced, even one that appeared while
  /// writing (a hard link, which fails on an existing name, then the
  /// temporary name removed): InputError saying so.
  void commit(bool replace = true);

 private:
  std::filesystem::path destination_;
  std::filesystem::path temp_;
  bool committed_ = false;
};

/// A temporary name in `folder` for `name` that a later run can tell is ours
/// and whose writer is gone: ".NAME_STEM.tmpPID-N.EXT" (the extension kept).
std::filesystem::path temporary_path(const std::filesystem::path& folder, const std::string& name);

/// Removes our temporaries in `folder` (files or folders named as
/// temporary_path names them) whose process no longer runs: what a killed
/// run left behind. Every AtomicOutput calls it for its folder.
void remove_stale_temporaries(const std::filesystem::path& folder);

/// Writes `text` to `path` atomically; `what` names the file in the error
/// ("could not write the WHAT"). With replace false an existing file is kept
/// (AtomicOutput::commit).
void write_text_file(const std::filesystem::path& path, const std::string& text, const char* what, bool replace = true);

}  // namespace deepguide
