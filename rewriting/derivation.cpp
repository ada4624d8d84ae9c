#include "rewriting/detail/derivation.hpp"

#include <algorithm>
#include <unordered_map>

#include <fmt/format.h>

namespace dartcheck {
namespace {

// An added arc x -i-> y needs the i-slot of x empty once L \ K is deleted:
// x's i-arc in G (if any) must be deleted by the rule, and no two added
// arcs may leave x with the same label.
std::string representability(const Rule& rule, const Map& g, const Match& m) {
  const TopoGraph &L = rule.left(), &R = rule.right();
  for (ArcId e = 0; e < R.arc_count(); ++e) {
    if (rule.preserved_right_arc(e)) continue;
    const auto& a = R.arc(e);
    for (ArcId f = e + 1; f < R.arc_count(); ++f)
      if (!rule.preserved_right_arc(f) && R.arc(f).source == a.source && R.arc(f).label == a.label)
        return fmt::format("R adds two {}-arcs out of '{}'; H would break I({}) there", a.label, R.name(a.source), a.label);
    const NodeId x = rule.to_left(a.source);
    if (x == no_node || g.link(a.label, m.node[x]) == no_dart) continue;
    bool freed = false;
    for (ArcId f = 0; f < L.arc_count(); ++f) freed |= !rule.preserved_left_arc(f) && L.arc(f).source == x && L.arc(f).label == a.label;
    bool kept = false;
    for (ArcId f = 0; f < R.arc_count(); ++f) kept |= rule.preserved_right_arc(f) && R.arc(f).source == a.source && R.arc(f).label == a.label;
    if (!freed || kept)
      return fmt::format("R adds a {}-arc out of '{}' (dart {}), which keeps its {}-arc to dart {}; H would break I({}) there", a.label,
                         R.name(a.source), m.node[x], a.label, g.link(a.label, m.node[x]), a.label);
  }
  return {};
}

}  // namespace

std::vector<std::pair<Dart, Dart>> compact(Map& g, std::vector<Dart> holes, std::span<const Dart> sources) {
  // While holes remain, drop the last dart if it is a hole, otherwise move
  // it into the smallest hole. holes[lo, hi) are unfilled.
  std::vector<std::pair<Dart, Dart>> moved;
  std::sort(holes.begin(), holes.end());
  std::size_t size = g.size(), lo = 0, hi = holes.size();
  while (lo < hi) {
    if (holes[hi - 1] == size - 1) {
      --hi;
    } else {
      const Dart last = static_cast<Dart>(size - 1);
      g.relocate(last, holes[lo]);
      moved.emplace_back(last, holes[lo]);
      ++lo;
    }
    --size;
  }
  g.truncate(size);
  if (!moved.empty() && !sources.empty()) {
    const std::unordered_map<Dart, Dart> to(moved.begin(), moved.end());
    auto renumbered = [&](Dart d) {
      const auto it = to.find(d);
      return it == to.end() ? d : it->second;
    };
    for (Dart s : sources) {
      const Dart x = renumbered(s);
      if (x >= g.size()) continue;  // a deleted dart
      for (Dim i : g.model().dims)
        if (!g.model().is_oriented(i))
          if (const Dart e = g.link(i, x); e != no_dart && e != renumbered(e)) g.set_link_raw(i, x, renumbered(e));
    }
  }
  return moved;
}

Outcome<Derivation> apply_rule(const Rule& rule, Map& g, std::span<const Dart> hook_darts) {
  auto matched = match_from_hooks(rule, g, hook_darts);
  if (!matched.ok()) return refuse<Derivation>(matched.refusal, matched.why);
  return rewrite_rule(rule, g, std::move(*matched.value));
}

Outcome<Derivation> rewrite_rule(const Rule& rule, Map& g, Match match) {
  Derivation d{std::move(match), {}, {}};
  if (auto why = dangling_violation(rule, g, d.match); !why.empty()) return refuse<Derivation>(Refusal::dangling, why);
  if (auto why = representability(rule, g, d.match); !why.empty()) return refuse<Derivation>(Refusal::not_representable, why);

  const TopoGraph &L = rule.left(), &R = rule.right();
  // Delete the arcs of L \ K, then free the darts of deleted nodes.
  for (ArcId e = 0; e < L.arc_count(); ++e)
    if (!rule.preserved_left_arc(e)) g.remove_link(L.arc(e).label, d.match.node[L.arc(e).source]);
  std::vector<Dart> holes;
  for (NodeId v = 0; v < L.node_count(); ++v)
    if (rule.to_right(v) == no_node) holes.push_back(d.match.node[v]);
  std::sort(holes.begin(), holes.end(), std::greater<>());  // reuse the smallest first

  // Place R's nodes: preserved ones where they were, added ones in holes or
  // new darts.
  d.comatch.assign(R.node_count(), no_dart);
  for (NodeId v = 0; v < R.node_count(); ++v) {
    if (rule.to_left(v) != no_node) {
      d.comatch[v] = d.match.node[rule.to_left(v)];
    } else if (!holes.empty()) {
      d.comatch[v] = holes.back();
      holes.pop_back();
    } else {
      d.comatch[v] = g.add_darts(1);
    }
  }
  for (ArcId e = 0; e < R.arc_count(); ++e)
    if (!rule.preserved_right_arc(e)) g.set_link(R.arc(e).label, d.comatch[R.arc(e).source], d.comatch[R.arc(e).target]);

  d.moved = compact(g, std::move(holes), d.comatch);
  for (auto& x : d.comatch)
    for (auto [from, to] : d.moved)
      if (x == from) x = to;
  return {std::move(d), Refusal::none, {}};
}

}  // namespace dartcheck
