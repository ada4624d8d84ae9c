#include "analysis/fuzz.hpp"
#include "core/terminal.hpp"
#include "core/wording.hpp"
#include "analysis/event_checks.hpp"
#include "analysis/interrupt.hpp"

#include "analysis/embedded_fuzz.hpp"
#include "checkers/embedding_conditions.hpp"

#include <algorithm>
#include <random>
#include <span>

#include <fmt/format.h>

#include "checkers/host_search.hpp"
#include "checkers/map_validity.hpp"
#include "rewriting/application.hpp"
#include "generators/random_maps.hpp"

namespace dartcheck::analysis {

std::string_view name_of(FuzzClass c) {
  switch (c) {
    case FuzzClass::consistent:
      return "consistent";
    case FuzzClass::confirmed:
      return "inconsistent, confirmed";
    case FuzzClass::unconfirmed:
      return "inconsistent statically, unconfirmed";
    case FuzzClass::soundness_bug:
      return "SOUNDNESS BUG";
  }
  return "?";
}

std::vector<std::string> Counterexample::broken() const {
  std::vector<std::string> b;
  for (const auto& v : violations) b.push_back(constraint_name(v));
  if (!unrepresentable.empty()) b.push_back("not-representable");
  for (const auto& e : broken_embeddings) b.push_back(fmt::format("embedding({})", e));
  if (!event_contradictions.empty()) b.push_back("events");
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  return b;
}

std::string Counterexample::broken_predicate() const {
  std::vector<std::string> constraints;
  for (const auto& name : broken())
    if (name != "not-representable" && name != "events") constraints.push_back(name);
  return broken_predicate(fmt::format("{}", fmt::join(constraints, ", ")));
}

std::string Counterexample::broken_predicate(std::string_view constraints) const {
  std::vector<std::string> clauses;
  if (!constraints.empty()) clauses.push_back(fmt::format("breaks {}", constraints));
  if (!unrepresentable.empty()) clauses.push_back("has no dense form (not-representable)");
  if (!event_contradictions.empty()) clauses.push_back("contradicts the static event log (events)");
  if (clauses.empty()) return "breaks nothing";
  return fmt::format("{}", fmt::join(clauses, " and "));
}

// A stable per-rule stream: the same rule gets the same hosts whether it is
// fuzzed alone (--rule) or with its whole catalog.
std::uint64_t rule_seed(std::uint64_t seed, const std::string& name) {
  std::uint64_t h = 1469598103934665603ULL ^ seed;
  for (unsigned char c : name) h = (h ^ c) * 1099511628211ULL;
  return h;
}

std::vector<std::string> static_failures(const RuleVerdict& v) {
  std::vector<std::string> f;
  for (const auto& c : v.conditions)
    if (!c.holds) f.push_back(c.name());
  return f;
}

namespace {

using Clock = std::chrono::steady_clock;

Map map_of(const Model& model, std::size_t n, const std::vector<std::vector<NodeId>>& sigma) {
  Map g(model, n);
  for (std::size_t k = 0; k < model.dims.size(); ++k)
    for (Dart d = 0; d < n; ++d) g.set_link(model.dims[k], d, sigma[k][d]);
  return g;
}

// The connected components of the hooks, renumbered in dart order: the
// rule reads and writes nothing else (patterns and matches are connected
// to a hook), so a failure there is a failure on this smaller map.
std::pair<Map, std::vector<Dart>> hook_components(const Map& g, std::span<const Dart> hooks) {
  const Model& model = g.model();
  std::vector<Dart> index(g.size(), no_dart), darts(hooks.begin(), hooks.end());
  for (Dart h : hooks) index[h] = 0;
  for (std::size_t k = 0; k < darts.size(); ++k)
    for (Dim i : model.dims)
      for (Dart e : {g.link(i, darts[k]), g.inverse_link(i, darts[k])})
        if (e != no_dart && index[e] == no_dart) {
          index[e] = 0;
          darts.push_back(e);
        }
  std::sort(darts.begin(), darts.end());
  darts.erase(std::unique(darts.begin(), darts.end()), darts.end());
  for (std::size_t k = 0; k < darts.size(); ++k) index[darts[k]] = static_cast<Dart>(k);
  Map sub(model, darts.size());
  for (std::size_t k = 0; k < darts.size(); ++k)
    for (Dim i : model.dims)
      if (const Dart e = g.link(i, darts[k]); e != no_dart) sub.set_link(i, static_cast<Dart>(k), index[e]);
  std::vector<Dart> renamed;
  for (Dart h : hooks) renamed.push_back(index[h]);
  return {std::move(sub), std::move(renamed)};
}

// Mean darts per recipe face: G-maps 2 per edge, 2-O-maps 1, 3-O-maps 2
// (each face and its 3-twin); faces have 1-6 edges.
std::size_t darts_per_face(const Model& m) { return m.is_generalized() || m.dimension() == 3 ? 7 : 4; }

}  // namespace

std::optional<Counterexample> apply_and_check(const Operation& entry, const Map& g, std::span<const Dart> hooks, Map& scratch, Refusal& refusal,
                                              Applier* applier) {
  const Rule& rule = entry.rule;
  scratch = g;
  std::optional<Applier> own;
  if (!applier) applier = &own.emplace(entry);
  auto r = applier->apply(scratch, hooks);
  refusal = r.refusal;
  std::string why = std::move(r.why);
  std::vector<std::pair<std::string, Dart>> match, comatch;
  if (r.ok()) {
    if (!r.value->pattern)  // a DPO rule: L's nodes on their darts
      for (NodeId v = 0; v < rule.left().node_count(); ++v) match.emplace_back(rule.left().name(v), r.value->match[v][0]);
    for (NodeId v = 0; v < rule.right().node_count() && v < r.value->comatch.size(); ++v)
      for (Dart d : r.value->comatch[v]) comatch.emplace_back(rule.right().name(v), d);
    applier->recycle(std::move(*r.value));
  }
  if (refusal != Refusal::none && refusal != Refusal::not_representable) return std::nullopt;
  Counterexample cx{g, {hooks.begin(), hooks.end()}, std::move(match), std::nullopt, {}, {}, {}, false, {}, {}, {}, {}, {}};
  if (refusal == Refusal::not_representable) {
    cx.unrepresentable = std::move(why);
    return cx;
  }
  auto report = check_map(scratch);
  if (report.valid()) return std::nullopt;
  cx.result = scratch;
  cx.violations = std::move(report.violations);
  cx.comatch = std::move(comatch);
  return cx;
}

namespace {

class Fuzzer {
 public:
  Fuzzer(const Operation& entry, const FuzzOptions& o, FuzzReport& out)
      : entry_(entry),
        rule_(entry.rule),
        o_(o),
        out_(out),
        rng_(static_cast<std::uint32_t>(rule_seed(o.seed, entry.rule.name()) % 4294967291U)),
        start_(Clock::now()),
        events_(entry) {}

