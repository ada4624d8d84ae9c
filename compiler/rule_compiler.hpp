// Compiled operations (issue 41): a rule or rule scheme becomes C++ that
// applies it on dartcheck's Map through the runtime of
// rewriting/compiled_runtime.hpp, with everything that depends on the rule
// alone resolved when the code is generated: W's generators spelt out as
// links, the match's propagation as one case per node of L with its arcs'
// dimensions and shift tables, the dangling and representability checks
// per node and arc, the rewrite as one loop per deleted and added arc, the
// placement of R's nodes. What depends on the host (P_v, its shifts, the
// darts) is computed at run time exactly as the interpreter computes it,
// so a compiled rule gives the interpreter's H, dart for dart.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "rewriting/operation.hpp"

namespace dartcheck::compiler {

/// One operation to compile: the operation, its name in the catalog and
/// where it was read (for the generated comments).
struct CompileUnit {
  const Operation* operation = nullptr;
  std::string origin;  // "catalogs/seed-operations.yaml:384:5"
  /// The embedding conditions the static checker finds failing ("A(pos)
  /// label(norm)"), for a rule compiled although they fail; empty for a
  /// consistent rule.
  std::string embedding_failures = {};
};

/// Why an operation cannot be compiled (yet), or nullopt when it can.
/// A rule with terms compiles when every function its terms call is one
/// of the built-in algebra's (compiler/term_compiler.hpp).
std::optional<std::string> not_compilable(const Operation& op);

/// A C++ identifier for a rule name: letters, digits and '_' kept, every
/// other byte '_' (a run of '_' made one where two would reserve it),
/// `rule_` before a name that is no usable identifier (a keyword, a macro,
/// reserved, or one of `used`: compiler/cpp_identifiers.hpp), and numbered
/// (_2, _3...) until neither it nor its `_everywhere` is in `declared`.
/// `why`, when given, receives the reason for a prefix or a number ("" if none).
std::string function_name(std::string_view rule_name, const std::set<std::string, std::less<>>& declared,
                          const std::set<std::string, std::less<>>& used, std::string* why = nullptr);

/// Why `ns` cannot be the generated header's namespace ("is not" identifiers
/// joined by ::, a segment that is no usable identifier, or std or
/// dartcheck first), or nullopt.
std::optional<std::string> namespace_conflict(std::string_view ns);

/// The generated function for one compilable operation, named `function`:
/// a comment with the rule's nodes and arcs, then an inline function
///   dartcheck::Refusal function(dartcheck::Map&, std::span<const dartcheck::Dart>, dartcheck::compiled::Workspace&)
/// and, when has_everywhere(op), function_everywhere(Map&, Workspace&).
std::string compile_operation(const CompileUnit& unit, const std::string& function);

/// Whether compile_operation also writes NAME_everywhere, the scheme at
/// every connected component at once (rewriting/compiled_runtime.hpp,
/// whole_map_patterns): one hook, L the hook with a loop per letter of W,
/// and W's single letters name every dimension.
bool has_everywhere(const Operation& op);

/// A whole header: the includes, the functions of `units` (each compilable)
/// in namespace `ns`, and a table `operations` of {rule name, function} in
/// catalog order. `source` names the catalog in the header's first line.
/// `renamed` says, per rule whose function is not its name's plain
/// spelling, which name it got and why.
struct CompiledHeader {
  std::string code;
  std::vector<std::string> renamed;
};
CompiledHeader compile_header(const std::vector<CompileUnit>& units, std::string_view ns, std::string_view source);

}  // namespace dartcheck::compiler
