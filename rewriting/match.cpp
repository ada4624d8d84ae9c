#include "rewriting/match.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace dartcheck {

std::string_view name_of(Refusal r) {
  switch (r) {
    case Refusal::none:
      return "none";
    case Refusal::bad_hooks:
      return "bad-hooks";
    case Refusal::not_combinatorial:
      return "not-combinatorial";
    case Refusal::no_match:
      return "no-match";
    case Refusal::not_injective:
      return "not-injective";
    case Refusal::dangling:
      return "dangling";
    case Refusal::not_representable:
      return "not-representable";
    case Refusal::disconnected:
      return "disconnected-instance";
    case Refusal::label_mismatch:
      return "label-mismatch";
    case Refusal::overlap:
      return "overlap";
    case Refusal::no_value:
      return "no-value";
  }
  return "?";
}

std::string combinatorial_violation(const Map& g, Dart d) {
  for (Dim i : g.model().dims) {
    const Dart s = g.link(i, d);
    const bool partial = has_dim(g.model().partial, i);
    if (s == no_dart) {
      if (!partial) return fmt::format("dart {} has no {}-arc", d, i);
      continue;
    }
    if (g.inverse_link(i, s) != d) return fmt::format("the {}-arc {} -> {} is not recorded back at dart {}", i, d, s, s);
    if (g.model().is_oriented(i)) {
      const Dart p = g.inverse_link(i, d);
      if (p == no_dart ? !partial : g.link(i, p) != d) return fmt::format("the {}-predecessor of dart {} does not link to it", i, d);
    }
  }
  return {};
}

Outcome<Match> match_from_hooks(const Rule& rule, const Map& g, std::span<const Dart> hook_darts) {
  const TopoGraph& L = rule.left();
  if (hook_darts.size() != rule.hooks().size())
    return refuse<Match>(Refusal::bad_hooks,
                         fmt::format("rule '{}' has {} hook(s), {} dart(s) given", rule.name(), rule.hooks().size(), hook_darts.size()));
  if (!(g.model() == rule.model()))
    return refuse<Match>(Refusal::bad_hooks, fmt::format("rule '{}' is for {}, the map is a {}", rule.name(), rule.model().name, g.model().name));
  Match m{std::vector<Dart>(L.node_count(), no_dart)};
  std::vector<NodeId> queue;
  for (std::size_t k = 0; k < hook_darts.size(); ++k) {
    if (hook_darts[k] >= g.size())
      return refuse<Match>(Refusal::bad_hooks, fmt::format("hook dart {} is not a dart of the map ({} darts)", hook_darts[k], g.size()));
    m.node[rule.hooks()[k]] = hook_darts[k];
    queue.push_back(rule.hooks()[k]);
  }
  // Propagate: an arc x -i-> y fixes m(y) = link_i(m(x)), and
  // m(x) = inverse_link_i(m(y)) when only y is known.
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const NodeId v = queue[q];
    if (auto why = combinatorial_violation(g, m.node[v]); !why.empty())
      return refuse<Match>(Refusal::not_combinatorial,
                           fmt::format("{} (matched to node '{}'); DPO application needs a combinatorial host", why, L.name(v)));
    for (const auto& a : L.arcs()) {
      NodeId other = no_node;
      Dart image = no_dart;
      if (a.source == v && m.node[a.target] == no_dart) {
        other = a.target;
        image = g.link(a.label, m.node[v]);
      } else if (a.target == v && m.node[a.source] == no_dart) {
        other = a.source;
        image = g.inverse_link(a.label, m.node[v]);
      } else {
        continue;
      }
      if (image == no_dart)
        return refuse<Match>(Refusal::no_match, fmt::format("L has {} -{}-> {} but dart {} has no {}-arc that way", L.name(a.source), a.label,
                                                            L.name(a.target), m.node[v], a.label));
      m.node[other] = image;
      queue.push_back(other);
    }
  }
  // Every arc must land on an arc; distinct nodes on distinct darts; distinct
  // arcs on distinct arcs (an arc of G is identified by source and label).
  for (const auto& a : L.arcs())
    if (g.link(a.label, m.node[a.source]) != m.node[a.target])
      return refuse<Match>(Refusal::no_match,
                           fmt::format("L has {} -{}-> {} (darts {} and {}) but the {}-arc of dart {} goes elsewhere", L.name(a.source), a.label,
                                       L.name(a.target), m.node[a.source], m.node[a.target], a.label, m.node[a.source]));
  std::vector<std::pair<Dart, NodeId>> images;
  for (NodeId v = 0; v < L.node_count(); ++v) images.emplace_back(m.node[v], v);
  std::sort(images.begin(), images.end());
  for (std::size_t k = 1; k < images.size(); ++k)
    if (images[k].first == images[k - 1].first)
      return refuse<Match>(Refusal::not_injective, fmt::format("nodes '{}' and '{}' of L both match dart {}", L.name(images[k - 1].second),
                                                               L.name(images[k].second), images[k].first));
  for (ArcId e = 0; e < L.arc_count(); ++e)
    for (ArcId f = e + 1; f < L.arc_count(); ++f)
      if (L.arc(e).source == L.arc(f).source && L.arc(e).label == L.arc(f).label)
        return refuse<Match>(Refusal::not_injective,
                             fmt::format("L has two {}-arcs out of '{}', but a dart has one", L.arc(e).label, L.name(L.arc(e).source)));
  return {std::move(m), Refusal::none, {}};
}

std::string dangling_violation(const Rule& rule, const Map& g, const Match& m) {
  const TopoGraph& L = rule.left();
  for (NodeId v = 0; v < L.node_count(); ++v) {
    if (rule.to_right(v) != no_node) continue;
    const Dart d = m.node[v];
    for (Dim i : g.model().dims) {
      // In a combinatorial host, d has at most its own i-arc out and the
      // arc from inverse_link(d) in; both must be images of L arcs.
      bool out = g.link(i, d) == no_dart, in = g.inverse_link(i, d) == no_dart;
      for (const auto& a : L.arcs()) {
        if (a.label != i) continue;
        out |= a.source == v;
        in |= a.target == v;
      }
      if (!out) return fmt::format("deleted node '{}' (dart {}) keeps its {}-arc to dart {}, which L does not match", L.name(v), d, i, g.link(i, d));
      if (!in)
        return fmt::format("deleted node '{}' (dart {}) keeps the {}-arc from dart {}, which L does not match", L.name(v), d, i,
                           g.inverse_link(i, d));
    }
  }
  return {};
}

}  // namespace dartcheck
