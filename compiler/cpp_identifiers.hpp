// Names the compiler declares in generated C++ (issue 62): a rule named
// `int`, `NULL`, `Map` or `q_everywhere` must not give a header that fails
// to compile or declares one function twice. A name is usable when it is
// no keyword, no reserved identifier, no macro of the standard library or
// of POSIX headers, and no name the generated code itself uses.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace dartcheck::compiler {

/// Why generated code cannot declare `name` in its namespace, or nullopt:
/// "a C++ keyword", "reserved (contains __)", "reserved (_ and a capital)",
/// "a macro of the C and POSIX headers", "spelt like a macro (capitals
/// first)", or "a name the generated header uses" (one of `used`).
std::optional<std::string> identifier_conflict(std::string_view name, const std::set<std::string, std::less<>>& used);

/// The identifiers of C++ text outside its comments and string and
/// character literals: the names generated code refers to.
std::set<std::string, std::less<>> code_identifiers(std::string_view code);

}  // namespace dartcheck::compiler
