#include "checkers/rule_conditions.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <array>

#include <fmt/format.h>

namespace dartcheck {

std::string condition_name(RuleCondition c, Dim i, Dim j) {
  switch (c) {
    case RuleCondition::incident_arcs:
      return fmt::format("I({})", i);
    case RuleCondition::dangling:
      return fmt::format("dangling({})", i);
    case RuleCondition::non_orientation:
      return fmt::format("O({})", i);
    case RuleCondition::cycle:
      return fmt::format("C({},{})", i, j);
    case RuleCondition::no_loop:
      return fmt::format("no-loop({})", i);
  }
  return "?";
}

bool RuleVerdict::consistent() const {
  return std::all_of(conditions.begin(), conditions.end(), [](const ConditionVerdict& c) { return c.holds; });
}

const ConditionVerdict* RuleVerdict::find(const std::string& name) const {
  for (const auto& c : conditions)
    if (c.name() == name) return &c;
  return nullptr;
}

namespace {

std::size_t count_arcs(const TopoGraph& g, NodeId v, Dim i, bool out) {
  std::size_t n = 0;
  for (ArcId e : out ? g.out_arcs(v) : g.in_arcs(v)) n += g.arc(e).label == i;
  return n;
}

ConditionVerdict verdict(RuleCondition c, Dim i, Dim j = -1) { return ConditionVerdict{c, i, j, true, {}, {}}; }

void fail(ConditionVerdict& v, RuleWitness w) {
  v.holds = false;
  v.witnesses.push_back(std::move(w));
}

}  // namespace

std::string label_text(Dim d, const ConjWord& w, bool scheme) { return scheme ? fmt::format("({},{})", w.str(), d) : std::to_string(d); }

std::string arc_text(const TopoGraph& g, ArcId e, const std::vector<ConjWord>& words, bool scheme) {
  const auto& a = g.arc(e);
  return fmt::format("{} -{}-> {}", g.name(a.source), label_text(a.label, arc_word(words, e), scheme), g.name(a.target));
}

ConditionVerdict check_incident_arcs(const Rule& rule, Dim i, const ArcWords&) {
  auto v = verdict(RuleCondition::incident_arcs, i);
  const TopoGraph &L = rule.left(), &R = rule.right();
  for (NodeId x = 0; x < L.node_count(); ++x) {
    const NodeId y = rule.to_right(x);
    if (y == no_node) continue;
    for (bool out : {true, false}) {
      const std::size_t nl = count_arcs(L, x, i, out), nr = count_arcs(R, y, i, out);
      // Def. 11 says "an i-arc in L iff an i-arc in R"; the count matters:
      // with one arc in L and two in R the host's arc is kept and a second
      // added (found by the Theorem 1 brute force). Algorithm 1's test.
      if (nl > 1)
        fail(v, {1,
                 'L',
                 {L.name(x)},
                 {},
                 {},
                 fmt::format("preserved node {} is the {} of {} {}-arcs in L: no host satisfying I({}) contains L", L.name(x),
                             out ? "source" : "target", nl, i, i)});
      else if (nl != nr)
        fail(v, {1,
                 'L',
                 {L.name(x)},
                 {},
                 {},
                 fmt::format("preserved node {} is the {} of {} {}-arc{} in L and {} in R", L.name(x), out ? "source" : "target", nl, i,
                             nl == 1 ? "" : "s", nr)});
    }
  }
  for (NodeId y = 0; y < R.node_count(); ++y) {
    if (rule.to_left(y) != no_node) continue;
    for (bool out : {true, false}) {
      const std::size_t nr = count_arcs(R, y, i, out);
      if (nr != 1)
        fail(v, {2,
                 'R',
                 {R.name(y)},
                 {},
                 {},
                 fmt::format("added node {} is the {} of {} {}-arcs in R (exactly one needed)", R.name(y), out ? "source" : "target", nr, i)});
    }
  }
  return v;
}

ConditionVerdict check_dangling(const Rule& rule, Dim i, const ArcWords&) {
  auto v = verdict(RuleCondition::dangling, i);
  const TopoGraph& L = rule.left();
  for (NodeId x = 0; x < L.node_count(); ++x) {
    if (rule.to_right(x) != no_node) continue;
    for (bool out : {true, false}) {
      const std::size_t nl = count_arcs(L, x, i, out);
      if (nl != 1)
        fail(v, {0,
                 'L',
                 {L.name(x)},
                 {},
                 {},
                 fmt::format("deleted node {} is the {} of {} {}-arcs in L: {}", L.name(x), out ? "source" : "target", nl, i,
                             nl == 0 ? "the host's arc would dangle" : "no combinatorial host matches it")});
    }
  }
  return v;
}

ConditionVerdict check_non_orientation(const Rule& rule, Dim i, const ArcWords& words) {
  auto v = verdict(RuleCondition::non_orientation, i);
  ConjugateRewriting rw(rule.model());
  for (const char side : {'L', 'R'}) {
    const TopoGraph& g = side == 'L' ? rule.left() : rule.right();
    const auto& ws = side == 'L' ? words.left : words.right;
    auto kept = [&](ArcId e) { return side == 'L' ? rule.preserved_left_arc(e) : rule.preserved_right_arc(e); };
    for (ArcId e = 0; e < g.arc_count(); ++e) {
      const auto& a = g.arc(e);
      if (a.label != i || kept(e)) continue;
      // The reverse of (w, i): t -> s labeled (conj(w), i); a loop whose
      // word is its own conjugate is its own reverse.
      const ConjWord back = rw.conjugate(arc_word(ws, e));
      std::vector<ArcId> reverse;
      for (ArcId f : g.out_arcs(a.target)) {
        const auto& b = g.arc(f);
        if (b.label == i && b.target == a.source && arc_word(ws, f) == back) reverse.push_back(f);
      }
      const char* what = side == 'L' ? "deleted" : "added";
      if (reverse.size() != 1) {
        fail(v, {0,
                 side,
                 {g.name(a.source), g.name(a.target)},
                 {arc_text(g, e, ws, words.scheme)},
                 {},
                 fmt::format("{} arc {} has {} reverse arcs {} -{}-> {} in {} (exactly one needed)", what, arc_text(g, e, ws, words.scheme),
                             reverse.size(), g.name(a.target), label_text(i, back, words.scheme), g.name(a.source), side)});
      } else if (kept(reverse[0])) {
        fail(v, {0,
                 side,
                 {g.name(a.source), g.name(a.target)},
                 {arc_text(g, e, ws, words.scheme), arc_text(g, reverse[0], ws, words.scheme)},
                 {},
                 fmt::format("{} arc {} has its reverse {} in the interface", what, arc_text(g, e, ws, words.scheme),
                             arc_text(g, reverse[0], ws, words.scheme))});
      }
    }
  }
  return v;
}

namespace {

// One side of a rule restricted to the i- and j-arcs, after ij-completion.
struct CycleArc {
  NodeId source, target;
  Dim label;
  bool changed;  // deleted (L) or added (R)
  ConjWord word;
  std::string text;
};

struct CycleSide {
  char name;
  const TopoGraph* graph;
  std::vector<CycleArc> arcs;
  std::vector<std::vector<int>> from, into;  // arcs by source (target) node, in index order
  std::vector<std::array<int, 4>> cycles;    // ijij-walks that close
  std::vector<std::vector<int>> optimal;     // (i,j)-optimal paths

