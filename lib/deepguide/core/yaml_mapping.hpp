#pragma once
// Library-internal (uses yaml-cpp types; nothing public includes it): one
// YAML mapping of known keys, read with the file's line numbers in every
// error. Unknown and duplicate keys are refused up front; values are read by
// key with what was expected (core/error.hpp's one-line InputError). The
// scenario and mission readers share it.

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "deepguide/core/error.hpp"

namespace deepguide {

/// "line N" (1-based) of a node, or "" when yaml-cpp has no mark.
std::string line_of(const YAML::Node& node);
/// The file's one YAML document. YAML::Load takes the first and drops the
/// rest without a word; a later document that holds anything is an
/// InputError naming `source` and its line (a trailing empty one is not).
/// Malformed text throws YAML::Exception as YAML::Load does.
YAML::Node load_one_document(const std::string& text, const std::string& source);
/// A number as messages show it (up to 10 significant digits).
std::string yaml_number(double v);
/// A number as files written to be read back write it: the shortest text
/// that reads back to the same double (.inf, -.inf, .nan for the others).
std::string yaml_exact_number(double v);

/// A numeric key's range: lo < v (or lo <= v when lo_closed) and v <= hi, in the file's unit.
struct Range {
  double lo, hi;
  bool lo_closed;
  const char* what;  ///< e.g. "a depth in metres"

  bool holds(double v) const;
  std::string text() const;
};

class Mapping {
 public:
  /// Throws InputError when `node` is not a mapping (expected: `expected`) or
  /// holds a key outside `known` or a key twice. `prefix` is put before key
  /// names in messages ("sonar." for a nested mapping).
  Mapping(const YAML::Node& node, std::string source, std::string prefix, std::initializer_list<const char*> known,
          const std::string& expected)
      : Mapping(node, std::move(source), std::move(prefix), std::vector<std::string>(known.begin(), known.end()),
                expected) {}
  /// The same with the known keys from a table (the vehicle file's fields).
  Mapping(const YAML::Node& node, std::string source, std::string prefix, const std::vector<std::string>& known,
          const std::string& expected);

  bool has(const char* key) const { return index(key) >= 0; }
  /// The value, or an undefined node when absent.
  YAML::Node value(const char* key) const { return index(key) >= 0 ? values_[index(key)] : YAML::Node(); }
  InputLocation where(const char* key) const;
  std::string full(const char* key) const { return prefix_ + key; }
  const std::string& source() const { return source_; }
  const YAML::Node& node() const { return node_; }

  /// A number within `r` (required).
  double number(const char* key, const Range& r) const;
  double number_or(const char* key, const Range& r, double fallback) const {
    return has(key) ? number(key, r) : fallback;
  }
  /// A finite number (required), `what` it is in messages; its range is the caller's to check.
  double finite_number(const char* key, const char* what) const;
  /// A non-empty scalar (required).
  std::string text(const char* key, const char* expected) const;
  /// A path, relative to `base_dir` unless absolute.
  std::string path(const char* key, const std::string& base_dir) const;

 private:
  int index(const char* key) const;
  /// The value as a number, `what` it is in messages (no range).
  double scalar_number(const char* key, const char* what) const;
  YAML::Node node_;
  std::string source_, prefix_;
  std::vector<std::pair<std::string, YAML::Node>> entries_;  // key text, key node (for its line)
  std::vector<YAML::Node> values_;
};

}  // namespace deepguide
