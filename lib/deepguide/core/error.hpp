#pragma once
// Errors that reach the user. Every one is a single line that names where the
// problem is (file, feature or line, field) and what was expected.
// A message names a parameter the caller set by its field in backquotes,
// "`margin`: expected ...", so that a program with its own names for them
// (the command line's flags) can rename each with rename_parameters.
// Exit codes (apps/cli.cpp): 1 bad input (and internal errors), 2 usage,
// 3 no safe route or a manoeuvre that cannot be done, 4 done with some inputs
// skipped.

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// Bad input: a file, a feature, a field or an option value. Exit code 1.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The problem is well posed but no safe route exists. Exit code 3.
class NoRouteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The manoeuvre is well posed but cannot be done (a current stronger than
/// the vehicle, a position never reached). Exit code 3, as NoRouteError.
class ManoeuvreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The work was done, but some of its inputs were skipped (a batch with a
/// broken scenario): every output was written, and they say what was left
/// out. Exit code 4.
class PartialError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Where in an input a problem sits; formats as "FILE: feature F: field 'X'".
struct InputLocation {
  std::string file;
  std::string feature;  ///< e.g. "feature 3 (id 'w1')" or "line 12"; may be empty
  std::string field;    ///< may be empty

  std::string describe() const;
};

/// Text from a file (an id, a name) made safe for a one-line message: C0 and
/// C1 control characters and bytes that are not UTF-8 escaped as \xNN, the
/// invisible format and bidirectional controls (U+200B-U+200F, U+2028-U+202E,
/// U+2060-U+2069, U+061C, U+FEFF) as \uNNNN; cut after `max_chars` bytes with "...".
std::string printable(const std::string& text, std::size_t max_chars = 60);

/// Builds an InputError "LOCATION: expected EXPECTED[, got GOT]".
InputError input_error(const InputLocation& where, const std::string& expected, const std::string& got = {});

/// For parameter structs' validate(): throws input_error({group, "", field},
/// expected, got) unless `ok`. E.g. "reactive: field 'margin_m': expected a
/// margin >= 0 m, got -1".
void require_param(bool ok, const char* group, const char* field, const char* expected, double got);

/// `message` with each parameter name in backquotes (`min_cell_m`: a letter,
/// then letters, digits and '_') replaced by what `rename` returns for it,
/// backquotes included; a name it returns nothing for, and any other text,
/// stays as it is.
std::string rename_parameters(std::string_view message,
                              const std::function<std::optional<std::string>(std::string_view)>& rename);

}  // namespace deepguide
