// Text of generated C++ shared by the compiler's emitters: file-derived
// strings as literals or comments, and a pattern position's shift.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "core/conjugate_words.hpp"

namespace dartcheck::compiler {

/// A C++ string literal holding exactly the bytes of s (names come from
/// files: quotes, backslashes and control bytes are escaped, other bytes
/// as octal, so a name can neither end the literal nor a comment line).
inline std::string cpp_literal(std::string_view s) {
  std::string out = "\"";
  for (const unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += fmt::format("\\{:03o}", c);
    }
  }
  return out + "\"";
}

/// Text from a file inside a // comment: as it is when it is printable
/// ASCII and cannot continue the comment onto the next line (a trailing
/// backslash), otherwise as a literal.
inline std::string comment_text(std::string_view s) {
  const bool plain = std::all_of(s.begin(), s.end(), [](char c) { return c >= 0x20 && c < 0x7f; }) && !s.ends_with('\\');
  return plain ? std::string(s) : cpp_literal(s);
}

/// Whether `ns` names a C++ namespace: identifiers ([A-Za-z_][A-Za-z0-9_]*)
/// joined by "::".
inline bool namespace_name(std::string_view ns) {
  const auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  bool start = true;  // at the first letter of an identifier
  for (std::size_t k = 0; k < ns.size(); ++k) {
    if (start) {
      if (!alpha(ns[k])) return false;
      start = false;
    } else if (ns.substr(k, 2) == "::") {
      start = true;
      ++k;
    } else if (!alpha(ns[k]) && !digit(ns[k])) {
      return false;
    }
  }
  return !start;
}

/// The index of w among W's generators, -1 for ε.
inline int generator_index(const std::vector<ConjWord>& gens, const ConjWord& w) {
  return w.empty() ? -1 : static_cast<int>(std::find(gens.begin(), gens.end(), w) - gens.begin());
}

/// The position of p·w as an expression in `p` (ε stays at p).
inline std::string shifted(int generator, std::string_view p) {
  return generator < 0 ? std::string(p) : fmt::format("ws.shift[{}][{}]", generator, p);
}

}  // namespace dartcheck::compiler
