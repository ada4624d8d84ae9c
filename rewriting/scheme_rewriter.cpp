#include "rewriting/detail/scheme_rewriter.hpp"

#include <algorithm>
#include <iterator>
#include <unordered_map>

#include <fmt/format.h>

#include "rewriting/pattern_walk.hpp"

namespace dartcheck {

std::vector<ConjWord> scheme_generators(const Model& model, const ArcWords& words) {
  const ConjugateRewriting rw(model);
  std::vector<ConjWord> gens;
  for (const auto* ws : {&words.left, &words.right})
    for (const auto& w : *ws)
      for (const ConjWord& x : {w, rw.conjugate(w)})
        if (!x.empty() && std::find(gens.begin(), gens.end(), x) == gens.end()) gens.push_back(x);
  return gens;
}

namespace {

int generator_index(const std::vector<ConjWord>& gens, const ConjWord& w) {
  return w.empty() ? -1 : static_cast<int>(std::find(gens.begin(), gens.end(), w) - gens.begin());
}

// The letter of each generator read as one link (a one-letter word
// without a bar: every word of a G-map scheme's implicit arcs), -1 for a
// word followed as a path.
std::vector<int> letters_of(const std::vector<ConjWord>& gens) {
  std::vector<int> letter(gens.size(), -1);
  for (std::size_t w = 0; w < gens.size(); ++w)
    if (gens[w].size() == 1 && !gens[w].bar(0)) letter[w] = gens[w].dim(0);
  return letter;
}

// P_v by BFS into `out` (its vectors reused); position[d] is d's position
// in P_v (the table is none everywhere between calls, and cleared through
// the pattern's own darts, which are exactly the darts it set), and
// shift[k][p] the position of p·gens[k], recorded as the BFS follows it
// (so every p·w is a table lookup, not a walk). With several hooks (one
// per component of L, Sec. 6.3) every P_{v_k} is walked in the same order
// and must give the same tables: the pattern graphs are isomorphic, and
// darts[k][p] is the image of pattern node p under that isomorphism. On
// refusal sets `refusal` and `why`. The walk is pattern_walk.hpp's, which
// the generated code shares.
bool walk_patterns(const Map& g, std::span<const Dart> hook_darts, const std::vector<int>& letter, std::vector<std::uint32_t>& position,
                   std::vector<Dart>& queue, PatternGraphs& out, Refusal& refusal, std::string& why) {
  if (position.size() < g.size()) position.resize(g.size(), DartTable::none);
  if (queue.size() < g.size() + 1) queue.resize(g.size() + 1);
  out.shift.resize(out.gens.size());
  for (auto& s : out.shift) s.clear();
  out.darts.resize(hook_darts.size());
  auto follow_generator = [&](std::size_t w, Dart d) { return letter[w] >= 0 ? g.link(letter[w], d) : follow(g, d, out.gens[w]); };
  const PatternWalkStop stop =
      walk_pattern_graphs(hook_darts, out.gens.size(), follow_generator, position, queue, out.shift,
                          [&](std::size_t h, std::span<const Dart> darts) { out.darts[h].assign(darts.begin(), darts.end()); });
  if (stop.kind == PatternWalkStop::no_path) {
    refusal = Refusal::not_combinatorial;
    why = fmt::format("dart {} has no {}-path: the host is not combinatorial", stop.at, out.gens[stop.generator].str());
  } else if (stop.kind == PatternWalkStop::not_isomorphic) {
    refusal = Refusal::no_match;
    why = fmt::format("the pattern graphs of hook darts {} and {} are not isomorphic (Sec. 6.3 needs one pattern for every component of L)",
                      hook_darts[0], hook_darts[stop.hook]);
  }
  return stop.kind == PatternWalkStop::none;
}

}  // namespace

Outcome<PatternGraphs> pattern_graphs(const Model& model, const ArcWords& words, const Map& g, std::span<const Dart> hook_darts) {
  PatternGraphs out;
  out.gens = scheme_generators(model, words);
  std::vector<std::uint32_t> position;
  std::vector<Dart> queue;
  Refusal refusal = Refusal::none;
  std::string why;
  if (!walk_patterns(g, hook_darts, letters_of(out.gens), position, queue, out, refusal, why)) return refuse<PatternGraphs>(refusal, std::move(why));
  return {std::move(out), Refusal::none, {}};
}

int PatternGraphs::generator(const ConjWord& w) const { return generator_index(gens, w); }

// What an application derives from the rule alone, in the order
// match_scheme checks it, and the tables reused across applications.
struct SchemeRewriter::State {
  const Rule& core;
  const ArcWords& words;
  std::vector<ConjWord> gens;
  std::vector<int> letter;  // letters_of(gens)
  // Generator index of each arc's word, forward (L, R) and backward (L).
  std::vector<int> left_fwd, left_bwd, right_fwd;
  // The arcs of L at each node, as the propagation follows them: out of
  // the node (forward, loops included) or into it (backward).
  struct Step {
    ArcId arc;
    Dim label;
    bool forward;
    int generator;
    NodeId other;
  };
  std::vector<std::vector<Step>> steps;
  // The refusals and placements that depend on the rule alone
  // (scheme_facts: two L arcs with one label, dangling, representability,
  // the identity match).
  std::string two_arcs_in_l;
  std::vector<SchemeFacts::Dangling> dangling;
  std::vector<SchemeFacts::Added> added;
  std::size_t added_nodes = 0;
  bool identity_match = false;

