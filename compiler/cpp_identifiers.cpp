#include "compiler/cpp_identifiers.hpp"

#include <array>

namespace dartcheck::compiler {
namespace {

bool alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool digit(char c) { return c >= '0' && c <= '9'; }
bool upper(char c) { return c >= 'A' && c <= 'Z'; }

// C++20's keywords and alternative tokens, and the identifiers with a
// special meaning where a declaration may stand (final, override, import,
// module).
constexpr std::array keywords{
    "alignas",  "alignof",  "and",       "and_eq",       "asm",       "auto",       "bitand",        "bitor",       "bool",
    "break",    "case",     "catch",     "char",         "char8_t",   "char16_t",   "char32_t",      "class",       "compl",
    "concept",  "const",    "consteval", "constexpr",    "constinit", "const_cast", "continue",      "co_await",    "co_return",
    "co_yield", "decltype", "default",   "delete",       "do",        "double",     "dynamic_cast",  "else",        "enum",
    "explicit", "export",   "extern",    "false",        "float",     "for",        "friend",        "goto",        "if",
    "inline",   "int",      "long",      "mutable",      "namespace", "new",        "noexcept",      "not",         "not_eq",
    "nullptr",  "operator", "or",        "or_eq",        "private",   "protected",  "public",        "register",    "reinterpret_cast",
    "requires", "return",   "short",     "signed",       "sizeof",    "static",     "static_assert", "static_cast", "struct",
    "switch",   "template", "this",      "thread_local", "throw",     "true",       "try",           "typedef",     "typeid",
    "typename", "union",    "unsigned",  "using",        "virtual",   "void",       "volatile",      "wchar_t",     "while",
    "xor",      "xor_eq",   "final",     "override",     "import",    "module"};

// Macros with a lower-case name that the C, C++ and POSIX headers of a
// Debian 12 system define (g++ and clang++ -dM -E on the generated
// header's includes, in GNU and ISO modes), and the common ones a caller's
// other headers bring (assert, setjmp, major, minor, makedev). Names in
// capitals are caught by their spelling instead.
constexpr std::array macros{"alloca",
                            "assert",
                            "errno",
                            "offsetof",
                            "stdin",
                            "stdout",
                            "stderr",
                            "linux",
                            "unix",
                            "i386",
                            "math_errhandling",
                            "issubnormal",
                            "sched_priority",
                            "va_arg",
                            "va_copy",
                            "va_end",
                            "va_start",
                            "setjmp",
                            "major",
                            "minor",
                            "makedev",
                            "be16toh",
                            "be32toh",
                            "be64toh",
                            "htobe16",
                            "htobe32",
                            "htobe64",
                            "htole16",
                            "htole32",
                            "htole64",
                            "le16toh",
                            "le32toh",
                            "le64toh",
                            "pthread_cleanup_pop",
                            "pthread_cleanup_push",
                            "pthread_cleanup_pop_restore_np",
                            "pthread_cleanup_push_defer_np"};

template <std::size_t N>
bool listed(const std::array<const char*, N>& list, std::string_view name) {
  for (const char* k : list)
    if (name == k) return true;
  return false;
}

}  // namespace

std::optional<std::string> identifier_conflict(std::string_view name, const std::set<std::string, std::less<>>& used) {
  if (listed(keywords, name)) return "a C++ keyword";
  if (name.find("__") != std::string_view::npos) return "reserved (contains __)";
  if (name.size() >= 2 && name[0] == '_' && upper(name[1])) return "reserved (_ and a capital)";
  if (listed(macros, name)) return "a macro of the C and POSIX headers";
  // NULL, EOF, INT_MAX, M_PIf, SYS_read, L_tmpnam: capitals, then a capital, a digit or _.
  if (name.size() >= 2 && upper(name[0]) && (upper(name[1]) || digit(name[1]) || name[1] == '_')) return "spelt like a macro (capitals first)";
  if (used.contains(name)) return "a name the generated header uses";
  return std::nullopt;
}

std::set<std::string, std::less<>> code_identifiers(std::string_view code) {
  std::set<std::string, std::less<>> out;
  const std::size_t n = code.size();
  // Skips a literal that starts at `k` with `quote`, escapes included.
  const auto skip_literal = [&](std::size_t k, char quote) {
    for (++k; k < n && code[k] != quote && code[k] != '\n'; ++k)
      if (code[k] == '\\') ++k;
    return k + 1;
  };
  for (std::size_t k = 0; k < n;) {
    const char c = code[k];
    if (code.substr(k, 2) == "//") {
      k = code.find('\n', k);
      if (k == std::string_view::npos) break;
    } else if (code.substr(k, 2) == "/*") {
      k = code.find("*/", k + 2);
      if (k == std::string_view::npos) break;
      k += 2;
    } else if (c == '"' || c == '\'') {
      k = skip_literal(k, c);
    } else if (digit(c)) {  // a number with its suffix and separators (1'000, 2.5e-3f, 0x1fu)
      for (++k; k < n && (alpha(code[k]) || digit(code[k]) || code[k] == '.' || code[k] == '\'' ||
                          ((code[k] == '+' || code[k] == '-') && (code[k - 1] == 'e' || code[k - 1] == 'E')));
           ++k) {
      }
    } else if (alpha(c)) {
      const std::size_t start = k;
      while (k < n && (alpha(code[k]) || digit(code[k]))) ++k;
      out.emplace(code.substr(start, k - start));
    } else {
      ++k;
    }
  }
  return out;
}

}  // namespace dartcheck::compiler
