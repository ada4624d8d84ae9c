#include "checkers/embedding_conditions.hpp"

#include <algorithm>
#include <functional>
#include <optional>
#include <map>
#include <numeric>

#include <fmt/format.h>

#include "core/disjoint_sets.hpp"

namespace dartcheck {

namespace {

bool in_orbit(const std::vector<Dim>& o, Dim d) { return std::find(o.begin(), o.end(), d) != o.end(); }

// Orbit ids of a side's nodes through arcs labeled in <o> (only ε-word
// arcs with `explicit_only`), as the smallest node id of each orbit.
std::vector<NodeId> orbits(const TopoGraph& g, const std::vector<ConjWord>& words, const std::vector<Dim>& o, bool explicit_only,
                           const std::vector<bool>* keep = nullptr) {
  DisjointSets<NodeId> orbit(g.node_count());
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    const auto& a = g.arc(e);
    if (!in_orbit(o, a.label) || (explicit_only && !arc_word(words, e).empty()) || (keep && !(*keep)[e])) continue;
    orbit.join(a.source, a.target);
  }
  return orbit.representatives();
}

// A term's value is the same at pattern copies p and p·w when every
// variable y is read through an access or collect whose orbit contains
// the label of an L loop on y with word w: the two copies' darts then lie
// in one such orbit of G.
// The variable a node term (x, x.alpha_i, ...) starts from.
const std::string& root_variable(const Term& t) { return t.kind == Term::Kind::neighbour ? root_variable(t.args[0]) : t.name; }

// An each term's dart variable ranges over a whole orbit, the same one
// from every dart of it: what the body reads through it is the same at
// every copy whenever the orbit is (`bound`: the dart variables in scope).
//
// A neighbour read y.alpha_c1...alpha_ck.pi is invariant too when the
// loop's label l commutes with every c (both involutions, total, and
// (l, c) exchangeable: alpha_l alpha_c is an involution, hence
// alpha_l alpha_c = alpha_c alpha_l): the copy's neighbour is then
// alpha_l of the first copy's, in the same <o>-orbit since l is in <o>.
bool copy_invariant(const Term& t, const ConjWord& w, const TopoGraph& L, const ArcWords& words, const RuleTerms& terms, const Model& model,
                    std::vector<std::string>& bound) {
  auto is_bound = [&](const Term& node) { return std::find(bound.begin(), bound.end(), root_variable(node)) != bound.end(); };
  auto commutes = [&](Dim l, Dim c) {
    const auto total_involution = [&](Dim i) { return !model.is_oriented(i) && !has_dim(model.partial, i); };
    const std::pair<Dim, Dim> p{std::min(l, c), std::max(l, c)};
    return l != c && total_involution(l) && total_involution(c) &&
           std::find(model.exchangeable.begin(), model.exchangeable.end(), p) != model.exchangeable.end();
  };
  auto moves_inside = [&](const std::string& y, const std::vector<Dim>& orbit, const std::vector<Dim>& chain = {}) {
    const auto v = L.find(y);
    if (!v) return false;
    for (ArcId e = 0; e < L.arc_count(); ++e) {
      const auto& a = L.arc(e);
      if (a.source == *v && a.target == *v && arc_word(words.left, e) == w && in_orbit(orbit, a.label) &&
          std::all_of(chain.begin(), chain.end(), [&](Dim c) { return commutes(a.label, c); }))
        return true;
    }
    return false;
  };
  switch (t.kind) {
    case Term::Kind::literal:
    case Term::Kind::parameter:
      return true;
    case Term::Kind::access:
    case Term::Kind::collect: {
      if (is_bound(t.args[0])) return true;
      std::vector<Dim> orbit = t.orbit;
      if (t.kind == Term::Kind::access)
        for (const auto& e : terms.embeddings)
          if (e.name == t.name) orbit = e.orbit;
      std::vector<Dim> chain;  // y.alpha_c1...alpha_ck, innermost first
      const Term* node = &t.args[0];
      for (; node->kind == Term::Kind::neighbour; node = &node->args[0]) chain.push_back(node->dim);
      if (node->kind != Term::Kind::variable) return false;
      return moves_inside(node->name, orbit, chain);
    }
    case Term::Kind::each: {
      if (!is_bound(t.args[0]) && (t.args[0].kind != Term::Kind::variable || !moves_inside(t.args[0].name, t.orbit))) return false;
      bound.push_back(t.name);
      const bool body = copy_invariant(t.args[1], w, L, words, terms, model, bound);
      bound.pop_back();
      return body;
    }
    case Term::Kind::variable:
    case Term::Kind::neighbour:
      return false;
    case Term::Kind::call:
    case Term::Kind::list:
      break;
  }
  return std::all_of(t.args.begin(), t.args.end(), [&](const Term& a) { return copy_invariant(a, w, L, words, terms, model, bound); });
}

bool copy_invariant(const Term& t, const ConjWord& w, const TopoGraph& L, const ArcWords& words, const RuleTerms& terms, const Model& model) {
  std::vector<std::string> bound;
  return copy_invariant(t, w, L, words, terms, model, bound);
}

std::string list(const TopoGraph& g, const std::vector<NodeId>& nodes) {
  std::vector<std::string> n;
  for (NodeId v : nodes) n.push_back(g.name(v));
  return fmt::format("{}", fmt::join(n, ", "));
}

}  // namespace

