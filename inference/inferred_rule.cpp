#include "inference/inferred_rule.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <tuple>
#include <stdexcept>

namespace dartcheck::inference {

RuleOrWhy to_rule(const GraphScheme& scheme, const Model& model, const std::string& name) {
  const std::size_t count = scheme.nodes.size();
  // The L partner of each R node (through its κ-arc).
  std::vector<int> partner(count, -1);
  for (const auto& a : scheme.arcs)
    if (a.d == kappa_arc) {
      partner[static_cast<std::size_t>(a.a)] = a.b;
      partner[static_cast<std::size_t>(a.b)] = a.a;
    }
  std::vector<int> node_of_left, node_of_right;
  std::size_t preserved = 0;
  JerboaLabels labels;
  labels.parameter.assign(scheme.orbit.begin(), scheme.orbit.end());
  TopoGraph left, right;
  std::vector<ConjWord> left_words, right_words;
  // Names: L nodes n0, n1... in folding order, then the added R nodes; a
  // preserved R node takes its L node's name.
  std::vector<int> number(count, -1);
  int next = 0;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t m = 0; m < count; ++m)
      if (scheme.nodes[m].after == (pass == 1) && (pass == 0 || partner[m] < 0)) number[m] = next++;
  for (std::size_t m = 0; m < count; ++m)
    if (number[m] < 0) number[m] = number[static_cast<std::size_t>(partner[m])];
  std::vector<std::string> names(count);
  for (std::size_t m = 0; m < count; ++m) names[m] = fmt::format("n{}", number[m]);
  std::vector<NodeId> rule_node(count);
  for (std::size_t m = 0; m < count; ++m) {
    const auto& node = scheme.nodes[m];
    const bool after = node.after;
    TopoGraph& g = after ? right : left;
    rule_node[m] = g.add_node(names[m]);
    add_implicit_arcs(g, after ? right_words : left_words, rule_node[m], labels.parameter, node.label, model);
    (after ? labels.right : labels.left).push_back(node.label);
    (after ? node_of_right : node_of_left).push_back(static_cast<int>(m));
    if (!after && partner[m] >= 0) ++preserved;
  }
  // Explicit arcs: a non-loop arc is the non-oriented pair of (ε,d)-arcs,
  // a loop one (ε,d)-loop, as Jerboa modelers are read.
  for (const auto& a : scheme.arcs) {
    if (a.d == kappa_arc) continue;
    const bool after = scheme.nodes[static_cast<std::size_t>(a.a)].after;
    TopoGraph& g = after ? right : left;
    auto& words = after ? right_words : left_words;
    const NodeId x = rule_node[static_cast<std::size_t>(a.a)], y = rule_node[static_cast<std::size_t>(a.b)];
    g.add_arc(x, y, a.d);
    words.emplace_back();
    if (x != y) {
      g.add_arc(y, x, a.d);
      words.emplace_back();
    }
  }
  try {
    Rule rule(name, model, std::move(left), std::move(right), {"n0"}, left_words, right_words);
    Operation op{std::move(rule), ArcWords{true, std::move(left_words), std::move(right_words)}, std::move(labels), {}, {}, std::nullopt};
    return {InferredRule{std::move(op), std::move(node_of_left), std::move(node_of_right), preserved, std::move(names)}, {}};
  } catch (const ValueError& e) {
    return {std::nullopt, fmt::format("the inferred scheme is not a rule with one hook: {}", e.what())};
  }
}