  // position[d]: d's position in P_v while a pattern is walked, then a
  // mark of matched darts (injectivity); none between uses. pattern_queue:
  // the walk's queue (longer than the map).
  std::vector<std::uint32_t> position;
  std::vector<Dart> pattern_queue;
  PatternGraphs spare_pattern;
  std::vector<std::vector<Dart>> spare_match, spare_comatch;
  std::vector<std::pair<std::uint32_t, NodeId>> queue;
  std::vector<Dart> holes;

  State(const Rule& r, const ArcWords& w);
  Outcome<SchemeMatch> match(const Map& g, std::span<const Dart> hook_darts);
  SchemeDerivation rewrite(Map& g, const SchemeMatch& match);

  // match's steps, each a refusal or nothing.
  struct Refused {
    Refusal refusal;
    std::string why;
  };
  std::optional<Refused> propagate(const Map& g, std::span<const Dart> hook_darts, const PatternGraphs& pg, std::vector<std::vector<Dart>>& m);
  std::optional<Refused> check_injective(const Map& g, const std::vector<Dart>& pattern, const std::vector<std::vector<Dart>>& m);
  std::optional<Refused> check_applicable(const Map& g, std::size_t np, const std::vector<std::vector<Dart>>& m) const;
};

SchemeRewriter::State::State(const Rule& r, const ArcWords& w) : core(r), words(w), gens(scheme_generators(r.model(), w)), letter(letters_of(gens)) {
  SchemeFacts facts = scheme_facts(r, w);
  two_arcs_in_l = std::move(facts.two_arcs_in_l);
  dangling = std::move(facts.dangling);
  added = std::move(facts.added);
  added_nodes = facts.added_nodes;
  identity_match = facts.identity_match;
  const ConjugateRewriting rw(core.model());
  const TopoGraph &L = core.left(), &R = core.right();
  for (ArcId e = 0; e < L.arc_count(); ++e) {
    left_fwd.push_back(generator_index(gens, arc_word(words.left, e)));
    left_bwd.push_back(generator_index(gens, rw.conjugate(arc_word(words.left, e))));
  }
  for (ArcId e = 0; e < R.arc_count(); ++e) right_fwd.push_back(generator_index(gens, arc_word(words.right, e)));
  // Each node's arcs in id order, a loop once (forward); by the graph's
  // incidence lists, so building the state is linear in the rule.
  steps.resize(L.node_count());
  for (NodeId x = 0; x < L.node_count(); ++x) {
    std::vector<ArcId> incident;
    std::merge(L.out_arcs(x).begin(), L.out_arcs(x).end(), L.in_arcs(x).begin(), L.in_arcs(x).end(), std::back_inserter(incident));
    incident.erase(std::unique(incident.begin(), incident.end()), incident.end());
    for (ArcId e : incident) {
      const auto& a = L.arc(e);
      if (a.source == x)
        steps[x].push_back({e, a.label, true, left_fwd[e], a.target});
      else
        steps[x].push_back({e, a.label, false, left_bwd[e], a.source});
    }
  }
}

SchemeFacts scheme_facts(const Rule& core, const ArcWords& words) {
  const TopoGraph &L = core.left(), &R = core.right();
  SchemeFacts f;
  f.gens = scheme_generators(core.model(), words);
  // L is the hook alone and each of its arcs a loop x -(i, i)-> x on a
  // non-oriented dimension i, and every generator of W is one of these
  // letters: the match is then (p, hook) -> the p-th dart of P_v. (The
  // propagation would find it: following letter i from the p-th dart is
  // the p·i-th dart, and P_v, the closure under these letters, is every
  // position reached; the darts of P_v are distinct, so it is injective.)
  // Jerboa's hook node <0,1,...> is this case.
  f.identity_match = L.node_count() == 1 && core.hooks().size() == 1;
  std::vector<Dim> loops;
  for (ArcId e = 0; e < L.arc_count() && f.identity_match; ++e) {
    const ConjWord& word = arc_word(words.left, e);
    const Dim i = L.arc(e).label;
    f.identity_match = word.size() == 1 && !word.bar(0) && word.dim(0) == i && !core.model().is_oriented(i);
    loops.push_back(i);
  }
  for (const ConjWord& w : f.gens)
    f.identity_match = f.identity_match && w.size() == 1 && !w.bar(0) && std::find(loops.begin(), loops.end(), w.dim(0)) != loops.end();
  for (ArcId e = 0; e < L.arc_count() && f.two_arcs_in_l.empty(); ++e)
    for (ArcId g : L.out_arcs(L.arc(e).source))
      if (g > e && L.arc(e).label == L.arc(g).label) {
        f.two_arcs_in_l = fmt::format("L has two {}-arcs out of {}: their instances share one arc", L.arc(e).label, L.name(L.arc(e).source));
        break;
      }
  auto has_label = [](const TopoGraph& g, const std::vector<ArcId>& arcs, Dim i) {
    return std::any_of(arcs.begin(), arcs.end(), [&](ArcId e) { return g.arc(e).label == i; });
  };
  for (NodeId x = 0; x < L.node_count(); ++x) {
    if (core.to_right(x) != no_node) continue;
    for (Dim i : core.model().dims) {
      const bool out = has_label(L, L.out_arcs(x), i), in = has_label(L, L.in_arcs(x), i);
      if (!out || !in) f.dangling.push_back({x, i, out, in});
    }
  }
  for (ArcId e = 0; e < R.arc_count(); ++e) {
    if (core.preserved_right_arc(e)) continue;
    const auto& a = R.arc(e);
    SchemeFacts::Added x{e, {}, core.to_left(a.source), a.label, false, false};
    for (ArcId g : R.out_arcs(a.source))
      if (g > e && !core.preserved_right_arc(g) && R.arc(g).label == a.label) {
        x.always = fmt::format("R adds two {}-arcs out of {}", a.label, R.name(a.source));
        break;
      }
    if (x.x != no_node) {
      for (ArcId g : L.out_arcs(x.x)) x.freed |= !core.preserved_left_arc(g) && L.arc(g).label == a.label;
      for (ArcId g : R.out_arcs(a.source)) x.kept |= core.preserved_right_arc(g) && R.arc(g).label == a.label;
    }
    f.added.push_back(std::move(x));
  }
  for (NodeId y = 0; y < R.node_count(); ++y) f.added_nodes += core.to_left(y) == no_node;
  return f;
}

// The match: m[x][p] is the image of product node (p, x), propagated from
// (v, hook) -> v along the instantiated arcs (p, x) -(d)-> (p·w, y).
std::optional<SchemeRewriter::State::Refused> SchemeRewriter::State::propagate(const Map& g, std::span<const Dart> hook_darts,
                                                                               const PatternGraphs& pg, std::vector<std::vector<Dart>>& m) {
  const TopoGraph& L = core.left();
  const auto& shift = pg.shift;
  const std::vector<Dart>& pattern = pg.darts[0];
  auto step = [&](std::size_t p, int k) { return k < 0 ? static_cast<std::uint32_t>(p) : shift[static_cast<std::size_t>(k)][p]; };
  for (auto& column : m) column.assign(pattern.size(), no_dart);
  queue.clear();
  for (std::size_t h = 0; h < hook_darts.size(); ++h) {
    const NodeId hook = core.hooks()[h];
    if (m[hook][0] != no_dart) return Refused{Refusal::bad_hooks, "two hooks name one node of L"};
    m[hook][0] = hook_darts[h];
    queue.emplace_back(0, hook);
  }
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const auto [p, x] = queue[k];
    const Dart here = m[x][p];
    for (const Step& s : steps[x]) {
      const std::uint32_t q = step(p, s.generator);
      const Dart there = s.forward ? g.link(s.label, here) : g.inverse_link(s.label, here);
      if (there == no_dart) {
        const auto& a = L.arc(s.arc);
        return Refused{Refusal::no_match, fmt::format("arc {} -{}-> {} of L at pattern dart {}: dart {} has no {}-arc", L.name(a.source), a.label,
                                                      L.name(a.target), pattern[p], here, a.label)};
      }
      Dart& slot = m[s.other][q];
      if (slot == no_dart) {
        slot = there;
        queue.emplace_back(q, s.other);
      } else if (slot != there) {
        return Refused{Refusal::no_match, fmt::format("node ({}, {}) of the instantiated L would be both dart {} and dart {}", pattern[q],
                                                      L.name(s.other), slot, there)};
      }
    }
  }
  return std::nullopt;
}

