#include "events/static_events.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace dartcheck::events {

std::string_view name_of(Event e) {
  switch (e) {
    case Event::creation:
      return "creation";
    case Event::deletion:
      return "deletion";
    case Event::split:
      return "split";
    case Event::merge:
      return "merge";
    case Event::non_modification:
      return "no-modification";
    case Event::modification:
      return "modification";
  }
  return "?";
}

std::string_view name_of(Certainty c) {
  switch (c) {
    case Certainty::certain:
      return "certain";
    case Certainty::conditional:
      return "conditional";
    case Certainty::potential:
      return "potential";
  }
  return "?";
}

std::string rule_orbit_name(const EventRule& r, const KindEvents& k, bool left, int orbit) {
  const TopoGraph& g = left ? r.rule->left() : r.rule->right();
  const RuleOrbit& o = (left ? k.left : k.right).orbits[static_cast<std::size_t>(orbit)];
  std::vector<std::string> names;
  for (NodeId v : o.nodes) names.push_back(g.name(v));
  return fmt::format("{}{}({})", left ? 'L' : 'R', k.kind.str(), fmt::join(names, ","));
}

std::string claim_summary(const EventRule& r, const KindEvents& k, const EventClaim& c) {
  std::string s = fmt::format("{} {}", name_of(c.certainty), name_of(c.event));
  if (c.implicit) s += fmt::format(" along position {} (letter {})", c.position, r.parameter[static_cast<std::size_t>(c.position)]);
  if (!c.loop_positions.empty()) {
    std::vector<std::string> loops;
    for (int pos : c.loop_positions) loops.push_back(fmt::format("{} (letter {})", pos, r.parameter[static_cast<std::size_t>(pos)]));
    s += fmt::format(" where the links at position{} {} stay the same (loops, or a fold)", c.loop_positions.size() > 1 ? "s" : "",
                     fmt::join(loops, ", "));
  }
  if (!c.others.empty() && c.event == Event::merge && !c.implicit) {
    std::vector<std::string> names;
    for (int o : c.others) names.push_back(rule_orbit_name(r, k, true, o));
    s += fmt::format(" with {}", fmt::join(names, ", "));
  }
  return s;
}

namespace {

// The explicit arcs of `side` inside node set `nodes` whose label is a
// letter of a generator of <o>, as (source name, target name, label).
std::multiset<std::tuple<std::string, std::string, int>> orbit_arcs(const EventSide& side, const std::vector<NodeId>& nodes, const OrbitKind& kind) {
  std::set<Dim> letters;
  for (const OrbitWord& w : kind.generators) letters.insert(w.begin(), w.end());
  std::multiset<std::tuple<std::string, std::string, int>> out;
  for (ArcId e : side.explicit_arcs) {
    const auto& a = side.graph->arc(e);
    if (letters.count(a.label) && std::binary_search(nodes.begin(), nodes.end(), a.source))
      out.emplace(side.graph->name(a.source), side.graph->name(a.target), a.label);
  }
  return out;
}

// Def. 3.4.2 on X and the right orbit Y of its preserved nodes (every
// node of X preserved): the same nodes, the same labels at the positions
// in <o> on either side, the same explicit o-arcs (by node names). The
// positions in `as_loops` are read as explicit loops instead: this is the
// rule on a match where those links are loops (the case the proof of
// Prop. 3.2.1 names), where an implicit i-link at position k is an
// explicit i-loop on either side.
bool keeps_orbit(const EventRule& r, const OrbitKind& kind, const RuleOrbit& x, const RuleOrbit& yo, const std::set<std::size_t>& as_loops) {
  const Rule& rule = *r.rule;
  if (yo.nodes.size() != x.nodes.size()) return false;
  auto arcs_l = orbit_arcs(r.left, x.nodes, kind), arcs_r = orbit_arcs(r.right, yo.nodes, kind);
  for (NodeId v : x.nodes) {
    const NodeId w = rule.to_right(v);
    for (std::size_t pos = 0; pos < r.parameter.size(); ++pos) {
      const auto &a = r.left.labels[v][pos], &b = r.right.labels[w][pos];
      if (as_loops.count(pos)) {
        if (in_kind(kind, a)) arcs_l.emplace(r.left.graph->name(v), r.left.graph->name(v), *a);
        if (in_kind(kind, b)) arcs_r.emplace(r.right.graph->name(w), r.right.graph->name(w), *b);
      } else if ((in_kind(kind, a) || in_kind(kind, b)) && a != b) {
        return false;
      }
    }
  }
  if (kind.single_letters()) return arcs_l == arcs_r;
  // Orbit-word generators (O-map vertices): the orbit is unchanged when every
  // generator path ends at the same node on both sides, or leaves the
  // pattern from the same node after the same prefix (by an unmatched arc
  // of a preserved node, which the rule keeps). Nodes are compared by name.
  for (NodeId v : x.nodes)
    for (const OrbitWord& w : kind.generators) {
      const ExplicitPathEnd a = follow_explicit(r.left, v, w), b = follow_explicit(r.right, rule.to_right(v), w);
      if (a.letters != b.letters || r.left.graph->name(a.node) != r.right.graph->name(b.node)) return false;
    }
  return true;
}

}  // namespace

