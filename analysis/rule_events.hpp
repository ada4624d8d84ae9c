// The events of one catalog rule (004), as `dartcheck events` reports
// them: per orbit type the static events and, for one application G => H
// at hook darts, the instantiated log with each event's rule orbits, and
// on request the labeling's (dynamic) log and its cross-check.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "checkers/violation.hpp"
#include "events/cross_check.hpp"
#include "events/orbit_kind.hpp"
#include "io/catalog.hpp"

namespace dartcheck::analysis {

/// One orbit type: the rule's static events and, for an application, the
/// instantiated log (with the rule orbits of each event), and with a
/// dynamic check the labeling's log and the cross-check.
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

/// The orbit types --orbit names ("<0,1>", repeated; none or "all": every
/// orbit type of the model); InputError naming --orbit otherwise.
std::vector<events::OrbitKind> requested_orbit_kinds(const std::vector<std::string>& texts, const Model& model);
/// The syntax of every --orbit text, whatever the model: InputError naming
/// --orbit, before any rule is analysed.
void check_orbit_syntax(const std::vector<std::string>& texts);

/// Applies `rule` to a copy of `g` (the map --map `map_name` names) at
/// `hooks`, with H's validity; or why it did not apply. `g` must be a valid map of the rule's model
/// (InputError otherwise: events are defined on maps, and on an invalid G
/// the logs disagree for reasons that are not the rule's).
EventsApplication apply_for_events(const CatalogRule& rule, Map g, const std::vector<Dart>& hooks, const std::string& map_name);

/// The events of `rule` (its Jerboa view `view`) on `kinds`, and with an
/// application that applied its logs (`dynamic`: also the labeling's log
/// and the cross-check).
std::vector<KindEventsResult> analyse_events(const events::EventRule& view, const CatalogRule& rule, const std::vector<events::OrbitKind>& kinds,
                                             const std::optional<EventsApplication>& app, bool dynamic);

/// The exit status of one rule's events: 1 if the application did not
/// apply or H is no map of the model (as apply); 3 if the cross-check on a
/// valid H contradicts the static events (a defect of the event
/// analysis; on an invalid H the logs mean nothing); 0 otherwise.
int events_status(const RuleEvents& r);

}  // namespace dartcheck::analysis
