// Every number an option takes is finite (issue 39, item 4): NaN passes
// every range check (each comparison with it is false) and means "not given"
// in many of the library's requests, so `--arc-tolerance nan` wrote arcs as
// single chords and `--depth nan` planned as if no depth were given. The
// sweep walks the whole command tree, so an option added later is covered
// (and checked here) without naming it.

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "deepguide/core/error.hpp"
#include "test_support.hpp"

namespace deepguide::app {
namespace {

TEST(FiniteOptions, FiniteNumberReadsOnlyFiniteNumbers) {
  EXPECT_EQ(finite_number("1.5"), 1.5);
  EXPECT_EQ(finite_number(" +2 "), 2.0);
  EXPECT_EQ(finite_number("-3e2"), -300.0);
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "+inf", "infinity", "1e999", "", " ", "1,2", "1m", "0x10"}) {
    EXPECT_FALSE(finite_number(bad).has_value()) << "'" << bad << "'";
  }
}

struct NumberOption {
  std::vector<std::string> path;  // subcommands down to the option's command
  std::string flag;               // its longest name, e.g. "--depth"
};

void collect(CLI::App& app, std::vector<std::string> path, std::vector<NumberOption>& out) {
  for (CLI::Option* o : app.get_options()) {
    if (o->get_type_name().find("FLOAT") == std::string::npos || o->get_lnames().empty()) continue;
    out.push_back({path, "--" + o->get_lnames().front()});
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    std::vector<std::string> deeper = path;
    deeper.push_back(sub->get_name());
    collect(*sub, deeper, out);
  }
}

std::string parse_error(const std::vector<std::string>& words) {
  CLI::App app{"deepguide"};
  register_commands(app);
  std::vector<std::string> args(words.rbegin(), words.rend());  // CLI11 takes them last first
  try {
    app.parse(args);
  } catch (const CLI::Error& e) {
    return e.what();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("not a parse error: ") + e.what();
  }
  return "accepted";
}

TEST(FiniteOptions, EveryNumberOptionOfEveryCommandRefusesNanAndInfinities) {
  CLI::App app{"deepguide"};
  register_commands(app);
  std::vector<NumberOption> options;
  collect(app, {}, options);
  // plan (15 of them), chart, check route, mission, simulate, evaluate ...: 36 when written.
  ASSERT_GT(options.size(), 30u);
  std::size_t depth_flags = 0;
  for (const NumberOption& o : options) {
    depth_flags += o.flag == "--depth";
    for (const char* value : {"nan", "inf", "-inf", "NAN", "+inf"}) {
      std::vector<std::string> words = o.path;
      words.push_back(o.flag);
      words.push_back(value);
      const std::string why = parse_error(words);
      std::string where;
      for (const std::string& w : o.path) where += w + " ";
      // Refused, naming the flag: by this check, or first by the option's own range (an infinity);
      // NaN passes every range, so only this check catches it.
      const bool nan = std::string(value).find_first_of("nN") == 0;
      const bool finite_check =
          why.find("expected a finite number, got '" + std::string(value) + "'") != std::string::npos;
      const bool range_check = why.find("not in range") != std::string::npos;
      EXPECT_TRUE(finite_check || (!nan && range_check)) << where << o.flag << " " << value << ": " << why;
      EXPECT_NE(why.find(o.flag), std::string::npos) << where << o.flag << " " << value << ": " << why;
    }
  }
  EXPECT_GE(depth_flags, 3u) << "plan, chart nogo, check route ... take --depth";
  // The cases by name.
  for (const std::vector<std::string>& words :
       {std::vector<std::string>{"mission", "export", "--arc-tolerance", "nan"},
        std::vector<std::string>{"plan", "--depth", "nan"}, std::vector<std::string>{"plan", "--max-dive", "nan"},
        std::vector<std::string>{"plan", "--from-depth", "nan"}}) {
    EXPECT_NE(parse_error(words).find("expected a finite number"), std::string::npos) << words[1] << " " << words[2];
  }
}

// Lists of numbers given as text are read by finite_number too.
TEST(FiniteOptions, NumbersInsideTextOptionsAreFinite) {
  const std::string obstacles = test::source_file("data/sample_obstacles.geojson");
  for (const char* band : {"nan,5", "2,inf", "-inf,3"}) {
    char* argv[] = {const_cast<char*>("deepguide"),    const_cast<char*>("plan"),
                    const_cast<char*>("--graph"),      const_cast<char*>("octree"),
                    const_cast<char*>("--depth-band"), const_cast<char*>(band),
                    const_cast<char*>("--obstacles"),  const_cast<char*>(obstacles.c_str()),
                    const_cast<char*>("--from"),       const_cast<char*>("8,54"),
                    const_cast<char*>("--to"),         const_cast<char*>("8.01,54"),
                    const_cast<char*>("--depth"),      const_cast<char*>("5")};
    testing::internal::CaptureStderr();
    const int rc = run(static_cast<int>(std::size(argv)), argv);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(rc, 0) << band;
    EXPECT_NE(err.find("--depth-band"), std::string::npos) << band << ": " << err;
  }
}

}  // namespace
}  // namespace deepguide::app
