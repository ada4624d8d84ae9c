#include "events/cross_check.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "core/orbit.hpp"

namespace dartcheck::events {
namespace {

std::vector<Dart> representatives(const Map& m, const OrbitKind& kind) {
  std::vector<Dart> rep(m.size(), no_dart);
  OrbitWalker walker(m);
  for (Dart d = 0; d < m.size(); ++d)
    if (rep[d] == no_dart)
      for (Dart e : walker.orbit(d, kind.generators)) rep[e] = d;
  return rep;
}

bool involves(const LoggedEvent& e, bool before, Dart rep) {
  const auto& v = before ? e.before : e.after;
  return std::find(v.begin(), v.end(), rep) != v.end();
}

}  // namespace

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
  const std::vector<Dart> grep = representatives(g, k.kind), hrep = representatives(h, k.kind);
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

  auto happened = [&](Event ev, bool before, Dart rep) {
    return std::any_of(dynamic.events.begin(), dynamic.events.end(), [&](const LoggedEvent& e) { return e.event == ev && involves(e, before, rep); });
  };
  auto claim_name = [&](const EventClaim& cl) {
    return fmt::format("{} {} of {}", certainty_name(cl.certainty), event_name(cl.event),
                       rule_orbit_name(r, k, cl.event != Event::creation, cl.orbit));
  };

  for (const EventClaim& cl : k.claims) {
    const bool left = cl.event != Event::creation;
    const auto& touched = left ? touched_g[static_cast<std::size_t>(cl.orbit)] : touched_h[static_cast<std::size_t>(cl.orbit)];
    for (Dart rep : touched) {
      if (happened(cl.event, left, rep)) continue;
      // A modification gives way to a split or merge by definition (Sec. 3.4.3).
      if (cl.event == Event::modification && (happened(Event::split, true, rep) || happened(Event::merge, true, rep))) continue;
      const std::string where = fmt::format("{}{}({})", left ? 'G' : 'H', o, rep);
      if (cl.certainty == Certainty::certain) {
        out.contradictions.push_back(fmt::format("{}: {} does not happen on {}", o, claim_name(cl), where));
        continue;
      }
      if (cl.certainty == Certainty::potential) {
        out.resolutions.push_back(fmt::format("{} does not happen on {}", claim_name(cl), where));
        continue;
      }
      // Conditional: find the loop or fold that prevents it.
      std::string witness;
      const RuleOrbit& x = k.left.orbits[static_cast<std::size_t>(cl.orbit)];
      const auto pos = static_cast<std::size_t>(cl.position);
      if (cl.event == Event::split && cl.implicit) {
        for (NodeId v : x.nodes) {
          const auto& label = r.left.labels[v][pos];
          if (!in_kind(k.kind, label)) continue;
          for (Dart d : t.match[v]) {
            if (grep[d] != rep || !witness.empty()) continue;
            const Dart e = g.link(*label, d);
            if (e == d)
              witness = fmt::format("the {}-link of dart {} is a loop", *label, d);
            else if (e != no_dart && c.to_h(d) != no_dart && c.to_h(e) != no_dart && hrep[c.to_h(d)] == hrep[c.to_h(e)])
              witness = fmt::format("darts {} and {} ({}-linked in G) stay in one orbit of H: the orbit is folded", d, e, *label);
          }
        }
      } else if (cl.event == Event::merge && cl.implicit) {
        const RuleOrbit& y = k.right.orbits[static_cast<std::size_t>(cl.others.at(0))];
        for (NodeId v : y.nodes) {
          const auto& label = r.right.labels[v][pos];
          if (!in_kind(k.kind, label)) continue;
          for (Dart d : t.comatch[v]) {
            if (!witness.empty() || c.to_g(d) == no_dart || grep[c.to_g(d)] != rep) continue;
            const Dart e = h.link(*label, d);
            if (e == d)
              witness = fmt::format("the {}-link of dart {} of H is a loop", *label, d);
            else if (e != no_dart && c.to_g(e) != no_dart && grep[c.to_g(d)] == grep[c.to_g(e)])
              witness = fmt::format("darts {} and {} of H ({}-linked) were already in one orbit of G: the orbit is folded", d, e, *label);
          }
        }
      }
      if (witness.empty())
        out.contradictions.push_back(fmt::format("{}: {} does not happen on {} and no loop or fold explains it", o, claim_name(cl), where));
      else
        out.resolutions.push_back(fmt::format("{} does not happen on {}: {}", claim_name(cl), where, witness));
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
