// The event cross-check of one application, for the fuzz engine: the
// rule's static events (004 Sec. 3) against the instantiated and the
// dynamic event logs of the application (events/cross_check).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "events/static_events.hpp"

namespace dartcheck::analysis {

/// The static events of one rule on every orbit type of its model,
/// computed once and checked against many applications.
class EventOracle {
 public:
  /// Empty (no checks) when the rule has no Jerboa view.
  explicit EventOracle(const Operation& op);
  bool active() const { return view_.has_value(); }
  /// Applies the rule to a copy of g at `hooks` and cross-checks every
  /// orbit type; the contradictions, empty if none or if the rule does not
  /// apply. `h` receives the result.
  std::vector<std::string> contradictions(const Map& g, std::span<const Dart> hooks, Map& h) const;

 private:
  const Operation& op_;
  std::optional<events::EventRule> view_;
  std::vector<events::KindEvents> kinds_;
};

}  // namespace dartcheck::analysis
