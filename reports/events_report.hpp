// The renderers of `dartcheck events` (004): a rule's events per orbit
// type and, for one application, the event logs, the dynamic check and
// whether H is a map of the model at all.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "checkers/violation.hpp"
#include "events/cross_check.hpp"
#include "io/catalog.hpp"
#include "reports/json_document.hpp"

namespace dartcheck::reports {

/// One orbit type: the rule's static events and, for an application, the
/// instantiated log (with the rule orbits of each event), and with
/// --dynamic the labeling's log and the cross-check.
struct KindEventsResult {
  events::KindEvents statics;
  std::optional<events::EventLog> instantiated, dynamic;
  std::vector<std::vector<std::string>> rule_orbits;  // per event of `instantiated`
  std::optional<events::CrossCheck> check;
};

/// One application G => H of the rule, or why it did not apply.
struct EventsApplication {
  std::string host;  // "cube (2-gmap, 48 darts)"
  std::vector<Dart> hooks;
  std::string refusal, why;  // set when the rule did not apply
  Map before, after;
  std::optional<Application> trace;
  ValidityReport validity;  // of H: a log of an invalid H means nothing
  bool applied() const { return trace.has_value(); }
};

struct RuleEvents {
  const CatalogRule* rule = nullptr;
  const events::EventRule* view = nullptr;
  std::optional<EventsApplication> application;
  std::vector<KindEventsResult> kinds;
};

std::string events_text(const RuleEvents& r);
Json events_json(const RuleEvents& r);

}  // namespace dartcheck::reports
