// The text of `dartcheck apply`'s run (cli/apply_run.cpp applies, checks
// and writes; these render what it found): the refusal, the application
// and the values it wrote, each embedding's consistency, the dart
// correspondence.
#pragma once

#include <cstddef>
#include <string>

#include "checkers/embedding_consistency.hpp"
#include "rewriting/application.hpp"

namespace dartcheck::reports {

/// "not applied (REFUSAL): WHY".
std::string not_applied_text(Refusal refusal, const std::string& why);

/// An embedded rule's application: darts matched and added, the size of
/// H, then each value written and each conflict (003 Def. 13).
std::string embedded_application_text(const EmbeddedApplication& a, Instantiation instantiation, std::size_t h_size);

/// A topological application: the pattern's size (schemes), H's size and
/// the comatch per node of R.
std::string application_text(const Rule& rule, const Application& a, std::size_t h_size);

/// One embedding of H: its orbits and whether it is consistent, then up
/// to `limit` of its conflicts (0: all). A `foreign` embedding (the file's,
/// not the rule's modeler's) is said not to count.
std::string embedding_check_text(const Embedding& e, const EmbeddingConsistency& c, bool foreign, std::size_t limit);

/// How many preserved darts changed id ("" when none did), with the hint
/// of --kappa-out unless `kappa_out` is set.
std::string renumbered_text(std::size_t moved, std::size_t preserved, bool kappa_out);

}  // namespace dartcheck::reports