// Incomplete orbits are 'potential' because the map's orbit reaches
// beyond the match (004, end of Sec. 3.2). Two cases are definite anyway
// (single-letter orbit types). A complete rule orbit matches whole orbits
// made of its own darts, so the map orbit O of an incomplete X meets only
// unmatched darts, whose links the rule keeps, and darts of incomplete
// rule orbits. Hence:
//  - if every incomplete orbit of <o> keeps its nodes, labels and arcs
//    (Def. 3.4.2), no link of O changes: X's no-modification is certain;
//  - if every incomplete orbit has neither split, merge nor deletion, O
//    neither splits (the preserved nodes of each stay in one right orbit,
//    so every path of O has a path in H) nor merges, and if X deletes a
//    node or its right orbit gains a created one, O's darts change: X's
//    modification is certain (a triangulated face's vertex, 004 Table 1).
void sharpen_incomplete(const EventRule& r, KindEvents& k) {
  if (!k.kind.single_letters()) return;
  const Rule& rule = *r.rule;
  bool all_keep = true, quiet = true;
  for (const EventClaim& c : k.claims) {
    if (c.event == Event::creation || k.left.orbits[static_cast<std::size_t>(c.orbit)].complete) continue;
    if (c.event == Event::split || c.event == Event::merge || c.event == Event::deletion) quiet = false;
    if (c.event != Event::non_modification || !c.loop_positions.empty()) all_keep = false;
  }
  all_keep = all_keep && quiet;
  for (EventClaim& c : k.claims) {
    if (c.event == Event::creation || c.certainty != Certainty::potential) continue;
    const RuleOrbit& x = k.left.orbits[static_cast<std::size_t>(c.orbit)];
    if (x.complete) continue;
    if (c.event == Event::non_modification && c.loop_positions.empty() && all_keep) {
      c.certainty = Certainty::certain;
      c.reason +=
          "; every incomplete orbit of this type keeps its links and complete ones match whole orbits of their own, so no link of the "
          "map's orbit changes";
      continue;
    }
    const bool only =
        std::count_if(k.claims.begin(), k.claims.end(), [&](const EventClaim& o) { return o.event != Event::creation && o.orbit == c.orbit; }) == 1;
    if (c.event != Event::modification || !only || !quiet) continue;
    std::size_t preserved = 0, right_nodes = 0;
    for (NodeId v : x.nodes)
      if (const NodeId w = rule.to_right(v); w != no_node) {
        ++preserved;
        right_nodes = k.right.orbits[static_cast<std::size_t>(k.right.orbit_of[w])].nodes.size();
      }
    if (preserved == x.nodes.size() && right_nodes == preserved) continue;  // the same nodes: a change of links, maybe none
    c.certainty = Certainty::certain;
    c.reason += "; no incomplete orbit of this type splits, merges or is deleted, and this one loses or gains darts, so the map's orbit changes";
  }
}