namespace {

// Overlap in R (003 Lemma 3 defines it on L, K and R, but its condition
// on the match excludes it on L only): preserved nodes of one pi-orbit of
// L that R splits into two pi-orbits are matched in one pi-orbit of G,
// and links the rule does not match (a dimension of <o> with no arc of L
// at the node) may join them again in H, through darts outside the
// match. The extended rule then gives that orbit both R-orbits' terms:
// unless they are the same term, (A) fails for the extended rule, which
// Theorem 4 assumes. Found by the fuzzer on 2-dart hosts: L n0 -2- n1
// with n0, n1 free of 1-arcs, R unsewing them with two constants, G a
// 2-dart map whose 1-link still joins the two darts.
void split_orbits(const Rule& rule, const EmbeddingSignature& e, const std::vector<NodeId>& lo, const std::vector<NodeId>& ro,
                  const std::function<const Term*(char, NodeId)>& term, TermConditionVerdict& a) {
  const TopoGraph &L = rule.left(), &R = rule.right();
  // The term of each R-orbit (A holds or is reported apart: its first).
  std::map<NodeId, const Term*> orbit_term;
  for (NodeId r = 0; r < R.node_count(); ++r)
    if (const Term* t = term('R', r); t && !orbit_term.count(ro[r])) orbit_term[ro[r]] = t;
  auto unmatched_dim = [&](NodeId v) -> std::optional<Dim> {
    for (Dim i : e.orbit) {
      bool arc = false;
      for (ArcId x = 0; x < L.arc_count() && !arc; ++x) arc = L.arc(x).source == v && L.arc(x).label == i;
      if (!arc) return i;
    }
    return std::nullopt;
  };
  for (NodeId r1 = 0; r1 < R.node_count(); ++r1)
    for (NodeId r2 = r1 + 1; r2 < R.node_count(); ++r2) {
      const NodeId v1 = rule.to_left(r1), v2 = rule.to_left(r2);
      if (v1 == no_node || v2 == no_node || lo[v1] != lo[v2] || ro[r1] == ro[r2]) continue;
      const auto t1 = orbit_term.find(ro[r1]), t2 = orbit_term.find(ro[r2]);
      const Term* x = t1 == orbit_term.end() ? nullptr : t1->second;
      const Term* y = t2 == orbit_term.end() ? nullptr : t2->second;
      if ((!x && !y) || (x && y && x->same(*y))) continue;
      const auto d1 = unmatched_dim(v1), d2 = unmatched_dim(v2);
      if (!d1 || !d2) continue;
      a.holds = false;
      a.witnesses.push_back({0,
                             'R',
                             {R.name(r1), R.name(r2)},
                             {},
                             {},
                             fmt::format("R: nodes {} and {} share a {}-orbit <{}> of L that R splits, with terms {} and {}; their darts' {}- and "
                                         "{}-links, which L does not match, may join the two orbits again in H (003 Lemma 3's overlap in R, "
                                         "which its condition on the match does not exclude)",
                                         R.name(r1), R.name(r2), e.name, fmt::join(e.orbit, ","), x ? x->str() : "unlabeled",
                                         y ? y->str() : "unlabeled", *d1, *d2)});
    }
}

}  // namespace