// Injectivity on nodes; every product node matched (ι(L, P_v) connected).
// The marks are cleared through the matched darts met.
std::optional<SchemeRewriter::State::Refused> SchemeRewriter::State::check_injective(const Map& g, const std::vector<Dart>& pattern,
                                                                                     const std::vector<std::vector<Dart>>& m) {
  const TopoGraph& L = core.left();
  const std::size_t np = pattern.size();
  constexpr std::uint32_t none = DartTable::none;
  std::size_t marked = 0;
  auto unmark = [&] {
    for (NodeId x = 0; x < L.node_count() && marked > 0; ++x)
      for (std::size_t p = 0; p < np && marked > 0; ++p, --marked) position[m[x][p]] = none;
  };
  if (position.size() < g.size()) position.resize(g.size(), none);
  for (NodeId x = 0; x < L.node_count(); ++x)
    for (std::size_t p = 0; p < np; ++p) {
      const Dart d = m[x][p];
      if (d == no_dart) {
        unmark();
        return Refused{Refusal::disconnected, fmt::format("node ({}, {}) of the instantiated L is unreachable from the hooks: ι(L, P_v) is not "
                                                          "connected, so the hooks do not fix the match (002 Sec. 6.3)",
                                                          pattern[p], L.name(x))};
      }
      if (position[d] != none) {
        unmark();
        return Refused{Refusal::not_injective, fmt::format("two nodes of the instantiated L match dart {}", d)};
      }
      position[d] = 0;
      ++marked;
    }
  unmark();
  return std::nullopt;
}