namespace {

// A left orbit of the rule as its claims read it.
struct LeftOrbit {
  int li;
  const RuleOrbit& x;
  std::string name, incomplete;  // incomplete: " (incomplete: ...)" or ""
  Certainty explicit_certainty, implicit_certainty;
  std::vector<NodeId> preserved;  // its nodes that R keeps
  std::set<int> ys;               // the right orbits they go to
};

// The explicit split and merge of a left orbit (Def. 3.2.1, 3.3.1): its
// preserved nodes go to several right orbits, or meet another left
// orbit's there.
void explicit_claims(const EventRule& r, const KindEvents& k, const LeftOrbit& o, std::vector<EventClaim>& claims) {
  const Rule& rule = *r.rule;
  if (o.ys.size() >= 2) {
    std::vector<std::string> parts;
    for (int y : o.ys) parts.push_back(rule_orbit_name(r, k, false, y));
    claims.push_back({Event::split,
                      o.explicit_certainty,
                      o.li,
                      false,
                      -1,
                      {o.ys.begin(), o.ys.end()},
                      fmt::format("the preserved nodes of {} go to {} (explicit, Def. 3.2.1){}", o.name, fmt::join(parts, ", "), o.incomplete)});
  }
  // Explicit merge: a preserved node of another left orbit lands in one of ys.
  std::set<int> joined;
  for (NodeId v = 0; v < rule.left().node_count(); ++v)
    if (k.left.orbit_of[v] != o.li && rule.to_right(v) != no_node && o.ys.count(k.right.orbit_of[rule.to_right(v)]))
      joined.insert(k.left.orbit_of[v]);
  if (!joined.empty()) {
    std::vector<std::string> parts;
    for (int other : joined) parts.push_back(rule_orbit_name(r, k, true, other));
    claims.push_back({Event::merge,
                      o.explicit_certainty,
                      o.li,
                      false,
                      -1,
                      {joined.begin(), joined.end()},
                      fmt::format("{} and {} meet in one right orbit (explicit, Def. 3.3.1){}", o.name, fmt::join(parts, ", "), o.incomplete)});
  }
}

// The implicit split and merge along each position of the parameter,
// per right orbit of the preserved nodes.
void implicit_claims(const EventRule& r, const KindEvents& k, const LeftOrbit& o, std::vector<EventClaim>& claims) {
  const OrbitKind& kind = k.kind;
  for (int y : o.ys) {
    const RuleOrbit& yo = k.right.orbits[static_cast<std::size_t>(y)];
    for (std::size_t pos = 0; pos < r.parameter.size(); ++pos) {
      const bool in_left = std::any_of(o.x.nodes.begin(), o.x.nodes.end(), [&](NodeId v) { return in_kind(kind, r.left.labels[v][pos]); });
      const bool in_right = std::any_of(yo.nodes.begin(), yo.nodes.end(), [&](NodeId v) { return in_kind(kind, r.right.labels[v][pos]); });
      if (in_left && !in_right)
        claims.push_back({Event::split,
                          o.implicit_certainty,
                          o.li,
                          true,
                          static_cast<int>(pos),
                          {y},
                          fmt::format("position {} (letter {}) links {} inside <o> but no node of {} keeps it there (implicit, Def. 3.2.1){}", pos,
                                      r.parameter[pos], o.name, rule_orbit_name(r, k, false, y), o.incomplete)});
      if (!in_left && in_right)
        claims.push_back({Event::merge,
                          o.implicit_certainty,
                          o.li,
                          true,
                          static_cast<int>(pos),
                          {y},
                          fmt::format("position {} (letter {}) links {} inside <o> but no node of {} did (implicit, Def. 3.3.1){}", pos,
                                      r.parameter[pos], rule_orbit_name(r, k, false, y), o.name, o.incomplete)});
    }
  }
}

// Non-modification (Def. 3.4.2) when the orbit keeps its nodes, labels
// and arcs; otherwise modification (Sec. 3.4.3), the potential events of
// word orbit types, and the loop case of Prop. 3.2.1 and 3.3.1.
void change_claims(const EventRule& r, const KindEvents& k, const LeftOrbit& o, std::vector<EventClaim>& claims) {
  const Rule& rule = *r.rule;
  const OrbitKind& kind = k.kind;
  const bool unchanged = claims.empty() && o.preserved.size() == o.x.nodes.size() && o.ys.size() == 1 &&
                         keeps_orbit(r, kind, o.x, k.right.orbits[static_cast<std::size_t>(*o.ys.begin())], {});
  if (unchanged) {
    claims.push_back({Event::non_modification,
                      o.explicit_certainty,
                      o.li,
                      false,
                      -1,
                      {},
                      o.x.complete ? fmt::format("{} keeps its nodes, o-labels and o-arcs (Prop. 3.4.2)", o.name)
                                   : fmt::format("{} keeps its nodes, o-labels and o-arcs, but the map's orbit may reach other matched parts{}",
                                                 o.name, o.incomplete)});
  } else {
    // Orbit-word generators: a generator path may pass through matched darts
    // and end outside the match, so an incomplete orbit whose paths the
    // rule changes can split or merge without any of the paper's flags
    // (found by the fuzz cross-check on fig18b-rewire-paths, <21>).
    if (!kind.single_letters() && !o.x.complete) {
      const bool has_split = std::any_of(claims.begin(), claims.end(), [](const EventClaim& c) { return c.event == Event::split; });
      const bool has_merge = std::any_of(claims.begin(), claims.end(), [](const EventClaim& c) { return c.event == Event::merge; });
      const std::string why =
          fmt::format("a generator path of {} leaves the pattern and the rule changes the orbit (word orbit types){}", o.name, o.incomplete);
      if (!has_split) claims.push_back({Event::split, Certainty::potential, o.li, false, -1, {}, why});
      if (!has_merge) claims.push_back({Event::merge, Certainty::potential, o.li, false, -1, {}, why});
    }
    // The loop case of the proofs of Prop. 3.2.1 and 3.3.1: where the
    // links at the positions the rule changes inside <o> are loops on the
    // matched darts, the rule reads as one with explicit loops there. If
    // that reading keeps the orbit (Def. 3.4.2), the orbit comes out
    // identical: a no-modification on exactly those matches.
    std::set<std::size_t> loops;
    for (NodeId v : o.x.nodes)
      if (const NodeId w = rule.to_right(v); w != no_node)
        for (std::size_t pos = 0; pos < r.parameter.size(); ++pos) {
          const auto &a = r.left.labels[v][pos], &b = r.right.labels[w][pos];
          if ((in_kind(kind, a) || in_kind(kind, b)) && a != b) loops.insert(pos);
        }
    const bool explicit_change = std::any_of(claims.begin(), claims.end(), [](const EventClaim& c) { return !c.implicit; });
    const bool loop_case = kind.single_letters() && !explicit_change && !loops.empty() && o.preserved.size() == o.x.nodes.size() &&
                           o.ys.size() == 1 && keeps_orbit(r, kind, o.x, k.right.orbits[static_cast<std::size_t>(*o.ys.begin())], loops);
    std::vector<std::string> loop_names;
    for (std::size_t pos : loops) loop_names.push_back(fmt::format("{} (letter {})", pos, r.parameter[pos]));
    // Modification (Sec. 3.4.3) is what remains when no split or merge
    // happens: certain only when none was announced and no loop case
    // keeps the orbit.
    const bool certain_other = std::any_of(claims.begin(), claims.end(), [](const EventClaim& c) { return c.certainty == Certainty::certain; });
    if (!certain_other) {
      const Certainty c = !claims.empty() || loop_case ? o.implicit_certainty : o.explicit_certainty;
      std::string why = claims.empty() ? fmt::format("{} changes its nodes, o-labels or o-arcs without a split or merge (Sec. 3.4.3)", o.name)
                                       : fmt::format("{} is modified where the announced split or merge does not happen", o.name);
      if (loop_case)
        why += fmt::format(", unless the links at position{} {} stay the same (loops, or a fold)", loops.size() > 1 ? "s" : "",
                           fmt::join(loop_names, ", "));
      claims.push_back({Event::modification, c, o.li, false, -1, {}, why + o.incomplete});
    }
    if (loop_case)
      claims.push_back({Event::non_modification,
                        o.implicit_certainty,
                        o.li,
                        false,
                        -1,
                        {},
                        fmt::format("where the links at position{} {} of the matched darts are loops (or folded so that the relabeled "
                                    "links coincide), {} keeps its nodes, o-labels and o-arcs (Prop. 3.4.2 on the loop case of the "
                                    "proofs of Prop. 3.2.1, 3.3.1){}",
                                    loops.size() > 1 ? "s" : "", fmt::join(loop_names, ", "), o.name, o.incomplete),
                        {loops.begin(), loops.end()}});
  }
}

}  // namespace