std::string TermConditionVerdict::name() const { return fmt::format("{}({})", condition, embedding); }

std::vector<std::string> failing_names(const std::vector<TermConditionVerdict>& v) {
  std::vector<std::string> r;
  for (const auto& c : v)
    if (c.required && !c.holds) r.push_back(c.name());
  return r;
}

namespace {

// What the conditions on one embedding pi read: its orbits on L, on K
// (preserved arcs only), on R, and on R with a scheme's implicit arcs, and
// the terms of pi on each side.
struct PiOrbits {
  const Rule& rule;
  const ArcWords& words;
  const RuleTerms& terms;
  const EmbeddingSignature& e;
  std::string orbit;  // "<0,1>"
  std::vector<bool> kept;
  std::vector<NodeId> lo, ro, ko, re;

  PiOrbits(const Rule& r, const ArcWords& w, const RuleTerms& t, const EmbeddingSignature& sig)
      : rule(r), words(w), terms(t), e(sig), orbit(fmt::format("<{}>", fmt::join(sig.orbit, ","))), kept(r.left().arc_count()) {
    for (ArcId a = 0; a < r.left().arc_count(); ++a) kept[a] = r.preserved_left_arc(a);
    lo = orbits(r.left(), w.left, sig.orbit, false);
    ro = orbits(r.right(), w.right, sig.orbit, false);
    ko = orbits(r.left(), w.left, sig.orbit, false, &kept);
    re = orbits(r.right(), w.right, sig.orbit, w.scheme);
  }
  const Term* term(char side, NodeId v) const { return terms.find(side, (side == 'L' ? rule.left() : rule.right()).name(v), e.name); }

