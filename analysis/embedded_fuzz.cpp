#include "analysis/embedded_fuzz.hpp"

#include "rewriting/application.hpp"
#include "analysis/interrupt.hpp"

#include <random>

#include <fmt/format.h>

#include "checkers/embedding_conditions.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/host_search.hpp"
#include "checkers/map_validity.hpp"
#include "rewriting/application.hpp"
#include "rewriting/application.hpp"
#include "core/orbit.hpp"
#include "rewriting/term_eval.hpp"
#include "generators/random_embedding.hpp"
#include "generators/random_maps.hpp"
#include "core/wording.hpp"

namespace dartcheck::analysis {

namespace {

using Clock = std::chrono::steady_clock;

// The darts L's nodes match at `hooks` (first pattern copy for schemes),
// or nothing when L does not match there.
std::vector<std::vector<Dart>> match_darts(const Operation& entry, const Map& g, std::span<const Dart> hooks) {
  auto m = Applier(entry).match(g, hooks);
  return m.ok() ? std::move(m.value->match) : std::vector<std::vector<Dart>>{};
}

// Gives the host orbits of L's matched darts the values of L's terms
// (closed terms always, others when `all`), so the labeled match holds.
void plant(const Operation& entry, EmbeddedMap& g, std::span<const Dart> hooks, bool all) {
  const auto darts = match_darts(entry, g.map, hooks);
  if (darts.empty()) return;
  const TopoGraph& L = entry.rule.left();
  for (const NodeTerm& t : entry.terms->left) {
    if (!all && !t.term.variables().empty()) continue;
    const NodeId x = *L.find(t.node);
    std::vector<Dart> column;
    for (const auto& d : darts) column.push_back(d[0]);
    try {
      TermEvaluator ev(g);
      Value v = ev.value(t.term, L.names(), column);
      for (std::size_t k = 0; k < g.embeddings.size(); ++k)
        if (g.embeddings[k].signature.name == t.embedding) g.label_orbit(k, darts[x][0], v);
    } catch (const EvaluationError&) {
      return;  // the attempt will be refused with the reason
    }
  }
}

// Tags every dart of the pi-orbit of d in H with its value (or "none"),
// for the counterexample picture.
void mark_orbit(const EmbeddedMap& h, const Embedding& e, Dart d, std::vector<std::string>& tags) {
  tags.resize(h.map.size());
  OrbitWalker walker(h.map);
  for (Dart x : walker.orbit(d, dims_generators(e.signature.orbit))) {
    const Value* v = e.value(x);
    const std::string tag = v ? fmt::format("{} {}", e.signature.name, v->str()) : fmt::format("{}: none", e.signature.name);
    tags[x] = tags[x].empty() ? tag : fmt::format("{}\n{}", tags[x], tag);
  }
}

// Hosts: the given maps of the model, then every map of up to 6 darts
// (containing L for a DPO rule), at most 2,000 -- a rule whose L random
// maps rarely match (a free dart, a loop) still applies, as in the
// topological fuzzer's first phase -- then random maps growing to
// max_darts (in rounds, so small hosts come first).
class EmbeddedHosts {
 public:
  EmbeddedHosts(const Operation& entry, const std::vector<Map>& seeds, std::size_t max_darts) : model_(entry.rule.model()), max_darts_(max_darts) {
    for (const Map& m : seeds)
      if (m.model() == model_) given_.push_back(m);
    user_maps_ = given_.size();
    const std::size_t small_budget = 2000;
    for (std::size_t n = 1; n <= std::min<std::size_t>(6, max_darts) && small_count_ < small_budget; ++n)
      for_each_small_map(
          model_, n,
          [&](const std::vector<std::vector<NodeId>>& sigma) {
            Map m(model_, n);
            for (std::size_t k = 0; k < model_.dims.size(); ++k)
              for (Dart d = 0; d < n; ++d) m.set_link(model_.dims[k], d, sigma[k][d]);
            given_.push_back(std::move(m));
            ++small_count_;
            return small_count_ < small_budget;
          },
          small_budget - small_count_, entry.is_scheme() ? nullptr : &entry.rule.left());
  }

  /// The next host, or none when the given ones are used up and the
  /// model has no random generator (or 8 draws were too large).
  std::optional<Map> next(std::mt19937& rng) {
    kind_ = next_given_ < user_maps_ ? "given" : next_given_ < given_.size() ? "enumerated" : "random";
    if (next_given_ < given_.size()) return given_[next_given_++];
    if (!has_random_generator(model_)) return std::nullopt;
    for (int tries = 0; tries < 8; ++tries) {
      Map m = build_random_map(model_, draw_recipe(rng, static_cast<std::uint32_t>(faces_), model_.dimension()));
      faces_ = faces_ % 12 + 1;
      if (m.size() <= max_darts_ && m.size() > 0) return m;
    }
    return std::nullopt;
  }
  /// Of the last host: given, enumerated or random.
  const char* kind() const { return kind_; }
  std::size_t small_count() const { return small_count_; }

