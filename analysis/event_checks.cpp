#include "analysis/event_checks.hpp"

#include "events/cross_check.hpp"

namespace dartcheck::analysis {

EventOracle::EventOracle(const Operation& op) : op_(op) {
  auto v = events::event_rule(op);
  if (!v.rule) return;
  view_ = std::move(*v.rule);
  for (const auto& kind : events::all_orbit_kinds(op.rule.model())) kinds_.push_back(events::static_events(*view_, kind));
}

std::vector<std::string> EventOracle::contradictions(const Map& g, std::span<const Dart> hooks, Map& h) const {
  if (!view_) return {};
  h = g;
  auto traced = Applier(op_).apply(h, hooks);
  if (!traced.ok()) return {};
  std::vector<std::string> out;
  for (const auto& k : kinds_) {
    const auto dyn = events::dynamic_log(g, h, op_.rule, *traced.value, k.kind);
    const auto inst = events::instantiated_log(g, h, *view_, k, *traced.value);
    auto cc = events::cross_check(*view_, k, g, h, *traced.value, dyn, inst);
    out.insert(out.end(), cc.contradictions.begin(), cc.contradictions.end());
  }
  return out;
}

}  // namespace dartcheck::analysis
