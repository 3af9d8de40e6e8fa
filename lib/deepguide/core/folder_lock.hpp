#pragma once
// An advisory lock on an output folder, so two processes never write one run
// (two `evaluate` tasks given the same -o, a requeued Slurm task that starts
// while the old one still runs, a merge into a folder being written). It is
// flock(2) on a hidden file in the folder: the kernel drops it when the
// process dies, so a killed run never leaves a stale lock; on NFS, Linux
// maps it to a POSIX byte-range lock across nodes.

#include <filesystem>
#include <string>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

class FolderLock {
 public:
  /// Locks `folder` (which must exist) or throws InputError naming it and the
  /// process that holds it. `what` says who asks ("evaluate", "evaluate merge").
  FolderLock(const std::filesystem::path& folder, const std::string& what);
  ~FolderLock();  ///< unlocks and removes the lock file
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  static constexpr const char* kFileName = ".deepguide.lock";

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace deepguide
