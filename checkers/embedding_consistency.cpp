#include "checkers/embedding_consistency.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/orbit.hpp"

namespace dartcheck {

std::string OrbitConflict::describe(const MapEmbedding& e) const {
  std::vector<std::string> vs;
  for (const auto& [d, v] : values) vs.push_back(fmt::format("\"{}\" at dart {}", v, d));
  std::string s = fmt::format("{}-orbit <{}> of dart {} ({} darts)", e.name, fmt::join(e.orbit, ","), dart, size);
  if (values.size() > 1) s += fmt::format(" has {} values: {}", values.size(), fmt::join(vs, ", "));
  if (!unlabeled.empty()) {
    std::vector<Dart> shown(unlabeled.begin(), unlabeled.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(unlabeled.size(), 8)));
    s += fmt::format("{} {} dart{} without a value ({}{})", values.size() > 1 ? "; and" : " has", unlabeled.size(), unlabeled.size() == 1 ? "" : "s",
                     fmt::join(shown, ", "), unlabeled.size() > shown.size() ? ", ..." : "");
  }
  return s;
}

EmbeddingConsistency check_embedding(const Map& map, const MapEmbedding& e) {
  EmbeddingConsistency out{e.name, 0, 0, {}};
  const auto gens = dims_generators(e.orbit);
  OrbitWalker walker(map);
  std::vector<bool> seen(map.size(), false);
  for (Dart d = 0; d < map.size(); ++d) {
    if (seen[d]) continue;
    const auto& orbit = walker.orbit(d, gens);
    ++out.orbits;
    OrbitConflict c{d, orbit.size(), {}, {}};
    auto note = [&](Dart x, const std::string& v) {
      if (std::none_of(c.values.begin(), c.values.end(), [&](const auto& p) { return p.second == v; })) c.values.emplace_back(x, v);
    };
    for (Dart x : orbit) {
      seen[x] = true;
      if (x < e.values.size() && e.values[x]) note(x, *e.values[x]);
      else c.unlabeled.push_back(x);
    }
    for (const auto& [x, v] : e.reassigned)
      if (std::find(orbit.begin(), orbit.end(), x) != orbit.end()) note(x, v);
    if (!c.values.empty()) ++out.labeled;
    if (c.values.size() > 1 || (!c.values.empty() && !c.unlabeled.empty())) out.conflicts.push_back(std::move(c));
  }
  return out;
}

}  // namespace dartcheck
