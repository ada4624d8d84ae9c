// Event logs of one application (004 Sec. 4, Table 1): for an orbit type
// <o>, the orbits of G that were deleted, split, merged, modified or left
// unchanged, and the orbits of H that were created, each named by its
// smallest dart (004 Sec. 5: "a single representative of the target orbit
// as the dart with the lowest identifier").
//
// Two ways to the same log:
//  - dynamic_log labels every dart of G and H with its orbit (the oracle,
//    O(|G| + |H|));
//  - instantiated_log instantiates the rule's orbits on the pattern
//    positions (the static approach): a complete rule orbit matches whole
//    orbits, so their union over the pattern is found from the match and
//    comatch alone; only incomplete rule orbits are traversed in the map,
//    and only from their matched darts.
#pragma once

#include <string>
#include <vector>

#include "core/map.hpp"
#include "rewriting/application.hpp"
#include "events/static_events.hpp"

namespace dartcheck::events {

struct LoggedEvent {
  Event event;
  std::vector<Dart> before;  // orbits of G (their smallest dart)
  std::vector<Dart> after;   // orbits of H
  friend bool operator==(const LoggedEvent&, const LoggedEvent&) = default;
  friend auto operator<=>(const LoggedEvent&, const LoggedEvent&) = default;
};

struct EventLog {
  OrbitKind kind;
  std::vector<LoggedEvent> events;  // sorted
};

/// The oracle: every orbit of G and H labeled. Orbits of G without a
/// matched dart that are unchanged are left out (there are as many as the
/// map has orbits); any other event on them stays in.
EventLog dynamic_log(const Map& g, const Map& h, const Rule& rule, const Application& t, const OrbitKind& kind);

/// The static approach: orbits from the rule's orbits instantiated on the
/// pattern (`k` from static_events), traversal only for incomplete ones.
/// `g` is the map before the application; only matched darts and the
/// orbits of incomplete rule orbits are read.
EventLog instantiated_log(const Map& g, const Map& h, const EventRule& r, const KindEvents& k, const Application& t);

/// Each dart's orbit, named by its smallest dart (004 Sec. 5).
std::vector<Dart> orbit_representatives(const Map& m, const OrbitKind& kind);

/// The rule orbits each event of `log` concerns, named as rule_orbit_name
/// names them: the left orbits with a matched dart in its G orbits, and
/// for a creation the right orbits with a comatched dart in its H orbit.
std::vector<std::vector<std::string>> event_rule_orbits(const EventRule& r, const KindEvents& k, const Map& g, const Map& h, const Application& t,
                                                        const EventLog& log);

/// "split G<1>(4) -> {H<1>(4), H<1>(17)}" (Table 1's notation).
std::string event_line(const OrbitKind& kind, const LoggedEvent& e);

}  // namespace dartcheck::events
