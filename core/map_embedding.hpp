// Embedding values carried by a map (003 Sec. 5.1): one embedding
// pi : <o> -> tau with a value per dart, kept as opaque text (a Jerboa
// file's "0.0 1.0 0.5"). The embedding consistency constraint (Def. 6) is
// checked by checkers/embedding_consistency.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/map.hpp"

namespace dartcheck {

struct MapEmbedding {
  std::string name, type;
  std::vector<Dim> orbit;
  std::vector<std::optional<std::string>> values;  // per dart; nullopt: unlabeled
  /// Darts the file gave a second, different value (dart, that value).
  std::vector<std::pair<Dart, std::string>> reassigned;
};

}  // namespace dartcheck
