// Differential testing of an embedded rule or rule scheme (003): random
// valid maps with random values per orbit (generators/random_embedding),
// application by the Applier (rewriting/application.hpp), then the result checked for
// topological validity and embedding consistency (every dart labeled, one
// value per orbit, Def. 6). Set against the static verdict (topological
// conditions plus Theorem 2 / Theorem 4): a rule that passes them and
// yields an orbit with two values or an unlabeled dart is a soundness bug.
//
// L's terms restrict the match (the labeled match of the evaluated rule):
// before each attempt, the host orbits of closed L terms (concrete values,
// Fig. 13a) and, on every other attempt, of the other L terms are set to
// the terms' values, so rules that match only given values still apply.
#pragma once

#include <fmt/format.h>

#include "analysis/fuzz.hpp"
#include "core/shell_quote.hpp"

namespace dartcheck::analysis {

FuzzReport fuzz_embedded_rule(const Operation& entry, const std::vector<Map>& seeds, const FuzzOptions& options);

/// The command that finds an embedded counterexample again. Map files do
/// not carry values, so a host file would replay with other values: the
/// fuzz itself is the replay (one stream per rule and seed, stopped at
/// the counterexample's application).
inline std::string embedded_replay(const std::string& catalog, const FuzzReport& r, std::uint64_t seed) {
  return fmt::format("dartcheck fuzz {} --rule {} --seed {} --runs {}", shell_quote(catalog), shell_quote(r.rule), seed, r.applications);
}

}  // namespace dartcheck::analysis