  // Where random maps exist the enumeration takes at most half of the
  // applications, so larger hosts get the other half; it resumes if the
  // random maps rarely admit a match (L with loops, say).
  void run(const std::vector<Map>& seeds) {
    const bool random = has_random_generator(rule_.model());
    host_budget_ = random ? o_.exhaustive_hosts : 50 * o_.exhaustive_hosts;
    n_ = scheme() ? 1 : std::max<std::size_t>(rule_.left().node_count(), 1);
    first_n_ = n_;
    exhaustive(random ? o_.runs / 2 : o_.runs);
    if (!out_.counterexample && budget_left()) given(seeds);
    if (!out_.counterexample && budget_left() && random) random_hosts();
    if (!out_.counterexample && budget_left()) exhaustive(o_.runs);
    // Minimal when every host with one dart fewer was enumerated (none
    // below |L| can hold an image of L), whichever phase found it.
    if (out_.counterexample) to_hook_components(*out_.counterexample);
    if (out_.counterexample)
      out_.counterexample->minimal = out_.counterexample->host.size() <= std::max(out_.exhaustive_darts + 1, scheme() ? 1 : first_n_);
    out_.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
  }

 private:
  const Operation& entry_;
  const Rule& rule_;
  const FuzzOptions& o_;
  FuzzReport& out_;
  std::mt19937 rng_;
  Clock::time_point start_;
  Map scratch_{Model::gmap(2)};
  Applier applier_{entry_};  // a scheme's tables stay from one application to the next
  // The rule's static events, checked on its first applications.
  EventOracle events_;
  std::size_t attempts_ = 0, next_progress_ = 4096;
  std::string phase_;  // where hosts come from now: the origin of an event contradiction
  // Where the enumeration stands: hosts of n_ darts, the first skip_ of
  // them already tried; host_budget_ hosts left.
  std::size_t n_ = 1, first_n_ = 1, skip_ = 0, host_budget_ = 0;