// The rule's own refusals on a match: arc injectivity (two arcs of L out
// of one node with one label share their images), dangling (a deleted
// node needs an L arc in and out for every dimension its darts carry),
// representability per scheme arc (the same for every pattern node).
std::optional<SchemeRewriter::State::Refused> SchemeRewriter::State::check_applicable(const Map& g, std::size_t np,
                                                                                      const std::vector<std::vector<Dart>>& m) const {
  const TopoGraph &L = core.left(), &R = core.right();
  if (!two_arcs_in_l.empty()) return Refused{Refusal::not_injective, two_arcs_in_l};
  for (const SchemeFacts::Dangling& c : dangling)
    for (std::size_t p = 0; p < np; ++p)
      if ((!c.out && g.link(c.i, m[c.x][p]) != no_dart) || (!c.in && g.inverse_link(c.i, m[c.x][p]) != no_dart))
        return Refused{Refusal::dangling, fmt::format("deleted dart {} (node {}) keeps a {}-arc outside the match", m[c.x][p], L.name(c.x), c.i)};
  for (ArcId e = 0, k = 0; e < R.arc_count(); ++e) {
    if (core.preserved_right_arc(e)) continue;
    const SchemeFacts::Added& a = added[k++];
    if (!a.always.empty()) return Refused{Refusal::not_representable, a.always};
    if (a.x == no_node) continue;
    for (std::size_t p = 0; p < np && !a.freed; ++p)
      if (a.kept || g.link(a.label, m[a.x][p]) != no_dart)
        return Refused{Refusal::not_representable,
                       fmt::format("R adds a {}-arc out of {} whose dart {} keeps its {}-arc", a.label, R.name(R.arc(e).source), m[a.x][p], a.label)};
  }
  return std::nullopt;
}

