// The rule's static events set against one application (004 Sec. 3's
// propositions as checks):
//  - the instantiated log equals the dynamic one (the static approach
//    finds the same events as labeling the whole map);
//  - every certain event happens on every orbit of G (or H) its rule
//    orbit matches;
//  - a conditional event that does not happen has its witness: the k-th
//    link of a matched dart is a loop, or its two ends stay in one orbit
//    (a fold);
//  - every event in the log was announced by a rule orbit that matches the
//    orbit, and orbits with no matched dart are unchanged.
// A failure of the first, second or last kind contradicts the paper's
// propositions (or dartcheck): `contradictions`. Resolved conditional
// and potential events are `resolutions`, for the log.
#pragma once

#include <string>
#include <vector>

#include "events/event_log.hpp"

namespace dartcheck::events {

struct CrossCheck {
  std::vector<std::string> contradictions;
  std::vector<std::string> resolutions;
  /// Indices of k.claims whose event happened on an orbit its rule orbit
  /// touches (a witness for a potential or conditional claim).
  std::vector<std::size_t> happened;
};

/// `g` before and `h` after the application traced by `t`.
CrossCheck cross_check(const EventRule& r, const KindEvents& k, const Map& g, const Map& h, const Application& t, const EventLog& dynamic,
                       const EventLog& instantiated);

}  // namespace dartcheck::events
