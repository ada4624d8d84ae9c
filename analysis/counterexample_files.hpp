// The files a counterexample leaves behind, shared by `dartcheck fuzz` and
// `dartcheck prove`: DIR/STEM.host.yaml (the host map), STEM.result.yaml
// (H, when it has a dense form) and STEM.counterexample.yaml (rule, match,
// broken constraints, violations and the `dartcheck apply` command that
// replays it).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "analysis/fuzz.hpp"
#include "rewriting/embedded_map.hpp"

namespace dartcheck::analysis {

/// A rule's name as a file name: '/' (variants) becomes '.', letters,
/// digits and - _ + = , @ stay, every other byte is %XX (so '.', ' ' and
/// '%' are escaped and no two names share a stem).
std::string file_stem(const std::string& name);

/// What the replay command runs: the application (`dartcheck apply`), or
/// the event logs set against the static events (`dartcheck events
/// --dynamic`).
enum class ReplayCommand { apply, events };

/// Writes the three files; `fields` are extra (key, value) lines of the
/// counterexample file (seed, class, constraint...). Returns the replay
/// command.
std::string write_counterexample(const std::string& dir, const std::string& stem, const std::string& catalog, const std::string& rule,
                                 const std::vector<std::pair<std::string, std::string>>& fields, const std::vector<std::string>& static_failures,
                                 const Counterexample& cx, ReplayCommand replay = ReplayCommand::apply);

/// An embedding counterexample of the solver (proofs/embedding_prover):
/// DIR/STEM.host.jba, the host with its values, read back by `dartcheck
/// apply --map` and `validate-map`. Returns the commands that replay it
/// (apply writes STEM.result.jba, exit 1, which validate-map rejects at the darts
/// whose values differ), shell-quoted; empty when the host has no .jba
/// form (an O-map, a partial link).
std::string write_embedding_counterexample(const std::string& dir, const std::string& stem, const std::string& catalog, const std::string& rule,
                                           const EmbeddedMap& host, const std::vector<Dart>& hooks);

/// A witness of a potential event (analysis/potential_events): DIR/STEM.host.yaml
/// and the command that shows the event on it (`dartcheck events --map
/// ... --dynamic`), shell-quoted.
std::string write_event_witness(const std::string& dir, const std::string& stem, const std::string& catalog, const std::string& rule, const Map& host,
                                const std::vector<Dart>& hooks);

}  // namespace dartcheck::analysis
