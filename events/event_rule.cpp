#include "events/event_rule.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace dartcheck::events {
namespace {

std::string arc_text(const TopoGraph& g, const Arc<int>& a, const ConjWord& w) {
  return fmt::format("{} -({},{})- {}", g.name(a.source), w.str(), a.label, g.name(a.target));
}

// Fills side.labels and side.explicit_arcs; returns why not, or "".
std::string read_side(const TopoGraph& g, const std::vector<ConjWord>& words, const std::vector<Dim>& parameter, EventSide& side, const char* which) {
  side.graph = &g;
  side.labels.assign(g.node_count(), std::vector<std::optional<Dim>>(parameter.size()));
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    const auto& a = g.arc(e);
    const ConjWord& w = arc_word(words, e);
    if (w.empty()) {
      side.explicit_arcs.push_back(e);
      continue;
    }
    if (a.source != a.target || w.size() != 1 || w.bar(0))
      return fmt::format("{} arc {} is not a Jerboa link (an implicit link is a loop whose word is one letter)", which, arc_text(g, a, w));
    const auto k = std::find(parameter.begin(), parameter.end(), w.dim(0)) - parameter.begin();
    if (k == static_cast<std::ptrdiff_t>(parameter.size()))
      return fmt::format("{} arc {}: letter {} is not in the hook's orbit type", which, arc_text(g, a, w), w.dim(0));
    auto& slot = side.labels[a.source][static_cast<std::size_t>(k)];
    if (slot) return fmt::format("{} node {} has two implicit links at position {}", which, g.name(a.source), k);
    slot = a.label;
  }
  return {};
}

}  // namespace

EventRuleOutcome event_rule(const Operation& op) {
  EventRule r;
  r.rule = &op.rule;
  if (op.is_scheme()) {
    if (op.jerboa) {
      for (const auto& d : op.jerboa->parameter) r.parameter.push_back(*d);
    } else {
      // The (W,D) notation: the parameter is the set of letters of W.
      for (const auto* ws : {&op.words.left, &op.words.right})
        for (const ConjWord& w : *ws)
          for (std::size_t k = 0; k < w.size(); ++k)
            if (std::find(r.parameter.begin(), r.parameter.end(), w.dim(k)) == r.parameter.end()) r.parameter.push_back(w.dim(k));
      std::sort(r.parameter.begin(), r.parameter.end());
    }
    if (!op.rule.model().is_generalized())
      return {std::nullopt, fmt::format("{} is not a G-map model: events of rule schemes are read from Jerboa node labels (004 Sec. 2.2), "
                                        "which only G-map schemes have",
                                        op.rule.model().name)};
  }
  for (Dim d : r.parameter) r.position_words.push_back(ConjWord::of_dims({d}));
  if (auto why = read_side(op.rule.left(), op.words.left, r.parameter, r.left, "L"); !why.empty()) return {std::nullopt, why};
  if (auto why = read_side(op.rule.right(), op.words.right, r.parameter, r.right, "R"); !why.empty()) return {std::nullopt, why};
  return {std::move(r), {}};
}

}  // namespace dartcheck::events
