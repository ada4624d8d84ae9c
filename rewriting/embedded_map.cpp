#include "rewriting/embedded_map.hpp"

#include <fmt/format.h>

#include "core/orbit.hpp"

namespace dartcheck {

std::size_t EmbeddedMap::add_embedding(EmbeddingSignature s) {
  Embedding e;
  e.signature = std::move(s);
  e.slot.assign(map.size(), Embedding::none);
  embeddings.push_back(std::move(e));
  return embeddings.size() - 1;
}

Embedding* EmbeddedMap::find(const std::string& name) {
  for (auto& e : embeddings)
    if (e.signature.name == name) return &e;
  return nullptr;
}

const Embedding* EmbeddedMap::find(const std::string& name) const { return const_cast<EmbeddedMap*>(this)->find(name); }

std::vector<EmbeddingSignature> EmbeddedMap::signatures() const {
  std::vector<EmbeddingSignature> r;
  for (const auto& e : embeddings) r.push_back(e.signature);
  return r;
}

void EmbeddedMap::label_orbit(std::size_t k, Dart d, Value v) {
  Embedding& e = embeddings[k];
  const std::uint32_t idx = e.store(std::move(v));
  OrbitWalker walker(map);
  for (Dart x : walker.orbit(d, dims_generators(e.signature.orbit))) e.set_index(x, idx);
}

void Embedding::grow(Dart d) { slot.resize(std::size_t{d} + 1, none); }

void EmbeddedMap::follow(const std::vector<std::pair<Dart, Dart>>& moved) {
  for (Embedding& e : embeddings) {
    std::size_t need = map.size();
    for (const auto& [from, to] : moved) need = std::max<std::size_t>(need, std::max(from, to) + 1);
    if (e.slot.size() < need) e.slot.resize(need, Embedding::none);
    for (const auto& [from, to] : moved) {
      e.slot[to] = e.slot[from];
      e.slot[from] = Embedding::none;
    }
    e.slot.resize(map.size(), Embedding::none);
  }
}

std::optional<Embedding> typed_embedding(const MapEmbedding& m, std::string* why) {
  const auto t = type_by_name(m.type);
  Embedding e;
  e.signature = {m.name, t.value_or(ValueType::string), m.orbit};
  e.slot.assign(m.values.size(), Embedding::none);
  for (std::size_t d = 0; d < m.values.size(); ++d) {
    if (!m.values[d]) continue;
    std::string reason;
    auto v = parse_value(e.signature.type, *m.values[d], &reason);
    if (!v) {
      if (why) *why = fmt::format("{} value of dart {}: {}", m.name, d, reason);
      return std::nullopt;
    }
    e.set(static_cast<Dart>(d), std::move(*v));
  }
  return e;
}

}  // namespace dartcheck