Outcome<SchemeMatch> SchemeRewriter::State::match(const Map& g, std::span<const Dart> hook_darts) {
  if (hook_darts.size() != core.hooks().size())
    return refuse<SchemeMatch>(Refusal::bad_hooks, fmt::format("the scheme needs {} hook dart{}, one per component of L", core.hooks().size(),
                                                               core.hooks().size() == 1 ? "" : "s"));
  for (Dart h : hook_darts)
    if (h >= g.size()) return refuse<SchemeMatch>(Refusal::bad_hooks, fmt::format("hook dart {} is not below {}", h, g.size()));
  SchemeMatch found{std::move(spare_pattern), std::move(spare_match)};
  PatternGraphs& pg = found.pattern;
  pg.gens = gens;
  {
    Refusal refusal = Refusal::none;
    std::string why;
    if (!walk_patterns(g, hook_darts, letter, position, pattern_queue, pg, refusal, why)) {
      spare_pattern = std::move(pg);
      spare_match = std::move(found.node);
      return refuse<SchemeMatch>(refusal, std::move(why));
    }
  }
  const std::vector<Dart>& pattern = pg.darts[0];
  auto& m = found.node;
  m.resize(core.left().node_count());
  std::optional<Refused> refused;
  if (identity_match)
    m[0].assign(pattern.begin(), pattern.end());
  else if (!(refused = propagate(g, hook_darts, pg, m)))
    refused = check_injective(g, pattern, m);
  if (!refused) refused = check_applicable(g, pattern.size(), m);
  if (refused) {  // the tables are handed back for the next match
    spare_pattern = std::move(found.pattern);
    spare_match = std::move(found.node);
    return refuse<SchemeMatch>(refused->refusal, std::move(refused->why));
  }
  return {std::move(found), Refusal::none, {}};
}

