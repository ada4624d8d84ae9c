#include "rewriting/graph_derivation.hpp"

#include <algorithm>
#include <functional>
#include <string>

namespace dartcheck {

std::vector<GraphMatch> all_matches(const TopoGraph& L, const TopoGraph& G) {
  std::vector<GraphMatch> result;
  GraphMatch m{std::vector<NodeId>(L.node_count(), no_node), std::vector<ArcId>(L.arc_count(), 0)};
  std::vector<bool> node_used(G.node_count(), false), arc_used(G.arc_count(), false);
  // Arcs once all nodes are placed: each L arc picks an unused G arc with the
  // same label between the images of its ends.
  std::function<void(std::size_t)> place_arc = [&](std::size_t e) {
    if (e == L.arc_count()) {
      result.push_back(m);
      return;
    }
    const auto& a = L.arc(static_cast<ArcId>(e));
    for (ArcId f = 0; f < G.arc_count(); ++f) {
      const auto& b = G.arc(f);
      if (arc_used[f] || b.label != a.label || b.source != m.node[a.source] || b.target != m.node[a.target]) continue;
      arc_used[f] = true;
      m.arc[e] = f;
      place_arc(e + 1);
      arc_used[f] = false;
    }
  };
  std::function<void(NodeId)> place_node = [&](NodeId v) {
    if (v == L.node_count()) {
      place_arc(0);
      return;
    }
    for (NodeId w = 0; w < G.node_count(); ++w) {
      if (node_used[w]) continue;
      node_used[w] = true;
      m.node[v] = w;
      place_node(v + 1);
      node_used[w] = false;
    }
  };
  place_node(0);
  return result;
}

bool satisfies_dangling(const Rule& rule, const TopoGraph& G, const GraphMatch& m) {
  const TopoGraph& L = rule.left();
  std::vector<bool> matched(G.arc_count(), false);
  for (ArcId f : m.arc) matched[f] = true;
  for (NodeId v = 0; v < L.node_count(); ++v) {
    if (rule.to_right(v) != no_node) continue;
    for (ArcId f = 0; f < G.arc_count(); ++f)
      if (!matched[f] && (G.arc(f).source == m.node[v] || G.arc(f).target == m.node[v])) return false;
  }
  return true;
}

TopoGraph derive(const Rule& rule, const TopoGraph& G, const GraphMatch& m, std::vector<NodeId>* comatch) {
  const TopoGraph &L = rule.left(), &R = rule.right();
  std::vector<bool> deleted_node(G.node_count(), false), deleted_arc(G.arc_count(), false);
  for (NodeId v = 0; v < L.node_count(); ++v) deleted_node[m.node[v]] = rule.to_right(v) == no_node;
  for (ArcId e = 0; e < L.arc_count(); ++e) deleted_arc[m.arc[e]] = !rule.preserved_left_arc(e);

  TopoGraph H;
  std::vector<NodeId> image(G.node_count(), no_node);
  for (NodeId w = 0; w < G.node_count(); ++w)
    if (!deleted_node[w]) image[w] = H.add_node(G.name(w));
  for (ArcId f = 0; f < G.arc_count(); ++f)
    if (!deleted_arc[f]) H.add_arc(image[G.arc(f).source], image[G.arc(f).target], G.arc(f).label);
  std::vector<NodeId> co(R.node_count());
  for (NodeId v = 0; v < R.node_count(); ++v) co[v] = rule.to_left(v) != no_node ? image[m.node[rule.to_left(v)]] : H.add_node(R.name(v));
  for (ArcId e = 0; e < R.arc_count(); ++e)
    if (!rule.preserved_right_arc(e)) H.add_arc(co[R.arc(e).source], co[R.arc(e).target], R.arc(e).label);
  if (comatch) *comatch = std::move(co);
  return H;
}

TopoGraph to_graph(const Map& map) {
  TopoGraph g;
  for (Dart d = 0; d < map.size(); ++d) g.add_node(std::to_string(d));
  for (Dart d = 0; d < map.size(); ++d)
    for (Dim i : map.model().dims)
      if (Dart e = map.link(i, d); e != no_dart) g.add_arc(d, e, i);
  return g;
}

}  // namespace dartcheck
