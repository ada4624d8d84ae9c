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
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "core/input_error.hpp"

namespace dartcheck {

struct BaselineEntry {
  std::string rule;
  /// The failing conditions ({} = consistent); unset for "not checked".
  std::optional<std::vector<std::string>> failures;
  SourceLocation location;
};

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
