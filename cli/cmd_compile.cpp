// `dartcheck compile` (issue 41): the consistent rules of a catalog as C++
// functions on dartcheck's Map (compiler/rule_compiler.hpp). A rule the
// static checker does not call consistent is refused with its failing
// conditions: the generated code is only as consistent as the rule.

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

}  // namespace

int compile(const CompileOptions& o) {
  const std::string ns = o.ns.empty() ? default_namespace(o.catalog) : o.ns;
  if (const auto why = compiler::namespace_conflict(ns))
    throw InputError("<command line>", 0, 0,
                     fmt::format("--namespace: '{}' {}", printable(ns), why->starts_with("is not ") ? *why : "cannot be used: " + *why));
  if (!o.output.empty()) {
    if (!o.output.ends_with(".hpp") && !o.output.ends_with(".h") && !o.output.ends_with(".hh"))
      throw InputError("<command line>", 0, 0, fmt::format("-o: '{}': expected a header name ending in .hpp, .hh or .h", o.output));
    check_writable(o.output);
  }
  const Catalog catalog = analysis::read_rule_catalog(o.catalog, o.rule);
  std::vector<compiler::CompileUnit> units;
  std::size_t inconsistent = 0, unsupported = 0;
  for (const CatalogRule& r : catalog.rules) {
    if (!o.rule.empty() && r.rule.name() != o.rule) continue;
    // The failing conditions as `check` gives them (002, and 003 for terms).
    if (const std::string fails = fmt::format("{}", fmt::join(analysis::analyse_static(catalog, r, 0).failures, " ")); !fails.empty()) {
      ++inconsistent;
      if (!o.rule.empty()) {
        fmt::print(stderr, "error: compile: rule '{}' ({}) fails {}: only a rule the static checker calls consistent is compiled\n",
                   printable(r.rule.name()), printable(r.location.str()), fails);
        return violation;
      }
      fmt::print(stderr, "skipped {} ({}): fails {}\n", printable(r.rule.name()), printable(r.location.str()), fails);
      continue;
    }
    if (const auto why = compiler::not_compilable(r)) {
      ++unsupported;
      if (!o.rule.empty()) {
        fmt::print(stderr, "error: compile: rule '{}' ({}) is not compiled: {}\n", printable(r.rule.name()), printable(r.location.str()), *why);
        return bad_input;
      }
      fmt::print(stderr, "skipped {} ({}): {}\n", printable(r.rule.name()), printable(r.location.str()), *why);
      continue;
    }
    units.push_back({&r, r.location.str()});
  }
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
    fmt::print(stderr, "{} compiled; {} skipped as inconsistent, {} with what the compiler does not handle\n", counted(units.size(), "rule"),
             inconsistent, unsupported);
  return ok;
}

}  // namespace dartcheck::cli
