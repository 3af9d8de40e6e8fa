#include "deepguide/core/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "deepguide/core/error.hpp"

namespace deepguide {

FolderLock::FolderLock(const std::filesystem::path& folder, const std::string& what) : path_(folder / kFileName) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw InputError(folder.string() + ": could not create the lock file " + kFileName + ": " + std::strerror(errno));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    std::string holder;
    std::ifstream(path_) >> holder;
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK) {
      throw InputError(folder.string() + ": expected a folder no other process is writing, got one that " +
                       (holder.empty() ? std::string("another deepguide") : "process " + holder) +
                       " holds (wait for it to end, or choose another -o)");
    }
    throw InputError(folder.string() + ": could not lock " + kFileName + ": " + std::strerror(err));
  }
  const std::string pid = std::to_string(::getpid()) + " (" + what + ")\n";
  if (::ftruncate(fd_, 0) != 0 || ::write(fd_, pid.data(), pid.size()) < 0) {
    // The lock holds without the note; the note only names the holder in the other's message.
  }
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  // Unlinked while still held: a process that opened it meanwhile locks a file no one else will see,
  // which is harmless for a folder whose run has just ended.
  std::error_code ec;
  std::filesystem::remove(path_, ec);
  ::flock(fd_, LOCK_UN);
  ::close(fd_);
}

}  // namespace deepguide
