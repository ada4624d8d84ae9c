#include "rewriting/application.hpp"

#include "rewriting/detail/derivation.hpp"
#include "rewriting/detail/embedded_rewriter.hpp"
#include "rewriting/detail/scheme_rewriter.hpp"

namespace dartcheck {

namespace {

std::size_t total(const std::vector<std::vector<Dart>>& v) {
  std::size_t n = 0;
  for (const auto& x : v) n += x.size();
  return n;
}

// Per-node vectors of one dart each, reusing what `v` already holds.
void assign_one_each(std::vector<std::vector<Dart>>& v, const std::vector<Dart>& darts) {
  v.resize(darts.size());
  for (std::size_t k = 0; k < darts.size(); ++k) v[k].assign(1, darts[k]);
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

// The topological engine: a scheme's SchemeRewriter, or a DPO rule's
// match and derivation, with the tables kept between applications.
struct Applier::Topology {
  std::unique_ptr<SchemeRewriter> scheme;
  Application spare;  // a DPO rule's recycled tables (one vector per node)
  Match dpo_match;    // a DPO rule's match, rebuilt for its derivation
};

Applier::Applier(const Operation& op, EvaluationOptions options) : op_(op), options_(options), topology_(std::make_unique<Topology>()) {
  if (op.is_scheme()) topology_->scheme = std::make_unique<SchemeRewriter>(op.rule, op.words);
}

Applier::~Applier() = default;

Outcome<Application> Applier::match(const Map& g, std::span<const Dart> hooks) {
  Topology& t = *topology_;
  Application a = t.scheme ? Application{} : std::move(t.spare);
  a.g_size = g.size();
  if (t.scheme) {
    auto m = t.scheme->match(g, hooks);
    if (!m.ok()) return refuse<Application>(m.refusal, std::move(m.why));
    a.match = std::move(m.value->node);
    a.pattern = std::move(m.value->pattern);
  } else {
    auto m = match_from_hooks(op_.rule, g, hooks);
    if (!m.ok()) {
      t.spare = std::move(a);
      return refuse<Application>(m.refusal, std::move(m.why));
    }
    assign_one_each(a.match, m.value->node);
  }
  return {std::move(a), Refusal::none, {}};
}

Outcome<Application> Applier::rewrite(Map& g, Application&& matched) {
  Topology& t = *topology_;
  Application a = std::move(matched);
  if (t.scheme) {
    SchemeMatch m{std::move(*a.pattern), std::move(a.match)};
    SchemeDerivation d = t.scheme->rewrite(g, m);
    a.pattern = std::move(m.pattern);
    a.match = std::move(m.node);
    a.comatch = std::move(d.comatch);
    a.moved = std::move(d.moved);
    return {std::move(a), Refusal::none, {}};
  }
  t.dpo_match.node.resize(a.match.size());
  for (std::size_t x = 0; x < a.match.size(); ++x) t.dpo_match.node[x] = a.match[x][0];
  auto d = rewrite_rule(op_.rule, g, std::move(t.dpo_match));
  if (!d.ok()) {
    t.spare = std::move(a);
    return refuse<Application>(d.refusal, std::move(d.why));
  }
  t.dpo_match = std::move(d.value->match);
  assign_one_each(a.comatch, d.value->comatch);
  a.moved = std::move(d.value->moved);
  return {std::move(a), Refusal::none, {}};
}

Outcome<Application> Applier::apply(Map& g, std::span<const Dart> hooks) {
  auto m = match(g, hooks);
  if (!m.ok()) return m;
  return rewrite(g, std::move(*m.value));
}

Outcome<EmbeddedApplication> Applier::apply(EmbeddedMap& g, std::span<const Dart> hooks, bool record) {
  if (!embedded_ || embedded_map_ != &g) {
    if (embedded_) {
      const ShortcutCounts c = embedded_->kept_label_shortcuts();
      earlier_shortcuts_.taken += c.taken;
      earlier_shortcuts_.refused += c.refused;
    }
    static const RuleTerms no_terms;
    embedded_ = std::make_unique<EmbeddedRewriter>(*this, op_, op_.terms ? *op_.terms : no_terms, g, options_);
    embedded_map_ = &g;
  }
  return embedded_->apply(hooks, record);
}

void Applier::recycle(Application&& a) {
  Topology& t = *topology_;
  if (!t.scheme) {
    t.spare = std::move(a);
    return;
  }
  if (a.pattern) t.scheme->recycle(SchemeMatch{std::move(*a.pattern), std::move(a.match)});
  SchemeDerivation d;
  d.moved = std::move(a.moved);
  d.comatch = std::move(a.comatch);
  t.scheme->recycle(std::move(d));
}

Applier::ShortcutCounts Applier::kept_label_shortcuts() const {
  ShortcutCounts c = earlier_shortcuts_;
  if (embedded_) {
    c.taken += embedded_->kept_label_shortcuts().taken;
    c.refused += embedded_->kept_label_shortcuts().refused;
  }
  return c;
}

}  // namespace dartcheck
