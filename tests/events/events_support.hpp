// Shared by the event tests: one application of a catalog rule with its
// static events, both logs and their cross-check, per orbit type.
#pragma once

#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "analysis/map_sources.hpp"
#include "events/cross_check.hpp"
#include "io/catalog.hpp"

namespace dartcheck::events::test {

/// How many random maps the event properties draw: DARTCHECK_EVENT_RUNS,
/// 60 by default (CI); more for a longer search.
inline int runs() {
  const char* env = std::getenv("DARTCHECK_EVENT_RUNS");
  return env ? std::atoi(env) : 60;
}

inline const Catalog& event_catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/event-operations.yaml");
  return c;
}

inline Map catalog_map(const std::string& name) { return analysis::build_source(*event_catalog().find_map(name)); }

/// One application G => H and what detection says about it.
struct Applied {
  Map before, after;
  Application trace;
  EventRule rule;
  std::map<std::string, KindEvents> statics;  // by orbit type text
  std::map<std::string, EventLog> dynamic, instantiated;
  std::map<std::string, CrossCheck> checks;
  /// The dynamic log's lines for an orbit type, e.g. "split G<1>(0) -> {H<1>(0), H<1>(7)}".
  std::vector<std::string> lines(const std::string& kind) const {
    std::vector<std::string> out;
    for (const auto& e : dynamic.at(kind).events) out.push_back(event_line(dynamic.at(kind).kind, e));
    return out;
  }
  std::map<Event, int> counts(const std::string& kind) const {
    std::map<Event, int> c;
    for (const auto& e : dynamic.at(kind).events) ++c[e.event];
    return c;
  }
};

inline Applied apply_with_events(const Operation& op, Map g, std::vector<Dart> hooks) {
  auto view = event_rule(op);
  if (!view.rule) throw std::runtime_error(view.why);
  Map h = g;
  auto traced = Applier(op).apply(h, hooks);
  if (!traced.ok()) throw std::runtime_error(traced.why);
  Applied a{std::move(g), std::move(h), std::move(*traced.value), std::move(*view.rule), {}, {}, {}, {}};
  a.rule.rule = &op.rule;
  for (const OrbitKind& kind : all_orbit_kinds(op.rule.model())) {
    const std::string name = kind.str();
    a.statics.emplace(name, static_events(a.rule, kind));
    a.dynamic.emplace(name, dynamic_log(a.before, a.after, op.rule, a.trace, kind));
    a.instantiated.emplace(name, instantiated_log(a.before, a.after, a.rule, a.statics.at(name), a.trace));
    a.checks.emplace(name, cross_check(a.rule, a.statics.at(name), a.before, a.after, a.trace, a.dynamic.at(name), a.instantiated.at(name)));
  }
  return a;
}

inline Applied apply_catalog_rule(const std::string& rule, const std::string& map, std::vector<Dart> hooks) {
  return apply_with_events(*event_catalog().find_rule(rule), catalog_map(map), std::move(hooks));
}

/// The claims of one orbit type as "event certainty L<o>(nodes)" strings.
inline std::vector<std::string> claim_texts(const Applied& a, const std::string& kind) {
  std::vector<std::string> out;
  const KindEvents& k = a.statics.at(kind);
  for (const auto& c : k.claims)
    out.push_back(fmt::format("{} {}{} {}", name_of(c.event), name_of(c.certainty), c.implicit ? " implicit" : "",
                              rule_orbit_name(a.rule, k, c.event != Event::creation, c.orbit)));
  return out;
}

inline void expect_no_contradiction(const Applied& a) {
  for (const auto& [kind, check] : a.checks)
    for (const auto& c : check.contradictions) ADD_FAILURE() << c;
}

}  // namespace dartcheck::events::test
