// κ read from a YAML file (docs/inference.md):
//
//   identity: true                 # darts with the same id (Jerboa snapshots)
//   pairs: [[0, 0], [5, 17]]       # before dart, after dart
//   orbits:                        # orbits walked in parallel
//     - {orbit: "<1,2>", before: 0, after: 12}
//
// Every error is an InputError with file:line:column.
#pragma once

#include <string>

#include "inference/kappa_graph.hpp"

namespace dartcheck::inference {

KappaSpec read_kappa_file(const std::string& file, const Model& model);

/// The text of a κ file of explicit pairs (before dart, after dart), which
/// read_kappa_file reads back; `comment` goes first, one "# " line each.
std::string kappa_file_text(const std::vector<std::pair<Dart, Dart>>& pairs, const std::vector<std::string>& comment);

}  // namespace dartcheck::inference
