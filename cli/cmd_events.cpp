// dartcheck events: the topological events of every rule (004 Sec. 3) and,
// with a map and hooks, the event log of one application (Sec. 4), from
// the static instantiation and, with --dynamic, from labeling both maps.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/map_sources.hpp"
#include "cli/commands.hpp"
#include "analysis/interrupt.hpp"
#include "campaign/shard_stream.hpp"
#include "cli/options.hpp"
#include "core/wording.hpp"
#include "reports/validity_text.hpp"
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
  Map g = resolve_map(o.map, rule.rule.model(), &catalog);
  if (!(g.model() == rule.rule.model()))
    throw InputError("<command line>", 0, 0,
                     fmt::format("--map {} is a {} but rule '{}' rewrites {}", o.map, g.model().name, o.rule, rule.rule.model().name));
  check_hooks(rule, o.hooks, g, o.map);
  // Events are defined on maps (004): on an invalid G the logs disagree for
  // reasons that are not the rule's (a false alarm), so G must be valid, as
  // fuzz --maps asks of its hosts.
  if (const auto report = check_map(g); !report.valid())
    throw InputError("<command line>", 0, 0,
                     fmt::format("--map {}: not a valid {} ({} violations, first: dart {} {}): events are defined on maps (004)", o.map,
                                 g.model().name, report.violations.size(), report.violations[0].element, constraint_name(report.violations[0])));
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
  const bool json = o.format == "json", jsonl = o.format == "jsonl";
  Catalog catalog = read_command_catalog(o.catalog, o.rule, json ? "json" : "text");
  const campaign::Shard shard = command_shard(o.shard);
  campaign::keep_shard(catalog, shard);
  if (!o.map.empty() && o.rule.empty()) throw InputError("<command line>", 0, 0, "--map needs --rule: an event log is for one rule");
  if (o.map.empty() && (!o.hooks.empty() || o.dynamic))
    throw InputError("<command line>", 0, 0, "--hook and --dynamic need --map: they concern one application");
  std::optional<campaign::ShardWriter> lines;
  if (jsonl) {
    std::vector<std::string> hooks;
    for (Dart h : o.hooks) hooks.push_back(std::to_string(h));
    lines.emplace(campaign::make_header("events", o.catalog, "", o.rule, shard,
                                        reports::Json{{"orbits", o.orbits}, {"map", o.map}, {"hooks", hooks}, {"dynamic", o.dynamic}}));
  }
  int status = ok;
  reports::Json json_rules = reports::Json::array();
  // Each rule's part of the output: its JSON object (none for a rule
  // skipped by --orbit) and its text; a shard writes both, for merge.
  const auto emit = [&](const CatalogRule& rule, std::optional<reports::Json> j, const std::string& text) {
    if (lines)
      lines->fragment(rule.rule.name(), j ? *j : reports::Json(nullptr), text);
    else if (json && j)
      json_rules.push_back(std::move(*j));
    else if (!json)
      fmt::print("{}", text);
  };
  std::optional<std::string> first_orbit_error;
  std::size_t analysed = 0;
  analysis::catch_interrupts();  // Ctrl-C: the rules analysed so far are printed, exit 130
  for (const CatalogRule& rule : catalog.rules) {
    if (analysis::interrupted()) break;
    if (!o.rule.empty() && rule.rule.name() != o.rule) continue;
    const EventRuleOutcome view = event_rule(rule);
    if (!view.rule) {
      emit(rule, reports::Json{{"rule", rule.rule.name()}, {"model", rule.rule.model().name}, {"analysed", false}, {"why", view.why}},
           fmt::format("rule {} ({}): not analysed: {}\n", rule.rule.name(), rule.rule.model().name, view.why));
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
      emit(rule, std::nullopt, fmt::format("rule {} ({}): skipped: {}\n", rule.rule.name(), rule.rule.model().name, e.what()));
      continue;
    }
    ++analysed;
    reports::RuleEvents r{&rule, &*view.rule, {}, {}};
    if (!o.map.empty()) r.application = apply_at(o, rule, catalog);
    r.kinds = analyse(*view.rule, rule, kinds, r.application, o.dynamic);
    // A rule that does not apply, or an H that is no map of the model: exit 1, as apply.
    if (r.application && (!r.application->applied() || !r.application->validity.valid())) status = std::max(status, int(violation));
    // A contradiction on an invalid H is no defect of the event analysis
    // (the logs mean nothing there); the invalid H is exit 1 above.
    const bool valid_h = !r.application || r.application->validity.valid();
    for (const auto& k : r.kinds)
      if (valid_h && k.check && !k.check->contradictions.empty()) status = soundness_bug;
    emit(rule, reports::events_json(r), reports::events_text(r));
  }
  // A shard may hold only rules that --orbit does not fit: not an error there.
  if (analysed == 0 && first_orbit_error && shard.whole())
    throw InputError("<command line>", 0, 0, first_orbit_error->substr(first_orbit_error->find("--orbit")));
  if (analysis::interrupted()) {
    fmt::print(stderr, "interrupted: {} analysed; the output holds them\n", counted(analysed, "rule"));
    status = analysis::interrupted_exit;
  }
  if (lines) {
    lines->summary(reports::Json{{"status", status}, {"analysed", analysed}, {"interrupted", analysis::interrupted()}});
  } else if (json) {
    reports::Json doc = reports::json_document("events");
    doc["catalog"] = o.catalog;
    doc["rules"] = std::move(json_rules);
    fmt::print("{}\n", reports::json_text(std::move(doc)));
  }
  return status;
}

}  // namespace dartcheck::cli
