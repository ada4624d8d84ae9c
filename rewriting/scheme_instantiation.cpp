#include "rewriting/scheme_instantiation.hpp"

#include <fmt/format.h>

namespace dartcheck {
namespace {

TopoGraph product(const TopoGraph& side, const std::vector<ConjWord>& words, const PatternGraphs& pattern) {
  const std::vector<Dart>& darts = pattern.darts.front();
  const std::size_t np = darts.size();
  TopoGraph out;
  for (NodeId x = 0; x < side.node_count(); ++x)
    for (std::size_t p = 0; p < np; ++p) out.add_node(fmt::format("{}@{}", side.name(x), darts[p]));
  auto node = [&](NodeId x, std::size_t p) { return static_cast<NodeId>(x * np + p); };
  for (ArcId e = 0; e < side.arc_count(); ++e) {
    const auto& a = side.arc(e);
    const ConjWord& w = arc_word(words, e);
    for (std::size_t p = 0; p < np; ++p) out.add_arc(node(a.source, p), node(a.target, pattern.step(p, w)), a.label);
  }
  return out;
}

}  // namespace

Rule instantiate(const Rule& core, const ArcWords& words, const PatternGraphs& pattern) {
  TopoGraph left = product(core.left(), words.left, pattern), right = product(core.right(), words.right, pattern);
  int count = 0;
  const std::vector<int> component = Rule::components(left, &count);
  std::vector<std::string> hooks(static_cast<std::size_t>(count));
  for (NodeId v = left.node_count(); v-- > 0;) hooks[static_cast<std::size_t>(component[v])] = left.name(v);
  return Rule(core.name() + "@" + std::to_string(pattern.darts.front().front()), core.model(), std::move(left), std::move(right), std::move(hooks));
}

}  // namespace dartcheck
