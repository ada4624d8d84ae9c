#include "rewriting/scheme_application.hpp"

#include <algorithm>
#include <unordered_map>

#include <fmt/format.h>

namespace dartcheck {
namespace {

template <class T>
Outcome<T> refuse(Refusal r, std::string why) {
  return {std::nullopt, r, std::move(why)};
}

}  // namespace

Outcome<PatternGraphs> pattern_graphs(const Model& model, const ArcWords& words, const Map& g, std::span<const Dart> hook_darts,
                                      DartTable* scratch) {
  const ConjugateRewriting rw(model);
  PatternGraphs out;
  // W: the words of the scheme, each with its conjugate (P_v takes the
  // darts reachable to and from v).
  for (const auto* ws : {&words.left, &words.right})
    for (const auto& w : *ws)
      for (const ConjWord& x : {w, rw.conjugate(w)})
        if (!x.empty() && std::find(out.gens.begin(), out.gens.end(), x) == out.gens.end()) out.gens.push_back(x);

  // P_v by BFS; index[d] is d's position in P_v, and shift[k][p] the
  // position of p·gens[k], recorded as the BFS follows it (so every p·w
  // is a table lookup, not a walk). With several hooks (one per
  // component of L, Sec. 6.3) every P_{v_k} is walked in the same order
  // and must give the same tables: the pattern graphs are isomorphic, and
  // darts[k][p] is the image of pattern node p under that isomorphism.
  constexpr std::uint32_t none = DartTable::none;
  DartTable local;
  DartTable& index = scratch ? *scratch : local;
  const DartTable::ClearOnExit emptied{index};
  out.shift.resize(out.gens.size());
  out.darts.resize(hook_darts.size());
  for (std::size_t h = 0; h < hook_darts.size(); ++h) {
    std::vector<Dart>& pattern = out.darts[h];
    pattern.push_back(hook_darts[h]);
    index.set(hook_darts[h], 0);
    for (std::size_t k = 0; k < pattern.size(); ++k)
      for (std::size_t w = 0; w < out.gens.size(); ++w) {
        const Dart t = follow(g, pattern[k], out.gens[w]);
        if (t == no_dart)
          return refuse<PatternGraphs>(Refusal::not_combinatorial, fmt::format("dart {} has no {}-path: the host is not combinatorial",
                                                                               pattern[k], out.gens[w].str()));
        std::uint32_t at = index.get(t);
        if (at == none) {
          at = static_cast<std::uint32_t>(pattern.size());
          index.set(t, at);
          pattern.push_back(t);
        }
        if (h == 0) {
          out.shift[w].push_back(at);
        } else if (out.shift[w][k] != at) {
          return refuse<PatternGraphs>(Refusal::no_match,
                                       fmt::format("the pattern graphs of hook darts {} and {} are not isomorphic (Sec. 6.3 needs one "
                                                   "pattern for every component of L)",
                                                   hook_darts[0], hook_darts[h]));
        }
      }
    index.clear();
  }
  return {std::move(out), Refusal::none, {}};
}

int PatternGraphs::generator(const ConjWord& w) const {
  return w.empty() ? -1 : static_cast<int>(std::find(gens.begin(), gens.end(), w) - gens.begin());
}

namespace {

// Generator index of each arc's word, forward (L, R) and backward (L).
struct ArcGenerators {
  std::vector<int> left_fwd, left_bwd, right_fwd;
  ArcGenerators(const Rule& core, const ArcWords& words, const std::vector<ConjWord>& gens) {
    const ConjugateRewriting rw(core.model());
    auto gen_of = [&](const ConjWord& w) { return w.empty() ? -1 : static_cast<int>(std::find(gens.begin(), gens.end(), w) - gens.begin()); };
    const TopoGraph &L = core.left(), &R = core.right();
    left_fwd.resize(L.arc_count());
    left_bwd.resize(L.arc_count());
    right_fwd.resize(R.arc_count());
    for (ArcId e = 0; e < L.arc_count(); ++e) {
      left_fwd[e] = gen_of(arc_word(words.left, e));
      left_bwd[e] = gen_of(rw.conjugate(arc_word(words.left, e)));
    }
    for (ArcId e = 0; e < R.arc_count(); ++e) right_fwd[e] = gen_of(arc_word(words.right, e));
  }
};

}  // namespace

Outcome<SchemeDerivation> apply_scheme(const Rule& core, const ArcWords& words, Map& g, std::span<const Dart> hook_darts) {
  auto found = match_scheme(core, words, g, hook_darts);
  if (!found.ok()) return refuse<SchemeDerivation>(found.refusal, std::move(found.why));
  return {rewrite_scheme(core, words, g, *found.value), Refusal::none, {}};
}

Outcome<SchemeMatch> match_scheme(const Rule& core, const ArcWords& words, const Map& g, std::span<const Dart> hook_darts,
                                  DartTable* scratch) {
  const TopoGraph &L = core.left(), &R = core.right();
  if (hook_darts.size() != core.hooks().size())
    return refuse<SchemeMatch>(Refusal::bad_hooks, fmt::format("the scheme needs {} hook dart{}, one per component of L", core.hooks().size(),
                                                  core.hooks().size() == 1 ? "" : "s"));
  for (Dart h : hook_darts)
    if (h >= g.size()) return refuse<SchemeMatch>(Refusal::bad_hooks, fmt::format("hook dart {} is not below {}", h, g.size()));
  auto found = pattern_graphs(core.model(), words, g, hook_darts, scratch);
  if (!found.ok()) return refuse<SchemeMatch>(found.refusal, std::move(found.why));
  const PatternGraphs& pg = *found.value;
  const auto& shift = pg.shift;
  const std::vector<Dart>& pattern = pg.darts[0];
  const std::size_t np = pattern.size();
  auto step = [&](std::size_t p, int k) { return k < 0 ? static_cast<std::uint32_t>(p) : shift[static_cast<std::size_t>(k)][p]; };
  const ArcGenerators ag(core, words, pg.gens);
  const auto &left_fwd = ag.left_fwd, &left_bwd = ag.left_bwd;

  // The match: m[x][p] is the image of product node (p, x), propagated from
  // (v, hook) -> v along the instantiated arcs (p, x) -(d)-> (p·w, y).
  std::vector<std::vector<Dart>> m(L.node_count(), std::vector<Dart>(np, no_dart));
  std::vector<std::pair<std::uint32_t, NodeId>> queue;
  for (std::size_t h = 0; h < hook_darts.size(); ++h) {
    const NodeId hook = core.hooks()[h];
    if (m[hook][0] != no_dart) return refuse<SchemeMatch>(Refusal::bad_hooks, "two hooks name one node of L");
    m[hook][0] = hook_darts[h];
    queue.emplace_back(0, hook);
  }
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const auto [p, x] = queue[k];
    const Dart here = m[x][p];
    for (ArcId e = 0; e < L.arc_count(); ++e) {
      const auto& a = L.arc(e);
      std::uint32_t q;
      NodeId y;
      Dart there;
      if (a.source == x) {
        q = step(p, left_fwd[e]);
        y = a.target;
        there = g.link(a.label, here);
      } else if (a.target == x) {
        q = step(p, left_bwd[e]);
        y = a.source;
        there = g.inverse_link(a.label, here);
      } else {
        continue;
      }
      if (there == no_dart)
        return refuse<SchemeMatch>(Refusal::no_match, fmt::format("arc {} -{}-> {} of L at pattern dart {}: dart {} has no {}-arc", L.name(a.source),
                                                     a.label, L.name(a.target), pattern[p], here, a.label));
      if (m[y][q] == no_dart) {
        m[y][q] = there;
        queue.emplace_back(q, y);
      } else if (m[y][q] != there) {
        return refuse<SchemeMatch>(Refusal::no_match, fmt::format("node ({}, {}) of the instantiated L would be both dart {} and dart {}", pattern[q],
                                                     L.name(y), m[y][q], there));
      }
    }
  }
  // Injectivity on nodes; every product node matched (ι(L, P_v) connected).
  DartTable local;
  DartTable& taken = scratch ? *scratch : local;
  const DartTable::ClearOnExit emptied{taken};
  for (NodeId x = 0; x < L.node_count(); ++x)
    for (std::size_t p = 0; p < np; ++p) {
      const Dart d = m[x][p];
      if (d == no_dart)
        return refuse<SchemeMatch>(Refusal::disconnected, fmt::format("node ({}, {}) of the instantiated L is unreachable from the hooks: ι(L, P_v) "
                                                         "is not connected, so the hooks do not fix the match (002 Sec. 6.3)",
                                                         pattern[p], L.name(x)));
      if (taken.get(d) != DartTable::none)
        return refuse<SchemeMatch>(Refusal::not_injective, fmt::format("two nodes of the instantiated L match dart {}", d));
      taken.set(d, 1);
    }
  // Arc injectivity: two arcs of L out of one node with one label share
  // their images.
  for (ArcId e = 0; e < L.arc_count(); ++e)
    for (ArcId f = e + 1; f < L.arc_count(); ++f)
      if (L.arc(e).source == L.arc(f).source && L.arc(e).label == L.arc(f).label)
        return refuse<SchemeMatch>(Refusal::not_injective,
                      fmt::format("L has two {}-arcs out of {}: their instances share one arc", L.arc(e).label, L.name(L.arc(e).source)));
  // Dangling: a deleted node needs an L arc in and out for every dimension
  // its darts carry.
  for (NodeId x = 0; x < L.node_count(); ++x) {
    if (core.to_right(x) != no_node) continue;
    for (Dim i : core.model().dims) {
      bool out = false, in = false;
      for (const auto& a : L.arcs()) {
        out |= a.source == x && a.label == i;
        in |= a.target == x && a.label == i;
      }
      for (std::size_t p = 0; p < np; ++p)
        if ((!out && g.link(i, m[x][p]) != no_dart) || (!in && g.inverse_link(i, m[x][p]) != no_dart))
          return refuse<SchemeMatch>(Refusal::dangling, fmt::format("deleted dart {} (node {}) keeps a {}-arc outside the match", m[x][p], L.name(x), i));
    }
  }
  // Representability, per scheme arc (the same for every pattern node).
  for (ArcId e = 0; e < R.arc_count(); ++e) {
    if (core.preserved_right_arc(e)) continue;
    const auto& a = R.arc(e);
    for (ArcId f = e + 1; f < R.arc_count(); ++f)
      if (!core.preserved_right_arc(f) && R.arc(f).source == a.source && R.arc(f).label == a.label)
        return refuse<SchemeMatch>(Refusal::not_representable, fmt::format("R adds two {}-arcs out of {}", a.label, R.name(a.source)));
    const NodeId x = core.to_left(a.source);
    if (x == no_node) continue;
    bool freed = false, kept = false;
    for (ArcId f = 0; f < L.arc_count(); ++f) freed |= !core.preserved_left_arc(f) && L.arc(f).source == x && L.arc(f).label == a.label;
    for (ArcId f = 0; f < R.arc_count(); ++f) kept |= core.preserved_right_arc(f) && R.arc(f).source == a.source && R.arc(f).label == a.label;
    for (std::size_t p = 0; p < np && !freed; ++p)
      if (kept || g.link(a.label, m[x][p]) != no_dart)
        return refuse<SchemeMatch>(Refusal::not_representable, fmt::format("R adds a {}-arc out of {} whose dart {} keeps its {}-arc", a.label,
                                                              R.name(a.source), m[x][p], a.label));
  }
  return {SchemeMatch{std::move(*found.value), std::move(m)}, Refusal::none, {}};
}

