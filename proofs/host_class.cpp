#include "proofs/host_class.hpp"

#include <fmt/format.h>

namespace dartcheck::proofs {

std::vector<HConstraint> model_constraints(const Model& m) {
  std::vector<HConstraint> out;
  for (Dim i : m.dims) out.push_back({RuleCondition::incident_arcs, i});
  for (Dim i : m.dims)
    if (!m.is_oriented(i)) out.push_back({RuleCondition::non_orientation, i});
  for (auto [i, j] : m.exchangeable) out.push_back({RuleCondition::cycle, i, j});
  if (m.loop_free)
    for (Dim i : m.dims) out.push_back({RuleCondition::no_loop, i});
  return out;
}

std::optional<HostClass> theorem_class(const HConstraint& c) {
  HostClass h;
  h.kind = HostClass::Kind::theorem;
  switch (c.kind) {
    case RuleCondition::incident_arcs:
      h.theorem = 1;
      h.name = fmt::format("Theorem 1 hosts: D-graphs satisfying I({})", c.i);
      h.symbolic = dim_bit(c.i);
      break;
    case RuleCondition::non_orientation:
      h.theorem = 2;
      h.name = fmt::format("Theorem 2 hosts: D-combinatorial graphs satisfying O({})", c.i);
      h.symbolic = h.involutive = dim_bit(c.i);
      h.others_combinatorial = true;
      break;
    case RuleCondition::cycle:
      h.theorem = 3;
      h.name = fmt::format("Theorem 3 hosts: D-combinatorial graphs satisfying C({},{})", c.i, c.j);
      h.symbolic = dim_bit(c.i) | dim_bit(c.j);
      h.cycles = {{c.i, c.j}};
      h.others_combinatorial = true;
      break;
    default:
      return std::nullopt;
  }
  return h;
}

HostClass model_class(const Model& m) {
  HostClass h;
  h.kind = HostClass::Kind::model;
  h.name = fmt::format("valid {}s", m.name);
  h.symbolic = m.dim_set();
  h.partial = m.partial;
  h.involutive = m.non_oriented;
  h.cycles = m.exchangeable;
  h.loop_free = m.loop_free;
  h.others_combinatorial = true;
  return h;
}

std::string unmatchable_outside(const Rule& rule, const HostClass& c) {
  const TopoGraph& L = rule.left();
  for (Dim d : rule.model().dims) {
    const bool functional = has_dim(c.symbolic, d) || c.others_combinatorial;
    if (!functional) continue;
    for (NodeId v = 0; v < L.node_count(); ++v) {
      const auto out = L.out_arcs(v, d), in = L.in_arcs(v, d);
      if (out.size() > 1 || in.size() > 1)
        return fmt::format("L has {} {}-arcs {} node {}, and a host of the class has one per dart", std::max(out.size(), in.size()), d,
                           out.size() > 1 ? "out of" : "into", L.name(v));
      if (has_dim(c.symbolic, d) || rule.to_right(v) != no_node) continue;
      // A deleted node of a D-combinatorial host has a d-arc out and in;
      // unless L matches both, the dangling condition forbids the match.
      if (out.empty() || in.empty())
        return fmt::format("deleted node {} has no {}-arc {} in L, so every match on a D-combinatorial host dangles", L.name(v), d,
                           out.empty() ? "out" : "in");
    }
  }
  return {};
}

const ConditionVerdict* static_condition(const RuleVerdict& v, const HConstraint& c) { return v.find(c.name()); }

bool combinatorial(const RuleVerdict& v) {
  for (const auto& c : v.conditions)
    if ((c.condition == RuleCondition::incident_arcs || c.condition == RuleCondition::dangling) && !c.holds) return false;
  return true;
}

}  // namespace dartcheck::proofs
