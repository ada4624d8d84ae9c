// Static detection of topological events on a rule (004 Sec. 3): what the
// rule does to each of its <o>-orbits, and how sure that is.
//
// Certainty follows the proofs of Prop. 3.2.1 and 3.3.1:
//  - certain: the event happens at every application. Explicit events on
//    a complete orbit, creation, deletion, non-modification of a complete
//    orbit.
//  - conditional: implicit split or merge along position k on a complete
//    orbit. It fails exactly where the k-th link of a matched dart is a
//    loop or the matched orbit is folded along it (a one-dart face does
//    not split under triangulation).
//  - potential: the orbit is incomplete, so the map's orbit reaches beyond
//    the match; a dynamic check must look at the named orbit and links.
// Events are flags, not a partition: an orbit can split and merge at once
// (edge collapse, 004 Fig. 1).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/formatting.hpp"
#include "events/rule_orbits.hpp"

namespace dartcheck::events {

enum class Event { creation, deletion, split, merge, non_modification, modification };
enum class Certainty { certain, conditional, potential };
std::string_view name_of(Event e);
std::string_view name_of(Certainty c);

/// One event of one rule orbit. `orbit` indexes the left orbits (the right
/// ones for a creation). For a split, `others` are the right orbits the
/// preserved nodes go to; for an explicit merge, the other left orbits
/// that join this one.
struct EventClaim {
  Event event;
  Certainty certainty;
  int orbit = -1;
  bool implicit = false;
  int position = -1;  // implicit split or merge: the label position k
  std::vector<int> others;
  std::string reason;  // one sentence: what in the rule says so
  /// A no-modification that holds where the links at these label
  /// positions are loops on the matched darts (the loop case of the proofs
  /// of Prop. 3.2.1 and 3.3.1); empty for Def. 3.4.2's own.
  std::vector<int> loop_positions = {};
};

struct KindEvents {
  OrbitKind kind;
  SideOrbits left, right;
  std::vector<EventClaim> claims;
};

/// The events of every <o>-orbit of `r`'s two sides.
KindEvents static_events(const EventRule& r, const OrbitKind& kind);

/// "conditional split along position 1 (letter 1)", "certain merge with
/// L<0,2>(n1)": a claim in one phrase, for tables and the CLI.
std::string claim_summary(const EventRule& r, const KindEvents& k, const EventClaim& c);

/// "L<0,1>(n0)" or "R<0,2>(n1,n2)".
std::string rule_orbit_name(const EventRule& r, const KindEvents& k, bool left, int orbit);

}  // namespace dartcheck::events