  bool scheme() const { return entry_.is_scheme(); }
  std::size_t hook_count() const { return rule_.hooks().size(); }

  // Stops at --runs applications, at the deadline, or after 20 attempts
  // per requested application when none applied (a rule that matches
  // nowhere: refusals are cheap, and the report counts them).
  bool budget_left() {
    if (out_.applications >= o_.runs) return false;
    if (out_.applications == 0 && attempts_ / 20 >= std::max<std::size_t>(o_.runs, 1)) return false;
    if (o_.deadline && Clock::now() > *o_.deadline) {
      out_.out_of_time = true;
      return false;
    }
    return !interrupted();
  }

  void note_host(const Map& g) {
    ++out_.hosts;
    out_.largest_host = std::max(out_.largest_host, g.size());
  }

  // One application on a copy of g; the counterexample if H is invalid or
  // has no dense form (two i-arcs at a dart: I(i) breaks).
  std::optional<Counterexample> attempt(const Map& g, std::span<const Dart> hooks) {
    ++attempts_;
    if (o_.progress && attempts_ >= next_progress_) {
      next_progress_ += 4096;
      o_.progress({&rule_.name(), out_.applications, out_.hosts, std::chrono::duration<double>(Clock::now() - start_).count()});
    }
    Refusal refusal = Refusal::none;
    auto cx = apply_and_check(entry_, g, hooks, scratch_, refusal, &applier_);
    if (refusal == Refusal::not_representable)
      ++out_.refusals["not-representable"];
    else if (refusal != Refusal::none)
      ++out_.refusals[std::string(name_of(refusal))];
    else
      ++out_.applications;
    // Events are about the topology of a valid H, whatever the static
    // verdict says of the rule (an embedding failure, a condition that
    // does not bite on this host).
    if (!cx && refusal == Refusal::none && events_.active() && !out_.event_contradiction && out_.event_checks < o_.event_checks) {
      ++out_.event_checks;
      Map h{rule_.model()};
      auto contradictions = events_.contradictions(g, hooks, h);
      if (!contradictions.empty()) {
        Counterexample e{g, {hooks.begin(), hooks.end()}, {}, std::move(h), {}, {}, phase_, false, {}, {}, {}, {}, {}};
        e.event_contradictions = std::move(contradictions);
        out_.event_contradiction = std::move(e);
      }
    }
    return cx;
  }

  // Every hook of a single-hook rule; random tuples of distinct darts (all
  // of them when there are few) for several hooks. Stops at the first
  // counterexample, or when `budget` says so.
  std::optional<Counterexample> every_match(const Map& g, bool budgeted) {
    const std::size_t n = g.size(), h = hook_count();
    if (n < h) return std::nullopt;
    std::vector<Dart> hooks(h);
    if (h == 1) {
      for (Dart d = 0; d < n; ++d) {
        if (budgeted && !budget_left()) return std::nullopt;
        hooks[0] = d;
        if (auto cx = attempt(g, hooks)) return cx;
      }
      return std::nullopt;
    }
    std::size_t tuples = 1;
    for (std::size_t k = 0; k < h && tuples <= 4096; ++k) tuples *= n;
    if (tuples <= 4096) {
      for (std::size_t t = 0; t < tuples; ++t) {
        std::size_t x = t;
        for (auto& d : hooks) d = static_cast<Dart>(x % n), x /= n;
        if (budgeted && !budget_left()) return std::nullopt;
        if (auto cx = attempt(g, hooks)) return cx;
      }
      return std::nullopt;
    }
    std::uniform_int_distribution<Dart> dart(0, static_cast<Dart>(n - 1));
    for (std::size_t t = 0; t < 4 * n; ++t) {
      for (auto& d : hooks) d = dart(rng_);
      if (budgeted && !budget_left()) return std::nullopt;
      if (auto cx = attempt(g, hooks)) return cx;
    }
    return std::nullopt;
  }

