// Recorded verdicts kept beside a catalog that cannot hold them (a Jerboa
// .jme modeler): a YAML side file that `dartcheck check --baseline` reads
// and `--write-baseline` writes, so CI on a Jerboa project passes while
// the verdicts stay what they were.
//
//   # dartcheck baseline of MyModeler.jme
//   verdicts:
//     SewA2: consistent
//     CutEdge: ["I(1)", "C(0,2)"]
//     Weird: not checked
//   solver:                      (check --solver --write-baseline)
//     SewA2: {pos: breaks, color: false alarm}
//
// A solver class per embedding (solver_class_names): `holds` (the static
// conditions hold, no host breaks it), `breaks` (a host breaks it in
// dartcheck's algebra), `false alarm` (a condition fails, no host up to K
// breaks it in either reading), `other algebra` (only an interpretation
// other than dartcheck's breaks it), `unknown`.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.hpp"

namespace dartcheck {

struct BaselineEntry {
  std::string rule;
  /// The failing conditions ({} = consistent); unset for "not checked".
  std::optional<std::vector<std::string>> failures;
  SourceLocation location;
  /// The solver's class per embedding, (embedding, class); unset when the
  /// baseline has no solver entry for the rule.
  std::optional<std::vector<std::pair<std::string, std::string>>> solver;
  SourceLocation solver_location;
};

/// The classes a baseline's `solver` section may hold.
const std::vector<std::string>& solver_class_names();

struct Baseline {
  std::string file;
  std::vector<BaselineEntry> entries;
  const BaselineEntry* find(const std::string& rule) const;
};

/// Reads a baseline; InputError with file:line:column on anything else
/// than the form above (a rule twice, a verdict that is not "consistent",
/// "not checked" or a list of condition names).
Baseline read_baseline(const std::string& file);

/// Writes a baseline of `entries` (in order) for `source`.
void write_baseline(std::ostream& out, const std::string& source, const std::vector<BaselineEntry>& entries);

}  // namespace dartcheck
