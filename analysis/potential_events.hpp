// 004's potential events decided on small hosts (issue 61, item 2): a
// claim is potential when its rule orbit is incomplete, so whether the
// event happens depends on the map beyond the match. Every host up to K
// darts (checkers/host_search's for_each_rooted_host) is applied, its
// event log computed by labeling every orbit (events/event_log's oracle)
// and set against the claims (events/cross_check): a potential claim gets
// the smallest host on which it happens (a witness, replayable with
// `dartcheck events --map HOST --dynamic`) or "never up to K darts".
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/map.hpp"
#include "rewriting/operation.hpp"

namespace dartcheck::analysis {

struct PotentialEvent {
  std::string kind;   // the orbit type, "<0,1>"
  std::string claim;  // claim_summary: "potential split of L<1>(n0) ..."
  bool happens = false;
  std::size_t darts = 0;  // the witness's size, or K searched
  std::optional<Map> host;
  std::vector<Dart> hooks;
};

struct PotentialEvents {
  std::vector<PotentialEvent> events;
  std::size_t hosts = 0, applications = 0;
  std::string not_decided;  // why nothing was asked (no Jerboa view), or the budget
  bool interrupted = false;
  double seconds = 0;
};

PotentialEvents decide_potential_events(const Operation& op, std::size_t max_darts, const std::function<bool()>& stop = {});

}  // namespace dartcheck::analysis
