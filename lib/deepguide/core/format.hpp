#pragma once
// Numbers (and names) as text for messages and files, in one place: printf's fixed
// ("%.*f") and general ("%g") forms, and a point as "(x, y)". A buffer of
// 384 characters holds any double in fixed form.

#include <Eigen/Core>
#include <string>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// `v` with `digits` decimals ("%.*f").
std::string fixed(double v, int digits);
/// `v` in printf's %g form (`significant` digits, no trailing zeros).
std::string general(double v, int significant = 6);
/// `text` for HTML text or a quoted attribute: & < > " as entities.
std::string html_text(const std::string& text);
/// "(x, y)" with `digits` decimals, e.g. "(120.0, 45.5)".
std::string point_text(double x, double y, int digits = 1);
inline std::string point_text(const Eigen::Vector2d& p, int digits = 1) { return point_text(p.x(), p.y(), digits); }
/// A duration as a clock, "H:MM:SS", rounded to the second (e.g. "1:47:47"); "-" for
/// a negative or non-finite one.
std::string clock_text(double seconds);
/// One line of a command's text report: the label padded to column 18, the
/// value, a newline ("length           12.00 m\n").
std::string report_line(const std::string& label, const std::string& value);
/// printf's formatting into a string of any length: the rows of a command's
/// text tables ("%4zu %10.1f ...").
std::string printf_text(const char* format, ...) __attribute__((format(printf, 1, 2)));
/// `s` with ASCII letters in lower case (names in files: units, extensions, attributes).
std::string ascii_lower(std::string s);

}  // namespace deepguide
