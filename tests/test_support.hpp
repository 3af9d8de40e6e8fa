#pragma once
// Small helpers shared by the test suites: scratch folders, files, running the CLI.

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <random>
#include <string>

#include "deepguide/core/error.hpp"

namespace deepguide::test {

/// Under AddressSanitizer and UndefinedBehaviorSanitizer (scripts/test.sh
/// --sanitize) the heaviest randomized tests run a fifth of their cases: the
/// sanitizers look for memory and UB faults, which a fifth finds as well, and
/// the Release run keeps the full counts the acceptance figures rest on.
#ifdef DEEPGUIDE_SANITIZED
inline constexpr int kCaseDivisor = 5;
#else
inline constexpr int kCaseDivisor = 1;
#endif
inline constexpr int cases(int n) { return n / kCaseDivisor; }

/// A time limit that tells a hang from a slow run: the sanitizers make the
/// command 5 to 10 times slower (and CI's machine, shared, slower still), so
/// a limit set for Release is multiplied there. Never a speed assertion.
#ifdef DEEPGUIDE_SANITIZED
inline constexpr int kHangLimitFactor = 6;
#else
inline constexpr int kHangLimitFactor = 1;
#endif
inline constexpr int hang_limit_s(int release_s) { return release_s * kHangLimitFactor; }

/// Skips a test under the sanitizers when another case runs the same code
/// there: on this project's machines a chart read under AddressSanitizer
/// costs 20 to 40 times its Release time (page faults of its large
/// allocations), and CI has a time limit. `why` names the case that remains.
#ifdef DEEPGUIDE_SANITIZED
#define DEEPGUIDE_SKIP_UNDER_SANITIZERS(why) GTEST_SKIP() << "under the sanitizers " << why
#else
#define DEEPGUIDE_SKIP_UNDER_SANITIZERS(why) static_cast<void>(0)
#endif

/// A fresh folder under the system temp dir, removed at the end of the test.
class ScratchDir {
 public:
  ScratchDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("deepguide-test-" + std::to_string(rd()) + "-" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }
  /// Writes `content` to NAME in the folder and returns the full path.
  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(path_ / name, std::ios::binary) << content;
    return file(name);
  }

 private:
  std::filesystem::path path_;
};

/// Where the project's shared real data lives; empty if absent (tests then skip).
inline std::string shared_real_data() {
  const auto p = std::filesystem::path(DEEPGUIDE_SOURCE_DIR) / ".." / "shared" / "data" / "real";
  return std::filesystem::is_directory(p) ? p.lexically_normal().string() : std::string();
}

/// Path of a real file (or folder: an exchange set) under ../shared/data/real, or empty when
/// the data or that file is absent, or is not of that type.
inline std::string real_data(const std::string& rel, std::filesystem::file_type type) {
  const std::string dir = shared_real_data();
  if (dir.empty()) return {};
  const auto p = std::filesystem::path(dir) / rel;
  return std::filesystem::status(p).type() == type ? p.string() : std::string();
}
inline std::string real_file(const std::string& rel) { return real_data(rel, std::filesystem::file_type::regular); }
inline std::string real_folder(const std::string& rel) { return real_data(rel, std::filesystem::file_type::directory); }

/// Declares `var` as the real file (or folder) `rel`, or skips the test with a message when it is absent.
#define DEEPGUIDE_REAL_OR_SKIP_(var, rel, type)                                                \
  const std::string var = ::deepguide::test::real_data(rel, std::filesystem::file_type::type); \
  if (var.empty()) GTEST_SKIP() << "../shared/data/real/" << (rel) << " is absent: skipping the test on real data"
#define DEEPGUIDE_REAL_FILE_OR_SKIP(var, rel) DEEPGUIDE_REAL_OR_SKIP_(var, rel, regular)
#define DEEPGUIDE_REAL_FOLDER_OR_SKIP(var, rel) DEEPGUIDE_REAL_OR_SKIP_(var, rel, directory)

inline std::string source_file(const std::string& rel) {
  return (std::filesystem::path(DEEPGUIDE_SOURCE_DIR) / rel).string();
}

/// The whole file's bytes; empty when it cannot be read.
inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs the deepguide binary with ARGS (a shell-quoted string) and captures
/// its output. With `limit_s` > 0 the run is stopped after that many seconds
/// (coreutils timeout: exit code 124).
inline RunResult run_cli(const std::string& args, int limit_s = 0) {
  ScratchDir tmp;
  const std::string out = tmp.file("stdout");
  const std::string err = tmp.file("stderr");
  const std::string limit = limit_s > 0 ? "timeout -k 2 " + std::to_string(limit_s) + " " : std::string();
  const std::string cmd = limit + "'" + DEEPGUIDE_CLI + "' " + args + " >'" + out + "' 2>'" + err + "' </dev/null";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  auto slurp = [](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

/// The InputError `fn` throws, its text; empty when it throws none.
inline std::string error_of(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const deepguide::InputError& e) {
    return e.what();
  }
  return {};
}

/// Expects `msg` (an InputError's text, empty when none was thrown) to be one
/// line that contains every one of `parts`.
inline void expect_error(const std::string& msg, std::initializer_list<const char*> parts) {
  ASSERT_FALSE(msg.empty()) << "no InputError was thrown";
  EXPECT_EQ(msg.find('\n'), std::string::npos) << "not one line: " << msg;
  for (const char* part : parts) EXPECT_NE(msg.find(part), std::string::npos) << "'" << part << "' not in: " << msg;
}

/// Expects `fn` to throw a deepguide::InputError whose message is one line
/// and contains `needle`.
template <class Fn>
void expect_one_line_error(Fn fn, const std::string& needle) {
  try {
    fn();
    ADD_FAILURE() << "no InputError";
  } catch (const deepguide::InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_NE(msg.find(needle), std::string::npos) << msg;
  }
}

}  // namespace deepguide::test
