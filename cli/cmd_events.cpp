// dartcheck events: the topological events of every rule (004 Sec. 3) and,
// with a map and hooks, the event log of one application (Sec. 4), from
// the static instantiation and, with --dynamic, from labeling both maps.
#include <fmt/format.h>

#include "analysis/map_sources.hpp"
#include "analysis/rule_events.hpp"
#include "cli/commands.hpp"
#include "analysis/interrupt.hpp"
#include "campaign/events_output.hpp"
#include "cli/options.hpp"
#include "core/wording.hpp"
#include "core/input_error.hpp"

namespace dartcheck::cli {

using namespace analysis;
using namespace events;

namespace {

// G => H at the hooks, G as --map names it.
EventsApplication application(const EventsOptions& o, const CatalogRule& rule, const Catalog& catalog) {
  Map g = resolve_map(o.map, rule.rule.model(), &catalog);
  if (!(g.model() == rule.rule.model()))
    throw UsageError(fmt::format("--map {} is a {} but rule '{}' rewrites {}", o.map, g.model().name, o.rule, rule.rule.model().name));
  check_hooks(rule, o.hooks, g, o.map);
  return apply_for_events(rule, std::move(g), o.hooks, o.map);
}

}  // namespace

int events_command(const EventsOptions& o) {
  Catalog catalog = read_rule_catalog(o.catalog, o.rule);
  const campaign::Shard shard = campaign::shard_option(o.shard);
  campaign::keep_shard(catalog, shard);
  if (!o.map.empty() && o.rule.empty()) throw UsageError("--map needs --rule: an event log is for one rule");
  if (o.map.empty() && (!o.hooks.empty() || o.dynamic)) throw UsageError("--hook and --dynamic need --map: they concern one application");
  // --orbit: its syntax, and that it fits some rule's model, once before
  // any rule (a shard may hold only rules it does not fit); a rule whose
  // model lacks one of its dimensions is skipped.
  check_orbit_syntax(o.orbits);
  if (o.rule.empty() && shard.whole() && !catalog.rules.empty()) {
    std::optional<std::string> misfit;
    for (const CatalogRule& rule : catalog.rules) {
      try {
        requested_orbit_kinds(o.orbits, rule.rule.model());
        misfit.reset();
        break;
      } catch (const InputError& e) {
        if (!misfit) misfit = e.message();
      }
    }
    if (misfit) throw UsageError(*misfit);
  }
  std::vector<std::string> hooks;
  for (Dart h : o.hooks) hooks.push_back(std::to_string(h));
  campaign::EventsOutput out(reports::output_format(o.format), o.catalog, o.rule, shard,
                             {{"orbits", o.orbits}, {"map", o.map}, {"hooks", hooks}, {"dynamic", o.dynamic}});
  int status = ok;
  std::size_t analysed = 0;
  analysis::catch_interrupts();  // Ctrl-C: the rules analysed so far are printed, exit 130
  for (const CatalogRule& rule : catalog.rules) {
    if (analysis::interrupted()) break;
    if (!o.rule.empty() && rule.rule.name() != o.rule) continue;
    const EventRuleOutcome view = event_rule(rule);
    if (!view.rule) {
      out.not_analysed(rule, view.why);
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
      out.skipped(rule, e.what());
      continue;
    }
    ++analysed;
    RuleEvents r{&rule, &*view.rule, {}, {}};
    if (!o.map.empty()) r.application = application(o, rule, catalog);
    r.kinds = analyse_events(*view.rule, rule, kinds, r.application, o.dynamic);
    status = std::max(status, events_status(r));
    out.analysed(r);
  }
  if (analysis::interrupted()) {
    fmt::print(stderr, "interrupted: {} analysed; the output holds them\n", counted(analysed, "rule"));
    status = analysis::interrupted_exit;
  }
  out.finish(status, analysed, analysis::interrupted());
  return status;
}

}  // namespace dartcheck::cli