KindEvents static_events(const EventRule& r, const OrbitKind& kind) {
  KindEvents k{kind, side_orbits(r, r.left, kind), side_orbits(r, r.right, kind), {}};
  const Rule& rule = *r.rule;
  auto name = [&](bool left, int o) { return rule_orbit_name(r, k, left, o); };
  auto incompleteness = [&](const RuleOrbit& o) { return fmt::format("incomplete: {}", fmt::join(o.missing, "; ")); };

  for (int ri = 0; ri < static_cast<int>(k.right.orbits.size()); ++ri) {
    const RuleOrbit& y = k.right.orbits[static_cast<std::size_t>(ri)];
    if (std::all_of(y.nodes.begin(), y.nodes.end(), [&](NodeId v) { return rule.to_left(v) == no_node; }))
      k.claims.push_back({Event::creation,
                          y.complete ? Certainty::certain : Certainty::potential,
                          ri,
                          false,
                          -1,
                          {},
                          y.complete ? fmt::format("every node of {} is created (Prop. 3.1.1)", name(false, ri))
                                     : fmt::format("every node of {} is created but it is {}", name(false, ri), incompleteness(y))});
  }

  for (int li = 0; li < static_cast<int>(k.left.orbits.size()); ++li) {
    const RuleOrbit& x = k.left.orbits[static_cast<std::size_t>(li)];
    LeftOrbit o{li,
                x,
                name(true, li),
                x.complete ? std::string() : fmt::format(" ({})", incompleteness(x)),
                x.complete ? Certainty::certain : Certainty::potential,
                x.complete ? Certainty::conditional : Certainty::potential,
                {},
                {}};
    for (NodeId v : x.nodes)
      if (rule.to_right(v) != no_node) o.preserved.push_back(v);
    if (o.preserved.empty()) {
      k.claims.push_back({Event::deletion,
                          o.explicit_certainty,
                          li,
                          false,
                          -1,
                          {},
                          fmt::format("every node of {} is deleted (Prop. 3.4.1){}", o.name, o.incomplete)});
      continue;
    }
    for (NodeId v : o.preserved) o.ys.insert(k.right.orbit_of[rule.to_right(v)]);
    std::vector<EventClaim> claims;
    explicit_claims(r, k, o, claims);
    implicit_claims(r, k, o, claims);
    change_claims(r, k, o, claims);
    k.claims.insert(k.claims.end(), claims.begin(), claims.end());
  }
  sharpen_incomplete(r, k);
  return k;
}

}  // namespace dartcheck::events
