#include "checkers/embedding_presence.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include <fmt/format.h>

#include "core/disjoint_sets.hpp"

namespace dartcheck {
namespace {

// The pi-orbits of one side: a component id per node, through explicit
// arcs (ε-word in a scheme) labeled in <o>.
std::vector<std::size_t> orbits(const TopoGraph& g, const std::vector<ConjWord>& words, bool scheme, const std::vector<Dim>& o) {
  DisjointSets<std::size_t> orbit(g.node_count());
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    const auto& a = g.arc(e);
    if (scheme && !arc_word(words, e).empty()) continue;
    if (std::find(o.begin(), o.end(), a.label) == o.end()) continue;
    orbit.attach(a.source, a.target);
  }
  return orbit.representatives();
}

std::string names(const TopoGraph& g, const std::vector<NodeId>& nodes) {
  std::vector<std::string> out;
  for (NodeId v : nodes) out.push_back(g.name(v));
  return fmt::format("{}", fmt::join(out, ", "));
}

}  // namespace

std::string EmbeddingVerdict::name() const {
  switch (condition) {
    case EmbeddingCondition::defined:
      return fmt::format("defined({})", embedding);
    case EmbeddingCondition::merge:
      return fmt::format("merge({})", embedding);
    case EmbeddingCondition::one_value:
      return fmt::format("one-value({})", embedding);
  }
  return embedding;
}

std::vector<EmbeddingVerdict> check_embedding_presence(const Rule& rule, const ArcWords& words, const std::vector<EmbeddingDecl>& embeddings,
                                                       const std::vector<NodeExpression>& expressions) {
  const TopoGraph &L = rule.left(), &R = rule.right();
  std::vector<EmbeddingVerdict> out;
  for (const auto& ebd : embeddings) {
    const auto lo = orbits(L, words.left, words.scheme, ebd.orbit), ro = orbits(R, words.right, words.scheme, ebd.orbit);
    // Per R-orbit: its nodes, its preserved nodes, its expressions.
    std::map<std::size_t, std::vector<NodeId>> members, kept;
    std::map<std::size_t, std::vector<const NodeExpression*>> exprs;
    for (NodeId v = 0; v < R.node_count(); ++v) {
      members[ro[v]].push_back(v);
      if (rule.to_left(v) != no_node) kept[ro[v]].push_back(v);
    }
    for (const auto& x : expressions)
      if (x.embedding == ebd.name)
        if (auto v = R.find(x.node)) exprs[ro[*v]].push_back(&x);

    EmbeddingVerdict defined{EmbeddingCondition::defined, ebd.name, true, {}};
    EmbeddingVerdict merge{EmbeddingCondition::merge, ebd.name, true, {}};
    EmbeddingVerdict one{EmbeddingCondition::one_value, ebd.name, true, {}};
    for (const auto& [orbit, nodes] : members) {
      const bool labeled = exprs.contains(orbit);
      if (!kept.contains(orbit) && !labeled) {
        defined.holds = false;
        defined.witnesses.push_back({0, 'R', {}, {}, {}, ""});
        auto& w = defined.witnesses.back();
        for (NodeId v : nodes) w.nodes.push_back(R.name(v));
        w.text =
            fmt::format("added node{} {} form{} a {}-orbit <{}> with no preserved node and no {} expression: its value is undefined",
                        nodes.size() == 1 ? "" : "s", names(R, nodes), nodes.size() == 1 ? "s" : "", ebd.name, fmt::join(ebd.orbit, ","), ebd.name);
      }
      if (kept.contains(orbit) && !labeled) {
        // Preserved nodes of this R-orbit, grouped by their L-orbit.
        std::map<std::size_t, std::vector<NodeId>> from;
        for (NodeId v : kept.at(orbit)) from[lo[rule.to_left(v)]].push_back(v);
        if (from.size() > 1) {
          merge.holds = false;
          RuleWitness w{0, 'R', {}, {}, {}, ""};
          std::vector<std::string> groups;
          for (const auto& [l, vs] : from) {
            groups.push_back(fmt::format("{{{}}}", names(R, vs)));
            for (NodeId v : vs) w.nodes.push_back(R.name(v));
          }
          w.text = fmt::format(
              "preserved nodes from {} different {}-orbits of L ({}) share one {}-orbit of R, which carries no {} expression: "
              "the merged orbit gets two values",
              from.size(), ebd.name, fmt::join(groups, " "), ebd.name, ebd.name);
          merge.witnesses.push_back(std::move(w));
        }
      }
      if (labeled) {
        const auto& xs = exprs.at(orbit);
        for (std::size_t k = 1; k < xs.size(); ++k)
          if (xs[k]->code != xs[0]->code) {
            one.holds = false;
            one.witnesses.push_back({0,
                                     'R',
                                     {xs[0]->node, xs[k]->node},
                                     {},
                                     {},
                                     fmt::format("nodes {} and {} of one {}-orbit carry different expressions: \"{}\" and \"{}\"", xs[0]->node,
                                                 xs[k]->node, ebd.name, xs[0]->code, xs[k]->code)});
          }
      }
    }
    out.push_back(std::move(defined));
    out.push_back(std::move(merge));
    out.push_back(std::move(one));
  }
  return out;
}

std::vector<std::string> failing_names(const std::vector<EmbeddingVerdict>& v) {
  std::vector<std::string> out;
  for (const auto& e : v)
    if (!e.holds) out.push_back(e.name());
  return out;
}

}  // namespace dartcheck
