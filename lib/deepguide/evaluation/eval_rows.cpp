#include "deepguide/evaluation/eval_rows.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "deepguide/core/angles.hpp"
#include "deepguide/core/error.hpp"
#include "deepguide/core/format.hpp"

namespace deepguide {

namespace {

constexpr const char* kHeader =
    "scenario_index,scenario,method,end,reached,collided,unavoidable,route_length_m,path_length_m,energy_kj,time_s,"
    "min_clearance_m,max_rate_ref_deg_s,rms_rate_ref_deg_s,max_rate_deg_s,rms_rate_deg_s,heading_reversals,"
    "compute_ms,graph_vertices,graph_edges,note";
constexpr std::size_t kColumns = 21;

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '\r' || c == '\n') {
      out += ' ';
      continue;
    }
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string number(double v, int digits) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  const std::string s = fixed(v, digits);
  return s == "-" + fixed(0.0, digits) ? fixed(0.0, digits) : s;  // no "-0.000"
}

// Splits one CSV line (no newline) into fields; false when quoting is broken.
bool split(const std::string& line, std::vector<std::string>& out) {
  out.clear();
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cur += c;
      }
    } else if (c == '"' && cur.empty()) {
      quoted = true;
    } else if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (quoted) return false;
  out.push_back(cur);
  return true;
}

bool to_double(const std::string& s, double& v) {
  if (s == "inf") return v = std::numeric_limits<double>::infinity(), true;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return !s.empty() && ec == std::errc() && p == s.data() + s.size() && std::isfinite(v);
}

template <class Int>
bool to_int(const std::string& s, Int& v) {
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return !s.empty() && ec == std::errc() && p == s.data() + s.size() && v >= 0;
}

bool parse_row(const std::vector<std::string>& f, EvalRow& row, std::string& why) {
  if (f.size() != kColumns) {
    why = "expected " + std::to_string(kColumns) + " columns, got " + std::to_string(f.size());
    return false;
  }
  MethodRun& r = row.run;
  auto flag = [&](const std::string& s, bool& b, const char* name) {
    if (s != "0" && s != "1") {
      why = std::string(name) + ": expected 0 or 1, got '" + printable(s) + "'";
      return false;
    }
    b = s == "1";
    return true;
  };
  struct Num {
    int col;
    double* v;
    double scale;
    const char* name;
  };
  const Num nums[] = {{7, &r.route_length_m, 1.0, "route_length_m"},
                      {8, &r.path_length_m, 1.0, "path_length_m"},
                      {9, &r.energy_j, 1000.0, "energy_kj"},
                      {10, &r.time_s, 1.0, "time_s"},
                      {11, &r.min_clearance_m, 1.0, "min_clearance_m"},
                      {12, &r.max_rate_ref, 1.0, "max_rate_ref_deg_s"},
                      {13, &r.rms_rate_ref, 1.0, "rms_rate_ref_deg_s"},
                      {14, &r.max_rate, 1.0, "max_rate_deg_s"},
                      {15, &r.rms_rate, 1.0, "rms_rate_deg_s"},
                      {17, &r.compute_ms, 1.0, "compute_ms"}};
  if (!to_int(f[0], row.scenario_index)) {
    why = "scenario_index: expected a whole number, got '" + printable(f[0]) + "'";
    return false;
  }
  row.scenario = f[1];
  row.method = f[2];
  r.end = f[3];
  if (row.scenario.empty() || row.method.empty() || r.end.empty()) {
    why = "scenario, method and end: expected text, got an empty field";
    return false;
  }
  if (!flag(f[4], r.reached, "reached") || !flag(f[5], r.collided, "collided") ||
      !flag(f[6], r.unavoidable, "unavoidable")) {
    return false;
  }
  for (const Num& n : nums) {
    double v = 0.0;
    if (!to_double(f[static_cast<std::size_t>(n.col)], v)) {
      why = std::string(n.name) + ": expected a number, got '" + printable(f[static_cast<std::size_t>(n.col)]) + "'";
      return false;
    }
    *n.v = v * n.scale;
  }
  for (double* rate : {&r.max_rate_ref, &r.rms_rate_ref, &r.max_rate, &r.rms_rate}) *rate = deg_to_rad(*rate);
  if (!to_int(f[16], r.heading_reversals) || !to_int(f[18], r.graph_vertices) || !to_int(f[19], r.graph_edges)) {
    why = "heading_reversals, graph_vertices, graph_edges: expected whole numbers";
    return false;
  }
  r.note = f[20];
  return true;
}

}  // namespace

std::string eval_rows_header() { return std::string(kHeader) + "\n"; }

std::string eval_row_csv(const EvalRow& row, bool timing) {
  const MethodRun& r = row.run;
  std::string s = std::to_string(row.scenario_index) + "," + field(row.scenario) + "," + field(row.method) + "," +
                  field(r.end) + "," + (r.reached ? "1" : "0") + "," + (r.collided ? "1" : "0") + "," +
                  (r.unavoidable ? "1" : "0") + ",";
  s += number(r.route_length_m, 3) + "," + number(r.path_length_m, 3) + "," + number(r.energy_j / 1000.0, 3) + "," +
       number(r.time_s, 2) + "," + number(r.min_clearance_m, 3) + ",";
  s += number(rad_to_deg(r.max_rate_ref), 4) + "," + number(rad_to_deg(r.rms_rate_ref), 4) + "," +
       number(rad_to_deg(r.max_rate), 4) + "," + number(rad_to_deg(r.rms_rate), 4) + ",";
  s += std::to_string(r.heading_reversals) + "," + number(timing ? r.compute_ms : 0.0, 3) + "," +
       std::to_string(r.graph_vertices) + "," + std::to_string(r.graph_edges) + "," + field(r.note) + "\n";
  return s;
}

std::vector<EvalRow> parse_eval_rows(const std::string& text, const std::string& source, bool lenient,
                                     std::size_t* dropped) {
  std::vector<EvalRow> rows;
  std::size_t bad = 0, line_no = 0, pos = 0;
  std::vector<std::string> fields;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    ++line_no;
    const bool complete = nl != std::string::npos;
    std::string line = text.substr(pos, complete ? nl - pos : std::string::npos);
    pos = complete ? nl + 1 : text.size();
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string at = source + ": line " + std::to_string(line_no);
    if (line_no == 1) {
      if (line != kHeader) {
        throw InputError(at + ": expected the evaluation rows' header (" + std::string(kHeader).substr(0, 40) +
                         "...), got '" + printable(line) + "'");
      }
      continue;
    }
    if (!complete && lenient) {
      ++bad;  // cut off while being written
      continue;
    }
    EvalRow row;
    std::string why = "broken quoting";
    if (!split(line, fields) || !parse_row(fields, row, why)) {
      if (!lenient) throw InputError(at + ": " + why);
      ++bad;
      continue;
    }
    rows.push_back(std::move(row));
  }
  if (line_no == 0 && !lenient) throw InputError(source + ": expected the evaluation rows' header, got an empty file");
  if (dropped != nullptr) *dropped = bad;
  return rows;
}

}  // namespace deepguide
