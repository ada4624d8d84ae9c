#include "rewriting/rule.hpp"

#include <fmt/format.h>
#include <numeric>
#include <stdexcept>

#include "core/error.hpp"
#include "core/disjoint_sets.hpp"

namespace dartcheck {
namespace {

void check_side(const TopoGraph& g, const Model& model, const char* side) {
  for (NodeId v = 0; v < g.node_count(); ++v)
    if (g.find(g.name(v)) != v) throw ValueError(fmt::format("{} declares node '{}' twice", side, g.name(v)));
  for (const auto& a : g.arcs())
    if (!model.contains(a.label))
      throw ValueError(fmt::format("{} has an arc {} -{}-> {} whose label is not a dimension of {}", side, g.name(a.source), a.label,
                                   g.name(a.target), model.name));
}

// Marks which arcs of `a` have a partner in `b` with the same endpoints (by
// name), label and word, pairing occurrences one to one.
// Each arc of `a` takes the first unused partner of `b` in id order, as
// the pairing by scanning did; the candidates are b's arcs out of the node
// of the same name.
std::vector<bool> kept_arcs(const TopoGraph& a, const TopoGraph& b, const std::vector<ConjWord>& wa, const std::vector<ConjWord>& wb) {
  std::vector<bool> kept(a.arc_count(), false), used(b.arc_count(), false);
  for (ArcId e = 0; e < a.arc_count(); ++e) {
    const auto& x = a.arc(e);
    const auto source = b.find(a.name(x.source));
    if (!source) continue;
    for (ArcId f : b.out_arcs(*source)) {
      const auto& y = b.arc(f);
      const bool same_word = (wa.empty() ? ConjWord{} : wa[e]) == (wb.empty() ? ConjWord{} : wb[f]);
      if (!used[f] && y.label == x.label && same_word && b.name(y.target) == a.name(x.target)) {
        used[f] = kept[e] = true;
        break;
      }
    }
  }
  return kept;
}

}  // namespace

std::vector<int> Rule::components(const TopoGraph& g, int* count) {
  DisjointSets<NodeId> component(g.node_count());
  for (const auto& a : g.arcs()) component.attach(a.source, a.target);
  std::vector<int> id(g.node_count(), -1), comp(g.node_count());
  int n = 0;
  for (NodeId v = 0; v < g.node_count(); ++v) {
    const NodeId r = component.find(v);
    if (id[r] < 0) id[r] = n++;
    comp[v] = id[r];
  }
  if (count) *count = n;
  return comp;
}

Rule::Rule(std::string name, Model model, TopoGraph left, TopoGraph right, std::vector<std::string> hooks)
    : Rule(std::move(name), std::move(model), std::move(left), std::move(right), std::move(hooks), {}, {}) {}

Rule::Rule(std::string name, Model model, TopoGraph left, TopoGraph right, std::vector<std::string> hooks, const std::vector<ConjWord>& left_words,
           const std::vector<ConjWord>& right_words)
    : name_(std::move(name)), model_(std::move(model)), left_(std::move(left)), right_(std::move(right)) {
  if ((!left_words.empty() && left_words.size() != left_.arc_count()) || (!right_words.empty() && right_words.size() != right_.arc_count()))
    throw ValueError("a rule scheme needs one word per arc");
  check_side(left_, model_, "L");
  check_side(right_, model_, "R");
  for (NodeId v = 0; v < left_.node_count(); ++v) left_to_right_.push_back(right_.find(left_.name(v)).value_or(no_node));
  for (NodeId v = 0; v < right_.node_count(); ++v) right_to_left_.push_back(left_.find(right_.name(v)).value_or(no_node));
  left_arc_kept_ = kept_arcs(left_, right_, left_words, right_words);
  right_arc_kept_ = kept_arcs(right_, left_, right_words, left_words);

  int count = 0;
  const auto comp = components(left_, &count);
  std::vector<int> hooked(static_cast<std::size_t>(count), -1);
  for (const auto& h : hooks) {
    auto v = left_.find(h);
    if (!v) throw ValueError(fmt::format("hook '{}' is not a node of L", h));
    if (hooked[comp[*v]] >= 0)
      throw ValueError(fmt::format("hooks '{}' and '{}' are in the same connected component of L (one hook per component)",
                                   left_.name(static_cast<NodeId>(hooked[comp[*v]])), h));
    hooked[comp[*v]] = static_cast<int>(*v);
    hooks_.push_back(*v);
  }
  for (NodeId v = 0; v < left_.node_count(); ++v)
    if (hooked[comp[v]] < 0)
      throw ValueError(fmt::format("the connected component of L containing '{}' has no hook (one hook per component)", left_.name(v)));
}

Rule Rule::inverse(std::vector<std::string> hooks) const { return Rule(name_ + "^-1", model_, right_, left_, std::move(hooks)); }

const ConjWord& arc_word(const std::vector<ConjWord>& words, ArcId e) {
  static const ConjWord eps;
  return words.empty() ? eps : words[e];
}

}  // namespace dartcheck