 private:
  const Model& model_;
  std::size_t max_darts_;
  std::vector<Map> given_;  // the seeds of the model, then the small maps
  std::size_t user_maps_ = 0, small_count_ = 0, next_given_ = 0, faces_ = 1;
  const char* kind_ = "random";
};

// What an application broke: H's topology, the rule's value conflicts and
// every embedding's orbits with two values or none; nullopt if nothing.
std::optional<Counterexample> broken(const EmbeddedMap& planted, const EmbeddedMap& h, const EmbeddedApplication& d, std::span<const Dart> hooks) {
  Counterexample cx{planted.map, {hooks.begin(), hooks.end()}, {}, h.map, {}, {}, {}, false, {}, {}, {}, {}, {}};
  cx.violations = check_map(h.map).violations;
  for (const auto& c : d.conflicts) cx.embedding_failures.push_back(c);
  for (const Embedding& e : h.embeddings) {
    const auto r = check_embedding(h.map, e, true);
    for (const auto& c : r.conflicts) {
      cx.embedding_failures.push_back(c.describe(e.signature.name, e.signature.orbit));
      mark_orbit(h, e, c.dart, cx.orbit_values);
    }
    if (!r.consistent()) cx.broken_embeddings.push_back(e.signature.name);
  }
  if (cx.violations.empty() && cx.embedding_failures.empty()) return std::nullopt;
  return cx;
}

// The match and the comatch, for the pictures: the application again (it
// is deterministic), recorded this time; schemes show their match as P_v
// from the hooks.
void add_match(const Operation& entry, const EmbeddedMap& planted, std::span<const Dart> hooks, Counterexample& cx) {
  if (!entry.is_scheme())
    if (const auto m = match_darts(entry, planted.map, hooks); !m.empty())
      for (NodeId v = 0; v < entry.rule.left().node_count(); ++v) cx.match.emplace_back(entry.rule.left().name(v), m[v][0]);
  EmbeddedMap again = planted;
  if (const auto r = Applier(entry).apply(again, hooks, true); r.ok())
    for (NodeId y = 0; y < entry.rule.right().node_count() && y < r.value->topology.comatch.size(); ++y)
      for (Dart dart : r.value->topology.comatch[y]) cx.comatch.emplace_back(entry.rule.right().name(y), dart);
}

// The verdict and its reason once the run ended.
void classify(FuzzReport& out, bool static_holds, std::size_t small_count) {
  if (out.counterexample) {
    out.verdict = static_holds ? FuzzClass::soundness_bug : FuzzClass::confirmed;
    return;
  }
  std::vector<std::string> refused;
  for (const auto& [why, count] : out.refusals) refused.push_back(fmt::format("{} {}", count, why));
  const std::string refusals = refused.empty() ? "" : fmt::format(" (refused: {})", fmt::join(refused, ", "));
  if (static_holds) {
    out.verdict = FuzzClass::consistent;
    if (out.applications == 0) out.reason = fmt::format("never applied{}", refusals);
    return;
  }
  out.verdict = FuzzClass::unconfirmed;
  out.reason =
      out.applications == 0
          ? fmt::format("never applied{}", refusals)
          : fmt::format("no failure in {} on {} of up to {} darts: the static conditions are sufficient, not necessary{}",
                        counted(out.applications, "application"),
                        counted(out.hosts, "embedded map") + fmt::format(" ({} enumerated maps of up to 6 darts, then random ones)", small_count),
                        out.largest_host, refusals);
  if (out.out_of_time) out.reason += " (stopped by --time)";
}

}  // namespace

FuzzReport fuzz_embedded_rule(const Operation& entry, const std::vector<Map>& seeds, const FuzzOptions& o) {
  FuzzReport out;
  out.rule = entry.rule.name();
  const RuleTerms& terms = *entry.terms;
  const RuleVerdict verdict = o.static_check ? o.static_check(entry) : check_rule(entry.rule, entry.words);
  out.static_failures = static_failures(verdict);
  for (const auto& name : failing_names(check_term_conditions(entry.rule, entry.words, terms))) out.static_failures.push_back(name);
  const auto start = Clock::now();
  std::mt19937 rng(static_cast<std::mt19937::result_type>(rule_seed(o.seed, out.rule)));
  EmbeddedHosts hosts(entry, seeds, o.max_darts);
  Applier applier(entry);
  std::size_t attempts = 0;
  while (out.applications < o.runs && attempts < o.runs * 20 && !out.counterexample) {
    if (o.deadline && Clock::now() > *o.deadline) {
      out.out_of_time = true;
      break;
    }
    if (interrupted()) break;
    auto host = hosts.next(rng);
    if (!host) break;
    ++out.hosts;
    out.largest_host = std::max(out.largest_host, host->size());
    const EmbeddedMap g = embed_randomly(std::move(*host), terms.embeddings, rng);
    const std::size_t tries = std::min<std::size_t>(2 * g.map.size(), 24);
    std::uniform_int_distribution<Dart> pick(0, static_cast<Dart>(g.map.size() - 1));
    for (std::size_t t = 0; t < tries && out.applications < o.runs; ++t, ++attempts) {
      std::vector<Dart> hooks;
      for (std::size_t k = 0; k < entry.rule.hooks().size(); ++k) hooks.push_back(pick(rng));
      // Where L does not match, the application is refused alike: said
      // without copying the host (most attempts of a rule with a rare match).
      if (const auto m = applier.match(g.map, hooks); !m.ok()) {
        ++out.refusals[std::string(name_of(m.refusal))];
        continue;
      }
      EmbeddedMap h = g;
      plant(entry, h, hooks, t % 2 == 0);
      const EmbeddedMap planted = h;
      auto d = applier.apply(h, hooks, false);
      if (!d.ok()) {
        ++out.refusals[std::string(name_of(d.refusal))];
        continue;
      }
      ++out.applications;
      if (auto cx = broken(planted, h, *d.value, hooks)) {
        cx->origin = fmt::format("{} {}-dart {} with random values (host {} of the run)", hosts.kind(), planted.map.size(), entry.rule.model().name,
                                 out.hosts);
        add_match(entry, planted, hooks, *cx);
        out.counterexample = std::move(cx);
        break;
      }
    }
  }
  out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  classify(out, out.static_failures.empty(), hosts.small_count());
  return out;
}

}  // namespace dartcheck::analysis