  CycleSide(char n, const TopoGraph& g) : name(n), graph(&g), from(g.node_count()), into(g.node_count()) {}
  void add(CycleArc a) {
    from[a.source].push_back(static_cast<int>(arcs.size()));
    into[a.target].push_back(static_cast<int>(arcs.size()));
    arcs.push_back(std::move(a));
  }
  const CycleArc& at(int e) const { return arcs[static_cast<std::size_t>(e)]; }
};

std::string path_text(const CycleSide& s, const std::vector<int>& p) {
  std::string t = s.graph->name(s.arcs[static_cast<std::size_t>(p.front())].source);
  for (int e : p) {
    const auto& a = s.arcs[static_cast<std::size_t>(e)];
    t += fmt::format(" -{}-> {}", a.word.empty() ? std::to_string(a.label) : fmt::format("({},{})", a.word.str(), a.label), s.graph->name(a.target));
  }
  return t;
}

ConjWord path_word(const CycleSide& s, const std::vector<int>& p) {
  ConjWord w;
  for (int e : p) w += s.arcs[static_cast<std::size_t>(e)].word;
  return w;
}

std::vector<Dim> path_labels(const CycleSide& s, const std::vector<int>& p) {
  std::vector<Dim> l;
  for (int e : p) l.push_back(s.arcs[static_cast<std::size_t>(e)].label);
  return l;
}

// Walks a -b- c -d- back to a's source, labels alternating; found through
// the arcs out of each node, in the order of a full scan of the arcs.
void find_cycles(CycleSide& s) {
  for (int a = 0; a < static_cast<int>(s.arcs.size()); ++a)
    for (int b : s.from[s.at(a).target]) {
      if (s.at(b).label == s.at(a).label) continue;
      for (int c : s.from[s.at(b).target]) {
        if (s.at(c).label != s.at(a).label) continue;
        for (int d : s.from[s.at(c).target])
          if (s.at(d).label == s.at(b).label && s.at(d).target == s.at(a).source) s.cycles.push_back({a, b, c, d});
      }
    }
}

// Def. 14: alternating, all arcs changed, no arc twice, maximal, not in a
// cycle of the side. A path is part of a longer one exactly when a changed
// arc not on it extends it at one end with the other label, so maximality
// is a test at both ends, not a search among all paths.
void find_optimal_paths(CycleSide& s) {
  std::vector<std::vector<int>> cycles_of(s.arcs.size());
  for (std::size_t c = 0; c < s.cycles.size(); ++c)
    for (int e : s.cycles[c]) cycles_of[static_cast<std::size_t>(e)].push_back(static_cast<int>(c));
  auto in_some_cycle = [&](const std::vector<int>& p) {
    for (int c : cycles_of[static_cast<std::size_t>(p.front())]) {
      const auto& cycle = s.cycles[static_cast<std::size_t>(c)];
      if (std::all_of(p.begin(), p.end(), [&](int e) { return std::find(cycle.begin(), cycle.end(), e) != cycle.end(); })) return true;
    }
    return false;
  };
  auto extends = [&](const std::vector<int>& p, int e, Dim next_to) {
    return s.at(e).changed && s.at(e).label != next_to && std::find(p.begin(), p.end(), e) == p.end();
  };
  auto maximal = [&](const std::vector<int>& p) {
    for (int e : s.from[s.at(p.back()).target])
      if (extends(p, e, s.at(p.back()).label)) return false;
    for (int e : s.into[s.at(p.front()).source])
      if (extends(p, e, s.at(p.front()).label)) return false;
    return true;
  };
  std::vector<int> cur;
  auto extend = [&](auto&& self) -> void {
    if (maximal(cur) && !in_some_cycle(cur)) s.optimal.push_back(cur);
    const CycleArc& last = s.at(cur.back());
    for (int e : s.from[last.target]) {
      if (!s.at(e).changed || s.at(e).label == last.label) continue;
      if (std::find(cur.begin(), cur.end(), e) != cur.end()) continue;
      cur.push_back(e);
      self(self);
      cur.pop_back();
    }
  };
  for (int e = 0; e < static_cast<int>(s.arcs.size()); ++e) {
    if (!s.at(e).changed) continue;
    cur = {e};
    extend(extend);
  }
}

// ij-completion (Sec. 5.2.1): an iji-path s ~> t of L closes with a
// j-arc t -> s in every host satisfying C(i,j); add it to L, and to the
// interface when both ends are preserved. Its word closes the cycle: the
// conjugate of the path's word. Completing R would restrict the matches,
// so only L is completed. The first open path in arc order is closed,
// then the search starts again.
void complete_left(const Rule& rule, ConjugateRewriting& rw, CycleSide& left, CycleSide& right) {
  for (bool grew = true; grew;) {
    grew = false;
    for (int a = 0; a < static_cast<int>(left.arcs.size()) && !grew; ++a)
      for (int b : left.from[left.at(a).target]) {
        if (left.at(b).label == left.at(a).label) continue;
        for (int c : left.from[left.at(b).target]) {
          if (left.at(c).label != left.at(a).label) continue;
          const NodeId s = left.at(a).source, t = left.at(c).target;
          const Dim y = left.at(b).label;
          const auto& out_of_t = left.from[t];
          if (std::any_of(out_of_t.begin(), out_of_t.end(), [&](int x) { return left.at(x).target == s && left.at(x).label == y; })) continue;
          const ConjWord w = rw.conjugate(left.at(a).word + left.at(b).word + left.at(c).word);
          const bool interface = rule.to_right(s) != no_node && rule.to_right(t) != no_node;
          left.add({t, s, y, !interface, w, "completion"});
          if (interface) right.add({rule.to_right(t), rule.to_right(s), y, false, w, "completion"});
          grew = true;
          break;
        }
        if (grew) break;
      }
  }
}

// Sub-condition 1 (Def. 15, 26): every optimal path has exactly one
// coherent optimal path on the other side, with a congruent W-label.
void check_optimal_paths(const Rule& rule, ConjugateRewriting& rw, const CycleSide& left, const CycleSide& right, Dim i, Dim j, ConditionVerdict& v) {
  for (const CycleSide* s : {&left, &right}) {
    const CycleSide* o = s == &left ? &right : &left;
    auto across = [&](NodeId x) { return s == &left ? rule.to_right(x) : rule.to_left(x); };
    std::map<std::pair<NodeId, NodeId>, std::vector<const std::vector<int>*>> by_ends;  // o's optimal paths, in order
    for (const auto& q : o->optimal) by_ends[{o->at(q.front()).source, o->at(q.back()).target}].push_back(&q);
    for (const auto& p : s->optimal) {
      const NodeId src = across(s->at(p.front()).source);
      const NodeId tgt = across(s->at(p.back()).target);
      std::vector<const std::vector<int>*> coherent;
      if (const auto it = by_ends.find({src, tgt}); src != no_node && tgt != no_node && it != by_ends.end())
        for (const auto* q : it->second)
          if (path_labels(*s, p) == path_labels(*o, *q)) coherent.push_back(q);
      if (coherent.size() != 1) {
        std::vector<std::string> shown{path_text(*s, p)};
        for (auto* q : coherent) shown.push_back(path_text(*o, *q));
        fail(v, {1,
                 s->name,
                 {},
                 shown,
                 {},
                 fmt::format("({},{})-optimal path {} in {} has {} coherent optimal paths in {} (exactly one needed)", i, j, path_text(*s, p),
                             s->name, coherent.size(), o->name)});
      } else if (!rw.congruent(path_word(*s, p), path_word(*o, *coherent[0]))) {
        fail(v, {1,
                 s->name,
                 {},
                 {path_text(*s, p), path_text(*o, *coherent[0])},
                 {path_word(*s, p).str(), path_word(*o, *coherent[0]).str()},
                 fmt::format("coherent optimal paths {} in {} and {} in {} have W-labels {} and {}, not congruent in R_{{N,E}}", path_text(*s, p),
                             s->name, path_text(*o, *coherent[0]), o->name, path_word(*s, p).str(), path_word(*o, *coherent[0]).str())});
      }
    }
  }
}

// Def. 27: the W-label of every ijij-cycle reduces to ε.
void check_cycle_labels(ConjugateRewriting& rw, const CycleSide& left, const CycleSide& right, Dim i, Dim j, ConditionVerdict& v) {
  for (const CycleSide* s : {&left, &right}) {
    std::set<std::array<int, 4>> reported;  // a cycle once, not once per rotation
    for (const auto& c : s->cycles) {
      std::array<int, 4> key = c;
      std::sort(key.begin(), key.end());
      if (!reported.insert(key).second) continue;
      const std::vector<int> p(c.begin(), c.end());
      const ConjWord w = path_word(*s, p);
      if (!rw.reduces_to_empty(w))
        fail(v, {0,
                 s->name,
                 {},
                 {path_text(*s, p)},
                 {w.str()},
                 fmt::format("({},{})-cycle {} in {} has W-label {}, which does not reduce to ε", i, j, path_text(*s, p), s->name, w.str())});
    }
  }
}

// Sub-conditions 2 and 3: a preserved node losing an i-arc, and an added
// node, must be the source of an i-arc in R on a cycle or optimal path.
void check_sources(const Rule& rule, const CycleSide& left, const CycleSide& right, Dim i, Dim j, ConditionVerdict& v) {
  const TopoGraph& R = rule.right();
  std::vector<bool> on_cycle_or_path(right.arcs.size(), false);
  for (const auto& c : right.cycles)
    for (int e : c) on_cycle_or_path[static_cast<std::size_t>(e)] = true;
  for (const auto& p : right.optimal)
    for (int e : p) on_cycle_or_path[static_cast<std::size_t>(e)] = true;
  for (NodeId y = 0; y < R.node_count(); ++y) {
    const NodeId x = rule.to_left(y);
    for (Dim d : {i, j}) {
      if (x != no_node) {
        const auto& out_of_x = left.from[x];
        if (std::none_of(out_of_x.begin(), out_of_x.end(), [&](int e) { return left.at(e).label == d && left.at(e).changed; })) continue;
      }
      const auto& out_of_y = right.from[y];
      const bool ok = std::any_of(out_of_y.begin(), out_of_y.end(),
                                  [&](int e) { return right.at(e).label == d && on_cycle_or_path[static_cast<std::size_t>(e)]; });
      if (!ok)
        fail(v, {x != no_node ? 2 : 3,
                 'R',
                 {R.name(y)},
                 {},
                 {},
                 x != no_node ? fmt::format("preserved node {} loses a {}-arc but is the source of no {}-arc in R on a ({},{})-cycle "
                                            "or optimal path",
                                            R.name(y), d, d, i, j)
                              : fmt::format("added node {} is the source of no {}-arc in R on a ({},{})-cycle or optimal path", R.name(y), d, i, j)});
    }
  }
}

}  // namespace

ConditionVerdict check_cycle(const Rule& rule, Dim i, Dim j, const ArcWords& words, bool complete) {
  auto v = verdict(RuleCondition::cycle, i, j);
  for (Dim d : {i, j})
    if (!check_incident_arcs(rule, d, words).holds || !check_dangling(rule, d, words).holds) {
      v.skipped = fmt::format("the rule fails I({}) or dangling({}): the cycle condition assumes a combinatorial rule", d, d);
      return v;
    }
  ConjugateRewriting rw(rule.model());
  const TopoGraph &L = rule.left(), &R = rule.right();
  CycleSide left('L', L), right('R', R);
  for (ArcId e = 0; e < L.arc_count(); ++e)
    if (L.arc(e).label == i || L.arc(e).label == j)
      left.add({L.arc(e).source, L.arc(e).target, L.arc(e).label, !rule.preserved_left_arc(e), arc_word(words.left, e), ""});
  for (ArcId e = 0; e < R.arc_count(); ++e)
    if (R.arc(e).label == i || R.arc(e).label == j)
      right.add({R.arc(e).source, R.arc(e).target, R.arc(e).label, !rule.preserved_right_arc(e), arc_word(words.right, e), ""});

  if (complete) complete_left(rule, rw, left, right);
  for (CycleSide* s : {&left, &right}) {
    find_cycles(*s);
    find_optimal_paths(*s);
  }

  check_optimal_paths(rule, rw, left, right, i, j, v);
  check_cycle_labels(rw, left, right, i, j, v);
  check_sources(rule, left, right, i, j, v);
  return v;
}

RuleVerdict check_rule(const Rule& rule, const ArcWords& words) {
  RuleVerdict r;
  const Model& m = rule.model();
  for (Dim i : m.dims) r.conditions.push_back(check_incident_arcs(rule, i, words));
  for (Dim i : m.dims) r.conditions.push_back(check_dangling(rule, i, words));
  for (Dim i : m.dims)
    if (!m.is_oriented(i)) r.conditions.push_back(check_non_orientation(rule, i, words));
  for (auto [i, j] : m.exchangeable) r.conditions.push_back(check_cycle(rule, i, j, words));
  if (m.loop_free)
    for (Dim i : m.dims) {
      auto v = verdict(RuleCondition::no_loop, i);
      const TopoGraph& R = rule.right();
      for (ArcId e = 0; e < R.arc_count(); ++e)
        if (R.arc(e).label == i && R.arc(e).source == R.arc(e).target && !rule.preserved_right_arc(e))
          fail(v, {0,
                   'R',
                   {R.name(R.arc(e).source)},
                   {arc_text(R, e, words.right, words.scheme)},
                   {},
                   fmt::format("added arc {} is a loop", arc_text(R, e, words.right, words.scheme))});
      r.conditions.push_back(std::move(v));
    }
  return r;
}

}  // namespace dartcheck