std::optional<std::string> canonical_form(const Operation& op) {
  if (!op.jerboa || op.rule.hooks().size() != 1) return std::nullopt;
  const Rule& r = op.rule;
  // Nodes of both sides as one list: L nodes first, then R nodes.
  const std::size_t nl = r.left().node_count(), count = nl + r.right().node_count();
  auto graph = [&](std::size_t u) -> const TopoGraph& { return u < nl ? r.left() : r.right(); };
  auto words = [&](std::size_t u) -> const std::vector<ConjWord>& { return u < nl ? op.words.left : op.words.right; };
  auto local = [&](std::size_t u) { return static_cast<NodeId>(u < nl ? u : u - nl); };
  // Explicit d-neighbour per node and dimension (at most one in a rule that
  // folds a G-map; a second is a different scheme, kept in the text).
  const Dim n = r.model().dimension();
  std::vector<std::vector<std::size_t>> next(count * static_cast<std::size_t>(n + 2));
  for (std::size_t u = 0; u < count; ++u) {
    const TopoGraph& g = graph(u);
    for (ArcId e = 0; e < g.arc_count(); ++e)
      if (g.arc(e).source == local(u) && arc_word(words(u), e).empty())
        next[u * static_cast<std::size_t>(n + 2) + static_cast<std::size_t>(g.arc(e).label)].push_back(u < nl ? g.arc(e).target
                                                                                                              : nl + g.arc(e).target);
    const NodeId partner = u < nl ? r.to_right(local(u)) : r.to_left(local(u));
    if (partner != no_node) next[u * static_cast<std::size_t>(n + 2) + static_cast<std::size_t>(n + 1)].push_back(u < nl ? nl + partner : partner);
  }
  std::vector<int> number(count, -1);
  std::vector<std::size_t> order{r.hooks()[0]};
  number[r.hooks()[0]] = 0;
  for (std::size_t k = 0; k < order.size(); ++k)
    for (std::size_t d = 0; d < static_cast<std::size_t>(n + 2); ++d)
      for (std::size_t v : next[order[k] * static_cast<std::size_t>(n + 2) + d])
        if (number[v] < 0) {
          number[v] = static_cast<int>(order.size());
          order.push_back(v);
        }
  if (order.size() != count) return std::nullopt;  // not connected through its arcs and preserved nodes
  std::string s = orbit_type_str(op.jerboa->parameter);
  for (std::size_t u : order) s += fmt::format(";{}{}", u < nl ? 'L' : 'R', orbit_type_str(u < nl ? op.jerboa->left[u] : op.jerboa->right[u - nl]));
  std::vector<std::string> arcs;
  for (std::size_t u = 0; u < count; ++u)
    for (std::size_t d = 0; d <= static_cast<std::size_t>(n); ++d)
      for (std::size_t v : next[u * static_cast<std::size_t>(n + 2) + d])
        if (number[u] <= number[v]) arcs.push_back(fmt::format("{}-{}-{}", number[u], d, number[v]));
  std::sort(arcs.begin(), arcs.end());
  for (const auto& a : arcs) s += ";" + a;
  return s;
}

std::string canonical_form(const GraphScheme& scheme) {
  std::string s = fmt::format("<{}>", fmt::join(scheme.orbit, ","));
  for (std::size_t m = 0; m < scheme.nodes.size(); ++m)
    s += fmt::format(";{}{}{}", m, scheme.nodes[m].after ? 'R' : 'L', orbit_type_str(scheme.nodes[m].label));
  for (const auto& a : scheme.arcs) s += fmt::format(";{}-{}-{}", a.a, a.d == kappa_arc ? std::string("k") : std::to_string(a.d), a.b);
  return s;
}

}  // namespace dartcheck::inference

namespace dartcheck::inference {

bool does_nothing(const Operation& op) {
  if (!op.jerboa) return false;
  const Rule& r = op.rule;
  if (r.left().node_count() != r.right().node_count()) return false;
  for (NodeId v = 0; v < r.left().node_count(); ++v) {
    const NodeId w = r.to_right(v);
    if (w == no_node || op.jerboa->left[v] != op.jerboa->right[w]) return false;
  }
  // Explicit arcs (those without a word), by node names.
  auto arcs = [](const TopoGraph& g, const std::vector<ConjWord>& words) {
    std::multiset<std::tuple<std::string, std::string, Dim>> out;
    for (ArcId e = 0; e < g.arc_count(); ++e)
      if (arc_word(words, e).empty()) out.emplace(g.name(g.arc(e).source), g.name(g.arc(e).target), g.arc(e).label);
    return out;
  };
  return arcs(r.left(), op.words.left) == arcs(r.right(), op.words.right);
}

}  // namespace dartcheck::inference