  // Phase 1: every map on n darts (containing L at the identity for DPO
  // rules), n growing, until `share` applications, the host budget or
  // n = first + 8. Resumable: a second call continues where this stopped.
  void exhaustive(std::size_t share) {
    const Model& model = rule_.model();
    const bool dpo = !scheme();
    const std::size_t last = std::min(o_.max_darts, first_n_ + 8);
    std::vector<Dart> hooks;
    for (NodeId v : rule_.hooks()) hooks.push_back(v);  // L's node v is dart v
    for (; n_ <= last && host_budget_ > 0 && budget_left() && out_.applications < share; ++n_, skip_ = 0) {
      const std::size_t n = n_;
      std::size_t seen = 0;
      bool stopped = false;
      phase_ = fmt::format("every {} of {} darts{}, in enumeration order", model.name, n, dpo ? " containing L" : "");
      for_each_small_map(
          model, n,
          [&](const std::vector<std::vector<NodeId>>& sigma) {
            if (seen++ < skip_) return true;  // tried by an earlier call
            --host_budget_;
            const Map g = map_of(model, n, sigma);
            note_host(g);
            auto cx = dpo ? attempt(g, hooks) : every_match(g, true);
            if (cx) {
              cx->origin = fmt::format("every {} of {} darts{}, in enumeration order", model.name, n, dpo ? " containing L" : "");
              out_.counterexample = std::move(cx);
            }
            stopped = out_.counterexample || host_budget_ == 0 || !budget_left() || out_.applications >= share;
            return !stopped;
          },
          skip_ + host_budget_, dpo ? &rule_.left() : nullptr);
      if (stopped) {
        skip_ = seen;
        return;
      }
      out_.exhaustive_darts = n;
    }
  }

  // Phase 2: the catalog's and the user's maps, smallest first.
  void given(const std::vector<Map>& seeds) {
    std::vector<const Map*> maps;
    for (const Map& m : seeds)
      if (m.model() == rule_.model()) maps.push_back(&m);
    std::stable_sort(maps.begin(), maps.end(), [](const Map* a, const Map* b) { return a->size() < b->size(); });
    for (const Map* g : maps) {
      note_host(*g);
      phase_ = fmt::format("a given map of {} darts", g->size());
      if (auto cx = every_match(*g, true)) {
        cx->origin = fmt::format("a given map of {} darts", g->size());
        out_.counterexample = std::move(cx);
        return;
      }
      if (!budget_left()) return;
    }
  }

  // Phase 3: random recipes, growing from one face to what --max-darts
  // allows and back; a failing recipe is shrunk while it still fails.
  // Gives up after 20 attempts per requested application if none applied
  // here, and after 500 if some did (a rule that needs a rare shape).
  void random_hosts() {
    const Model& model = rule_.model();
    phase_ = "a random map (not shrunk)";
    const std::size_t cap = std::max<std::size_t>(1, o_.max_darts / darts_per_face(model));
    const std::size_t attempts0 = attempts_, applications0 = out_.applications, runs = std::max<std::size_t>(o_.runs, 1);
    auto starving = [&] {
      const std::size_t tried = attempts_ - attempts0;
      return tried / (out_.applications == applications0 ? 20 : 500) >= runs;
    };
    // After the first failure, 256 more trials on smaller hosts look for a
    // smaller one: greedy shrinking stops at a local minimum.
    std::size_t hunt = 0;
    for (std::size_t trial = 0; budget_left() && !starving() && hunt < 256; ++trial) {
      const auto faces = static_cast<std::uint32_t>(1 + (trial / 4) % cap);
      MapRecipe recipe = draw_recipe(rng_, faces, model.dimension());
      Map g = build_random_map(model, recipe);
      const std::size_t limit = out_.counterexample ? out_.counterexample->host.size() - 1 : o_.max_darts;
      while (g.size() > limit && recipe.face_sizes.size() > 1) {
        recipe.face_sizes.pop_back();
        g = build_random_map(model, recipe);
      }
      if (out_.counterexample) ++hunt;
      if (g.size() > limit) continue;
      note_host(g);
      if (auto cx = every_match(g, true)) {
        const std::size_t before = g.size();
        shrink(recipe, *cx);
        cx->origin = fmt::format("random recipe (trial {}), shrunk from {} to {} darts", trial, before, cx->host.size());
        if (!out_.counterexample || cx->host.size() < out_.counterexample->host.size()) out_.counterexample = std::move(cx);
        if (out_.counterexample->host.size() <= out_.exhaustive_darts + 1) return;  // nothing smaller exists
      }
    }
  }

