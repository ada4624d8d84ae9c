#include "checkers/graph_constraints.hpp"

#include <algorithm>

namespace dartcheck {

void check_incidence(const TopoGraph& g, NodeId v, Dim i, bool at_most_one, std::vector<Violation>& out) {
  std::uint32_t s = 0, t = 0;
  for (const auto& a : g.arcs())
    if (a.label == i) {
      s += a.source == v;
      t += a.target == v;
    }
  if (s > 1 || (s == 0 && !at_most_one)) out.push_back({Constraint::incident_out, i, -1, v, s});
  if (t > 1 || (t == 0 && !at_most_one)) out.push_back({Constraint::incident_in, i, -1, v, t});
}

bool non_oriented_at(const TopoGraph& g, NodeId v, Dim i) {
  const auto& arcs = g.arcs();
  for (const auto& e : arcs) {
    if (e.label != i || (e.source != v && e.target != v)) continue;
    const bool reversed =
        std::any_of(arcs.begin(), arcs.end(), [&](const auto& r) { return r.label == i && r.source == e.target && r.target == e.source; });
    if (!reversed) return false;
  }
  return true;
}

bool cycle_at(const TopoGraph& g, NodeId v, Dim i, Dim j) {
  std::vector<NodeId> frontier{v}, next;
  for (Dim letter : {i, j, i, j}) {
    next.clear();
    for (const auto& a : g.arcs())
      if (a.label == letter && std::find(frontier.begin(), frontier.end(), a.source) != frontier.end() &&
          std::find(next.begin(), next.end(), a.target) == next.end())
        next.push_back(a.target);
    std::swap(frontier, next);
  }
  return std::find(frontier.begin(), frontier.end(), v) != frontier.end();
}

ValidityReport check_graph(const TopoGraph& g, const Model& model) {
  ValidityReport r;
  r.model = model.name;
  r.elements = g.node_count();
  for (const auto& a : g.arcs())
    if (!model.contains(a.label)) r.violations.push_back({Constraint::foreign_label, a.label, -1, a.source});
  for (NodeId v = 0; v < g.node_count(); ++v) {
    for (Dim i : model.dims) {
      check_incidence(g, v, i, has_dim(model.partial, i), r.violations);
      if (!model.is_oriented(i) && !non_oriented_at(g, v, i)) r.violations.push_back({Constraint::non_orientation, i, -1, v});
      if (model.loop_free)
        for (const auto& a : g.arcs())
          if (a.label == i && a.source == v && a.target == v) {
            r.violations.push_back({Constraint::loop, i, -1, v});
            break;
          }
    }
    for (auto [i, j] : model.exchangeable)
      if (!cycle_at(g, v, i, j)) r.violations.push_back({Constraint::cycle, i, j, v});
  }
  return r;
}

}  // namespace dartcheck
