#include "core/map.hpp"

#include <cassert>

namespace dartcheck {

Map::Map(Model model, std::size_t darts) : model_(std::move(model)) {
  int next = 0;
  for (Dim i : model_.dims) succ_slot_[i] = static_cast<std::int16_t>(next++);
  for (Dim i : model_.dims) pred_slot_[i] = model_.is_oriented(i) ? static_cast<std::int16_t>(next++) : succ_slot_[i];
  stride_ = static_cast<std::size_t>(next);
  add_darts(darts);
}

Dart Map::add_darts(std::size_t count) {
  Dart first = static_cast<Dart>(size());
  links_.resize(links_.size() + count * stride_, no_dart);
  return first;
}

void Map::sew(Dim i, Dart d, Dart e) {
  set_link(i, d, e);
  if (!model_.is_oriented(i)) slot(e, succ_slot_[i]) = d;
}

void Map::set_inverse_link_raw(Dim i, Dart d, Dart e) { slot(d, pred_slot_[i]) = e; }

void Map::relocate(Dart from, Dart to) {
  if (from == to) return;
  for (Dim i : model_.dims) {
    const int s = succ_slot_[i], p = pred_slot_[i];
    Dart next = slot(from, s), prev = slot(from, p);
    // Whoever points at `from` must point at `to`. For a non-oriented
    // dimension the only candidate is the link target itself.
    if (next != no_dart && next != from && slot(next, p) == from) slot(next, p) = to;
    if (model_.is_oriented(i) && prev != no_dart && prev != from && slot(prev, s) == from) slot(prev, s) = to;
    slot(to, s) = next == from ? to : next;
    if (model_.is_oriented(i)) slot(to, p) = prev == from ? to : prev;
    slot(from, s) = no_dart;
    if (model_.is_oriented(i)) slot(from, p) = no_dart;
  }
}

void Map::truncate(std::size_t new_size) {
  assert(new_size <= size());
  links_.resize(new_size * stride_);
}

}  // namespace dartcheck
