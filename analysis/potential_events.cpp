#include "analysis/potential_events.hpp"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "checkers/host_search.hpp"
#include "events/cross_check.hpp"
#include "events/event_log.hpp"
#include "events/event_rule.hpp"
#include "events/orbit_kind.hpp"
#include "rewriting/application.hpp"

namespace dartcheck::analysis {

PotentialEvents decide_potential_events(const Operation& op, std::size_t max_darts, const std::function<bool()>& stop) {
  PotentialEvents out;
  const auto start = std::chrono::steady_clock::now();
  auto view = events::event_rule(op);
  if (!view.rule) {
    out.not_decided = "no event view of the rule (004 reads Jerboa-style rules)";
    return out;
  }
  const events::EventRule& r = *view.rule;
  // The potential claims, per orbit type: (kind, claim index) -> answer.
  std::vector<events::KindEvents> kinds;
  std::vector<std::pair<std::size_t, std::size_t>> asked;
  for (const auto& kind : events::all_orbit_kinds(op.rule.model())) {
    kinds.push_back(events::static_events(r, kind));
    const auto& k = kinds.back();
    for (std::size_t c = 0; c < k.claims.size(); ++c)
      if (k.claims[c].certainty == events::Certainty::potential) {
        asked.emplace_back(kinds.size() - 1, c);
        const auto& cl = k.claims[c];
        out.events.push_back(
            {k.kind.str(),
             fmt::format("{}: {}", events::rule_orbit_name(r, k, cl.event != events::Event::creation, cl.orbit), events::claim_summary(r, k, cl)),
             false,
             0,
             std::nullopt,
             {}});
      }
  }
  if (asked.empty()) return out;
  std::size_t open = asked.size();
  Map h(op.rule.model());
  const RootedHosts searched = for_each_rooted_host(op, max_darts, [&](const Map& g, std::span<const Dart> hooks) {
    h = g;
    auto t = Applier(op).apply(h, hooks);
    if (!t.ok()) return !(stop && stop());
    ++out.applications;
    for (std::size_t a = 0; a < asked.size(); ++a) {
      if (out.events[a].happens) continue;
      const auto& k = kinds[asked[a].first];
      const auto dyn = events::dynamic_log(g, h, op.rule, *t.value, k.kind);
      const auto inst = events::instantiated_log(g, h, r, k, *t.value);
      const auto cc = events::cross_check(r, k, g, h, *t.value, dyn, inst);
      if (std::find(cc.happened.begin(), cc.happened.end(), asked[a].second) == cc.happened.end()) continue;
      out.events[a] = {k.kind.str(), out.events[a].claim, true, g.size(), g, std::vector<Dart>(hooks.begin(), hooks.end())};
      --open;
    }
    return open > 0 && !(stop && stop());
  });
  out.hosts = searched.hosts;
  out.interrupted = stop && stop();
  for (auto& e : out.events)
    if (!e.happens) e.darts = searched.complete;
  if (searched.budget_hit) out.not_decided = fmt::format("the host budget was reached at {} darts", searched.complete + 1);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace dartcheck::analysis
