#include "generators/random_embedding.hpp"

#include <fmt/format.h>

#include "core/orbit.hpp"

namespace dartcheck {

Value random_value(ValueType t, std::mt19937& rng) {
  std::uniform_int_distribution<int> small(0, 3);
  // Thirds: sums of them round, so a value that depends on the order of
  // a multiset shows up as two values in one orbit.
  auto coord = [&] { return static_cast<double>(small(rng)) / 3.0; };
  switch (t) {
    case ValueType::point2:
    case ValueType::vector2:
      return Value::coords(t, {coord(), coord(), 0});
    case ValueType::point3:
    case ValueType::vector3:
      return Value::coords(t, {coord(), coord(), coord()});
    case ValueType::color: {
      static constexpr std::array<std::array<double, 3>, 4> corners{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}}};
      return Value::coords(t, corners[static_cast<std::size_t>(small(rng))]);
    }
    case ValueType::real:
      return Value::real(coord());
    case ValueType::integer:
      return Value::integer(small(rng));
    case ValueType::boolean:
      return Value::boolean(small(rng) % 2 == 0);
    case ValueType::string:
      return Value::text(fmt::format("s{}", small(rng)));
  }
  return Value::real(0);
}

EmbeddedMap embed_randomly(Map map, const std::vector<EmbeddingSignature>& embeddings, std::mt19937& rng) {
  EmbeddedMap g(std::move(map));
  OrbitWalker walker(g.map);
  for (const auto& sig : embeddings) {
    const std::size_t k = g.add_embedding(sig);
    Embedding& e = g.embeddings[k];
    const auto gens = dims_generators(sig.orbit);
    for (Dart d = 0; d < g.map.size(); ++d) {
      if (e.value(d)) continue;
      const std::uint32_t idx = e.store(random_value(sig.type, rng));
      for (Dart x : walker.orbit(d, gens)) e.set_index(x, idx);
    }
  }
  return g;
}

}  // namespace dartcheck
