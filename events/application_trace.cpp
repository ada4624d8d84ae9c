#include "events/application_trace.hpp"

#include "rewriting/derivation.hpp"

namespace dartcheck::events {

Outcome<ApplicationTrace> apply_traced(const Operation& op, Map& g, std::span<const Dart> hooks) {
  ApplicationTrace t;
  t.g_size = g.size();
  if (op.words.scheme) {
    auto m = match_scheme(op.rule, op.words, g, hooks);
    if (!m.ok()) return {std::nullopt, m.refusal, std::move(m.why)};
    SchemeDerivation d = rewrite_scheme(op.rule, op.words, g, *m.value);
    t.match = std::move(m.value->node);
    t.pattern = std::move(m.value->pattern);
    t.comatch = std::move(d.comatch);
    t.moved = std::move(d.moved);
  } else {
    auto d = apply_rule(op.rule, g, hooks);
    if (!d.ok()) return {std::nullopt, d.refusal, std::move(d.why)};
    for (Dart x : d.value->match.node) t.match.push_back({x});
    for (Dart y : d.value->comatch) t.comatch.push_back({y});
    t.moved = std::move(d.value->moved);
  }
  return {std::move(t), Refusal::none, {}};
}

namespace {

std::size_t total(const std::vector<std::vector<Dart>>& v) {
  std::size_t n = 0;
  for (const auto& x : v) n += x.size();
  return n;
}

}  // namespace

Correspondence::Correspondence(const Rule& rule, const ApplicationTrace& t)
    : g2h_(total(t.match) + t.moved.size(), t.g_size),
      h2g_(total(t.comatch) + t.moved.size(), t.g_size + total(t.comatch)),
      matched_(total(t.match), t.g_size) {
  for (NodeId x = 0; x < t.match.size(); ++x)
    for (Dart d : t.match[x]) matched_.set(d, 1);
  // Unmatched darts that compaction renumbered; a moved dart that was
  // created, or matched, is already in its final place in the comatch.
  for (auto [from, to] : t.moved)
    if (from < t.g_size && !matched(from)) {
      g2h_.set(from, to);
      h2g_.set(to, from);
    }
  for (NodeId x = 0; x < t.match.size(); ++x) {
    const NodeId y = rule.to_right(x);
    for (std::size_t p = 0; p < t.match[x].size(); ++p) {
      const Dart h = y == no_node ? no_dart : t.comatch[y][p];
      g2h_.set(t.match[x][p], h == no_dart ? gone : h);
      if (h != no_dart) h2g_.set(h, t.match[x][p]);
    }
  }
  for (NodeId y = 0; y < t.comatch.size(); ++y)
    if (rule.to_left(y) == no_node)
      for (Dart h : t.comatch[y]) h2g_.set(h, gone);
}

}  // namespace dartcheck::events
