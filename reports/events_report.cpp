#include "reports/events_report.hpp"

#include "core/terminal.hpp"
#include "reports/json_document.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace dartcheck::reports {

using namespace events;

namespace {

std::string header(const RuleEvents& r) {
  return hanging("",
                 fmt::format("rule {} ({}{})", r.rule->rule.name(), r.rule->rule.model().name,
                             r.view->has_parameter() ? fmt::format(", scheme on <{}>", fmt::join(r.view->parameter, ",")) : ", DPO rule"),
                 0);
}

std::string where(const EventsApplication& a) { return fmt::format("hook {} of {}", fmt::join(a.hooks, ","), a.host); }

std::string invalid_result(const EventsApplication& a) {
  std::vector<std::string> first;
  for (std::size_t k = 0; k < a.validity.violations.size() && k < 3; ++k)
    first.push_back(describe(a.validity.violations[k], fmt::format("dart {}", a.validity.violations[k].element)));
  return fmt::format("H is not a valid {} ({} violation{}: {}{}): the event log below means nothing there (004 defines events on maps)",
                     a.after.model().name, a.validity.violations.size(), a.validity.violations.size() == 1 ? "" : "s", fmt::join(first, "; "),
                     a.validity.violations.size() > 3 ? "; ..." : "");
}

Json logged_json(const OrbitKind& kind, const LoggedEvent& e, const std::vector<std::string>& rule_orbits) {
  return Json{{"event", name_of(e.event)},  {"orbit_type", kind.str()},   {"g", e.before}, {"h", e.after},
              {"rule_orbits", rule_orbits}, {"text", event_line(kind, e)}};
}

Json log_json(const OrbitKind& kind, const EventLog& log, const std::vector<std::vector<std::string>>& rule_orbits) {
  Json out = Json::array();
  for (std::size_t k = 0; k < log.events.size(); ++k)
    out.push_back(logged_json(kind, log.events[k], k < rule_orbits.size() ? rule_orbits[k] : std::vector<std::string>{}));
  return out;
}

}  // namespace

std::string events_text(const RuleEvents& r) {
  std::string out = header(r);
  const auto& app = r.application;
  if (app && !app->applied()) return out + fmt::format("  does not apply at {} ({}): {}\n", where(*app), app->refusal, app->why);
  if (app && !app->validity.valid()) out += fmt::format("  {}\n", invalid_result(*app));
  for (const KindEventsResult& kr : r.kinds) {
    const KindEvents& k = kr.statics;
    out += fmt::format("  {}\n", k.kind.str());
    for (int side = 0; side < 2; ++side) {
      const SideOrbits& so = side == 0 ? k.left : k.right;
      for (int o = 0; o < static_cast<int>(so.orbits.size()); ++o) {
        std::vector<std::string> claims;
        for (const EventClaim& c : k.claims)
          if (c.orbit == o && (c.event == Event::creation) == (side == 1)) claims.push_back(claim_summary(*r.view, k, c));
        if (side == 1 && claims.empty()) continue;  // right orbits matter for creations only
        const RuleOrbit& ro = so.orbits[static_cast<std::size_t>(o)];
        // The claims and what is missing wrap under their column (38).
        out += hanging(fmt::format("    {:<22} {:<10} ", rule_orbit_name(*r.view, k, side == 0, o), ro.complete ? "complete" : "incomplete"),
                       claims.empty() ? "-" : fmt::format("{}", fmt::join(claims, "; ")), 38);
        if (!ro.complete) out += hanging("", fmt::format("({})", fmt::join(ro.missing, "; ")), 38);
      }
    }
    if (!kr.instantiated) continue;
    out += fmt::format("    event log at {} -> {} darts:\n", where(*app), app->after.size());
    for (const LoggedEvent& e : kr.instantiated->events) out += hanging("      ", event_line(k.kind, e), 6);
    if (kr.instantiated->events.empty()) out += "      (nothing matched changes)\n";
    if (!kr.check) continue;
    out += fmt::format("    dynamic detection: {}\n", kr.dynamic->events == kr.instantiated->events ? "the same log" : "DIFFERS");
    // Contradictions first: a resolution never follows a contradiction of the same claim.
    for (const auto& s : kr.check->contradictions) out += fmt::format("      EVENT ANALYSIS CONTRADICTED: {}\n", s);
    for (const auto& s : kr.check->resolutions) out += hanging("      resolved: ", s, 16);
  }
  return out;
}

Json events_json(const RuleEvents& r) {
  Json kinds = Json::array();
  for (const KindEventsResult& kr : r.kinds) {
    const KindEvents& k = kr.statics;
    auto orbits = [&](bool left) {
      Json out = Json::array();
      const SideOrbits& so = left ? k.left : k.right;
      const TopoGraph& g = left ? r.rule->rule.left() : r.rule->rule.right();
      for (const RuleOrbit& o : so.orbits) {
        std::vector<std::string> names;
        for (NodeId v : o.nodes) names.push_back(g.name(v));
        out.push_back(Json{{"nodes", names}, {"complete", o.complete}, {"missing", o.missing}});
      }
      return out;
    };
    Json claims = Json::array();
    for (const EventClaim& c : k.claims)
      claims.push_back(Json{{"event", name_of(c.event)},
                            {"certainty", name_of(c.certainty)},
                            {"side", c.event == Event::creation ? "R" : "L"},
                            {"orbit", c.orbit},
                            {"rule_orbit", rule_orbit_name(*r.view, k, c.event != Event::creation, c.orbit)},
                            {"implicit", c.implicit},
                            {"position", c.position},
                            {"loop_positions", c.loop_positions},
                            {"others", c.others},
                            {"reason", c.reason}});
    Json kind{{"orbit_type", k.kind.str()}, {"left", orbits(true)}, {"right", orbits(false)}, {"events", std::move(claims)}};
    if (kr.instantiated) {
      kind["log"] = log_json(k.kind, *kr.instantiated, kr.rule_orbits);
      if (kr.check) {
        kind["dynamic_log"] = log_json(k.kind, *kr.dynamic, {});
        kind["contradictions"] = kr.check->contradictions;
        kind["resolutions"] = kr.check->resolutions;
      }
    }
    kinds.push_back(std::move(kind));
  }
  Json out{{"rule", r.rule->rule.name()},
           {"model", r.rule->rule.model().name},
           {"analysed", true},
           {"parameter", r.view->parameter},
           {"orbit_types", std::move(kinds)}};
  if (const auto& a = r.application) {
    Json app{{"host", a->host}, {"hooks", a->hooks}, {"applied", a->applied()}};
    if (!a->applied()) {
      app["refusal"] = a->refusal;
      app["why"] = a->why;
    } else {
      app["before_darts"] = a->before.size();
      app["after_darts"] = a->after.size();
      app["result_valid"] = a->validity.valid();
      app["result_violations"] = a->validity.violations.size();
      if (!a->validity.valid()) app["warning"] = invalid_result(*a);
      // G -> H: one entry per dart of G, the dart of H it became (null: deleted).
      const Renumbering c = a->trace->renumbering(r.rule->rule, a->after.size());
      Json correspondence = Json::array();
      for (Dart d = 0; d < a->before.size(); ++d) correspondence.push_back(c.to_h(d) == no_dart ? Json(nullptr) : Json(c.to_h(d)));
      app["correspondence"] = std::move(correspondence);
    }
    out["application"] = std::move(app);
  }
  return out;
}

}  // namespace dartcheck::reports
