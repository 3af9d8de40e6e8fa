#pragma once
// The bench programs' command lines: CLI11, with Google Benchmark's own flags
// (--benchmark_*, which scripts/bench.sh passes to every bench_*) accepted
// and ignored. --help prints the options; a bad one exits 2, as the apps do.

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <string>

namespace deepguide::bench {

inline void parse_or_exit(CLI::App& app, int argc, char** argv) {
  app.allow_extras();
  try {
    app.parse(argc, argv);
    for (const std::string& extra : app.remaining()) {
      if (extra.rfind("--benchmark", 0) != 0) throw CLI::ExtrasError({extra});
    }
  } catch (const CLI::CallForHelp& e) {
    std::exit(app.exit(e));
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    std::exit(2);
  }
}

}  // namespace deepguide::bench
