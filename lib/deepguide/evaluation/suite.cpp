#include "deepguide/evaluation/suite.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "deepguide/core/atomic_file.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/fnv1a.hpp"
#include "deepguide/core/input_files.hpp"
#include "deepguide/core/yaml_mapping.hpp"
#include "deepguide/simulation/scenario_writer.hpp"

namespace deepguide {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSuiteFile = "suite.yaml";

MonteCarloParams read_generator(const Mapping& root) {
  const Mapping m(root.value("generate"), root.source(), "generate.",
                  {"scenarios", "seed", "min_obstacles", "max_obstacles", "min_size_m", "max_size_m",
                   "cross_track_sigma_m", "max_current_mps", "sonar_noise"},
                  "a mapping of generator keys (scenarios, seed, max_obstacles, ...)");
  MonteCarloParams p;
  auto integer = [&](const char* key, double hi, int fallback) {
    const double v = m.number_or(key, {0.0, hi, true, "a whole number"}, fallback);
    if (v != static_cast<int>(v)) throw input_error(m.where(key), "a whole number", yaml_number(v));
    return static_cast<int>(v);
  };
  p.scenarios = integer("scenarios", 1e6, 0);
  if (!m.has("scenarios") || p.scenarios < 1) {
    throw input_error(m.has("scenarios") ? m.where("scenarios") : root.where("generate"),
                      "generate.scenarios: a count of 1 .. 1000000", m.has("scenarios") ? "0" : "none");
  }
  if (m.has("seed")) {
    const YAML::Node v = m.value("seed");
    const std::string text = v.IsScalar() ? v.Scalar() : std::string();
    std::istringstream in(text);
    std::uint64_t seed = 0;
    if (text.empty() || text.front() == '-' || !(in >> seed) || !in.eof()) {
      throw input_error(m.where("seed"), "an unsigned integer seed", "'" + printable(text) + "'");
    }
    p.seed = seed;
  }
  p.max_obstacles = integer("max_obstacles", 1000, p.max_obstacles);
  p.min_obstacles = integer("min_obstacles", 1000, std::min(p.min_obstacles, p.max_obstacles));
  p.min_size_m = m.number_or("min_size_m", {0.1, 1000.0, true, "a size in metres"}, p.min_size_m);
  p.max_size_m = m.number_or("max_size_m", {0.1, 1000.0, true, "a size in metres"}, p.max_size_m);
  p.cross_track_sigma_m =
      m.number_or("cross_track_sigma_m", {0.0, 1e4, true, "a spread in metres"}, p.cross_track_sigma_m);
  p.max_current_mps = m.number_or("max_current_mps", {0.0, 20.0, true, "a speed in m/s"}, p.max_current_mps);
  p.sonar_noise = m.number_or("sonar_noise", {0.0, 100.0, true, "a factor"}, p.sonar_noise);
  try {
    validate(p);
  } catch (const InputError& e) {
    throw InputError(root.source() +
                     ": generate: " + std::string(e.what()).substr(std::string("monte carlo: ").size()));
  }
  return p;
}

// A file as one piece of `h`, read in chunks; one the scenario reader would
// refuse for its size (over 4 MiB) by its size alone, an unreadable one by a
// tag piece of its own.
void hash_file(Fnv1a& h, const std::string& path) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) {
    h.piece("unreadable");
    return;
  }
  if (size > kMaxScenarioFileBytes) {
    h.piece("over 4 MiB: " + std::to_string(size));
    return;
  }
  h.piece("file");
  const std::string length = std::to_string(size) + ":";
  h.raw(length.data(), length.size());
  char buffer[1 << 16];
  std::uintmax_t left = size;  // what the size promised, even if the file grows meanwhile
  while (left > 0 && in.read(buffer, static_cast<std::streamsize>(std::min<std::uintmax_t>(left, sizeof buffer)))) {
    h.raw(buffer, static_cast<std::size_t>(in.gcount()));
    left -= static_cast<std::uintmax_t>(in.gcount());
  }
  if (left > 0) h.piece("shorter than its size");
}

