#include "querymodify/modify.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include "core/error.hpp"
#include "rewriting/compaction.hpp"

namespace dartcheck::querymodify {
namespace {

// The darts as a sorted set, checked closed under β1 and β2. Sorted
// vectors, not flags over the map: a recombination merges thousands of
// small volumes in a large map, and each call must cost its own darts.
std::vector<Dart> volume_set(const Map& m, const std::vector<Dart>& darts) {
  std::vector<Dart> in = darts;
  std::sort(in.begin(), in.end());
  in.erase(std::unique(in.begin(), in.end()), in.end());
  for (Dart d : in)
    if (d >= m.size()) throw ValueError(fmt::format("dart {} is not in the map", d));
  for (Dart d : in)
    for (Dim i : {1, 2})
      if (const Dart e = m.link(i, d); e != no_dart && !std::binary_search(in.begin(), in.end(), e))
        throw ValueError(fmt::format("darts {} and {} are {}-linked but only {} is listed: not whole volumes", d, e, i, d));
  return in;
}

bool contains(const std::vector<Dart>& set, Dart d) { return std::binary_search(set.begin(), set.end(), d); }

Renumbering remove(Map& m, const std::vector<Dart>& gone) {
  for (Dart d : gone)
    for (Dim i : m.model().dims) m.remove_link(i, d);
  const std::size_t g_size = m.size();
  const auto moved = compact(m, gone);
  return Renumbering::compaction(g_size, m.size(), gone, moved);
}

}  // namespace

Renumbering delete_volumes(Map& m, const std::vector<Dart>& darts) {
  const auto in = volume_set(m, darts);
  for (Dart d : in)
    if (const Dart e = m.link(3, d); e != no_dart && !contains(in, e)) m.remove_link(3, e);  // the kept side becomes 3-free
  return remove(m, in);
}

namespace {

// Removing the cells between merged (k+1)-cells: a dart is removed when its
// b-link stays in the set `in` (a face between two merged volumes, b = 3;
// an edge between two merged faces, b = 2), and each kept dart's a-link
// (a = b - 1) becomes the next kept dart found by turning through the
// removed ones (a, then b, then a...). Relinks and removes; returns the
// renumbering.
Renumbering merge_across(Map& m, const std::vector<Dart>& in, Dim a, Dim b) {
  auto inner = [&](Dart d) {
    const Dart e = m.link(b, d);
    return e != no_dart && contains(in, e);
  };
  std::vector<std::pair<Dart, Dart>> relink;
  std::vector<Dart> gone;
  for (Dart x : in) {
    if (inner(x)) {
      gone.push_back(x);
      continue;
    }
    Dart y = m.link(a, x);
    for (std::size_t guard = 0; inner(y); ++guard) {
      if (guard > in.size()) throw InternalError(fmt::format("turning through the removed {}-cells did not leave them", b - 1));
      y = m.link(a, m.link(b, y));
    }
    if (y != m.link(a, x)) relink.emplace_back(x, y);
  }
  if (!in.empty() && gone.size() == in.size()) throw ValueError("nothing would be left of the merged cells");
  for (Dart d : gone) m.remove_link(a, d);  // first: an oriented a's predecessor records must end on kept darts
  for (const auto& [x, y] : relink) m.set_link(a, x, y);
  return remove(m, gone);
}

}  // namespace

Renumbering merge_volumes(Map& m, const std::vector<Dart>& darts) { return merge_across(m, volume_set(m, darts), 2, 3); }

Renumbering merge_faces(Map& m, const std::vector<Dart>& darts) {
  std::vector<Dart> in = darts;
  std::sort(in.begin(), in.end());
  in.erase(std::unique(in.begin(), in.end()), in.end());
  for (Dart d : in) {
    if (d >= m.size()) throw ValueError(fmt::format("dart {} is not in the map", d));
    if (m.link(3, d) != no_dart) throw ValueError(fmt::format("dart {} is 3-sewn: only 3-free faces can be merged", d));
  }
  for (Dart d : in)
    if (const Dart e = m.link(1, d); !contains(in, e))
      throw ValueError(fmt::format("darts {} and {} are 1-linked but only {} is listed: not whole faces", d, e, d));
  return merge_across(m, in, 1, 2);
}

namespace {

// Appends copies of T's darts flagged `copy`, with their links among
// themselves; returns T dart -> new input dart (no_dart if not copied).
std::vector<Dart> copy_darts(Map& m, const Map& t, const std::vector<bool>& copy) {
  std::vector<Dart> t_to_m(t.size(), no_dart);
  std::size_t count = 0;
  for (Dart d = 0; d < t.size(); ++d) count += copy[d];
  Dart next = m.add_darts(count);
  for (Dart d = 0; d < t.size(); ++d)
    if (copy[d]) t_to_m[d] = next++;
  for (Dart d = 0; d < t.size(); ++d) {
    if (!copy[d]) continue;
    for (Dim i : t.model().dims)
      if (const Dart e = t.link(i, d); e != no_dart && copy[e]) m.set_link(i, t_to_m[d], t_to_m[e]);
  }
  return t_to_m;
}

void check_models(const Map& m, const Map& q, const Map& t, const std::vector<Dart>& q_to_t, const std::vector<Dart>& q_to_m) {
  if (!(q.model() == m.model()) || !(t.model() == m.model())) throw ValueError("the query, the target and the input must have one model");
  if (q_to_t.size() != q.size() || q_to_m.size() != q.size()) throw ValueError("m_QT and m_QM must give a dart for every query dart");
  for (Dart x = 0; x < q.size(); ++x)
    if (q_to_m[x] >= m.size()) throw ValueError(fmt::format("m_QM sends query dart {} outside the input", x));
}

}  // namespace

std::vector<Dart> extend(Map& m, const Map& q, const Map& t, const std::vector<Dart>& q_to_t, const std::vector<Dart>& q_to_m) {
  check_models(m, q, t, q_to_t, q_to_m);
  std::vector<Dart> t_to_q(t.size(), no_dart);
  for (Dart x = 0; x < q.size(); ++x) {
    if (q_to_t[x] >= t.size() || t_to_q[q_to_t[x]] != no_dart) throw ValueError(fmt::format("m_QT is not injective at query dart {}", x));
    t_to_q[q_to_t[x]] = x;
  }
  for (Dart x = 0; x < q.size(); ++x)
    for (Dim i : q.model().dims)
      if (const Dart y = q.link(i, x); y != no_dart && t.link(i, q_to_t[x]) != q_to_t[y])
        throw ValueError(fmt::format("the target does not keep the query's {}-link from dart {}", i, x));
  std::vector<bool> fresh(t.size());
  for (Dart d = 0; d < t.size(); ++d) fresh[d] = t_to_q[d] == no_dart;
  // Lines 4-6, checked first: a new dart meets the query only by β3, at
  // an input dart that is 3-free.
  std::vector<std::pair<Dart, Dart>> glue;  // (target dart, input dart)
  for (Dart d = 0; d < t.size(); ++d) {
    if (!fresh[d]) continue;
    for (Dim i : t.model().dims) {
      const Dart e = t.link(i, d);
      if (e == no_dart || fresh[e]) continue;
      if (i != 3) throw ValueError(fmt::format("target dart {} is {}-linked to the query's image: only β3 may join new volumes", d, i));
      const Dart at = q_to_m[t_to_q[e]];
      if (m.link(3, at) != no_dart) throw ValueError(fmt::format("input dart {} must be 3-free to receive a new volume", at));
      glue.emplace_back(d, at);
    }
  }
  auto t_to_m = copy_darts(m, t, fresh);  // lines 1-3
  for (const auto& [d, at] : glue) m.sew(3, t_to_m[d], at);
  for (Dart d = 0; d < t.size(); ++d)
    if (!fresh[d]) t_to_m[d] = q_to_m[t_to_q[d]];
  return t_to_m;
}

std::vector<Dart> replace(Map& m, const Map& q, const Map& t, const std::vector<Dart>& q_to_t, const std::vector<Dart>& q_to_m,
                          Renumbering* moved_out) {
  check_models(m, q, t, q_to_t, q_to_m);
  // The boundaries must coincide: Q's 3-free darts onto T's, β1 kept.
  std::vector<Dart> t_boundary_of(t.size(), no_dart);
  std::size_t q_free = 0, t_free = 0;
  for (Dart d = 0; d < t.size(); ++d) t_free += t.link(3, d) == no_dart;
  for (Dart x = 0; x < q.size(); ++x) {
    if (q.link(3, x) != no_dart) continue;
    ++q_free;
    const Dart y = q_to_t[x];
    if (y >= t.size() || t.link(3, y) != no_dart || t_boundary_of[y] != no_dart)
      throw ValueError(fmt::format("m_QT must send query boundary dart {} to a boundary dart of the target, one to one", x));
    t_boundary_of[y] = x;
    if (t.link(1, y) != q_to_t[q.link(1, x)]) throw ValueError(fmt::format("m_QT does not keep β1 at query boundary dart {}", x));
  }
  if (q_free != t_free) throw ValueError(fmt::format("the query has {} boundary darts, the target {}", q_free, t_free));
  // The outside neighbour of each boundary dart, then the match goes. A
  // match whose boundary '*' let two of its boundary faces be 3-sewn to
  // each other keeps that link between their images in T.
  std::vector<Dart> outside(q.size(), no_dart), inside(q.size(), no_dart);
  std::unordered_map<Dart, Dart> query_dart_of;
  for (Dart x = 0; x < q.size(); ++x) query_dart_of.emplace(q_to_m[x], x);
  for (Dart x = 0; x < q.size(); ++x) {
    if (q.link(3, x) != no_dart) continue;
    const Dart o = m.link(3, q_to_m[x]);
    if (o == no_dart) continue;
    if (const auto it = query_dart_of.find(o); it != query_dart_of.end())
      inside[x] = it->second;
    else
      outside[x] = o;
  }
  std::vector<Dart> matched(q_to_m.begin(), q_to_m.end());
  Renumbering moved = delete_volumes(m, matched);
  for (Dart& o : outside)
    if (o != no_dart) o = moved.to_h(o);  // outside the match: kept
  auto t_to_m = copy_darts(m, t, std::vector<bool>(t.size(), true));
  for (Dart x = 0; x < q.size(); ++x) {
    if (outside[x] != no_dart) m.sew(3, t_to_m[q_to_t[x]], outside[x]);
    if (inside[x] != no_dart && x < inside[x]) m.sew(3, t_to_m[q_to_t[x]], t_to_m[q_to_t[inside[x]]]);
  }
  if (moved_out) *moved_out = std::move(moved);
  return t_to_m;
}

}  // namespace dartcheck::querymodify
