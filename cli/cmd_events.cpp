// dartcheck events: the topological events of every rule (004 Sec. 3) and,
// with a map and hooks, the event log of one application (Sec. 4), from
// the static instantiation and, with --dynamic, from labeling both maps.
#include <fmt/format.h>

#include "analysis/map_sources.hpp"
#include "analysis/rule_events.hpp"
#include "cli/commands.hpp"
#include "analysis/interrupt.hpp"
#include "campaign/shard_stream.hpp"
#include "cli/options.hpp"
#include "core/wording.hpp"
#include "reports/events_report.hpp"
#include "core/input_error.hpp"

namespace dartcheck::cli {

using namespace analysis;
using namespace events;

namespace {

// G => H at the hooks, G as --map names it.
EventsApplication application(const EventsOptions& o, const CatalogRule& rule, const Catalog& catalog) {
  Map g = resolve_map(o.map, rule.rule.model(), &catalog);
  if (!(g.model() == rule.rule.model()))
    throw InputError("<command line>", 0, 0,
                     fmt::format("--map {} is a {} but rule '{}' rewrites {}", o.map, g.model().name, o.rule, rule.rule.model().name));
  check_hooks(rule, o.hooks, g, o.map);
  return apply_for_events(rule, std::move(g), o.hooks, o.map);
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
      kinds = requested_orbit_kinds(o.orbits, rule.rule.model());
    } catch (const InputError& e) {
      if (!o.rule.empty()) throw;
      if (!first_orbit_error) first_orbit_error = e.what();
      emit(rule, std::nullopt, fmt::format("rule {} ({}): skipped: {}\n", rule.rule.name(), rule.rule.model().name, e.what()));
      continue;
    }
    ++analysed;
    RuleEvents r{&rule, &*view.rule, {}, {}};
    if (!o.map.empty()) r.application = application(o, rule, catalog);
    r.kinds = analyse_events(*view.rule, rule, kinds, r.application, o.dynamic);
    status = std::max(status, events_status(r));
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
