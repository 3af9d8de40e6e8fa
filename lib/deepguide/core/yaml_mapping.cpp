#include "deepguide/core/yaml_mapping.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace deepguide {

std::string yaml_number(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string yaml_exact_number(double v) {
  if (std::isinf(v)) return v > 0 ? ".inf" : "-.inf";
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : std::string(".nan");
}

std::string line_of(const YAML::Node& node) {
  const YAML::Mark m = node.Mark();
  return m.line >= 0 ? "line " + std::to_string(m.line + 1) : std::string();
}

YAML::Node load_one_document(const std::string& text, const std::string& source) {
  const std::vector<YAML::Node> docs = YAML::LoadAll(text);
  for (std::size_t i = 1; i < docs.size(); ++i) {
    if (!docs[i].IsNull()) {
      throw input_error({source, line_of(docs[i]), ""}, "one YAML document",
                        "a second one (after ---), which would be ignored");
    }
  }
  return docs.empty() ? YAML::Node() : docs.front();
}

bool Range::holds(double v) const { return std::isfinite(v) && (lo_closed ? v >= lo : v > lo) && v <= hi; }

std::string Range::text() const {
  return what + std::string(lo_closed ? " >= " : " > ") + yaml_number(lo) + " and <= " + yaml_number(hi);
}

Mapping::Mapping(const YAML::Node& node, std::string source, std::string prefix,
                 std::initializer_list<const char*> known, const std::string& expected)
    : node_(node), source_(std::move(source)), prefix_(std::move(prefix)) {
  if (!node.IsMap()) {
    const std::string where = prefix_.empty() ? std::string() : prefix_.substr(0, prefix_.size() - 1);
    throw input_error({source_, line_of(node), where}, expected, node.IsNull() ? "nothing" : "a scalar or list");
  }
  for (const auto& kv : node) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
    const InputLocation at{source_, line_of(kv.first), printable(prefix_ + key)};
    if (std::find_if(known.begin(), known.end(), [&](const char* k) { return key == k; }) == known.end()) {
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      throw input_error(at, "one of the known keys (" + list + ")", "an unknown key");
    }
    for (const auto& [k, first] : entries_)
      if (k == key) throw input_error(at, "each key once", "a duplicate (first at " + line_of(first) + ")");
    entries_.emplace_back(key, kv.first);
    values_.push_back(kv.second);
  }
}

int Mapping::index(const char* key) const {
  for (std::size_t i = 0; i < entries_.size(); ++i)
    if (entries_[i].first == key) return static_cast<int>(i);
  return -1;
}

InputLocation Mapping::where(const char* key) const {
  const int i = index(key);
  return {source_, i >= 0 ? line_of(entries_[static_cast<std::size_t>(i)].second) : line_of(node_), prefix_ + key};
}

double Mapping::number(const char* key, const Range& r) const {
  const YAML::Node v = value(key);
  if (!v.IsDefined()) throw input_error(where(key), r.text(), "nothing");
  const std::string expected = r.what + std::string(" (a number)");
  if (!v.IsScalar()) throw input_error(where(key), expected, v.IsNull() ? "nothing" : "a list or mapping");
  double x = 0.0;
  try {
    x = v.as<double>();
  } catch (const YAML::Exception&) {
    throw input_error(where(key), expected, "'" + printable(v.Scalar()) + "'");
  }
  if (!r.holds(x)) throw input_error(where(key), r.text(), printable(v.Scalar()));
  return x;
}

std::string Mapping::text(const char* key, const char* expected) const {
  const YAML::Node v = value(key);
  if (!v.IsScalar() || v.Scalar().empty()) {
    throw input_error(where(key), expected,
                      v.IsNull()     ? "nothing"
                      : v.IsScalar() ? "an empty text"
                                     : "a list or mapping");
  }
  return v.Scalar();
}

std::string Mapping::path(const char* key, const std::string& base_dir) const {
  const std::string p = text(key, "a file path");
  const std::filesystem::path path(p);
  return path.is_absolute() || base_dir.empty() ? p : (std::filesystem::path(base_dir) / path).string();
}

}  // namespace deepguide