std::string fingerprint_of(const Suite& suite) {
  Fnv1a f;
  for (const SuiteScenario& s : suite.scenarios) {
    f.piece(s.id);
    if (!s.path.empty()) hash_file(f, s.path);
  }
  if (!suite.scenarios.empty() && suite.scenarios.front().path.empty() && suite.generator) {
    // Every setting at full precision (suite_yaml writes them exactly), and
    // the generator's own version: a new way of drawing is another suite.
    f.piece("monte carlo generator 1");
    f.piece(suite_yaml(suite.name, *suite.generator));
  }
  return f.text();
}

void read_suite_file(const fs::path& file, Suite& suite) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw input_error({file.string(), "", ""}, "a readable suite file");
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().size() > (1u << 20)) throw input_error({file.string(), "", ""}, "a suite file under 1 MiB");
  YAML::Node doc;
  try {
    doc = load_one_document(text.str(), file.string());
  } catch (const YAML::Exception& e) {
    throw input_error({file.string(), e.mark.line >= 0 ? "line " + std::to_string(e.mark.line + 1) : std::string(), ""},
                      "a YAML suite file", printable(e.msg, 100));
  }
  const Mapping root(doc, file.string(), "", {"name", "generate"}, "a YAML mapping with name and generate");
  if (root.has("name")) suite.name = root.text("name", "the suite's name");
  if (root.has("generate")) suite.generator = read_generator(root);
}

}  // namespace

std::string generated_scenario_id(int k, int count) {
  const int digits = std::max<int>(4, static_cast<int>(std::to_string(std::max(count - 1, 0)).size()));
  std::string n = std::to_string(k);
  return "scenario-" + std::string(static_cast<std::size_t>(std::max(0, digits - static_cast<int>(n.size()))), '0') + n;
}

Suite read_suite(const std::string& path) {
  refuse_special_file(path);
  std::error_code ec;
  Suite suite;
  suite.source = path;
  if (fs::is_regular_file(path, ec)) {
    if (fs::path(path).filename() == kSuiteFile) {
      const fs::path parent = fs::path(path).parent_path();
      return read_suite(parent.empty() ? std::string(".") : parent.string());
    }
    suite.name = fs::path(path).stem().string();
    suite.scenarios.push_back({suite.name, path, -1});
    suite.fingerprint = fingerprint_of(suite);
    return suite;
  }
  if (!fs::is_directory(path, ec)) {
    throw input_error({path, "", ""}, "a suite folder, its suite.yaml or a scenario file", "nothing there");
  }
  const fs::path dir(path);
  suite.name = fs::absolute(dir).lexically_normal().filename().string();
  if (suite.name.empty()) suite.name = fs::absolute(dir).lexically_normal().parent_path().filename().string();
  if (fs::is_regular_file(dir / kSuiteFile, ec)) read_suite_file(dir / kSuiteFile, suite);
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const fs::path& p = e.path();
    if (p.extension() == ".yaml" && p.filename() != kSuiteFile && e.is_regular_file()) files.push_back(p);
  }
  if (ec) throw input_error({path, "", ""}, "a readable suite folder", ec.message());
  std::sort(files.begin(), files.end());
  for (const fs::path& p : files) suite.scenarios.push_back({p.stem().string(), p.string(), -1});
  if (suite.scenarios.empty() && suite.generator) {
    for (int k = 0; k < suite.generator->scenarios; ++k) {
      suite.scenarios.push_back({generated_scenario_id(k, suite.generator->scenarios), "", k});
    }
  }
  if (suite.scenarios.empty()) {
    throw input_error({path, "", ""}, "scenario files (*.yaml) or a suite.yaml with a generate section",
                      "an empty suite");
  }
  suite.fingerprint = fingerprint_of(suite);
  return suite;
}