  void to_hook_components(Counterexample& cx) {
    auto [sub, hooks] = hook_components(cx.host, cx.hooks);
    if (sub.size() == cx.host.size()) return;
    if (auto smaller = attempt(sub, hooks)) {
      smaller->origin = fmt::format("{}; cut to the hook's connected component", cx.origin);
      cx = std::move(*smaller);
    }
  }

  // Greedy shrinking: take the first smaller recipe that still fails, until
  // none does. Every candidate is a valid map (generators/random_maps).
  void shrink(MapRecipe& recipe, Counterexample& cx) {
    for (bool improved = true; improved;) {
      improved = false;
      for (auto& c : shrink_candidates(recipe)) {
        const Map g = build_random_map(rule_.model(), c);
        if (g.size() > cx.host.size()) continue;
        if (auto smaller = every_match(g, false)) {
          recipe = std::move(c);
          cx = std::move(*smaller);
          improved = true;
          break;
        }
      }
    }
  }
};

}  // namespace

FuzzReport fuzz_rule(const Operation& entry, const std::vector<Map>& seeds, const FuzzOptions& o) {
  if (entry.terms) {
    // A topological failure is first sought by the topological fuzzer,
    // which enumerates small hosts and confirms not-representable results
    // (the embedded one draws random hosts and only applies); the values
    // are fuzzed when the topology gives no counterexample.
    // The topological fuzzer also cross-checks the event logs (004), which
    // the embedded one does not: it runs first whenever events are asked.
    const RuleVerdict verdict = o.static_check ? o.static_check(entry) : check_rule(entry.rule, entry.words);
    std::optional<FuzzReport> t;
    if (!static_failures(verdict).empty() || o.event_checks > 0) {
      Operation topology = entry;
      topology.terms.reset();
      FuzzOptions first = o;  // with a time budget, half of it: the values get the rest
      if (o.deadline) first.deadline = std::chrono::steady_clock::now() + (*o.deadline - std::chrono::steady_clock::now()) / 2;
      t = fuzz_rule(topology, seeds, first);
      if (t->counterexample) {
        for (const auto& name : failing_names(check_term_conditions(entry.rule, entry.words, *entry.terms))) t->static_failures.push_back(name);
        return *t;
      }
    }
    FuzzReport e = fuzz_embedded_rule(entry, seeds, o);
    e.checked = "topology and values";
    if (t) {  // both phases' applications were checked
      e.event_checks = t->event_checks;
      e.event_contradiction = std::move(t->event_contradiction);
      e.applications += t->applications;
      e.hosts += t->hosts;
      e.largest_host = std::max(e.largest_host, t->largest_host);
      e.exhaustive_darts = t->exhaustive_darts;
      e.seconds += t->seconds;
      for (const auto& [why, n] : t->refusals) e.refusals[why] += n;
    }
    return e;
  }
  FuzzReport out;
  out.rule = entry.rule.name();
  if (!entry.expressions.empty()) out.checked = "topology; values not computed";
  const RuleVerdict verdict = o.static_check ? o.static_check(entry) : check_rule(entry.rule, entry.words);
  out.static_failures = static_failures(verdict);
  const bool static_holds = out.static_failures.empty();
  Fuzzer(entry, o, out).run(seeds);
  if (out.counterexample) {
    out.verdict = static_holds ? FuzzClass::soundness_bug : FuzzClass::confirmed;
    return out;
  }
  if (static_holds) {
    out.verdict = FuzzClass::consistent;
    if (out.applications == 0) out.reason = "never applied: no host admitted a derivation";
    return out;
  }
  out.verdict = FuzzClass::unconfirmed;
  std::vector<std::string> refused;
  for (const auto& [why, count] : out.refusals) refused.push_back(fmt::format("{} {}", count, why));
  if (out.applications == 0)
    out.reason = fmt::format("never applied: every attempt was refused ({})",
                             refused.empty() ? "L matched no host" : fmt::format("{}", fmt::join(refused, ", ")));
  else
    out.reason = fmt::format("no failure in {} on {} of up to {} darts", counted(out.applications, "application"), counted(out.hosts, "map"),
                             out.largest_host);
  if (out.exhaustive_darts)
    out.reason += fmt::format("; every map of up to {} darts{} was tried", out.exhaustive_darts, entry.is_scheme() ? "" : " containing L");
  if (entry.is_scheme() && std::all_of(out.static_failures.begin(), out.static_failures.end(), [](const std::string& f) { return f[0] == 'C'; }))
    out.reason += "; only the cycle condition fails, and Theorem 6 is sufficient, not necessary";
  if (out.out_of_time) out.reason += " (stopped by --time)";
  return out;
}

std::string outcome_text(const FuzzReport& r) {
  switch (r.verdict) {
    case FuzzClass::consistent:  // the static verdict is beside it: say only what the run saw
      return r.reason.empty() ? fmt::format("no counterexample in {} on {} of up to {} darts ({}{})", counted(r.applications, "application"),
                                            counted(r.hosts, "map"), r.largest_host, r.checked,
                                            r.event_checks ? fmt::format("; events of {} cross-checked", r.event_checks) : "")
                              : fmt::format("no counterexample: {}", r.reason);
    case FuzzClass::unconfirmed:
      return r.applications == 0 ? fmt::format("{}: {}", name_of(r.verdict), r.reason)
                                 : fmt::format("{}: {} ({})", name_of(r.verdict), r.reason, r.checked);
    case FuzzClass::confirmed:
    case FuzzClass::soundness_bug: {
      const auto& cx = *r.counterexample;
      return fmt::format("{}: at hook{} {} of a {}-dart map, H {}{}", name_of(r.verdict), cx.hooks.size() > 1 ? "s" : "", fmt::join(cx.hooks, ","),
                         cx.host.size(), cx.broken_predicate(), cx.minimal ? " (minimal)" : "");
    }
  }
  return "";
}

std::string event_outcome_text(const FuzzReport& r) {
  if (!r.event_contradiction) return "";
  const auto& cx = *r.event_contradiction;
  return fmt::format("EVENT ANALYSIS CONTRADICTED: at hook{} {} of a {}-dart map, {}", cx.hooks.size() > 1 ? "s" : "", fmt::join(cx.hooks, ","),
                     cx.host.size(), cx.event_contradictions.front());
}

namespace {

// A finished rule's line in a log: its class, and for a rule without a
// counterexample what the applications checked (never "consistent" alone).
std::string finished_line(const FuzzReport& r) {
  const std::string applications = counted(r.applications, "application");
  if (r.counterexample) return fmt::format("{}, {}", name_of(r.verdict), applications);
  const std::string_view verdict = r.verdict == FuzzClass::consistent ? "consistent statically" : name_of(r.verdict);
  if (r.applications == 0) return fmt::format("{}, never applied", verdict);
  return fmt::format("{}, no counterexample in {} ({})", verdict, applications, r.checked);
}

}  // namespace

std::vector<FuzzReport> fuzz_rules(const std::vector<const Operation*>& rules, const std::vector<Map>& seeds, FuzzOptions o,
                                   std::optional<double> seconds, bool progress,
                                   const std::function<void(std::size_t, const FuzzReport&)>& finished) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<FuzzReport> reports;
  std::size_t failures = 0;
  const bool quiet = terminal().quiet;  // --quiet: no progress at all
  for (std::size_t k = 0; k < rules.size() && !interrupted(); ++k) {
    if (seconds) {
      // An equal share of what is left for each remaining rule.
      const double left = *seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      o.deadline = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                          std::chrono::duration<double>(std::max(0.0, left) / double(rules.size() - k)));
    }
    if (progress && !quiet)
      o.progress = [&, k](const FuzzProgress& p) {
        fmt::print(stderr, "\r\033[K[{}/{}] {}: {} applications ({:.0f}/s), {} failure{}", k + 1, rules.size(), *p.rule, p.applications,
                   p.seconds > 0 ? double(p.applications) / p.seconds : 0.0, failures, failures == 1 ? "" : "s");
      };
    reports.push_back(fuzz_rule(*rules[k], seeds, o));
    if (interrupted()) {
      reports.pop_back();  // stopped halfway: not a result
      break;
    }
    if (reports.back().counterexample) ++failures;
    const auto& r = reports.back();
    // Without a terminal (CI logs), a line per finished rule instead.
    if (!progress && !quiet)
      fmt::print(stderr, "[{}/{}] {}: {}, {:.2f} s\n", k + 1, rules.size(), r.rule, finished_line(r), r.seconds);
    if (finished) finished(k, r);
  }
  if (progress && !quiet) fmt::print(stderr, "\r\033[K");
  return reports;
}

}  // namespace dartcheck::analysis
