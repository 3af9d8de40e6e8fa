#pragma once
// 64-bit FNV-1a, fed piece by piece: a fingerprint of what a result depends
// on (an evaluation suite's files, the obstacles a prepared graph was built
// over), not a defence against anyone who wants a collision.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace deepguide {

struct Fnv1a {
  std::uint64_t h = 14695981039346656037ull;

  void raw(const void* data, std::size_t n) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
      h ^= bytes[i];
      h *= 1099511628211ull;
    }
  }
  /// Each piece is preceded by its length, so that no two different
  /// sequences of pieces hash the same bytes.
  void piece(const std::string& s) {
    const std::string length = std::to_string(s.size()) + ":";
    raw(length.data(), length.size());
    raw(s.data(), s.size());
  }
  /// A number by its bytes (this machine's order): equal only when bit-equal.
  void number(double x) { raw(&x, sizeof x); }
  void number(std::uint64_t n) { raw(&n, sizeof n); }

  /// "fnv1a64:" and 16 hex digits.
  std::string text() const {
    char buf[32];
    std::snprintf(buf, sizeof buf, "fnv1a64:%016llx", static_cast<unsigned long long>(h));
    return buf;
  }
};

}  // namespace deepguide
