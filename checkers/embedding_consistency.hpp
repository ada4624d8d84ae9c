// The embedding consistency constraint (003 Def. 6) on a map: every dart of
// one pi-orbit carries the same value. Reported per orbit with its
// conflicting values, one dart for each.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rewriting/embedded_map.hpp"
#include "core/map_embedding.hpp"

namespace dartcheck {

struct OrbitConflict {
  Dart dart;                                         // the orbit's first dart
  std::size_t size = 0;                              // darts in the orbit
  std::vector<std::pair<Dart, std::string>> values;  // distinct values, a dart carrying each
  std::vector<Dart> unlabeled;                       // darts without a value in an orbit that has one
  std::string describe(const MapEmbedding& e) const { return describe(e.name, e.orbit); }
  std::string describe(const std::string& embedding, const std::vector<Dim>& orbit) const;
};

struct EmbeddingConsistency {
  std::string embedding;
  std::size_t orbits = 0, labeled = 0;  // orbits, and orbits with at least one value
  std::vector<OrbitConflict> conflicts;
  bool consistent() const { return conflicts.empty(); }
};

/// Orbits of <o> with two values, or with labeled and unlabeled darts; a
/// dart the input gave two values (MapEmbedding::reassigned) counts as
/// two values in its orbit.
EmbeddingConsistency check_embedding(const Map& map, const MapEmbedding& e);

/// The same on a typed embedding. With `total` (an embedded G-map, Def. 6:
/// pi is a total function), an orbit without any value is a conflict too.
EmbeddingConsistency check_embedding(const Map& map, const Embedding& e, bool total);

}  // namespace dartcheck
