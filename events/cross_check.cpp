#include "events/cross_check.hpp"

#include <algorithm>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "core/orbit.hpp"

namespace dartcheck::events {

CrossCheck cross_check(const EventRule& r, const KindEvents& k, const Map& g, const Map& h, const Application& t, const EventLog& dynamic,
                       const EventLog& instantiated) {
  CrossCheck out;
  const std::string o = k.kind.str();
  if (dynamic.events != instantiated.events) {
    std::set<LoggedEvent> a(dynamic.events.begin(), dynamic.events.end()), b(instantiated.events.begin(), instantiated.events.end());
    for (const auto& e : a)
      if (!b.count(e))
        out.contradictions.push_back(fmt::format("{}: dynamic detection finds '{}', the instantiation does not", o, event_line(k.kind, e)));
    for (const auto& e : b)
      if (!a.count(e))
        out.contradictions.push_back(fmt::format("{}: the instantiation finds '{}', dynamic detection does not", o, event_line(k.kind, e)));
  }
  const Rule& rule = *r.rule;
  const Renumbering c = t.renumbering(rule, h.size());
  const std::vector<Dart> grep = orbit_representatives(g, k.kind), hrep = orbit_representatives(h, k.kind);
  // The G orbits each left rule orbit touches, and the H orbits of each right one.
  std::vector<std::set<Dart>> touched_g(k.left.orbits.size()), touched_h(k.right.orbits.size());
  std::set<Dart> matched_g;
  for (NodeId x = 0; x < t.match.size(); ++x)
    for (Dart d : t.match[x]) {
      touched_g[static_cast<std::size_t>(k.left.orbit_of[x])].insert(grep[d]);
      matched_g.insert(grep[d]);
    }
  for (NodeId y = 0; y < t.comatch.size(); ++y)
    for (Dart d : t.comatch[y]) touched_h[static_cast<std::size_t>(k.right.orbit_of[y])].insert(hrep[d]);

  // Which (event, side, orbit) the dynamic log holds, indexed once: asked
  // per claim and touched orbit, a scan of the log was quadratic on a large map.
  std::set<std::tuple<Event, bool, Dart>> logged;
  for (const LoggedEvent& e : dynamic.events) {
    for (Dart d : e.before) logged.emplace(e.event, true, d);
    for (Dart d : e.after) logged.emplace(e.event, false, d);
  }
  auto happened = [&](Event ev, bool before, Dart rep) { return logged.contains({ev, before, rep}); };
  auto claim_name = [&](const EventClaim& cl) {
    return fmt::format("{} {} of {}", name_of(cl.certainty), name_of(cl.event), rule_orbit_name(r, k, cl.event != Event::creation, cl.orbit));
  };

  // The condition of a loop-case no-modification on G orbit `rep`: at
  // every matched dart of the orbit, the links along the letters the rule
  // changes (its positions' letters on either side, inside <o>) are the
  // same in G and H: loops, or a fold that the relabeling keeps. Empty
  // when it holds, else the first link that changes.
  auto changed_link = [&](const EventClaim& cl, Dart rep) -> std::string {
    const RuleOrbit& x = k.left.orbits[static_cast<std::size_t>(cl.orbit)];
    for (NodeId v : x.nodes)
      for (Dart d : t.match[v]) {
        const NodeId w = rule.to_right(v);
        if (grep[d] != rep || w == no_node || c.to_h(d) == no_dart) continue;
        for (int p : cl.loop_positions)
          for (const auto& letter : {r.left.labels[v][static_cast<std::size_t>(p)], r.right.labels[w][static_cast<std::size_t>(p)]}) {
            if (!in_kind(k.kind, letter)) continue;
            const Dart before = g.link(*letter, d), after = h.link(*letter, c.to_h(d));
            if ((before == no_dart ? no_dart : c.to_h(before)) != after)
              return fmt::format("the {}-link of dart {} changes ({} in G, {} in H)", *letter, d,
                                 before == d ? "a loop" : fmt::format("to {}", before), after == c.to_h(d) ? "a loop" : fmt::format("to {}", after));
          }
      }
    return {};
  };
  auto loop_claim = [&](const EventClaim& cl) {
    return std::find_if(k.claims.begin(), k.claims.end(),
                        [&](const EventClaim& n) { return n.event == Event::non_modification && n.orbit == cl.orbit && !n.loop_positions.empty(); });
  };

  // Pattern positions: a matched dart of G and a comatched dart of H give
  // their position; a position gives its G orbit through X's nodes (joined
  // by explicit o-arcs, so one orbit) and its H orbit through one
  // preserved node of Y. Created and deleted nodes have positions too.
  constexpr std::size_t no_position = static_cast<std::size_t>(-1);
  std::vector<std::size_t> gpos(g.size(), no_position), hpos(h.size(), no_position);
  for (const auto& darts : t.match)
    for (std::size_t x = 0; x < darts.size(); ++x) gpos[darts[x]] = x;
  for (const auto& darts : t.comatch)
    for (std::size_t x = 0; x < darts.size(); ++x) hpos[darts[x]] = x;
  auto g_orbit_at = [&](const RuleOrbit& x, std::size_t p) { return grep[t.match[x.nodes.front()][p]]; };
  auto h_orbit_at = [&](const RuleOrbit& y, std::size_t p) {
    for (NodeId w : y.nodes)
      if (rule.to_left(w) != no_node) return hrep[t.comatch[w][p]];
    return no_dart;
  };
  // Why an implicit split along k does not happen on G orbit `rep`: every
  // k-link of X's matched darts there is a loop, or its ends stay in one
  // orbit of H (a fold). Starts with "yet" when one is neither.
  auto split_blocked = [&](const EventClaim& cl, Dart rep) -> std::string {
    const RuleOrbit& x = k.left.orbits[static_cast<std::size_t>(cl.orbit)];
    const RuleOrbit& y = k.right.orbits[static_cast<std::size_t>(cl.others.at(0))];
    const auto pos = static_cast<std::size_t>(cl.position);
    std::size_t loops = 0, folds = 0;
    for (NodeId v : x.nodes) {
      const auto& label = r.left.labels[v][pos];
      if (!in_kind(k.kind, label)) continue;
      for (std::size_t p = 0; p < t.match[v].size(); ++p) {
        const Dart d = t.match[v][p];
        if (g_orbit_at(x, p) != rep) continue;
        const Dart e = g.link(*label, d);
        if (e == d) {
          ++loops;
        } else if (e != no_dart && gpos[e] != no_position && h_orbit_at(y, p) == h_orbit_at(y, gpos[e])) {
          ++folds;
        } else {
          return fmt::format("yet the {}-link of darts {} and {} is no loop and its ends go to two orbits of H", *label, d, e);
        }
      }
    }
    return fmt::format("every link at position {} (letter {}) there is a loop ({}) or folded ({})", pos, r.parameter[pos], loops, folds);
  };
  // Why an implicit merge along k does not happen: every k-link of Y's
  // comatched darts there is a loop in H, or joins two darts of one G orbit.
  auto merge_blocked = [&](const EventClaim& cl, Dart rep) -> std::string {
    const RuleOrbit& x = k.left.orbits[static_cast<std::size_t>(cl.orbit)];
    const RuleOrbit& y = k.right.orbits[static_cast<std::size_t>(cl.others.at(0))];
    const auto pos = static_cast<std::size_t>(cl.position);
    std::size_t loops = 0, folds = 0;
    for (NodeId w : y.nodes) {
      const auto& label = r.right.labels[w][pos];
      if (!in_kind(k.kind, label)) continue;
      for (std::size_t p = 0; p < t.comatch[w].size(); ++p) {
        const Dart d = t.comatch[w][p];
        if (g_orbit_at(x, p) != rep) continue;
        const Dart e = h.link(*label, d);
        if (e == d) {
          ++loops;
        } else if (e != no_dart && hpos[e] != no_position && g_orbit_at(x, hpos[e]) == rep) {
          ++folds;
        } else {
          return fmt::format("yet the {}-link of darts {} and {} of H is no loop and joins two orbits of G", *label, d, e);
        }
      }
    }
    return fmt::format("every link at position {} (letter {}) there is a loop ({}) or folded ({})", pos, r.parameter[pos], loops, folds);
  };

  for (const EventClaim& cl : k.claims) {
    const auto index = static_cast<std::size_t>(&cl - k.claims.data());
    const bool left = cl.event != Event::creation;
    const auto& touched = left ? touched_g[static_cast<std::size_t>(cl.orbit)] : touched_h[static_cast<std::size_t>(cl.orbit)];
    for (Dart rep : touched) {
      const std::string where = fmt::format("{}{}({})", left ? 'G' : 'H', o, rep);
      if (happened(cl.event, left, rep)) {
        if (out.happened.empty() || out.happened.back() != index) out.happened.push_back(index);
        // A loop-case no-modification must have its loops.
        if (!cl.loop_positions.empty() && cl.certainty == Certainty::conditional)
          if (auto why = changed_link(cl, rep); !why.empty())
            out.contradictions.push_back(fmt::format("{}: {} happens on {} but {}", o, claim_name(cl), where, why));
        continue;
      }
      // A modification gives way to a split or merge by definition (Sec. 3.4.3).
      if (cl.event == Event::modification && (happened(Event::split, true, rep) || happened(Event::merge, true, rep))) continue;
      // ... and to the no-modification of the loop case, where its loops are.
      if (cl.event == Event::modification && happened(Event::non_modification, true, rep) && loop_claim(cl) != k.claims.end() &&
          changed_link(*loop_claim(cl), rep).empty()) {
        out.resolutions.push_back(
            fmt::format("{} does not happen on {}: the links it changes are the same in G and H (loops or a fold), so the orbit is unchanged",
                        claim_name(cl), where));
        continue;
      }
      if (!cl.loop_positions.empty() && cl.certainty == Certainty::conditional) {
        // A loop-case no-modification that does not happen: some link is no loop.
        if (auto why = changed_link(cl, rep); !why.empty())
          out.resolutions.push_back(fmt::format("{} does not happen on {}: {}", claim_name(cl), where, why));
        else
          out.contradictions.push_back(
              fmt::format("{}: {} does not happen on {} though the links it changes are the same in G and H", o, claim_name(cl), where));
        continue;
      }
      if (cl.certainty == Certainty::certain) {
        out.contradictions.push_back(fmt::format("{}: {} does not happen on {}", o, claim_name(cl), where));
        continue;
      }
      if (cl.certainty == Certainty::potential) {
        out.resolutions.push_back(fmt::format("{} does not happen on {}", claim_name(cl), where));
        continue;
      }
      // Conditional: it fails only where every k-link of the orbit's
      // matched darts is a loop or folded (its two ends stay in one orbit
      // on the other side); one k-link that is neither makes it happen.
      if (cl.event == Event::modification) {
        // Not a split, a merge, nor the loop case's no-modification: what
        // the orbit became was announced by none of its claims.
        out.contradictions.push_back(
            fmt::format("{}: {} does not happen on {}, and none of the other events announced for it does", o, claim_name(cl), where));
        continue;
      }
      const std::string why = cl.event == Event::split ? split_blocked(cl, rep) : merge_blocked(cl, rep);
      if (why.rfind("yet", 0) == 0)
        out.contradictions.push_back(fmt::format("{}: {} does not happen on {}, {}", o, claim_name(cl), where, why));
      else
        out.resolutions.push_back(fmt::format("{} does not happen on {}: {}", claim_name(cl), where, why));
    }
  }

  // Every logged event was announced, and unmatched orbits do not change.
  for (const LoggedEvent& e : dynamic.events) {
    if (e.event == Event::creation) {
      bool announced = false;
      for (const EventClaim& cl : k.claims)
        announced = announced || (cl.event == Event::creation && touched_h[static_cast<std::size_t>(cl.orbit)].count(e.after[0]));
      if (!announced) out.contradictions.push_back(fmt::format("{}: '{}' was not announced by any rule orbit", o, event_line(k.kind, e)));
      continue;
    }
    for (Dart rep : e.before) {
      if (!matched_g.count(rep)) {
        out.contradictions.push_back(fmt::format("{}: '{}' changes an orbit no rule node matches", o, event_line(k.kind, e)));
        continue;
      }
      bool announced = false;
      for (const EventClaim& cl : k.claims)
        announced = announced || (cl.event == e.event && cl.event != Event::creation && touched_g[static_cast<std::size_t>(cl.orbit)].count(rep));
      if (!announced)
        out.contradictions.push_back(
            fmt::format("{}: '{}' on G{}({}) was not announced by any rule orbit that matches it", o, event_line(k.kind, e), o, rep));
    }
  }
  return out;
}

}  // namespace dartcheck::events
