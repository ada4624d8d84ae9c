// `dartcheck compile` (issue 41): the consistent rules of a catalog as C++
// functions on dartcheck's Map (compiler/rule_compiler.hpp). A rule the
// static checker does not call consistent is refused with its failing
// conditions: the generated code is only as consistent as the rule. With
// --with-embedding-failures a rule whose topology holds is compiled even
// when an embedding condition fails (Jerboa modelers: an embedding no rule
// computes, or a term the syntactic conditions cannot prove copy-invariant);
// its code gives the interpreter's values and says which conditions fail.

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/map_sources.hpp"
#include "analysis/rule_result.hpp"
#include "cli/commands.hpp"
#include "core/terminal.hpp"
#include "cli/options.hpp"
#include "compiler/cpp_text.hpp"
#include "compiler/rule_compiler.hpp"
#include "core/input_error.hpp"
#include "core/output_file.hpp"
#include "core/wording.hpp"

namespace dartcheck::cli {
namespace {

// The default namespace: compiled_ and the catalog's file stem.
std::string default_namespace(const std::string& catalog) {
  return "compiled_" + compiler::function_name(std::filesystem::path(catalog).stem().string(), {}, {});
}

// A line about a rule at its place in the catalog, in gcc's style.
std::string at(const CatalogRule& r, std::string_view severity, const std::string& message) {
  return painted_diagnostic(diagnostic(severity, printable(r.location.file), r.location.line, r.location.column, message));
}

}  // namespace

int compile(const CompileOptions& o) {
  const std::string ns = o.ns.empty() ? default_namespace(o.catalog) : o.ns;
  if (const auto why = compiler::namespace_conflict(ns))
    throw UsageError(fmt::format("--namespace: '{}' {}", printable(ns), why->starts_with("is not ") ? *why : "cannot be used: " + *why));
  if (!o.output.empty()) {
    if (!o.output.ends_with(".hpp") && !o.output.ends_with(".h") && !o.output.ends_with(".hh"))
      throw UsageError(fmt::format("-o: '{}': expected a header name ending in .hpp, .hh or .h", o.output));
    check_writable(o.output);
  }
  const Catalog catalog = analysis::read_rule_catalog(o.catalog, "");
  for (const std::string& name : o.rules) analysis::require_rule(catalog, o.catalog, name);
  const auto named = [&](const std::string& name) { return std::find(o.rules.begin(), o.rules.end(), name) != o.rules.end(); };
  std::vector<compiler::CompileUnit> units;
  std::size_t inconsistent = 0, unsupported = 0, with_failures = 0;
  int refused = ok;  // the first refusal of a rule --rule names
  for (const CatalogRule& r : catalog.rules) {
    if (!o.rules.empty() && !named(r.rule.name())) continue;
    // The failing conditions as `check` gives them (002, and 003 for terms).
    const analysis::RuleResult result = analysis::analyse_static(catalog, r, 0);
    const std::string fails = fmt::format("{}", fmt::join(result.failures, " "));
    const bool embedding_only = !result.consistent() && !result.topological_failure();
    if (!result.consistent() && !(o.embedding_failures && embedding_only)) {
      ++inconsistent;
      if (!o.rules.empty()) {
        fmt::print(stderr, "{}\n",
                   at(r, "error", fmt::format("rule '{}' fails {}: only a rule the static checker calls consistent is compiled{}", printable(r.rule.name()),
                                              fails, embedding_only ? " (its topology holds: --with-embedding-failures compiles it with the interpreter's values)" : "")));
        if (refused == ok) refused = violation;
        continue;
      }
      if (!terminal().quiet) fmt::print(stderr, "{}\n", at(r, "note", fmt::format("rule '{}' skipped: fails {}", printable(r.rule.name()), fails)));
      continue;
    }
    if (const auto why = compiler::not_compilable(r)) {
      ++unsupported;
      if (!o.rules.empty()) {
        fmt::print(stderr, "{}\n", at(r, "error", fmt::format("rule '{}' is not compiled: {}", printable(r.rule.name()), *why)));
        if (refused == ok) refused = bad_input;
        continue;
      }
      if (!terminal().quiet) fmt::print(stderr, "{}\n", at(r, "note", fmt::format("rule '{}' skipped: {}", printable(r.rule.name()), *why)));
      continue;
    }
    if (!result.consistent()) ++with_failures;
    units.push_back({&r, r.location.str(), result.consistent() ? std::string() : fails});
  }
  if (refused != ok) return refused;
  const compiler::CompiledHeader compiled = compiler::compile_header(units, ns, catalog.file);
  for (const std::string& line : compiled.renamed) fmt::print(stderr, "note: {}\n", printable(line));
  const std::string& header = compiled.code;
  if (o.output.empty()) {
    fmt::print("{}", header);
  } else {
    write_file(o.output, header);
    if (!terminal().quiet) fmt::print("written: {} ({} in namespace {})\n", printable(o.output), counted(units.size(), "compiled rule"), ns);
  }
  if (!terminal().quiet)
    fmt::print(stderr, "{} compiled{}; {} skipped as inconsistent, {} with what the compiler does not handle\n", counted(units.size(), "rule"),
               with_failures ? fmt::format(" ({} with failing embedding conditions)", with_failures) : "", inconsistent, unsupported);
  return ok;
}

}  // namespace dartcheck::cli
