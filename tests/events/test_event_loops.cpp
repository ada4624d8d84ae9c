// Property (the loop case of 004 Prop. 3.2.1 and 3.3.1, which the paper's
// proofs name without concluding; events/static_events concludes it): at
// every hook where a rule with a Jerboa view applies and gives a valid map,
// for every orbit type, events::cross_check finds no contradiction. In
// particular an orbit whose implicit k-links are loops (or folded so that
// the relabeled links coincide) comes out unchanged exactly where the rule
// announces the loop case's no-modification, and a conditional split,
// merge or modification that does not happen has its loop or fold.
//
// Random maps rarely have loops where rules change links, so the hosts
// are built for it:
//  - every 3-G-map of 1 to 3 darts, 4 with DARTCHECK_EVENT_RUNS above 60
//    (every loop and fold a small orbit can have; the fuzz phase that
//    found the false alarms);
//  - random surfaces 3-sewn to a mirror copy on a random subset of faces,
//    then unsewn along random dimensions on whole orbits as Jerboa's unsew
//    does (an i-link becomes a loop on a <dims except i-1,i,i+1>-orbit);
//  - Jerboa's pyramid.jba and cube.jba, mirrored and unsewn the same way.
// Rules: every rule with a Jerboa view of the bundled catalogs, of
// JerboaRebuilt2.jme and of the two jerboa-rebuild modelers in
// tests/data/jerboa-rebuild (167 rules of 3-G-maps, consistent or not: events concern
// the topology of a valid H, whatever the rule's verdict).
// DARTCHECK_EVENT_RUNS raises the number of random hosts (default 60).
#include <cstdlib>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <random>

#include <fmt/ranges.h>

#include "checkers/host_search.hpp"
#include "checkers/map_validity.hpp"
#include "core/orbit.hpp"
#include "events_support.hpp"
#include "generators/random_maps.hpp"
#include "io/jerboa_jba.hpp"
#include "tests/map_recipe_gen.hpp"

