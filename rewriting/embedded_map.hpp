// Embedded G-maps (003 Sec. 5.1, Def. 6): a map with several embedding
// operations pi : <o> -> tau. Like CGAL's attributes and Jerboa's
// embedding references, the darts of an orbit share one stored value: a
// dart holds an index into the embedding's value pool, so relabeling an
// orbit writes one value and an index per dart.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/map.hpp"
#include "core/map_embedding.hpp"
#include "rewriting/term.hpp"
#include "rewriting/value.hpp"

namespace dartcheck {

struct Embedding {
  static constexpr std::uint32_t none = 0xffffffffU;
  EmbeddingSignature signature;
  std::vector<std::uint32_t> slot;  // per dart: index into pool, or none
  std::vector<Value> pool;

  const Value* value(Dart d) const { return d < slot.size() && slot[d] != none ? &pool[slot[d]] : nullptr; }
  /// Stores v and returns its index, for set_index on many darts.
  std::uint32_t store(Value v) {
    pool.push_back(std::move(v));
    return static_cast<std::uint32_t>(pool.size() - 1);
  }
  void set_index(Dart d, std::uint32_t k) {
    if (d >= slot.size()) [[unlikely]]
      grow(d);
    slot[d] = k;
  }
  /// Extends `slot` to dart d (out of line: the hot set_index inlines).
  void grow(Dart d);
  void set(Dart d, Value v) { set_index(d, store(std::move(v))); }
};

struct EmbeddedMap {
  Map map;
  std::vector<Embedding> embeddings;

  explicit EmbeddedMap(Map m) : map(std::move(m)) {}
  /// Adds an unlabeled embedding; returns its index.
  std::size_t add_embedding(EmbeddingSignature s);
  Embedding* find(const std::string& name);
  const Embedding* find(const std::string& name) const;
  std::vector<EmbeddingSignature> signatures() const;
  /// Gives every dart of d's pi-orbit the value v (one pool entry).
  void label_orbit(std::size_t embedding, Dart d, Value v);
  /// Follows a derivation's renumbering (old, new) and the new dart count.
  void follow(const std::vector<std::pair<Dart, Dart>>& moved);
};

/// The typed embedding of a file's text values (.jba): values parse with
/// the declared type (type_by_name); a type dartcheck does not know keeps
/// its values as strings. Darts the file gave two values keep the first.
/// Returns nullopt and the reason for a value that does not parse.
std::optional<Embedding> typed_embedding(const MapEmbedding& e, std::string* why);

}  // namespace dartcheck
