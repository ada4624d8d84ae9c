#include "rewriting/application.hpp"

#include "rewriting/derivation.hpp"

namespace dartcheck {

namespace {

std::size_t total(const std::vector<std::vector<Dart>>& v) {
  std::size_t n = 0;
  for (const auto& x : v) n += x.size();
  return n;
}

}  // namespace

Renumbering Application::renumbering(const Rule& rule, std::size_t h_size) const {
  Renumbering r(g_size, h_size, total(match) + total(comatch) + moved.size());
  // Darts of G that compaction renumbered. A matched one among them is
  // already in its final place in the comatch, so the rule's entries,
  // written after, give it the same image.
  for (auto [from, to] : moved)
    if (from < g_size) r.map(from, to);
  for (NodeId x = 0; x < match.size(); ++x) {
    const NodeId y = rule.to_right(x);
    for (std::size_t p = 0; p < match[x].size(); ++p) {
      if (y == no_node)
        r.deleted(match[x][p]);
      else
        r.map(match[x][p], comatch[y][p]);
    }
  }
  for (NodeId y = 0; y < comatch.size(); ++y)
    if (rule.to_left(y) == no_node)
      for (Dart h : comatch[y]) r.created(h);
  return r;
}

Applier::Applier(const Operation& op) : op_(op) {
  if (op.is_scheme()) scheme_ = std::make_unique<SchemeRewriter>(op.rule, op.words);
}

Applier::~Applier() = default;

namespace {

// Per-node vectors of one dart each, reusing what `v` already holds.
void assign_one_each(std::vector<std::vector<Dart>>& v, const std::vector<Dart>& darts) {
  v.resize(darts.size());
  for (std::size_t k = 0; k < darts.size(); ++k) v[k].assign(1, darts[k]);
}

}  // namespace

Outcome<Application> Applier::apply(Map& g, std::span<const Dart> hooks) {
  Application a = scheme_ ? Application{} : std::move(spare_);
  a.g_size = g.size();
  if (scheme_) {
    auto m = scheme_->match(g, hooks);
    if (!m.ok()) return {std::nullopt, m.refusal, std::move(m.why)};
    SchemeDerivation d = scheme_->rewrite(g, *m.value);
    a.match = std::move(m.value->node);
    a.pattern = std::move(m.value->pattern);
    a.comatch = std::move(d.comatch);
    a.moved = std::move(d.moved);
  } else {
    auto d = apply_rule(op_.rule, g, hooks);
    if (!d.ok()) return {std::nullopt, d.refusal, std::move(d.why)};
    assign_one_each(a.match, d.value->match.node);
    assign_one_each(a.comatch, d.value->comatch);
    a.moved = std::move(d.value->moved);
  }
  return {std::move(a), Refusal::none, {}};
}

Outcome<std::vector<std::vector<Dart>>> Applier::match(const Map& g, std::span<const Dart> hooks) {
  if (scheme_) {
    auto m = scheme_->match(g, hooks);
    if (!m.ok()) return {std::nullopt, m.refusal, std::move(m.why)};
    auto node = std::move(m.value->node);
    return {std::move(node), Refusal::none, {}};
  }
  auto m = match_from_hooks(op_.rule, g, hooks);
  if (!m.ok()) return {std::nullopt, m.refusal, std::move(m.why)};
  std::vector<std::vector<Dart>> node;
  for (Dart d : m.value->node) node.push_back({d});
  return {std::move(node), Refusal::none, {}};
}

void Applier::recycle(Application&& a) {
  if (!scheme_) {
    spare_ = std::move(a);
    return;
  }
  if (a.pattern) scheme_->recycle(SchemeMatch{std::move(*a.pattern), std::move(a.match)});
  SchemeDerivation d;
  d.moved = std::move(a.moved);
  d.comatch = std::move(a.comatch);
  scheme_->recycle(std::move(d));
}

Outcome<Application> apply(const Operation& op, Map& g, std::span<const Dart> hooks) { return Applier(op).apply(g, hooks); }

}  // namespace dartcheck