namespace dartcheck::events::test {
namespace {

struct Subject {
  const Operation* op;
  EventRule view;
  std::vector<KindEvents> kinds;
};

const std::vector<Catalog>& catalogs() {
  static const std::vector<Catalog> c = [] {
    const std::string src = DARTCHECK_SOURCE_DIR;
    std::vector<Catalog> out;
    for (const char* f : {"/catalogs/seed-operations.yaml", "/catalogs/embedding-operations.yaml", "/catalogs/event-operations.yaml",
                          "/../shared/jerboa-samples/JerboaRebuilt2.jme", "/tests/data/jerboa-rebuild/JerboaRebuilt.jme",
                          "/tests/data/jerboa-rebuild/JerboaTrackingOrbit.jme"})
      out.push_back(read_catalog(src + f));
    return out;
  }();
  return c;
}

// The rules of 3-G-maps with a Jerboa view, their static events computed once.
const std::vector<Subject>& subjects() {
  static const std::vector<Subject> s = [] {
    std::vector<Subject> out;
    for (const Catalog& c : catalogs())
      for (const CatalogRule& r : c.rules) {
        if (!(r.rule.model() == Model::gmap(3))) continue;
        auto view = event_rule(r);
        if (!view.rule) continue;
        Subject sub{&r, std::move(*view.rule), {}};
        for (const OrbitKind& kind : all_orbit_kinds(r.rule.model())) sub.kinds.push_back(static_events(sub.view, kind));
        out.push_back(std::move(sub));
      }
    return out;
  }();
  return s;
}

struct Tally {
  std::size_t applied = 0, loop_cases = 0;
};

// Every hook (pairs among the first 8 darts for two-hook rules); an
// application counts when H is a valid map. Stops at the first contradiction.
void check_on(const Subject& s, const Map& g, Tally& t) {
  std::vector<std::vector<Dart>> hook_sets;
  const std::size_t hooks = s.op->rule.hooks().size();
  if (hooks == 0) hook_sets.push_back({});
  for (Dart d = 0; hooks == 1 && d < g.size(); ++d) hook_sets.push_back({d});
  for (Dart d = 0; hooks == 2 && d < std::min<std::size_t>(g.size(), 8); ++d)
    for (Dart e = 0; e < std::min<std::size_t>(g.size(), 8); ++e)
      if (d != e) hook_sets.push_back({d, e});
  for (const auto& hk : hook_sets) {
    Map h = g;
    auto traced = Applier(*s.op).apply(h, hk);
    if (!traced.ok() || !check_map(h).valid()) continue;
    ++t.applied;
    for (const KindEvents& k : s.kinds) {
      const EventLog dyn = dynamic_log(g, h, s.op->rule, *traced.value, k.kind);
      const EventLog inst = instantiated_log(g, h, s.view, k, *traced.value);
      const CrossCheck cc = cross_check(s.view, k, g, h, *traced.value, dyn, inst);
      for (const auto& why : cc.resolutions) t.loop_cases += why.find("loops or a fold") != std::string::npos;
      if (!cc.contradictions.empty()) {
        const std::string what =
            fmt::format("{} at hooks [{}] of a {}-dart map: {}", s.op->rule.name(), fmt::join(hk, ", "), g.size(), cc.contradictions[0]);
        ADD_FAILURE() << what;
        RC_FAIL(what);
      }
    }
  }
}

// g and a mirror copy, face f of the one 3-sewn to face f of the other for
// the faces `sewn` selects (only 3-free faces: C(0,3), C(1,3) hold since
// the copy has the same 0- and 1-links).
Map mirror_along_3(const Map& g, const std::vector<bool>& sewn) {
  const std::size_t n = g.size();
  Map m(g.model(), 2 * n);
  for (Dim i : g.model().dims)
    for (Dart d = 0; d < n; ++d) {
      m.set_link(i, d, g.link(i, d));
      m.set_link(i, d + static_cast<Dart>(n), g.link(i, d) + static_cast<Dart>(n));
    }
  OrbitWalker walker(g);
  std::vector<bool> seen(n, false);
  std::size_t face = 0;
  for (Dart d = 0; d < n; ++d) {
    if (seen[d]) continue;
    const std::vector<OrbitWord> face_gens{OrbitWord{0}, OrbitWord{1}};
    const auto& darts = walker.orbit(d, face_gens);
    bool free = true;
    for (Dart e : darts) seen[e] = true, free = free && g.link(3, e) == e;
    if (free && sewn[face++ % sewn.size()])
      for (Dart e : darts) m.sew(3, e, e + static_cast<Dart>(n));
  }
  return m;
}

// Jerboa's unsew along i at d: every dart of d's orbit over the dimensions
// other than i-1, i, i+1 (and its i-partner) gets an i-loop.
void unsew(Map& m, Dart d, Dim i) {
  std::vector<OrbitWord> gens;
  for (Dim j : m.model().dims)
    if (j + 1 < i || j > i + 1) gens.push_back({j});
  OrbitWalker walker(m);
  const std::vector<Dart> orbit = walker.orbit(d, gens);  // a copy: the links change below
  for (Dart e : orbit) {
    const Dart f = m.link(i, e);
    m.sew(i, e, e);
    m.sew(i, f, f);
  }
}

// Mirrored and unsewn variants of g; only valid ones (all of them, by the
// argument above; the check guards the test's own builder).
Map loop_host(const Map& g, std::mt19937& rng) {
  std::vector<bool> sewn(1 + rng() % 5);
  for (std::size_t k = 0; k < sewn.size(); ++k) sewn[k] = rng() % 2;
  Map m = rng() % 4 ? mirror_along_3(g, sewn) : g;
  const std::size_t cuts = rng() % 4;
  for (std::size_t k = 0; k < cuts && m.size(); ++k) unsew(m, static_cast<Dart>(rng() % m.size()), static_cast<Dim>(rng() % 4));
  return m;
}

TEST(EventLoopCase, EverySmallMap) {
  ASSERT_GE(subjects().size(), 160U);
  Tally t;
  std::size_t maps = 0;
  const std::size_t largest = runs() > 60 ? 4 : 3;  // 4 darts: 25 s
  for (std::size_t n = 1; n <= largest; ++n)
    for_each_small_map(Model::gmap(3), n, [&](const std::vector<std::vector<NodeId>>& sigma) {
      Map g(Model::gmap(3), n);
      for (std::size_t k = 0; k < 4; ++k)
        for (Dart d = 0; d < n; ++d) g.set_link(static_cast<Dim>(k), d, sigma[k][d]);
      ++maps;
      for (const Subject& s : subjects()) check_on(s, g, t);
      return !::testing::Test::HasFailure();
    });
  // Not vacuous: many applications, and the loop case resolved some.
  EXPECT_GT(maps, 10U);
  EXPECT_GT(t.applied, 1000U);
  EXPECT_GT(t.loop_cases, 100U);
}

RC_GTEST_PROP(EventLoopCase, MirroredAndUnsewnRandomSurfaces, ()) {
  const auto recipe = *gen_map_recipe(1, 4);
  const auto seed = *rc::gen::arbitrary<std::uint32_t>();
  std::mt19937 rng(seed);
  const Map g = loop_host(build_random_map(Model::gmap(3), recipe), rng);
  RC_ASSERT(check_map(g).valid());
  Tally t;
  for (const Subject& s : subjects()) check_on(s, g, t);
  RC_CLASSIFY(t.loop_cases > 0, "loop case");
}

TEST(EventLoopCase, MirroredAndUnsewnJerboaMaps) {
  const std::string dir = std::string(DARTCHECK_SOURCE_DIR) + "/../shared/jerboa-samples/";
  Tally t;
  std::mt19937 rng(11);
  for (const char* file : {"pyramid.jba", "cube.jba"}) {
    const Map base = read_jba(dir + file).map;
    for (int k = 0; k < std::max(2, runs() / 20); ++k) {
      const Map g = loop_host(base, rng);
      ASSERT_TRUE(check_map(g).valid()) << file;
      for (const Subject& s : subjects()) check_on(s, g, t);
      if (::testing::Test::HasFailure()) return;
    }
  }
  EXPECT_GT(t.applied, 1000U);
}

}  // namespace
}  // namespace dartcheck::events::test
