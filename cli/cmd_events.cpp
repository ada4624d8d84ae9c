// dartcheck events: the topological events of every rule (004 Sec. 3) and,
// with a map and hooks, the event log of one application (Sec. 4), from
// the static instantiation and, with --dynamic, from labeling both maps.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/map_sources.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/report_text.hpp"
#include "reports/events_report.hpp"
#include "checkers/map_validity.hpp"
#include "core/input_error.hpp"
#include "events/cross_check.hpp"

namespace dartcheck::cli {

using namespace analysis;
using namespace events;

namespace {

std::vector<OrbitKind> requested_kinds(const std::vector<std::string>& texts, const Model& model) {
  if (texts.empty() || (texts.size() == 1 && texts[0] == "all")) return all_orbit_kinds(model);
  std::vector<OrbitKind> out;
  for (const std::string& t : texts) {
    try {
      out.push_back(parse_orbit_kind(t, model));
    } catch (const std::invalid_argument& e) {
      throw InputError("<command line>", 0, 0, fmt::format("--orbit: {}", e.what()));
    }
  }
  return out;
}

// G => H at the hooks, with H's validity; or why the rule did not apply.
reports::EventsApplication apply_at(const EventsOptions& o, const CatalogRule& rule, const Catalog& catalog) {
  check_hook_count(rule, o.hooks);
  Map g = resolve_map(o.map, rule.rule.model(), &catalog);
  if (!(g.model() == rule.rule.model()))
    throw InputError("<command line>", 0, 0,
                     fmt::format("--map {} is a {} but rule '{}' rewrites {}", o.map, g.model().name, o.rule, rule.rule.model().name));
  reports::EventsApplication a{describe_target(o.map, g), o.hooks, {}, {}, g, g, {}, {}};
  auto traced = dartcheck::apply(rule, a.after, o.hooks);
  if (!traced.ok()) {
    a.refusal = refusal_name(traced.refusal);
    a.why = traced.why;
    return a;
  }
  a.trace = std::move(*traced.value);
  a.validity = check_map(a.after);
  return a;
}

// The events of `rule` on `kinds`, and with an application its logs
// (and with --dynamic the labeling's log and the cross-check).
std::vector<reports::KindEventsResult> analyse(const EventRule& view, const CatalogRule& rule, const std::vector<OrbitKind>& kinds,
                                               const std::optional<reports::EventsApplication>& app, bool dynamic) {
  std::vector<reports::KindEventsResult> out;
  for (const OrbitKind& kind : kinds) {
    reports::KindEventsResult r{static_events(view, kind), {}, {}, {}, {}};
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

}  // namespace

int events_command(const EventsOptions& o) {
  Catalog catalog = read_command_catalog(o.catalog, o.rule, o.format);
  campaign::keep_shard(catalog, command_shard(o.shard));
  if (!o.map.empty() && o.rule.empty()) throw InputError("<command line>", 0, 0, "--map needs --rule: an event log is for one rule");
  if (o.map.empty() && (!o.hooks.empty() || o.dynamic))
    throw InputError("<command line>", 0, 0, "--hook and --dynamic need --map: they concern one application");
  const bool json = o.format == "json";
  int status = ok;
  reports::Json json_rules = reports::Json::array();
  std::optional<std::string> first_orbit_error;
  std::size_t analysed = 0;
  for (const CatalogRule& rule : catalog.rules) {
    if (!o.rule.empty() && rule.rule.name() != o.rule) continue;
    const EventRuleOutcome view = event_rule(rule);
    if (!view.rule) {
      if (json)
        json_rules.push_back(reports::Json{{"rule", rule.rule.name()}, {"model", rule.rule.model().name}, {"analysed", false}, {"why", view.why}});
      else
        fmt::print("rule {} ({}): not analysed: {}\n", rule.rule.name(), rule.rule.model().name, view.why);
      if (!o.rule.empty()) status = violation;
      continue;
    }
    // --orbit on a catalog of several models: a rule whose model lacks a
    // dimension is skipped; the option is bad input only if it fits no rule.
    std::vector<OrbitKind> kinds;
    try {
      kinds = requested_kinds(o.orbits, rule.rule.model());
    } catch (const InputError& e) {
      if (!o.rule.empty()) throw;
      if (!first_orbit_error) first_orbit_error = e.what();
      if (!json) fmt::print("rule {} ({}): skipped: {}\n", rule.rule.name(), rule.rule.model().name, e.what());
      continue;
    }
    ++analysed;
    reports::RuleEvents r{&rule, &*view.rule, {}, {}};
    if (!o.map.empty()) r.application = apply_at(o, rule, catalog);
    r.kinds = analyse(*view.rule, rule, kinds, r.application, o.dynamic);
    // A rule that does not apply, or an H that is no map of the model: exit 1, as apply.
    if (r.application && (!r.application->applied() || !r.application->validity.valid())) status = std::max(status, int(violation));
    for (const auto& k : r.kinds)
      if (k.check && !k.check->contradictions.empty()) status = soundness_bug;
    if (json)
      json_rules.push_back(reports::events_json(r));
    else
      fmt::print("{}", reports::events_text(r));
  }
  if (analysed == 0 && first_orbit_error) throw InputError("<command line>", 0, 0, first_orbit_error->substr(first_orbit_error->find("--orbit")));
  if (json) {
    reports::Json doc = reports::json_document("events");
    doc["catalog"] = o.catalog;
    doc["rules"] = std::move(json_rules);
    fmt::print("{}\n", reports::json_text(std::move(doc)));
  }
  return status;
}

}  // namespace dartcheck::cli
