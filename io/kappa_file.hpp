// κ read from a YAML file (docs/inference.md):
//
//   identity: true                 # darts with the same id (Jerboa snapshots)
//   pairs: [[0, 0], [5, 17]]       # before dart, after dart
//   orbits:                        # orbits walked in parallel
//     - {orbit: "<1,2>", before: 0, after: 12}
//
// Every error is an InputError with file:line:column.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.hpp"
#include "core/map.hpp"

namespace dartcheck {

/// How the user states κ (000 Sec. 9: explicit pairs, Jerboa's snapshot
/// convention of equal dart ids, or orbits associated and walked in
/// parallel).
struct KappaSpec {
  bool identity = false;  // every dart id present in both maps
  std::vector<std::pair<Dart, Dart>> pairs;
  struct OrbitPair {
    std::vector<Dim> orbit;
    Dart before = 0, after = 0;
  };
  std::vector<OrbitPair> orbits;
  /// Where each pair and orbit association was read (a κ file), if known:
  /// errors then name file:line:column.
  std::vector<SourceLocation> pair_locations, orbit_locations;
};

KappaSpec read_kappa_file(const std::string& file, const Model& model);

/// The darts an application preserved, as `dartcheck apply -o X.yaml`
/// records them in the map file it writes when the application deleted
/// darts (a key `preserved: [[before, after], ...]`): then equal ids do not
/// mean the same dart. nullopt when the file has no such key.
std::optional<KappaSpec> read_recorded_kappa(const std::string& map_file);

/// The `preserved:` lines apply appends to a written map (comment first).
std::string preserved_text(const std::vector<std::pair<Dart, Dart>>& pairs);

/// The text of a κ file of explicit pairs (before dart, after dart), which
/// read_kappa_file reads back; `comment` goes first, one "# " line each.
std::string kappa_file_text(const std::vector<std::pair<Dart, Dart>>& pairs, const std::vector<std::string>& comment);

}  // namespace dartcheck
