// Property (004 Prop. 3.1.1-3.4.2, with the certainty levels of
// events/static_events.hpp): on random valid maps, at every hook where a
// consistent rule applies, for every orbit type of its model,
//  - the instantiated log equals the dynamic one (labeling every dart);
//  - every certain static event happens on every orbit its rule orbit
//    matches, and a conditional one fails only at a loop or a fold;
//  - every dynamic event on a matched orbit was announced by a rule orbit
//    that matches it, and unmatched orbits are unchanged.
// (events::cross_check.) Rules: every consistent rule of the bundled
// catalogs and of ../shared/jerboa-samples/JerboaRebuilt2.jme that has a
// Jerboa view, on the models with a random map generator.
// DARTCHECK_EVENT_RUNS raises the number of maps per catalog (default 60).
#include <cstdlib>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <iostream>
#include <random>

#include <fmt/ranges.h>

#include "checkers/rule_conditions.hpp"
#include "events_support.hpp"
#include "generators/random_maps.hpp"
#include "tests/map_recipe_gen.hpp"

namespace dartcheck::events::test {
namespace {

struct Subject {
  const Operation* op;
  EventRule view;
  std::vector<OrbitKind> kinds;
};

std::vector<Subject> subjects(const Catalog& c) {
  std::vector<Subject> out;
  for (const CatalogRule& r : c.rules) {
    if (!has_random_generator(r.rule.model()) || !check_rule(r.rule, r.words).consistent()) continue;
    auto view = event_rule(r);
    if (view.rule) out.push_back({&r, std::move(*view.rule), all_orbit_kinds(r.rule.model())});
  }
  return out;
}

// Applies the subject at every hook of g (pairs among the first 12 darts
// for two-hook rules) and cross-checks every orbit type. Returns the
// number of applications.
std::size_t check_on(const Subject& s, const Map& g) {
  std::size_t applied = 0;
  std::vector<std::vector<Dart>> hook_sets;
  if (s.op->rule.hooks().empty()) {
    hook_sets.push_back({});  // L is empty: one application per map
  } else if (s.op->rule.hooks().size() == 1) {
    for (Dart d = 0; d < g.size(); ++d) hook_sets.push_back({d});
  } else if (s.op->rule.hooks().size() == 2) {
    for (Dart d = 0; d < std::min<std::size_t>(g.size(), 12); ++d)
      for (Dart e = 0; e < std::min<std::size_t>(g.size(), 12); ++e)
        if (d != e) hook_sets.push_back({d, e});
  }
  for (const auto& hooks : hook_sets) {
    Map h = g;
    auto traced = Applier(*s.op).apply(h, hooks);
    if (!traced.ok()) continue;
    ++applied;
    for (const OrbitKind& kind : s.kinds) {
      const KindEvents k = static_events(s.view, kind);
      const EventLog dyn = dynamic_log(g, h, s.op->rule, *traced.value, kind);
      const EventLog inst = instantiated_log(g, h, s.view, k, *traced.value);
      const CrossCheck cc = cross_check(s.view, k, g, h, *traced.value, dyn, inst);
      if (!cc.contradictions.empty()) {
        const std::string what =
            fmt::format("{} at hooks [{}] of a {}-dart map: {}", s.op->rule.name(), fmt::join(hooks, ", "), g.size(), cc.contradictions[0]);
        ADD_FAILURE() << what;
        RC_FAIL(what);
      }
    }
  }
  return applied;
}

std::size_t check_all(const std::vector<Subject>& subs, const MapRecipe& recipe) {
  std::size_t applied = 0;
  for (const Subject& s : subs) applied += check_on(s, build_random_map(s.op->rule.model(), recipe));
  return applied;
}

const Catalog& seed_catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  return c;
}
const Catalog& embedding_catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  return c;
}
const Catalog& jerboa_catalog() {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/../shared/jerboa-samples/JerboaRebuilt2.jme");
  return c;
}

// Small maps (1-6 faces) keep every hook of every rule affordable.
void property(const Catalog& c) {
  static std::map<const Catalog*, std::vector<Subject>> cache;
  if (!cache.count(&c)) cache.emplace(&c, subjects(c));
  const auto recipe = *gen_map_recipe(1, 6);
  const std::size_t applied = check_all(cache.at(&c), recipe);
  RC_CLASSIFY(applied > 0, "applied");
}

RC_GTEST_PROP(EventCrossCheck, SeedCatalog, ()) { property(seed_catalog()); }
RC_GTEST_PROP(EventCrossCheck, EmbeddingCatalog, ()) { property(embedding_catalog()); }
RC_GTEST_PROP(EventCrossCheck, EventCatalog, ()) { property(event_catalog()); }
RC_GTEST_PROP(EventCrossCheck, JerboaRebuilt2, ()) { property(jerboa_catalog()); }

// The property is not vacuous: on the catalogs' own maps and on seeded
// random maps, most consistent rules with a Jerboa view apply somewhere
// and pass the cross-check; the ones that never apply are listed.
TEST(EventCrossCheck, RulesApplyOnCatalogAndRandomMaps) {
  // The catalogs' own maps first: some rules need a host random maps
  // rarely give (an isolated edge).
  std::size_t subjects_total = 0, never = 0;
  std::vector<std::string> idle;
  for (const Catalog* c : {&seed_catalog(), &embedding_catalog(), &event_catalog(), &jerboa_catalog()}) {
    const std::vector<Subject> subs = subjects(*c);
    for (const Subject& s : subs) {
      ++subjects_total;
      std::size_t applied = 0;
      for (const Catalog* m : {&seed_catalog(), &embedding_catalog(), &event_catalog()})
        for (const MapSource& source : m->maps)
          if (source.model == s.op->rule.model()) applied += check_on(s, analysis::build_source(source));
      std::mt19937 rng(7);
      for (int k = 0; k < runs() && applied == 0; ++k) {
        applied += check_all({s}, draw_recipe(rng, 1 + static_cast<std::uint32_t>(k % 6), s.op->rule.model().dimension()));
        if (::testing::Test::HasFailure()) return;
      }
      if (applied == 0) {
        ++never;
        idle.push_back(s.op->rule.name());
      }
    }
  }
  EXPECT_GE(subjects_total, 40U);
  EXPECT_LE(never * 5, subjects_total) << "rules never applied: " << fmt::format("{}", fmt::join(idle, ", "));
  if (!idle.empty()) std::cout << "never applied on random maps: " << fmt::format("{}", fmt::join(idle, ", ")) << "\n";
}

}  // namespace
}  // namespace dartcheck::events::test