Scenario load_suite_scenario(const Suite& suite, std::size_t index) {
  const SuiteScenario& s = suite.scenarios.at(index);
  if (s.generated < 0) return read_scenario_file(s.path);
  Scenario sc = monte_carlo_scenario(*suite.generator, s.generated);
  sc.name = s.id;
  sc.source = suite.source + ": " + s.id;
  return sc;
}

std::string suite_yaml(const std::string& name, const MonteCarloParams& p) {
  std::ostringstream o;
  o << "# A deepguide scenario suite (docs/EVALUATION.md). Without scenario files\n"
       "# beside it, `deepguide evaluate` makes the scenarios from `generate`.\n";
  o << "name: \"" << name << "\"\n";
  o << "generate:\n"
    << "  scenarios: " << p.scenarios << "\n"
    << "  seed: " << p.seed << "\n"
    << "  min_obstacles: " << p.min_obstacles << "\n"
    << "  max_obstacles: " << p.max_obstacles << "\n"
    << "  min_size_m: " << yaml_exact_number(p.min_size_m) << "\n"
    << "  max_size_m: " << yaml_exact_number(p.max_size_m) << "\n"
    << "  cross_track_sigma_m: " << yaml_exact_number(p.cross_track_sigma_m) << "\n"
    << "  max_current_mps: " << yaml_exact_number(p.max_current_mps) << "\n"
    << "  sonar_noise: " << yaml_exact_number(p.sonar_noise) << "\n";
  return o.str();
}

std::string write_suite(const std::string& dir, const std::string& given_name, const MonteCarloParams& params,
                        bool files, bool overwrite) {
  validate(params);
  fs::path target = fs::absolute(dir).lexically_normal();
  if (target.filename().empty()) target = target.parent_path();  // "suites/mine/"
  const std::string name = given_name.empty() ? target.filename().string() : given_name;
  if (name.empty() || name.find_first_of("\"\\\n\r") != std::string::npos) {
    throw InputError(dir + ": name: expected a suite name without quotes, backslashes or line breaks");
  }
  std::error_code ec;
  const fs::path here = fs::current_path(ec).lexically_normal();
  if (target.filename().empty() || target == target.root_path() ||
      (!ec && !fs::relative(here, target, ec).empty() && fs::relative(here, target, ec).native().rfind("..", 0) != 0)) {
    throw InputError(dir + ": expected a new folder outside the current one (it would be replaced whole)");
  }
  if (fs::exists(target, ec) && !overwrite) {
    throw InputError(dir + ": expected a new folder, got one that exists (`overwrite` replaces it)");
  }
  if (!fs::is_directory(target.parent_path(), ec)) {
    throw InputError(dir + ": expected an existing folder '" + target.parent_path().string() + "' to write into");
  }
  remove_stale_temporaries(target.parent_path());
  const fs::path temp = temporary_path(target.parent_path(), target.filename().string());
  struct Cleanup {
    fs::path p;
    ~Cleanup() {
      std::error_code ignored;
      if (!p.empty()) fs::remove_all(p, ignored);
    }
  } cleanup{temp};
  if (!fs::create_directory(temp, ec)) throw InputError(dir + ": could not create a folder (" + ec.message() + ")");
  write_text_file((temp / kSuiteFile).string(), suite_yaml(name, params), "suite file");
  if (files) {
    for (int k = 0; k < params.scenarios; ++k) {
      Scenario sc = monte_carlo_scenario(params, k);
      sc.name = generated_scenario_id(k, params.scenarios);
      write_text_file((temp / (sc.name + ".yaml")).string(),
                      scenario_yaml(sc, "Scenario " + std::to_string(k) + " of suite " + name + " (suite.yaml)."),
                      "scenario");
    }
  }
  if (fs::exists(target, ec)) fs::remove_all(target, ec);
  if (ec) throw InputError(dir + ": could not replace the folder (" + ec.message() + ")");
  fs::rename(temp, target, ec);
  if (ec) throw InputError(dir + ": could not move the suite into place (" + ec.message() + ")");
  cleanup.p.clear();
  return name;
}

}  // namespace deepguide
