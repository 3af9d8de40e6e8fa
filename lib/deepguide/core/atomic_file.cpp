#include "deepguide/core/atomic_file.hpp"

#include <fstream>

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <atomic>
#include <regex>
#include <string>
#include <system_error>
#include <vector>

#include "deepguide/core/error.hpp"

namespace deepguide {
namespace fs = std::filesystem;

AtomicOutput::AtomicOutput(fs::path destination) : destination_(std::move(destination)) {
  fs::path dir = destination_.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw InputError(destination_.string() + ": expected an existing folder '" + dir.string() + "' to write into");
  }
  if (fs::is_directory(destination_, ec)) {
    throw InputError(destination_.string() + ": expected a file path, got a folder");
  }
  remove_stale_temporaries(dir);
  temp_ = temporary_path(dir, destination_.filename().string());
  fs::remove_all(temp_, ec);
}

fs::path temporary_path(const fs::path& folder, const std::string& name) {
  static std::atomic<unsigned> counter{0};
  const fs::path n(name);
  return folder / ("." + n.stem().string() + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
                   n.extension().string());
}

void remove_stale_temporaries(const fs::path& folder) {
  static const std::regex ours(R"(^\..*\.tmp([0-9]{1,9})-[0-9]+(\.[^.]*)?$)");
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    std::smatch m;
    if (!std::regex_match(name, m, ours)) continue;
    const long pid = std::stol(m[1].str());
    // Gone: no such process. (A live process under a reused pid keeps its files; they are few.)
    if (pid > 0 && pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
      stale.push_back(e.path());
  }
  for (const fs::path& p : stale) fs::remove_all(p, ec);
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(temp_, ec);
  }
}

void AtomicOutput::commit(bool replace) {
  std::error_code ec;
  // On the disk before it takes the name: a write the file system reports only at fsync (a full
  // disk with delayed allocation, NFS) fails here, not after "wrote".
  if (fs::is_regular_file(temp_, ec)) {
    const int fd = ::open(temp_.c_str(), O_RDONLY | O_CLOEXEC);
    const bool synced = fd >= 0 && ::fsync(fd) == 0;
    const int err = errno;
    if (fd >= 0) ::close(fd);
    if (!synced) {
      throw InputError(destination_.string() + ": could not write the file (" + std::strerror(err) + ")");
    }
  }
  if (!replace) {
    if (::link(temp_.c_str(), destination_.c_str()) == 0) {
      fs::remove(temp_, ec);
      committed_ = true;
      return;
    }
    if (errno == EEXIST) {
      throw InputError(destination_.string() + ": expected a new file, got one that exists (`overwrite` replaces it)");
    }
    // A file system without hard links: the plain rename (checked for existence before writing).
  }
  fs::rename(temp_, destination_, ec);
  if (ec) {
    throw InputError(destination_.string() + ": could not write the file (" + ec.message() + ")");
  }
  committed_ = true;
}

void write_text_file(const std::filesystem::path& path, const std::string& text, const char* what, bool replace) {
  AtomicOutput out(path);
  {
    std::ofstream file(out.temp_path(), std::ios::binary);
    file.write(text.data(), static_cast<std::streamsize>(text.size()));
    file.flush();
    if (!file) throw InputError(path.string() + ": could not write the " + what);
  }
  out.commit(replace);
}

}  // namespace deepguide
