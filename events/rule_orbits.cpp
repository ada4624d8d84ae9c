#include "events/rule_orbits.hpp"

#include <numeric>

#include <fmt/format.h>

#include "core/disjoint_sets.hpp"

namespace dartcheck::events {

ExplicitPathEnd follow_explicit(const EventSide& side, NodeId v, const OrbitWord& w) {
  std::size_t k = 0;
  for (; k < w.size(); ++k) {
    NodeId next = no_node;
    for (ArcId e : side.explicit_arcs)
      if (side.graph->arc(e).source == v && side.graph->arc(e).label == w[k]) next = side.graph->arc(e).target;
    if (next == no_node) break;
    v = next;
  }
  return {v, k};
}

SideOrbits side_orbits(const EventRule&, const EventSide& side, const OrbitKind& kind) {
  const TopoGraph& g = *side.graph;
  const std::size_t n = g.node_count();
  DisjointSets<int> orbit(n);
  std::vector<std::vector<std::string>> missing(n);
  for (NodeId v = 0; v < n; ++v)
    for (const OrbitWord& w : kind.generators) {
      const ExplicitPathEnd end = follow_explicit(side, v, w);
      if (end.letters == w.size()) {
        orbit.attach(static_cast<int>(v), static_cast<int>(end.node));
        continue;
      }
      // A single letter may be an implicit link of the node's label.
      bool implicit = false;
      if (w.size() == 1)
        for (const auto& l : side.labels[v]) implicit = implicit || (l && *l == w[0]);
      if (!implicit) {
        std::string word;
        for (Dim d : w) word += std::to_string(d);
        missing[v].push_back(fmt::format("{} has no {}-{}", g.name(v), word, w.size() == 1 ? "link" : "path"));
      }
    }
  SideOrbits s;
  s.orbit_of.assign(n, -1);
  std::vector<int> index_of_root(n, -1);
  for (NodeId v = 0; v < n; ++v) {
    const int root = orbit.find(static_cast<int>(v));
    int& idx = index_of_root[static_cast<std::size_t>(root)];
    if (idx < 0) {
      idx = static_cast<int>(s.orbits.size());
      s.orbits.emplace_back();
    }
    RuleOrbit& o = s.orbits[static_cast<std::size_t>(idx)];
    o.nodes.push_back(v);
    if (!missing[v].empty()) {
      o.complete = false;
      o.missing.insert(o.missing.end(), missing[v].begin(), missing[v].end());
    }
    s.orbit_of[v] = idx;
  }
  return s;
}

}  // namespace dartcheck::events
