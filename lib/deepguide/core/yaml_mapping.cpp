#include "deepguide/core/yaml_mapping.hpp"

#include <yaml-cpp/eventhandler.h>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "deepguide/core/format.hpp"

namespace deepguide {

std::string yaml_number(double v) { return general(v, 10); }

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

namespace {

// Whether a document holds anything, and where it starts.
class DocumentProbe : public YAML::EventHandler {
 public:
  bool content = false;
  YAML::Mark at;
  void OnDocumentStart(const YAML::Mark& mark) override { at = mark; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { at = content ? at : mark; }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { hit(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string&) override { hit(mark); }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    hit(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    hit(mark);
  }
  void OnMapEnd() override {}

 private:
  void hit(const YAML::Mark& mark) {
    if (!content) at = mark;
    content = true;
  }
};

}  // namespace

YAML::Node load_one_document(const std::string& text, const std::string& source) {
  // Not YAML::LoadAll: yaml-cpp 0.7 loops on a stray "," outside a flow
  // collection, adding empty documents until memory runs out (yaml-cpp
  // issue 1040, fixed upstream by stopping at an empty one; found by
  // fuzz/fuzz_suite_yaml). The documents after the first are walked as
  // events, and the walk ends at an empty document that does not move on.
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentProbe first;
  if (!parser.HandleNextDocument(first)) return YAML::Node();
  int last_empty_at = -1;
  for (int k = 1; k < 100000; ++k) {
    DocumentProbe next;
    if (!parser.HandleNextDocument(next)) break;
    if (next.content) {
      throw input_error({source, "line " + std::to_string(next.at.line + 1), ""}, "one YAML document",
                        "a second one (after ---), which would be ignored");
    }
    if (next.at.pos == last_empty_at) {
      // Stuck: the parser no longer consumes the text (a stray ","), and
      // whatever follows would be dropped without a word.
      throw input_error({source, "line " + std::to_string(next.at.line + 1), ""}, "YAML the parser can read to the end",
                        "text it cannot read past (a stray ',' outside [ ] or { }?)");
    }
    last_empty_at = next.at.pos;
  }
  return YAML::Load(text);
}

bool Range::holds(double v) const { return std::isfinite(v) && (lo_closed ? v >= lo : v > lo) && v <= hi; }

std::string Range::text() const {
  return what + std::string(lo_closed ? " >= " : " > ") + yaml_number(lo) + " and <= " + yaml_number(hi);
}

Mapping::Mapping(const YAML::Node& node, std::string source, std::string prefix, const std::vector<std::string>& known,
                 const std::string& expected)
    : node_(node), source_(std::move(source)), prefix_(std::move(prefix)) {
  if (!node.IsMap()) {
    const std::string where = prefix_.empty() ? std::string() : prefix_.substr(0, prefix_.size() - 1);
    throw input_error({source_, line_of(node), where}, expected, node.IsNull() ? "nothing" : "a scalar or list");
  }
  for (const auto& kv : node) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string("?");
    const InputLocation at{source_, line_of(kv.first), printable(prefix_ + key)};
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
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

double Mapping::scalar_number(const char* key, const char* what) const {
  const YAML::Node v = value(key);
  const std::string expected = what + std::string(" (a number)");
  if (!v.IsScalar()) throw input_error(where(key), expected, v.IsNull() ? "nothing" : "a list or mapping");
  try {
    return v.as<double>();
  } catch (const YAML::Exception&) {
    throw input_error(where(key), expected, "'" + printable(v.Scalar()) + "'");
  }
}

double Mapping::number(const char* key, const Range& r) const {
  if (!value(key).IsDefined()) throw input_error(where(key), r.text(), "nothing");
  const double x = scalar_number(key, r.what);
  if (!r.holds(x)) throw input_error(where(key), r.text(), printable(value(key).Scalar()));
  return x;
}

double Mapping::finite_number(const char* key, const char* what) const {
  const double x = scalar_number(key, what);
  if (!std::isfinite(x)) {
    throw input_error(where(key), what + std::string(" (a finite number)"), printable(value(key).Scalar()));
  }
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
