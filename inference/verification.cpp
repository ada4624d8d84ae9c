#include "inference/verification.hpp"

#include <fmt/format.h>

#include "rewriting/application.hpp"

namespace dartcheck::inference {

Verification verify(const KappaGraph& graph, const GraphScheme& scheme, const InferredRule& rule, Dart start) {
  const Operation& op = rule.operation;
  Map host = graph.before();
  const Dart hooks[] = {start};
  Applier applier(op);
  auto match = applier.match(host, hooks);
  if (!match.ok()) return {false, fmt::format("the scheme does not apply to the before map at dart {}: {}", start, match.why)};
  if (!match.value->pattern) return {false, "the inferred operation is not a rule scheme"};
  const std::vector<Dart> pattern = match.value->pattern->darts[0];  // the rewrite takes the match's tables
  const auto& hook_darts = scheme.nodes[0].darts;
  if (pattern.size() != hook_darts.size())
    return {false, fmt::format("the pattern of dart {} has {} darts, the folded orbit {}", start, pattern.size(), hook_darts.size())};
  // Orbit position of each G dart of the hook orbit.
  std::vector<std::uint32_t> position(graph.before().size(), 0);
  std::vector<bool> in_orbit(graph.before().size(), false);
  for (std::size_t q = 0; q < hook_darts.size(); ++q) {
    position[hook_darts[q]] = static_cast<std::uint32_t>(q);
    in_orbit[hook_darts[q]] = true;
  }
  for (std::size_t p = 0; p < pattern.size(); ++p)
    if (!in_orbit[pattern[p]]) return {false, fmt::format("pattern dart {} is not in the folded orbit", pattern[p])};
  // The match must be the folding's L darts.
  for (std::size_t x = 0; x < rule.node_of_left.size(); ++x) {
    const auto& node = scheme.nodes[static_cast<std::size_t>(rule.node_of_left[x])];
    for (std::size_t p = 0; p < pattern.size(); ++p)
      if (match.value->match[x][p] != graph.local(node.darts[position[pattern[p]]]))
        return {false,
                fmt::format("node {} at pattern dart {} matches G dart {}, the folding put {} there", op.rule.left().name(static_cast<NodeId>(x)),
                            pattern[p], match.value->match[x][p], graph.name(node.darts[position[pattern[p]]]))};
  }
  const auto rewritten = applier.rewrite(host, std::move(*match.value));
  if (!rewritten.ok()) return {false, fmt::format("the scheme refuses to rewrite the before map at dart {}: {}", start, rewritten.why)};
  const Application& derivation = *rewritten.value;
  if (host.size() != graph.after().size())
    return {false, fmt::format("the result has {} darts, the after map {}", host.size(), graph.after().size())};
  std::vector<Dart> renumbered(graph.before().size());
  for (Dart x = 0; x < renumbered.size(); ++x) renumbered[x] = x;
  for (const auto& [from, to] : derivation.moved)
    if (from < renumbered.size()) renumbered[from] = to;
  // phi: result dart -> after dart.
  std::vector<Dart> phi(host.size(), no_dart);
  for (std::size_t y = 0; y < rule.node_of_right.size(); ++y) {
    const int s = rule.node_of_right[y];
    const auto& node = scheme.nodes[static_cast<std::size_t>(s)];
    const auto left = op.rule.to_left(static_cast<NodeId>(y));
    for (std::size_t p = 0; p < pattern.size(); ++p) {
      const Dart r = derivation.comatch[y][p];
      const Dart h = graph.local(node.darts[position[pattern[p]]]);
      if (r >= phi.size() || phi[r] != no_dart) return {false, fmt::format("result dart {} is the image of two darts of the instantiated R", r)};
      phi[r] = h;
      if (left != no_node) {
        // Preserved: the result keeps the matched dart, and κ sends it to h.
        const Dart g = derivation.match[left][p];
        if (renumbered[g] != r) return {false, fmt::format("preserved G dart {} became result dart {}, not {}", g, renumbered[g], r)};
        if (graph.kappa(g) == no_dart || graph.local(graph.kappa(g)) != h)
          return {false, fmt::format("preserved G dart {} lands on H dart {}, but κ sends it elsewhere", g, h)};
      }
    }
  }
  for (Dart r = 0; r < phi.size(); ++r)
    if (phi[r] == no_dart) return {false, fmt::format("result dart {} comes from no node of R", r)};
  for (Dart r = 0; r < phi.size(); ++r)
    for (Dim d : host.model().dims) {
      const Dart t = host.link(d, r);
      if (t == no_dart || phi[t] != graph.after().link(d, phi[r]))
        return {false, fmt::format("result dart {} is {}-linked to {}, but H dart {} is {}-linked to {}", r, d,
                                   t == no_dart ? -1L : static_cast<long>(t), phi[r], d, static_cast<long>(graph.after().link(d, phi[r])))};
    }
  // Every preserved dart of G is in the match, so κ is extended.
  for (Dart g = 0; g < graph.before().size(); ++g)
    if (graph.kappa(g) != no_dart && phi[renumbered[g]] != graph.local(graph.kappa(g)))
      return {false, fmt::format("κ sends G dart {} to H dart {}, the result to {}", g, graph.local(graph.kappa(g)), phi[renumbered[g]])};
  return {true, {}};
}

}  // namespace dartcheck::inference