  TermConditionVerdict condition_a() const;
  TermConditionVerdict condition_b() const;
  TermConditionVerdict condition_c() const;
  TermConditionVerdict condition_label() const;
};

// (A), on L, K (labels where L and R agree, preserved arcs) and R.
TermConditionVerdict PiOrbits::condition_a() const {
  const TopoGraph &L = rule.left(), &R = rule.right();
  const std::string& pi = e.name;
  const bool scheme = words.scheme;
  const bool direct = terms.instantiation == Instantiation::direct;
  TermConditionVerdict a{"A", pi, true, true, {}};
  auto check_side = [&](char side, const char* side_name, const TopoGraph& g, const std::vector<NodeId>& orb, const std::vector<ConjWord>& ws,
                        const std::vector<bool>* arc_keep, auto label_of) {
    std::map<NodeId, std::vector<NodeId>> groups;
    for (NodeId v = 0; v < g.node_count(); ++v) groups[orb[v]].push_back(v);
    for (const auto& [root, nodes] : groups) {
      const Term* first = nullptr;
      NodeId first_node = 0;
      for (NodeId v : nodes) {
        const Term* t = label_of(v);
        if (!t) continue;
        if (!first) {
          first = t;
          first_node = v;
        } else if (!t->same(*first)) {
          a.holds = false;
          a.witnesses.push_back({0,
                                 side,
                                 {g.name(first_node), g.name(v)},
                                 {},
                                 {},
                                 fmt::format("{}: nodes {} and {} share a {}-orbit {} ({}) but carry different terms {} and {}", side_name,
                                             g.name(first_node), g.name(v), pi, orbit, list(g, nodes), first->str(), t->str())});
        }
      }
      if (!first || !scheme) continue;
      // Copies of a node in one orbit: the moves are the words of the
      // orbit's arcs.
      for (ArcId x = 0; x < g.arc_count(); ++x) {
        const auto& arc = g.arc(x);
        if (orb[arc.source] != root || !in_orbit(e.orbit, arc.label) || (arc_keep && !(*arc_keep)[x])) continue;
        const ConjWord& w = arc_word(ws, x);
        if (w.empty()) continue;
        for (NodeId v : nodes) {
          const Term* t = label_of(v);
          if (t && !copy_invariant(*t, w, L, words, terms, rule.model())) {
            a.holds = false;
            a.witnesses.push_back({0,
                                   side,
                                   {g.name(v)},
                                   {arc_text(g, x, ws, true)},
                                   {},
                                   fmt::format("{}: the copies of {} joined by {} lie in one {}-orbit, but its term {} may differ between copies "
                                               "(a variable is not read through an orbit that contains the L loop moving the copy)",
                                               side_name, g.name(v), arc_text(g, x, ws, true), pi, t->str())});
            break;
          }
        }
      }
    }
  };
  check_side('L', "L", L, lo, words.left, nullptr, [&](NodeId v) { return term('L', v); });
  check_side('L', "K", L, ko, words.left, &kept, [&](NodeId v) -> const Term* {
    const NodeId r = rule.to_right(v);
    if (r == no_node) return nullptr;
    const Term *l = term('L', v), *rr = term('R', r);
    return l && rr && l->same(*rr) ? l : nullptr;
  });
  check_side('R', "R", R, ro, words.right, nullptr, [&](NodeId v) { return term('R', v); });
  if (!direct)
    split_orbits(
        rule, e, lo, ro, [this](char side, NodeId v) { return term(side, v); }, a);
  return a;
}

// (B): a preserved node whose term changes has a full, labeled R-orbit.
TermConditionVerdict PiOrbits::condition_b() const {
  const TopoGraph &L = rule.left(), &R = rule.right();
  const std::string& pi = e.name;
  const bool direct = terms.instantiation == Instantiation::direct;
  auto shown = [](const Term* t) { return t ? t->str() : std::string("unlabeled"); };
  TermConditionVerdict b{"B", pi, true, direct, {}};
  for (NodeId v = 0; v < L.node_count(); ++v) {
    const NodeId r = rule.to_right(v);
    if (r == no_node) continue;
    const Term *tl = term('L', v), *tr = term('R', r);
    if ((!tl && !tr) || (tl && tr && tl->same(*tr))) continue;
    for (NodeId w = 0; w < R.node_count(); ++w) {
      if (ro[w] != ro[r]) continue;
      std::string why;
      if (!term('R', w)) why = "is unlabeled";
      for (Dim i : e.orbit) {
        std::size_t n = 0;
        for (const auto& arc : R.arcs()) n += arc.source == w && arc.label == i;
        if (n != 1 && why.empty()) why = fmt::format("is the source of {} {}-arcs", n, i);
      }
      if (why.empty()) continue;
      b.holds = false;
      b.witnesses.push_back({0,
                             'R',
                             {R.name(r), R.name(w)},
                             {},
                             {},
                             fmt::format("{} changes {} from {} to {}, but node {} of its R-orbit {} {}: the orbit is not fully matched", R.name(r),
                                         pi, shown(tl), shown(tr), R.name(w), orbit, why)});
      break;
    }
  }
  return b;
}

// (C): an R-orbit that gains nodes keeps a value matched in L.
TermConditionVerdict PiOrbits::condition_c() const {
  const TopoGraph &L = rule.left(), &R = rule.right();
  const std::string& pi = e.name;
  const bool scheme = words.scheme;
  TermConditionVerdict c{"C", pi, true, true, {}};
  std::vector<bool> reported(R.node_count(), false);
  for (NodeId v = 0; v < L.node_count(); ++v) {
    const NodeId r = rule.to_right(v);
    if (r == no_node || reported[ro[r]]) continue;
    std::string grows;
    if (!scheme) {
      for (NodeId w = 0; w < R.node_count() && grows.empty(); ++w) {
        if (ro[w] != ro[r]) continue;
        const NodeId lw = rule.to_left(w);
        if (lw == no_node)
          grows = fmt::format("gains the added node {}", R.name(w));
        else if (lo[lw] != lo[v])
          grows = fmt::format("joins {}, of another {}-orbit of L", R.name(w), pi);
      }
    } else {
      for (ArcId x = 0; x < R.arc_count() && grows.empty(); ++x) {
        const auto& arc = R.arc(x);
        if (ro[arc.source] != ro[r] || !in_orbit(e.orbit, arc.label)) continue;
        if (rule.to_left(arc.target) == no_node)
          grows = fmt::format("gains the added node {}", R.name(arc.target));
        else if (!rule.preserved_right_arc(x))
          grows = fmt::format("gains the added arc {}", arc_text(R, x, words.right, true));
      }
    }
    if (grows.empty()) continue;
    bool matched = false;
    if (!scheme) {
      for (NodeId u = 0; u < L.node_count() && !matched; ++u) {
        const NodeId ru = rule.to_right(u);
        matched = ru != no_node && lo[u] == lo[v] && ro[ru] == ro[r] && term('L', u);
      }
    } else {
      matched = term('L', v) != nullptr;
    }
    if (matched) continue;
    c.holds = false;
    reported[ro[r]] = true;
    c.witnesses.push_back({0,
                           'R',
                           {R.name(r)},
                           {},
                           {},
                           fmt::format("the {}-orbit {} of {} in R {}, but {} has no node of K in both its orbits labeled in L{}: its old value "
                                       "would meet values that never were compared with it",
                                       pi, orbit, R.name(r), grows, scheme ? "the node itself" : R.name(r),
                                       scheme ? " (for a topological scheme the node itself must be labeled in L)" : "")});
  }
  return c;
}

// label: Def. 1's labeling, after propagation for extended rules.
TermConditionVerdict PiOrbits::condition_label() const {
  const TopoGraph& R = rule.right();
  const std::string& pi = e.name;
  const bool direct = terms.instantiation == Instantiation::direct;
  TermConditionVerdict lab{"label", pi, true, true, {}};
  auto orbit_labeled = [&](NodeId r) {
    for (NodeId w = 0; w < R.node_count(); ++w)
      if (re[w] == re[r] && term('R', w)) return true;
    return false;
  };
  for (NodeId r = 0; r < R.node_count(); ++r) {
    const NodeId v = rule.to_left(r);
    const bool needs = v == no_node || term('L', v);
    if (!needs || term('R', r) || (!direct && orbit_labeled(r))) continue;
    lab.holds = false;
    lab.witnesses.push_back({0,
                             'R',
                             {R.name(r)},
                             {},
                             {},
                             v == no_node ? fmt::format("added node {} gets no {} value: {}", R.name(r), pi,
                                                        direct ? "it is unlabeled in R (003 Def. 1)" : "no node of its R-orbit is labeled")
                                          : fmt::format("preserved node {} is labeled in L ({}) but {}: its value would be lost (003 Def. 1)",
                                                        R.name(r), term('L', v)->str(), direct ? "not in R" : "no node of its R-orbit is labeled")});
  }
  return lab;
}

}  // namespace

std::vector<TermConditionVerdict> check_term_conditions(const Rule& rule, const ArcWords& words, const RuleTerms& terms) {
  std::vector<TermConditionVerdict> out;
  for (const EmbeddingSignature& e : terms.embeddings) {
    const PiOrbits po(rule, words, terms, e);
    out.push_back(po.condition_a());
    out.push_back(po.condition_b());
    out.push_back(po.condition_c());
    out.push_back(po.condition_label());
  }
  return out;
}

}  // namespace dartcheck