SchemeDerivation rewrite_scheme(const Rule& core, const ArcWords& words, Map& g, const SchemeMatch& match) {
  const TopoGraph &L = core.left(), &R = core.right();
  const auto& m = match.node;
  const std::size_t np = match.pattern.darts[0].size();
  const auto& shift = match.pattern.shift;
  auto step = [&](std::size_t p, int k) { return k < 0 ? static_cast<std::uint32_t>(p) : shift[static_cast<std::size_t>(k)][p]; };
  const ArcGenerators ag(core, words, match.pattern.gens);
  const auto& right_fwd = ag.right_fwd;

  // Rewrite: delete the instances of L \ K, place R's nodes, add R \ K.
  SchemeDerivation out{np, np * L.node_count(), 0, {}, {}};
  for (ArcId e = 0; e < L.arc_count(); ++e)
    if (!core.preserved_left_arc(e))
      for (std::size_t p = 0; p < np; ++p) g.remove_link(L.arc(e).label, m[L.arc(e).source][p]);
  std::vector<Dart> holes;
  for (NodeId x = 0; x < L.node_count(); ++x)
    if (core.to_right(x) == no_node) holes.insert(holes.end(), m[x].begin(), m[x].end());
  std::vector<std::vector<Dart>> c(R.node_count());
  std::size_t added_nodes = 0;
  for (NodeId y = 0; y < R.node_count(); ++y) added_nodes += core.to_left(y) == no_node;
  const std::size_t reuse = std::min(holes.size(), added_nodes * np);
  const Dart first_new = added_nodes * np > reuse ? g.add_darts(added_nodes * np - reuse) : no_dart;
  std::size_t next_new = 0, next_hole = 0;
  for (NodeId y = 0; y < R.node_count(); ++y) {
    if (core.to_left(y) != no_node) {
      c[y] = m[core.to_left(y)];
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
    for (std::size_t p = 0; p < np; ++p) g.set_link(a.label, c[a.source][p], c[a.target][step(p, right_fwd[e])]);
  }
  holes.erase(holes.begin(), holes.begin() + static_cast<std::ptrdiff_t>(reuse));
  std::vector<Dart> sources;
  for (const auto& darts : c) sources.insert(sources.end(), darts.begin(), darts.end());
  out.moved = compact(g, std::move(holes), sources);
  if (!out.moved.empty()) {
    std::unordered_map<Dart, Dart> renumbered(out.moved.begin(), out.moved.end());
    for (auto& darts : c)
      for (Dart& d : darts)
        if (const auto it = renumbered.find(d); it != renumbered.end()) d = it->second;
  }
  out.comatch = std::move(c);
  return out;
}

}  // namespace dartcheck
