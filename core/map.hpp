// Dense maps: the representation of objects (G-maps, O-maps) of up to
// millions of darts.
//
// Darts are the indices 0..size()-1. For each dimension i a dart stores the
// target of its i-arc (`link`), or `no_dart`: the i-arcs of the map are
// the pairs (d, link_i(d)). An oriented dimension also records the source
// of the i-arc into each dart (`inverse_link`), so both directions are O(1);
// the validity checker reports a record that is not the inverse of the
// links (CGAL's beta0 must likewise be the inverse of beta1). A dart thus
// has at most one outgoing i-arc: a graph that needs two is not a dense map
// and must stay a small LabeledGraph.
//
// The links of one dart are stored next to each other (dart-major), not one
// array per dimension: every constraint check reads several dimensions of
// the same neighbour, and this layout turns those reads into one cache line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "core/huge_page_allocator.hpp"
#include "core/model.hpp"

namespace dartcheck {

using Dart = std::uint32_t;
inline constexpr Dart no_dart = std::numeric_limits<Dart>::max();

class Map {
 public:
  /// The model must have at least one dimension.
  explicit Map(Model model, std::size_t darts = 0);

  const Model& model() const { return model_; }
  std::size_t size() const { return links_.size() / stride_; }

  /// Target of the i-arc of d, or no_dart.
  Dart link(Dim i, Dart d) const { return links_[d * stride_ + succ_slot_[i]]; }
  /// Source of the i-arc into d: the recorded predecessor for an oriented
  /// dimension, the link itself for a non-oriented one.
  Dart inverse_link(Dim i, Dart d) const { return links_[d * stride_ + pred_slot_[i]]; }

  /// Makes d -> e the i-arc out of d, replacing d's previous i-arc. For an
  /// oriented dimension the predecessor of e becomes d (and the old target
  /// forgets d). Nothing else changes: for a non-oriented dimension the
  /// reverse arc is a separate arc, set by `sew`.
  void set_link(Dim i, Dart d, Dart e) {
    // Inline: schemes write millions of links. A dimension is oriented
    // exactly when its predecessor record has a slot of its own.
    const int s = succ_slot_[i], p = pred_slot_[i];
    if (s != p) remove_link(i, d);
    slot(d, s) = e;
    if (s != p && e != no_dart) slot(e, p) = d;
  }
  /// Removes the i-arc out of d (and, oriented, its predecessor record).
  void remove_link(Dim i, Dart d) {
    const int p = pred_slot_[i];
    Dart& s = slot(d, succ_slot_[i]);
    if (p != succ_slot_[i] && s != no_dart && slot(s, p) == d) slot(s, p) = no_dart;
    s = no_dart;
  }
  /// Non-oriented: d -i- e in both directions (a loop when d == e).
  /// Oriented: d -i-> e.
  void sew(Dim i, Dart d, Dart e);
  /// Overwrites only the predecessor record of an oriented dimension: a raw
  /// write that can desynchronise the two arrays (for corruption tests and
  /// for reading files that store both).
  void set_inverse_link_raw(Dim i, Dart d, Dart e);
  /// Overwrites only the link of d, leaving every predecessor record as it
  /// is (the counterpart of set_inverse_link_raw).
  void set_link_raw(Dim i, Dart d, Dart e) { slot(d, succ_slot_[i]) = e; }

  /// Appends `count` darts without links; returns the first new dart.
  Dart add_darts(std::size_t count);
  /// Moves dart `from` into slot `to` (which must be unused by any arc),
  /// redirecting every arc that pointed at `from`. O(|D|).
  void relocate(Dart from, Dart to);
  /// Drops the last darts; they must carry no arc and receive none.
  void truncate(std::size_t new_size);

  /// Number of link slots per dart, and raw access for tight loops.
  std::size_t stride() const { return stride_; }
  int succ_slot(Dim i) const { return succ_slot_[i]; }
  int pred_slot(Dim i) const { return pred_slot_[i]; }
  std::span<const Dart> raw() const { return links_; }

  friend bool operator==(const Map& a, const Map& b) { return a.model_ == b.model_ && a.size() == b.size() && a.links_ == b.links_; }

 private:
  Dart& slot(Dart d, int s) { return links_[d * stride_ + static_cast<std::size_t>(s)]; }

  Model model_;
  std::size_t stride_ = 0;
  // Not int: a store to a Dart (unsigned int) may alias an int, so the
  // compiler would reload the slot numbers after every link written; a
  // 16-bit type lets loops of set_link keep them in registers.
  std::int16_t succ_slot_[max_dimension + 1] = {};
  std::int16_t pred_slot_[max_dimension + 1] = {};
  std::vector<Dart, HugePageAllocator<Dart>> links_;
};

}  // namespace dartcheck
