// dartcheck events: the topological events of every rule (004 Sec. 3) and,
// with a map and hooks, the event log of one application (Sec. 4), from
// the static instantiation and, with --dynamic, from labeling both maps.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analysis/map_sources.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/report_text.hpp"
#include "reports/json_document.hpp"
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

struct AppliedMaps {
  Map before, after;
  dartcheck::Application trace;
};

struct KindResult {
  KindEvents statics;
  std::optional<EventLog> instantiated, dynamic;
  std::optional<CrossCheck> check;
};

void print_text(const CatalogRule& rule, const EventRule& view, const std::vector<KindResult>& results, const std::string& where) {
  fmt::print("rule {} ({}{})\n", rule.rule.name(), rule.rule.model().name,
             view.is_scheme() ? fmt::format(", scheme on <{}>", fmt::join(view.parameter, ",")) : ", DPO rule");
  for (const KindResult& r : results) {
    const KindEvents& k = r.statics;
    fmt::print("  {}\n", k.kind.str());
    for (int side = 0; side < 2; ++side) {
      const SideOrbits& so = side == 0 ? k.left : k.right;
      for (int o = 0; o < static_cast<int>(so.orbits.size()); ++o) {
        std::vector<std::string> events;
        for (const EventClaim& c : k.claims)
          if (c.orbit == o && (c.event == Event::creation) == (side == 1)) events.push_back(claim_summary(view, k, c));
        if (side == 1 && events.empty()) continue;  // right orbits matter for creations only
        const RuleOrbit& ro = so.orbits[static_cast<std::size_t>(o)];
        fmt::print("    {:<22} {:<10} {}\n", rule_orbit_name(view, k, side == 0, o), ro.complete ? "complete" : "incomplete",
                   events.empty() ? "-" : fmt::format("{}", fmt::join(events, "; ")));
        if (!ro.complete) fmt::print("    {:<22} {:<10} ({})\n", "", "", fmt::join(ro.missing, "; "));
      }
    }
    if (!r.instantiated) continue;
    fmt::print("    event log at {}:\n", where);
    for (const LoggedEvent& e : r.instantiated->events) fmt::print("      {}\n", event_line(k.kind, e));
    if (r.instantiated->events.empty()) fmt::print("      (nothing matched changes)\n");
    if (!r.check) continue;
    fmt::print("    dynamic detection: {}\n", r.dynamic->events == r.instantiated->events ? "the same log" : "DIFFERS");
    for (const auto& s : r.check->resolutions) fmt::print("      resolved: {}\n", s);
    for (const auto& s : r.check->contradictions) fmt::print("      CONTRADICTION: {}\n", s);
  }
}

reports::Json json_log(const OrbitKind& kind, const EventLog& log) {
  std::vector<std::string> lines;
  for (const auto& e : log.events) lines.push_back(event_line(kind, e));
  return lines;
}

reports::Json json_rule(const CatalogRule& rule, const EventRule& view, const std::vector<KindResult>& results) {
  using reports::Json;
  Json kinds = Json::array();
  for (const KindResult& r : results) {
    const KindEvents& k = r.statics;
    auto orbits = [&](bool left) {
      Json out = Json::array();
      const SideOrbits& so = left ? k.left : k.right;
      const TopoGraph& g = left ? rule.rule.left() : rule.rule.right();
      for (const RuleOrbit& o : so.orbits) {
        std::vector<std::string> names;
        for (NodeId v : o.nodes) names.push_back(g.name(v));
        out.push_back(Json{{"nodes", names}, {"complete", o.complete}, {"missing", o.missing}});
      }
      return out;
    };
    Json claims = Json::array();
    for (const EventClaim& c : k.claims)
      claims.push_back(Json{{"event", event_name(c.event)},
                            {"certainty", certainty_name(c.certainty)},
                            {"side", c.event == Event::creation ? "R" : "L"},
                            {"orbit", c.orbit},
                            {"implicit", c.implicit},
                            {"position", c.position},
                            {"others", c.others},
                            {"reason", c.reason}});
    Json kind{{"orbit_type", k.kind.str()}, {"left", orbits(true)}, {"right", orbits(false)}, {"events", std::move(claims)}};
    if (r.instantiated) {
      kind["log"] = json_log(k.kind, *r.instantiated);
      if (r.check) {
        kind["dynamic_log"] = json_log(k.kind, *r.dynamic);
        kind["contradictions"] = r.check->contradictions;
        kind["resolutions"] = r.check->resolutions;
      }
    }
    kinds.push_back(std::move(kind));
  }
  return Json{{"rule", rule.rule.name()},
              {"model", rule.rule.model().name},
              {"analysed", true},
              {"parameter", view.parameter},
              {"orbit_types", std::move(kinds)}};
}

}  // namespace

int events_command(const EventsOptions& o) {
  const Catalog catalog = read_command_catalog(o.catalog, o.rule, o.format);
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
    std::optional<AppliedMaps> app;
    std::string where;
    if (!o.map.empty()) {
      Map g = resolve_map(o.map, rule.rule.model(), &catalog);
      if (!(g.model() == rule.rule.model()))
        throw InputError("<command line>", 0, 0,
                         fmt::format("--map {} is a {} but rule '{}' rewrites {}", o.map, g.model().name, o.rule, rule.rule.model().name));
      Map h = g;
      auto traced = dartcheck::apply(rule, h, o.hooks);
      if (!traced.ok()) {
        fmt::print("rule {} does not apply at hook(s) {} of {} ({}): {}\n", rule.rule.name(), fmt::join(o.hooks, ","), describe_target(o.map, g),
                   refusal_name(traced.refusal), traced.why);
        return violation;
      }
      where = fmt::format("hook {} of {} -> {} darts", fmt::join(o.hooks, ","), describe_target(o.map, g), h.size());
      app.emplace(AppliedMaps{std::move(g), std::move(h), std::move(*traced.value)});
    }
    std::vector<KindResult> results;
    for (const OrbitKind& kind : kinds) {
      KindResult r{static_events(*view.rule, kind), {}, {}, {}};
      if (app) {
        r.instantiated = instantiated_log(app->before, app->after, *view.rule, r.statics, app->trace);
        if (o.dynamic) {
          r.dynamic = dynamic_log(app->before, app->after, rule.rule, app->trace, kind);
          r.check = cross_check(*view.rule, r.statics, app->before, app->after, app->trace, *r.dynamic, *r.instantiated);
          if (!r.check->contradictions.empty()) status = soundness_bug;
        }
      }
      results.push_back(std::move(r));
    }
    if (json)
      json_rules.push_back(json_rule(rule, *view.rule, results));
    else
      print_text(rule, *view.rule, results, where);
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