SchemeDerivation SchemeRewriter::State::rewrite(Map& g, const SchemeMatch& match) {
  const TopoGraph &L = core.left(), &R = core.right();
  const auto& m = match.node;
  const std::size_t np = match.pattern.darts[0].size();
  const auto& shift = match.pattern.shift;
  auto step = [&](std::size_t p, int k) { return k < 0 ? static_cast<std::uint32_t>(p) : shift[static_cast<std::size_t>(k)][p]; };

  // Rewrite: delete the instances of L \ K, place R's nodes, add R \ K.
  SchemeDerivation out{np, np * L.node_count(), 0, {}, std::move(spare_comatch)};
  for (ArcId e = 0; e < L.arc_count(); ++e)
    if (!core.preserved_left_arc(e))
      for (std::size_t p = 0; p < np; ++p) g.remove_link(L.arc(e).label, m[L.arc(e).source][p]);
  holes.clear();
  for (NodeId x = 0; x < L.node_count(); ++x)
    if (core.to_right(x) == no_node) holes.insert(holes.end(), m[x].begin(), m[x].end());
  auto& c = out.comatch;
  c.resize(R.node_count());
  const std::size_t reuse = std::min(holes.size(), added_nodes * np);
  const Dart first_new = added_nodes * np > reuse ? g.add_darts(added_nodes * np - reuse) : no_dart;
  std::size_t next_new = 0, next_hole = 0;
  for (NodeId y = 0; y < R.node_count(); ++y) {
    if (core.to_left(y) != no_node) {
      c[y].assign(m[core.to_left(y)].begin(), m[core.to_left(y)].end());
      continue;
    }
    c[y].resize(np);
    for (auto& d : c[y]) d = next_hole < reuse ? holes[next_hole++] : static_cast<Dart>(first_new + next_new++);
  }
  out.added_darts = added_nodes * np;
  for (ArcId e = 0; e < R.arc_count(); ++e) {
    if (core.preserved_right_arc(e)) continue;
    const auto& a = R.arc(e);
    // shift was read on G before the rewrite began.
    const int w = right_fwd[e];
    const std::vector<Dart>&from = c[a.source], &to = c[a.target];
    for (std::size_t p = 0; p < np; ++p) g.set_link(a.label, from[p], to[step(p, w)]);
  }
  if (holes.size() > reuse) {
    // Fewer darts added than deleted: the last darts fill the holes.
    holes.erase(holes.begin(), holes.begin() + static_cast<std::ptrdiff_t>(reuse));
    std::vector<Dart> sources;
    for (const auto& darts : c) sources.insert(sources.end(), darts.begin(), darts.end());
    out.moved = compact(g, holes, sources);
    if (!out.moved.empty()) {
      std::unordered_map<Dart, Dart> renumbered(out.moved.begin(), out.moved.end());
      for (auto& darts : c)
        for (Dart& d : darts)
          if (const auto it = renumbered.find(d); it != renumbered.end()) d = it->second;
    }
  }
  return out;
}

SchemeRewriter::SchemeRewriter(const Rule& core, const ArcWords& words) : s_(std::make_unique<State>(core, words)) {}
SchemeRewriter::~SchemeRewriter() = default;

Outcome<SchemeMatch> SchemeRewriter::match(const Map& g, std::span<const Dart> hook_darts) { return s_->match(g, hook_darts); }
SchemeDerivation SchemeRewriter::rewrite(Map& g, const SchemeMatch& match) { return s_->rewrite(g, match); }

Outcome<SchemeDerivation> SchemeRewriter::apply(Map& g, std::span<const Dart> hook_darts) {
  auto found = s_->match(g, hook_darts);
  if (!found.ok()) return refuse<SchemeDerivation>(found.refusal, std::move(found.why));
  Outcome<SchemeDerivation> out{s_->rewrite(g, *found.value), Refusal::none, {}};
  recycle(std::move(*found.value));
  return out;
}

void SchemeRewriter::recycle(SchemeMatch&& m) {
  s_->spare_pattern = std::move(m.pattern);
  s_->spare_match = std::move(m.node);
}

void SchemeRewriter::recycle(SchemeDerivation&& d) { s_->spare_comatch = std::move(d.comatch); }

Outcome<SchemeDerivation> apply_scheme(const Rule& core, const ArcWords& words, Map& g, std::span<const Dart> hook_darts) {
  return SchemeRewriter(core, words).apply(g, hook_darts);
}

Outcome<SchemeMatch> match_scheme(const Rule& core, const ArcWords& words, const Map& g, std::span<const Dart> hook_darts) {
  return SchemeRewriter(core, words).match(g, hook_darts);
}

SchemeDerivation rewrite_scheme(const Rule& core, const ArcWords& words, Map& g, const SchemeMatch& match) {
  return SchemeRewriter(core, words).rewrite(g, match);
}

}  // namespace dartcheck
