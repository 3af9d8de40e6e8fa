#pragma once
// The deepguide command line run in the test's own process (app::run), so
// that what the test registered (a toy graph, a toy reactive method) is there.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "commands.hpp"

namespace deepguide::test {

struct CliRun {
  int code = 0;
  std::string out, err;
};

inline CliRun deepguide_cli(std::vector<std::string> args) {
  args.insert(args.begin(), "deepguide");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  CliRun r;
  r.code = app::run(static_cast<int>(argv.size()), argv.data());
  r.out = testing::internal::GetCapturedStdout();
  r.err = testing::internal::GetCapturedStderr();
  return r;
}

}  // namespace deepguide::test
