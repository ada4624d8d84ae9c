// Stages that run over all the rules of a run at once (report --fuzz and
// --prove): one fuzz budget shared by the rules, and the solver until a
// signal; each outcome added to its rule's result.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/rule_result.hpp"

namespace dartcheck::analysis {

/// Fuzzes the rules of `rows` (the catalog's rules that `rule` selects,
/// in catalog order) within `seconds` shared, from `seed`, on the
/// catalog's maps of their models, and adds each outcome with its files
/// under `out_dir` (named after the rule plus ".fuzz"). A signal stops it:
/// the rules after it have no fuzz outcome.
void fuzz_all(std::vector<RuleResult>& rows, const Catalog& catalog, const std::string& rule, double seconds, std::uint64_t seed,
              const std::string& out_dir, const std::string& catalog_file, bool progress);

/// Proves every rule of `rows` on hosts of up to `max_darts` darts
/// (`scheme_darts` for schemes) until a signal, which also stops the
/// running solver query, and writes the counterexamples under `out_dir`
/// (rule plus ".prove"); progress on stderr (analysis/stage_progress.hpp),
/// as a status line when `terminal`.
void prove_all(std::vector<RuleResult>& rows, std::size_t max_darts, std::size_t scheme_darts, const std::string& out_dir,
               const std::string& catalog_file, bool terminal);

}  // namespace dartcheck::analysis
