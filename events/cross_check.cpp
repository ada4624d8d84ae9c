#include "events/cross_check.hpp"

#include <algorithm>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "core/orbit.hpp"

namespace dartcheck::events {

namespace {

// The cross-check of one kind's claims against one application: the
// application's G and H orbits, the positions of its darts, and the
// dynamic log indexed once.
class CrossChecker {
 public:
  CrossChecker(const EventRule& r, const KindEvents& k, const Map& g, const Map& h, const Application& t, const EventLog& dynamic);
  CrossCheck run(const EventLog& instantiated);

 private:
  bool happened(Event ev, bool before, Dart rep) const { return logged_.contains({ev, before, rep}); }
  std::string claim_name(const EventClaim& cl) const {
    return fmt::format("{} {} of {}", name_of(cl.certainty), name_of(cl.event), rule_orbit_name(r_, k_, cl.event != Event::creation, cl.orbit));
  }
  std::string changed_link(const EventClaim& cl, Dart rep) const;
  std::vector<EventClaim>::const_iterator loop_claim(const EventClaim& cl) const {
    return std::find_if(k_.claims.begin(), k_.claims.end(),
                        [&](const EventClaim& n) { return n.event == Event::non_modification && n.orbit == cl.orbit && !n.loop_positions.empty(); });
  }
  Dart g_orbit_at(const RuleOrbit& x, std::size_t p) const { return grep_[t_.match[x.nodes.front()][p]]; }
  Dart h_orbit_at(const RuleOrbit& y, std::size_t p) const {
    for (NodeId w : y.nodes)
      if (rule_.to_left(w) != no_node) return hrep_[t_.comatch[w][p]];
    return no_dart;
  }
  std::string split_blocked(const EventClaim& cl, Dart rep) const;
  std::string merge_blocked(const EventClaim& cl, Dart rep) const;
  void judge(const EventClaim& cl, std::size_t index, bool left, Dart rep);
  void check_announced();

