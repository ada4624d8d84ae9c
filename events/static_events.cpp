#include "events/static_events.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace dartcheck::events {

std::string_view event_name(Event e) {
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

std::string_view certainty_name(Certainty c) {
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
  std::string s = fmt::format("{} {}", certainty_name(c.certainty), event_name(c.event));
  if (c.implicit) s += fmt::format(" along position {} (letter {})", c.position, r.parameter[static_cast<std::size_t>(c.position)]);
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
  for (const Word& w : kind.generators) letters.insert(w.begin(), w.end());
  std::multiset<std::tuple<std::string, std::string, int>> out;
  for (ArcId e : side.explicit_arcs) {
    const auto& a = side.graph->arc(e);
    if (letters.count(a.label) && std::binary_search(nodes.begin(), nodes.end(), a.source))
      out.emplace(side.graph->name(a.source), side.graph->name(a.target), a.label);
  }
  return out;
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
    const std::string xn = name(true, li);
    const Certainty explicit_certainty = x.complete ? Certainty::certain : Certainty::potential;
    const Certainty implicit_certainty = x.complete ? Certainty::conditional : Certainty::potential;
    const std::string incomplete = x.complete ? std::string() : fmt::format(" ({})", incompleteness(x));
    std::vector<NodeId> preserved;
    for (NodeId v : x.nodes)
      if (rule.to_right(v) != no_node) preserved.push_back(v);
    if (preserved.empty()) {
      k.claims.push_back(
          {Event::deletion, explicit_certainty, li, false, -1, {}, fmt::format("every node of {} is deleted (Prop. 3.4.1){}", xn, incomplete)});
      continue;
    }
    std::set<int> ys;
    for (NodeId v : preserved) ys.insert(k.right.orbit_of[rule.to_right(v)]);
    std::vector<EventClaim> claims;
    if (ys.size() >= 2) {
      std::vector<std::string> parts;
      for (int y : ys) parts.push_back(name(false, y));
      claims.push_back({Event::split,
                        explicit_certainty,
                        li,
                        false,
                        -1,
                        {ys.begin(), ys.end()},
                        fmt::format("the preserved nodes of {} go to {} (explicit, Def. 3.2.1){}", xn, fmt::join(parts, ", "), incomplete)});
    }
    // Explicit merge: a preserved node of another left orbit lands in one of ys.
    std::set<int> joined;
    for (NodeId v = 0; v < rule.left().node_count(); ++v)
      if (k.left.orbit_of[v] != li && rule.to_right(v) != no_node && ys.count(k.right.orbit_of[rule.to_right(v)])) joined.insert(k.left.orbit_of[v]);
    if (!joined.empty()) {
      std::vector<std::string> parts;
      for (int o : joined) parts.push_back(name(true, o));
      claims.push_back({Event::merge,
                        explicit_certainty,
                        li,
                        false,
                        -1,
                        {joined.begin(), joined.end()},
                        fmt::format("{} and {} meet in one right orbit (explicit, Def. 3.3.1){}", xn, fmt::join(parts, ", "), incomplete)});
    }
    // Implicit events along position k, per right orbit of the preserved nodes.
    for (int y : ys) {
      const RuleOrbit& yo = k.right.orbits[static_cast<std::size_t>(y)];
      for (std::size_t pos = 0; pos < r.parameter.size(); ++pos) {
        const bool in_left = std::any_of(x.nodes.begin(), x.nodes.end(), [&](NodeId v) { return in_kind(kind, r.left.labels[v][pos]); });
        const bool in_right = std::any_of(yo.nodes.begin(), yo.nodes.end(), [&](NodeId v) { return in_kind(kind, r.right.labels[v][pos]); });
        if (in_left && !in_right)
          claims.push_back({Event::split,
                            implicit_certainty,
                            li,
                            true,
                            static_cast<int>(pos),
                            {y},
                            fmt::format("position {} (letter {}) links {} inside <o> but no node of {} keeps it there (implicit, Def. 3.2.1){}", pos,
                                        r.parameter[pos], xn, name(false, y), incomplete)});
        if (!in_left && in_right)
          claims.push_back({Event::merge,
                            implicit_certainty,
                            li,
                            true,
                            static_cast<int>(pos),
                            {y},
                            fmt::format("position {} (letter {}) links {} inside <o> but no node of {} did (implicit, Def. 3.3.1){}", pos,
                                        r.parameter[pos], name(false, y), xn, incomplete)});
      }
    }
    // Non-modification (Def. 3.4.2): the same nodes, the same labels at the
    // positions that are in <o> on either side, the same explicit o-arcs.
    bool unchanged = claims.empty() && preserved.size() == x.nodes.size() && ys.size() == 1;
    if (unchanged) {
      const RuleOrbit& yo = k.right.orbits[static_cast<std::size_t>(*ys.begin())];
      unchanged = yo.nodes.size() == x.nodes.size();
      for (NodeId v : x.nodes) {
        const NodeId w = rule.to_right(v);
        for (std::size_t pos = 0; unchanged && pos < r.parameter.size(); ++pos) {
          const auto &a = r.left.labels[v][pos], &b = r.right.labels[w][pos];
          if ((in_kind(kind, a) || in_kind(kind, b)) && a != b) unchanged = false;
        }
      }
      if (kind.single_letters()) {
        unchanged = unchanged && orbit_arcs(r.left, x.nodes, kind) == orbit_arcs(r.right, yo.nodes, kind);
      } else {
        // Word generators (O-map vertices): the orbit is unchanged when
        // every generator path ends at the same node on both sides, or
        // leaves the pattern from the same node after the same prefix (by
        // an unmatched arc of a preserved node, which the rule keeps).
        for (NodeId v : x.nodes)
          for (const Word& w : kind.generators) {
            // Nodes are compared by name across the two sides.
            const ExplicitPathEnd a = follow_explicit(r.left, v, w), b = follow_explicit(r.right, rule.to_right(v), w);
            unchanged = unchanged && a.letters == b.letters && r.left.graph->name(a.node) == r.right.graph->name(b.node);
          }
      }
    }
    if (unchanged) {
      claims.push_back(
          {Event::non_modification,
           explicit_certainty,
           li,
           false,
           -1,
           {},
           x.complete ? fmt::format("{} keeps its nodes, o-labels and o-arcs (Prop. 3.4.2)", xn)
                      : fmt::format("{} keeps its nodes, o-labels and o-arcs, but the map's orbit may reach other matched parts{}", xn, incomplete)});
    } else {
      // Word generators: a generator path may pass through matched darts
      // and end outside the match, so an incomplete orbit whose paths the
      // rule changes can split or merge without any of the paper's flags
      // (found by the fuzz cross-check on fig18b-rewire-paths, <21>).
      if (!kind.single_letters() && !x.complete) {
        const bool has_split = std::any_of(claims.begin(), claims.end(), [](const EventClaim& c) { return c.event == Event::split; });
        const bool has_merge = std::any_of(claims.begin(), claims.end(), [](const EventClaim& c) { return c.event == Event::merge; });
        const std::string why =
            fmt::format("a generator path of {} leaves the pattern and the rule changes the orbit (word orbit types){}", xn, incomplete);
        if (!has_split) claims.push_back({Event::split, Certainty::potential, li, false, -1, {}, why});
        if (!has_merge) claims.push_back({Event::merge, Certainty::potential, li, false, -1, {}, why});
      }
      // Modification (Sec. 3.4.3) is what remains when no split or merge
      // happens: certain only when none was announced.
      const bool certain_other = std::any_of(claims.begin(), claims.end(), [](const EventClaim& c) { return c.certainty == Certainty::certain; });
      if (!certain_other) {
        const Certainty c = !claims.empty() ? (x.complete ? Certainty::conditional : Certainty::potential) : explicit_certainty;
        claims.push_back({Event::modification,
                          c,
                          li,
                          false,
                          -1,
                          {},
                          claims.empty()
                              ? fmt::format("{} changes its nodes, o-labels or o-arcs without a split or merge (Sec. 3.4.3){}", xn, incomplete)
                              : fmt::format("{} is modified where the announced split or merge does not happen{}", xn, incomplete)});
      }
    }
    k.claims.insert(k.claims.end(), claims.begin(), claims.end());
  }
  return k;
}

}  // namespace dartcheck::events
