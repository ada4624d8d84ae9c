// A map from darts to 32-bit values that costs what the application
// touches: a hash table when few darts are involved, a dense array when
// the match covers a good part of the map (a whole-surface scheme), where
// hashing every dart would cost more than the array.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/map.hpp"

namespace dartcheck {

class DartIndex {
 public:
  static constexpr std::uint32_t none = static_cast<std::uint32_t>(-1);
  /// `expected` darts will be stored among darts below `universe`.
  DartIndex(std::size_t expected, std::size_t universe) : universe_(universe) {
    if (expected * 8 >= universe)
      dense_.assign(universe, none);
    else
      sparse_.reserve(expected);
  }
  std::uint32_t get(Dart d) const { return d < dense_.size() ? dense_[d] : lookup(d); }
  /// Calls f(dart, value) for every dart set (dense: in dart order).
  template <class F>
  void for_each(F&& f) const {
    for (std::size_t d = 0; d < dense_.size(); ++d)
      if (dense_[d] != none) f(static_cast<Dart>(d), dense_[d]);
    for (const auto& [d, v] : sparse_) f(d, v);
  }
  void set(Dart d, std::uint32_t v) {
    if (d < dense_.size()) {
      dense_[d] = v;
      return;
    }
    sparse_[d] = v;
    // A traversal that reaches most of the map (an incomplete orbit such
    // as the whole surface) is cheaper in an array.
    if (dense_.empty() && sparse_.size() * 8 >= universe_) {
      dense_.assign(universe_, none);
      std::unordered_map<Dart, std::uint32_t> rest;
      for (auto [k, x] : sparse_) (k < universe_ ? dense_[k] : rest[k]) = x;
      sparse_ = std::move(rest);
    }
  }

 private:
  std::uint32_t lookup(Dart d) const {
    const auto it = sparse_.find(d);
    return it == sparse_.end() ? none : it->second;
  }
  std::size_t universe_;
  std::vector<std::uint32_t> dense_;
  std::unordered_map<Dart, std::uint32_t> sparse_;
};

}  // namespace dartcheck