  static constexpr std::size_t no_position = static_cast<std::size_t>(-1);
  const EventRule& r_;
  const KindEvents& k_;
  const Map &g_, &h_;
  const Application& t_;
  const EventLog& dynamic_;
  const Rule& rule_;
  const std::string o_;  // the orbit kind, as messages name it
  const Renumbering c_;
  const std::vector<Dart> grep_, hrep_;
  // The G orbits each left rule orbit touches, and the H orbits of each right one.
  std::vector<std::set<Dart>> touched_g_, touched_h_;
  std::set<Dart> matched_g_;
  // Which (event, side, orbit) the dynamic log holds, indexed once: asked
  // per claim and touched orbit, a scan of the log was quadratic on a large map.
  std::set<std::tuple<Event, bool, Dart>> logged_;
  // Pattern positions: a matched dart of G and a comatched dart of H give
  // their position; a position gives its G orbit through X's nodes (joined
  // by explicit o-arcs, so one orbit) and its H orbit through one
  // preserved node of Y. Created and deleted nodes have positions too.
  std::vector<std::size_t> gpos_, hpos_;
  CrossCheck out_;
};

CrossChecker::CrossChecker(const EventRule& r, const KindEvents& k, const Map& g, const Map& h, const Application& t, const EventLog& dynamic)
    : r_(r),
      k_(k),
      g_(g),
      h_(h),
      t_(t),
      dynamic_(dynamic),
      rule_(*r.rule),
      o_(k.kind.str()),
      c_(t.renumbering(*r.rule, h.size())),
      grep_(orbit_representatives(g, k.kind)),
      hrep_(orbit_representatives(h, k.kind)),
      touched_g_(k.left.orbits.size()),
      touched_h_(k.right.orbits.size()),
      gpos_(g.size(), no_position),
      hpos_(h.size(), no_position) {
  for (NodeId x = 0; x < t.match.size(); ++x)
    for (Dart d : t.match[x]) {
      touched_g_[static_cast<std::size_t>(k.left.orbit_of[x])].insert(grep_[d]);
      matched_g_.insert(grep_[d]);
    }
  for (NodeId y = 0; y < t.comatch.size(); ++y)
    for (Dart d : t.comatch[y]) touched_h_[static_cast<std::size_t>(k.right.orbit_of[y])].insert(hrep_[d]);
  for (const LoggedEvent& e : dynamic.events) {
    for (Dart d : e.before) logged_.emplace(e.event, true, d);
    for (Dart d : e.after) logged_.emplace(e.event, false, d);
  }
  for (const auto& darts : t.match)
    for (std::size_t x = 0; x < darts.size(); ++x) gpos_[darts[x]] = x;
  for (const auto& darts : t.comatch)
    for (std::size_t x = 0; x < darts.size(); ++x) hpos_[darts[x]] = x;
}

CrossCheck CrossChecker::run(const EventLog& instantiated) {
  if (dynamic_.events != instantiated.events) {
    std::set<LoggedEvent> a(dynamic_.events.begin(), dynamic_.events.end()), b(instantiated.events.begin(), instantiated.events.end());
    for (const auto& e : a)
      if (!b.count(e))
        out_.contradictions.push_back(fmt::format("{}: dynamic detection finds '{}', the instantiation does not", o_, event_line(k_.kind, e)));
    for (const auto& e : b)
      if (!a.count(e))
        out_.contradictions.push_back(fmt::format("{}: the instantiation finds '{}', dynamic detection does not", o_, event_line(k_.kind, e)));
  }
  for (const EventClaim& cl : k_.claims) {
    const auto index = static_cast<std::size_t>(&cl - k_.claims.data());
    const bool left = cl.event != Event::creation;
    for (Dart rep : left ? touched_g_[static_cast<std::size_t>(cl.orbit)] : touched_h_[static_cast<std::size_t>(cl.orbit)])
      judge(cl, index, left, rep);
  }
  check_announced();
  return out_;
}

// The condition of a loop-case no-modification on G orbit `rep`: at
// every matched dart of the orbit, the links along the letters the rule
// changes (its positions' letters on either side, inside <o>) are the
// same in G and H: loops, or a fold that the relabeling keeps. Empty
// when it holds, else the first link that changes.
std::string CrossChecker::changed_link(const EventClaim& cl, Dart rep) const {
  const RuleOrbit& x = k_.left.orbits[static_cast<std::size_t>(cl.orbit)];
  for (NodeId v : x.nodes)
    for (Dart d : t_.match[v]) {
      const NodeId w = rule_.to_right(v);
      if (grep_[d] != rep || w == no_node || c_.to_h(d) == no_dart) continue;
      for (int p : cl.loop_positions)
        for (const auto& letter : {r_.left.labels[v][static_cast<std::size_t>(p)], r_.right.labels[w][static_cast<std::size_t>(p)]}) {
          if (!in_kind(k_.kind, letter)) continue;
          const Dart before = g_.link(*letter, d), after = h_.link(*letter, c_.to_h(d));
          if ((before == no_dart ? no_dart : c_.to_h(before)) != after)
            return fmt::format("the {}-link of dart {} changes ({} in G, {} in H)", *letter, d, before == d ? "a loop" : fmt::format("to {}", before),
                               after == c_.to_h(d) ? "a loop" : fmt::format("to {}", after));
        }
    }
  return {};
}

// Why an implicit split along k does not happen on G orbit `rep`: every
// k-link of X's matched darts there is a loop, or its ends stay in one
// orbit of H (a fold). Starts with "yet" when one is neither.
std::string CrossChecker::split_blocked(const EventClaim& cl, Dart rep) const {
  const RuleOrbit& x = k_.left.orbits[static_cast<std::size_t>(cl.orbit)];
  const RuleOrbit& y = k_.right.orbits[static_cast<std::size_t>(cl.others.at(0))];
  const auto pos = static_cast<std::size_t>(cl.position);
  std::size_t loops = 0, folds = 0;
  for (NodeId v : x.nodes) {
    const auto& label = r_.left.labels[v][pos];
    if (!in_kind(k_.kind, label)) continue;
    for (std::size_t p = 0; p < t_.match[v].size(); ++p) {
      const Dart d = t_.match[v][p];
      if (g_orbit_at(x, p) != rep) continue;
      const Dart e = g_.link(*label, d);
      if (e == d) {
        ++loops;
      } else if (e != no_dart && gpos_[e] != no_position && h_orbit_at(y, p) == h_orbit_at(y, gpos_[e])) {
        ++folds;
      } else {
        return fmt::format("yet the {}-link of darts {} and {} is no loop and its ends go to two orbits of H", *label, d, e);
      }
    }
  }
  return fmt::format("every link at position {} (letter {}) there is a loop ({}) or folded ({})", pos, r_.parameter[pos], loops, folds);
}

// Why an implicit merge along k does not happen: every k-link of Y's
// comatched darts there is a loop in H, or joins two darts of one G orbit.
std::string CrossChecker::merge_blocked(const EventClaim& cl, Dart rep) const {
  const RuleOrbit& x = k_.left.orbits[static_cast<std::size_t>(cl.orbit)];
  const RuleOrbit& y = k_.right.orbits[static_cast<std::size_t>(cl.others.at(0))];
  const auto pos = static_cast<std::size_t>(cl.position);
  std::size_t loops = 0, folds = 0;
  for (NodeId w : y.nodes) {
    const auto& label = r_.right.labels[w][pos];
    if (!in_kind(k_.kind, label)) continue;
    for (std::size_t p = 0; p < t_.comatch[w].size(); ++p) {
      const Dart d = t_.comatch[w][p];
      if (g_orbit_at(x, p) != rep) continue;
      const Dart e = h_.link(*label, d);
      if (e == d) {
        ++loops;
      } else if (e != no_dart && hpos_[e] != no_position && g_orbit_at(x, hpos_[e]) == rep) {
        ++folds;
      } else {
        return fmt::format("yet the {}-link of darts {} and {} of H is no loop and joins two orbits of G", *label, d, e);
      }
    }
  }
  return fmt::format("every link at position {} (letter {}) there is a loop ({}) or folded ({})", pos, r_.parameter[pos], loops, folds);
}

// One claim on one orbit it touches (G's for events before, H's for a
// creation): happened as announced, resolved (a potential or conditional
// claim that did not happen for a stated reason), or a contradiction.
void CrossChecker::judge(const EventClaim& cl, std::size_t index, bool left, Dart rep) {
  const std::string where = fmt::format("{}{}({})", left ? 'G' : 'H', o_, rep);
  if (happened(cl.event, left, rep)) {
    if (out_.happened.empty() || out_.happened.back() != index) out_.happened.push_back(index);
    // A loop-case no-modification must have its loops.
    if (!cl.loop_positions.empty() && cl.certainty == Certainty::conditional)
      if (auto why = changed_link(cl, rep); !why.empty())
        out_.contradictions.push_back(fmt::format("{}: {} happens on {} but {}", o_, claim_name(cl), where, why));
    return;
  }
  // A modification gives way to a split or merge by definition (Sec. 3.4.3).
  if (cl.event == Event::modification && (happened(Event::split, true, rep) || happened(Event::merge, true, rep))) return;
  // ... and to the no-modification of the loop case, where its loops are.
  if (cl.event == Event::modification && happened(Event::non_modification, true, rep) && loop_claim(cl) != k_.claims.end() &&
      changed_link(*loop_claim(cl), rep).empty()) {
    out_.resolutions.push_back(
        fmt::format("{} does not happen on {}: the links it changes are the same in G and H (loops or a fold), so the orbit is unchanged",
                    claim_name(cl), where));
    return;
  }
  if (!cl.loop_positions.empty() && cl.certainty == Certainty::conditional) {
    // A loop-case no-modification that does not happen: some link is no loop.
    if (auto why = changed_link(cl, rep); !why.empty())
      out_.resolutions.push_back(fmt::format("{} does not happen on {}: {}", claim_name(cl), where, why));
    else
      out_.contradictions.push_back(
          fmt::format("{}: {} does not happen on {} though the links it changes are the same in G and H", o_, claim_name(cl), where));
    return;
  }
  if (cl.certainty == Certainty::certain) {
    out_.contradictions.push_back(fmt::format("{}: {} does not happen on {}", o_, claim_name(cl), where));
    return;
  }
  if (cl.certainty == Certainty::potential) {
    out_.resolutions.push_back(fmt::format("{} does not happen on {}", claim_name(cl), where));
    return;
  }
  // Conditional: it fails only where every k-link of the orbit's
  // matched darts is a loop or folded (its two ends stay in one orbit
  // on the other side); one k-link that is neither makes it happen.
  if (cl.event == Event::modification) {
    // Not a split, a merge, nor the loop case's no-modification: what
    // the orbit became was announced by none of its claims.
    out_.contradictions.push_back(
        fmt::format("{}: {} does not happen on {}, and none of the other events announced for it does", o_, claim_name(cl), where));
    return;
  }
  const std::string why = cl.event == Event::split ? split_blocked(cl, rep) : merge_blocked(cl, rep);
  if (why.rfind("yet", 0) == 0)
    out_.contradictions.push_back(fmt::format("{}: {} does not happen on {}, {}", o_, claim_name(cl), where, why));
  else
    out_.resolutions.push_back(fmt::format("{} does not happen on {}: {}", claim_name(cl), where, why));
}

// Every logged event was announced, and unmatched orbits do not change.
void CrossChecker::check_announced() {
  for (const LoggedEvent& e : dynamic_.events) {
    if (e.event == Event::creation) {
      bool announced = false;
      for (const EventClaim& cl : k_.claims)
        announced = announced || (cl.event == Event::creation && touched_h_[static_cast<std::size_t>(cl.orbit)].count(e.after[0]));
      if (!announced) out_.contradictions.push_back(fmt::format("{}: '{}' was not announced by any rule orbit", o_, event_line(k_.kind, e)));
      continue;
    }
    for (Dart rep : e.before) {
      if (!matched_g_.count(rep)) {
        out_.contradictions.push_back(fmt::format("{}: '{}' changes an orbit no rule node matches", o_, event_line(k_.kind, e)));
        continue;
      }
      bool announced = false;
      for (const EventClaim& cl : k_.claims)
        announced = announced || (cl.event == e.event && cl.event != Event::creation && touched_g_[static_cast<std::size_t>(cl.orbit)].count(rep));
      if (!announced)
        out_.contradictions.push_back(
            fmt::format("{}: '{}' on G{}({}) was not announced by any rule orbit that matches it", o_, event_line(k_.kind, e), o_, rep));
    }
  }
}

}  // namespace

CrossCheck cross_check(const EventRule& r, const KindEvents& k, const Map& g, const Map& h, const Application& t, const EventLog& dynamic,
                       const EventLog& instantiated) {
  return CrossChecker(r, k, g, h, t, dynamic).run(instantiated);
}

}  // namespace dartcheck::events
