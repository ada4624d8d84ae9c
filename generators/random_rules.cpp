#include "generators/random_rules.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

#include <fmt/format.h>

namespace dartcheck {
namespace {

// Draws every permutation of s anew, on n nodes.
void shuffle_all(Perms& s, std::size_t n, std::mt19937& rng) {
  for (auto& p : s) {
    p.resize(n);
    std::iota(p.begin(), p.end(), 0);
    std::shuffle(p.begin(), p.end(), rng);
  }
}

}  // namespace

bool perms_in_model(const Model& m, const Perms& s) {
  const std::size_t n = s[0].size();
  auto at = [&](Dim d) -> const std::vector<NodeId>& {
    return s[static_cast<std::size_t>(std::find(m.dims.begin(), m.dims.end(), d) - m.dims.begin())];
  };
  for (NodeId v = 0; v < n; ++v) {
    for (Dim d : m.dims)
      if ((!m.is_oriented(d) && at(d)[at(d)[v]] != v) || (m.loop_free && at(d)[v] == v)) return false;
    for (auto [i, j] : m.exchangeable)
      if (at(j)[at(i)[at(j)[at(i)[v]]]] != v) return false;
  }
  return true;
}

// Hooks for a random rule: the first node of each component of L.
std::vector<std::string> first_node_per_component(const TopoGraph& L) {
  int comps = 0;
  const auto comp = Rule::components(L, &comps);
  std::vector<std::string> hooks;
  std::vector<bool> seen(static_cast<std::size_t>(comps), false);
  for (NodeId v = 0; v < L.node_count(); ++v)
    if (!seen[static_cast<std::size_t>(comp[v])]) {
      seen[static_cast<std::size_t>(comp[v])] = true;
      hooks.push_back(L.name(v));
    }
  return hooks;
}

// Random small rules: L on 1-3 nodes, often a subset of the arcs of a host
// of the class (so that matches exist), sometimes arbitrary arcs; R keeps a
// random part of L and adds nodes and arcs, biased towards repairing the
// incidences it removed so that many rules are combinatorial.
Rule random_rule(std::mt19937& rng, const Model& arcs_from, const Model& model, bool any_arcs_often) {
  auto coin = [&](int percent) { return static_cast<int>(rng() % 100) < percent; };
  auto pick = [&](std::size_t n) { return static_cast<NodeId>(rng() % n); };
  const std::size_t nl = 1 + rng() % 3;
  std::vector<std::tuple<NodeId, NodeId, Dim>> larcs;
  if (coin(75)) {
    Perms s(model.dims.size());
    do shuffle_all(s, nl, rng);
    while (!perms_in_model(arcs_from, s) && !(any_arcs_often && coin(50)));
    for (std::size_t k = 0; k < model.dims.size(); ++k)
      for (NodeId v = 0; v < nl; ++v)
        if (coin(70)) larcs.emplace_back(v, s[k][v], model.dims[k]);
  } else {
    for (int k = static_cast<int>(rng() % 5); k > 0; --k) larcs.emplace_back(pick(nl), pick(nl), model.dims[rng() % model.dims.size()]);
  }
  TopoGraph L, R;
  for (NodeId v = 0; v < nl; ++v) L.add_node(fmt::format("n{}", v));
  for (auto [s, t, d] : larcs) L.add_arc(s, t, d);
  std::vector<NodeId> keep;  // L node -> R node
  for (NodeId v = 0; v < nl; ++v) keep.push_back(coin(75) ? static_cast<NodeId>(R.add_node(L.name(v))) : no_node);
  for (int k = static_cast<int>(rng() % 3); k > 0; --k) R.add_node(fmt::format("a{}", R.node_count()));
  if (R.node_count() == 0) R.add_node("a0");
  for (auto [s, t, d] : larcs)
    if (keep[s] != no_node && keep[t] != no_node && coin(60)) R.add_arc(keep[s], keep[t], d);
  // Repair: give nodes missing an out-arc one, often with its reverse.
  for (NodeId v = 0; v < R.node_count(); ++v)
    for (Dim d : model.dims)
      if (R.out_arcs(v, d).empty() && coin(70)) {
        const NodeId t = pick(R.node_count());
        R.add_arc(v, t, d);
        if (t != v && coin(50)) R.add_arc(t, v, d);
      }
  for (int k = static_cast<int>(rng() % 2); k > 0; --k) R.add_arc(pick(R.node_count()), pick(R.node_count()), model.dims[rng() % model.dims.size()]);
  return Rule("random", model, L, R, first_node_per_component(L));
}

// Random D-combinatorial rules (Def. 12) by construction, so that Theorems
// 2 and 3 see many rules that do change the host: L is part of a host of
// the class; a node may be deleted only if L gives it every incidence; per
// dimension, R joins the out-slots of its nodes (as many as in L for a
// preserved node, one for an added node) to the in-slots by a random
// bijection, half of the time pairing slots two by two into reverse arcs.
Rule random_combinatorial_rule(std::mt19937& rng, const Model& host_class, const Model& model) {
  auto coin = [&](int percent) { return static_cast<int>(rng() % 100) < percent; };
  const std::size_t nl = 1 + rng() % 3;
  Perms s(model.dims.size());
  do shuffle_all(s, nl, rng);
  while (!perms_in_model(host_class, s));
  TopoGraph L, R;
  for (NodeId v = 0; v < nl; ++v) L.add_node(fmt::format("n{}", v));
  for (std::size_t k = 0; k < model.dims.size(); ++k)
    for (NodeId v = 0; v < nl; ++v)
      if (coin(75)) L.add_arc(v, s[k][v], model.dims[k]);
  std::vector<NodeId> keep;
  for (NodeId v = 0; v < nl; ++v) {
    bool full = true;
    for (Dim d : model.dims) full = full && L.out_arcs(v, d).size() == 1 && L.in_arcs(v, d).size() == 1;
    keep.push_back(full && coin(35) ? no_node : static_cast<NodeId>(R.add_node(L.name(v))));
  }
  const std::size_t added = rng() % 3;
  for (std::size_t k = 0; k < added; ++k) R.add_node(fmt::format("a{}", k));
  const bool symmetric = coin(50);
  for (Dim d : model.dims) {
    std::vector<NodeId> outs, ins;
    for (NodeId v = 0; v < nl; ++v) {
      if (keep[v] == no_node) continue;
      if (!L.out_arcs(v, d).empty()) outs.push_back(keep[v]);
      if (!L.in_arcs(v, d).empty()) ins.push_back(keep[v]);
    }
    for (NodeId v = static_cast<NodeId>(R.node_count() - added); v < R.node_count(); ++v) {
      outs.push_back(v);
      ins.push_back(v);
    }
    std::shuffle(ins.begin(), ins.end(), rng);
    if (symmetric) {
      // Pair an out-slot with the in-slot of a node whose own out-slot can
      // come back: v -> w and w -> v, or a loop v -> v.
      std::vector<bool> out_used(outs.size(), false), in_used(ins.size(), false);
      for (std::size_t a = 0; a < outs.size(); ++a) {
        if (out_used[a]) continue;
        for (std::size_t b = 0; b < ins.size(); ++b) {
          if (in_used[b]) continue;
          const NodeId v = outs[a], w = ins[b];
          if (v == w) {
            out_used[a] = in_used[b] = true;
            R.add_arc(v, v, d);
            break;
          }
          auto back_out = std::find_if(outs.begin(), outs.end(), [&, k = std::size_t{0}](NodeId x) mutable { return !out_used[k++] && x == w; });
          auto back_in = std::find_if(ins.begin(), ins.end(), [&, k = std::size_t{0}](NodeId x) mutable { return !in_used[k++] && x == v; });
          if (back_out == outs.end() || back_in == ins.end()) continue;
          out_used[a] = in_used[b] = true;
          out_used[static_cast<std::size_t>(back_out - outs.begin())] = true;
          in_used[static_cast<std::size_t>(back_in - ins.begin())] = true;
          R.add_arc(v, w, d);
          R.add_arc(w, v, d);
          break;
        }
      }
      // Leftovers (no partner found) are joined one way.
      std::vector<NodeId> lo, li;
      for (std::size_t a = 0; a < outs.size(); ++a)
        if (!out_used[a]) lo.push_back(outs[a]);
      for (std::size_t b = 0; b < ins.size(); ++b)
        if (!in_used[b]) li.push_back(ins[b]);
      for (std::size_t k = 0; k < lo.size(); ++k) R.add_arc(lo[k], li[k], d);
    } else {
      for (std::size_t k = 0; k < outs.size(); ++k) R.add_arc(outs[k], ins[k], d);
    }
  }
  if (R.node_count() == 0) R.add_node("a0");
  return Rule("random", model, L, R, first_node_per_component(L));
}

// Arbitrary arcs over the model's dimensions, for rules far from valid.
Rule random_rule_for(std::mt19937& rng, const Model& model) {
  auto pick = [&](std::size_t n) { return static_cast<NodeId>(rng() % n); };
  TopoGraph L, R;
  const std::size_t nl = 1 + rng() % 3;
  for (NodeId v = 0; v < nl; ++v) L.add_node(fmt::format("n{}", v));
  for (int k = static_cast<int>(rng() % 6); k > 0; --k) L.add_arc(pick(nl), pick(nl), model.dims[rng() % model.dims.size()]);
  for (NodeId v = 0; v < nl; ++v)
    if (rng() % 4) R.add_node(L.name(v));
  for (int k = static_cast<int>(rng() % 3); k > 0; --k) R.add_node(fmt::format("a{}", k));
  if (R.node_count() == 0) R.add_node("a0");
  for (int k = static_cast<int>(rng() % 8); k > 0; --k) R.add_arc(pick(R.node_count()), pick(R.node_count()), model.dims[rng() % model.dims.size()]);
  return Rule("random", model, L, R, first_node_per_component(L));
}

}  // namespace dartcheck
