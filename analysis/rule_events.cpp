#include "analysis/rule_events.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "analysis/exit_status.hpp"
#include "analysis/map_sources.hpp"
#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"
#include "events/event_log.hpp"
#include "rewriting/application.hpp"

namespace dartcheck::analysis {

using namespace events;

void check_orbit_syntax(const std::vector<std::string>& texts) {
  if (texts.size() == 1 && texts[0] == "all") return;
  for (const std::string& t : texts) {
    try {
      orbit_kind_entries(t);
    } catch (const ValueError& e) {
      throw UsageError(fmt::format("--orbit: {}", e.what()));
    }
  }
}

std::vector<OrbitKind> requested_orbit_kinds(const std::vector<std::string>& texts, const Model& model) {
  if (texts.empty() || (texts.size() == 1 && texts[0] == "all")) return all_orbit_kinds(model);
  std::vector<OrbitKind> out;
  for (const std::string& t : texts) {
    try {
      out.push_back(parse_orbit_kind(t, model));
    } catch (const ValueError& e) {
      throw UsageError(fmt::format("--orbit: {}", e.what()));
    }
  }
  return out;
}

EventsApplication apply_for_events(const CatalogRule& rule, Map g, const std::vector<Dart>& hooks, const std::string& map_name) {
  require_valid_map(g, "--map " + map_name, "events are defined on maps (004)");
  EventsApplication a{describe_target(map_name, g), hooks, {}, {}, g, std::move(g), {}, {}};
  auto traced = Applier(rule).apply(a.after, hooks);
  if (!traced.ok()) {
    a.refusal = name_of(traced.refusal);
    a.why = traced.why;
    return a;
  }
  a.trace = std::move(*traced.value);
  a.validity = check_map(a.after);
  return a;
}

std::vector<KindEventsResult> analyse_events(const EventRule& view, const CatalogRule& rule, const std::vector<OrbitKind>& kinds,
                                             const std::optional<EventsApplication>& app, bool dynamic) {
  std::vector<KindEventsResult> out;
  for (const OrbitKind& kind : kinds) {
    KindEventsResult r{static_events(view, kind), {}, {}, {}, {}};
    if (app && app->applied()) {
      r.instantiated = instantiated_log(app->before, app->after, view, r.statics, *app->trace);
      r.rule_orbits = event_rule_orbits(view, r.statics, app->before, app->after, *app->trace, *r.instantiated);
      if (dynamic) {
        r.dynamic = dynamic_log(app->before, app->after, rule.rule, *app->trace, kind);
        r.check = cross_check(view, r.statics, app->before, app->after, *app->trace, *r.dynamic, *r.instantiated);
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

int events_status(const RuleEvents& r) {
  if (r.application && (!r.application->applied() || !r.application->validity.valid())) return exit_status::violation;
  for (const auto& k : r.kinds)
    if (k.check && !k.check->contradictions.empty()) return exit_status::soundness_bug;
  return exit_status::ok;
}

}  // namespace dartcheck::analysis
