// G's darts against H's after a rewrite G => H: which dart of H each dart
// of G became (or that it was deleted), which dart of G each dart of H was
// (or that it was created). Darts the rewrite did not touch keep their
// number. Stored sparsely (core/dart_index.hpp), so building one costs what
// the rewrite touched, not the size of the map.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/dart_index.hpp"
#include "core/map.hpp"

namespace dartcheck {

class Renumbering {
 public:
  /// `touched`: about how many darts will be set (a sizing hint).
  Renumbering(std::size_t g_size, std::size_t h_size, std::size_t touched);
  /// The identity of an empty map (to be assigned).
  Renumbering() : Renumbering(0, 0, 0) {}
  /// A map made dense again after deleting `deleted` (its holes filled by
  /// the darts `moved`, (old, new), as compact() reports them): every
  /// other dart keeps its number.
  static Renumbering compaction(std::size_t g_size, std::size_t h_size, std::span<const Dart> deleted, std::span<const std::pair<Dart, Dart>> moved);

  /// g of G became h of H.
  void map(Dart g, Dart h);
  /// g of G has no image in H.
  void deleted(Dart g);
  /// h of H has no preimage in G.
  void created(Dart h);

  /// The dart of H that g became; no_dart if g was deleted.
  Dart to_h(Dart g) const { return decode(g2h_.get(g), g); }
  /// The dart of G that h was; no_dart if h was created.
  Dart to_g(Dart h) const { return decode(h2g_.get(h), h); }
  std::size_t g_size() const { return g_size_; }
  std::size_t h_size() const { return h_size_; }

  /// This renumbering followed by `next` (G => H => K): G against K.
  Renumbering then(const Renumbering& next) const;

  /// f(g, h) for every dart of G that became another dart h of H (not the
  /// deleted ones, not those that kept their number): O(touched darts).
  template <class F>
  void for_each_moved(F&& f) const {
    g2h_.for_each([&](Dart g, std::uint32_t v) {
      if (const Dart h = decode(v, g); h != no_dart && h != g) f(g, h);
    });
  }

  /// Per-dart data of G carried to H: out[h] = data[to_g(h)], `fill` for
  /// created darts.
  template <class T>
  std::vector<T> carry(std::span<const T> data, const T& fill) const {
    std::vector<T> out(h_size_, fill);
    for (Dart h = 0; h < h_size_; ++h)
      if (const Dart g = to_g(h); g != no_dart && g < data.size()) out[h] = data[g];
    return out;
  }

 private:
  // Stored values: a dart, or `gone` for deleted / created darts; absent
  // darts map to themselves.
  static constexpr std::uint32_t gone = DartIndex::none - 1;
  static Dart decode(std::uint32_t v, Dart self) { return v == DartIndex::none ? self : v == gone ? no_dart : v; }
  std::size_t g_size_, h_size_;
  DartIndex g2h_, h2g_;
};

}  // namespace dartcheck
