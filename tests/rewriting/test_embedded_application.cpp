// Embedded rule application (003 Def. 11-13): one evaluation per orbit and a
// kept rewriter agree with fresh applications, Lemma 3's overlap refusal,
// and the position triangulation of a mesh against the mesh file's
// barycenters.
#include <algorithm>
#include <bit>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <optional>
#include <random>
#include <set>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "checkers/embedding_conditions.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include "checkers/rule_conditions.hpp"
#include "analysis/embedded_fuzz.hpp"
#include "io/catalog.hpp"
#include "rewriting/application.hpp"
#include "rewriting/detail/scheme_rewriter.hpp"
#include "rewriting/instantiated_classes.hpp"
#include "core/input_error.hpp"
#include "io/mesh_io.hpp"
#include "core/orbit.hpp"
#include "rewriting/term_eval.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_embedding.hpp"
#include "generators/random_maps.hpp"
#include "generators/random_rules.hpp"
#include "tests/embedding_support.hpp"

namespace dartcheck {
namespace {

using namespace testing_support;

// Every embedding's value at every dart (none: nullopt), to compare two
// maps whose value pools differ.
std::vector<std::vector<std::optional<Value>>> values_of(const EmbeddedMap& g) {
  std::vector<std::vector<std::optional<Value>>> out;
  for (const Embedding& e : g.embeddings) {
    out.emplace_back();
    for (Dart d = 0; d < g.map.size(); ++d) out.back().push_back(e.value(d) ? std::optional(*e.value(d)) : std::nullopt);
  }
  return out;
}

TEST(EmbeddedRewriter, OneEvaluationPerOrbitAndReuseWriteWhatFreshApplicationsWrite) {
  // 003 Thm 2 and 4: when a rule passes the conditions, the instances of
  // one orbit of the extended rule have one value, so evaluating one per
  // orbit (Evaluation::one_per_orbit) writes what evaluating every
  // instance writes. And a rewriter kept across applications on a
  // changing map (tables left empty, walkers grown) acts as fresh
  // applications do. Three applications in a row on random embedded maps,
  // for the consistent rules of the embedding and subdivision catalogs.
  std::mt19937 rng(11);
  std::size_t compared = 0, rules = 0, propagated = 0;
  for (const Catalog* catalog : {&embedding_catalog(), &subdivision_catalog()}) {
    for (const auto& r : catalog->rules) {
      if (!static_failures_of(r).empty()) continue;
      ++rules;
      for (int round = 0; round < 80; ++round) {
        EmbeddedMap fresh = embed_randomly(build_random_map(r.rule.model(), draw_recipe(rng, 1 + round % 8, 2)), catalog->signatures, rng);
        EmbeddedMap reused = fresh;
        Applier rewriter(r, {Evaluation::one_per_orbit});
        for (int step = 0; step < 3; ++step) {
          std::vector<Dart> hooks;
          for (std::size_t h = 0; h < r.rule.hooks().size(); ++h)
            hooks.push_back(std::uniform_int_distribution<Dart>(0, static_cast<Dart>(fresh.map.size() - 1))(rng));
          const auto a = Applier(r).apply(fresh, hooks);
          const auto b = rewriter.apply(reused, hooks);
          ASSERT_EQ(a.refusal, b.refusal) << r.rule.name() << ": " << a.why << " / " << b.why;
          if (!a.ok()) continue;
          ASSERT_TRUE(a.value->conflicts.empty()) << r.rule.name() << ": " << a.value->conflicts.front();
          ASSERT_EQ(fresh.map, reused.map) << r.rule.name();
          ASSERT_EQ(values_of(fresh), values_of(reused)) << r.rule.name();
          ASSERT_EQ(a.value->written.size(), b.value->written.size()) << r.rule.name();
          for (std::size_t k = 0; k < a.value->written.size(); ++k) ASSERT_EQ(a.value->written[k].value, b.value->written[k].value) << r.rule.name();
          // Def. 12 (extended): the whole pi-orbit of H of every labeled
          // instance carries its value, whether the rewriter wrote it by
          // walking the orbit or by the classes of a closed R.
          if (r.terms->instantiation == Instantiation::extended) {
            OrbitWalker walk(fresh.map);
            for (const WrittenValue& w : a.value->written) {
              const Embedding& e = *fresh.find(w.embedding);
              for (Dart x : walk.orbit(w.dart, dims_generators(e.signature.orbit))) {
                ASSERT_NE(e.value(x), nullptr) << r.rule.name() << ": dart " << x << " of the orbit of " << w.node;
                ASSERT_EQ(*e.value(x), w.value) << r.rule.name() << ": dart " << x << " of the orbit of " << w.node;
                ++propagated;
              }
            }
          }
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(rules, 17u);  // the embedding catalog's 15 consistent rules + catmull-clark-points, catmull-clark
  EXPECT_GT(compared, 300u);
  EXPECT_GT(propagated, 10000u);
}

// The kept-label shortcut (EvaluationOptions::kept_label_shortcut), as
// its comment states it: under one evaluation per orbit, an application
// with the shortcut and one without give the same refusal (and reason)
// and the same H index for index: equal links, the same pool index at
// every dart of every embedding, pools equal bit for bit, the same written
// values and conflicts. Every extended rule of the embedding and
// subdivision catalogs (consistent or not), three applications in a row
// at random hooks, on random embedded maps in three forms: as drawn (one
// pool entry per orbit: a consistent G, where the check holds), with every
// labeled dart given its own pool entry of the same value (equal values in
// distinct entries: the check fails) and with one dart relabeled (G not
// consistent). The counts show both branches ran.
bool same_bits(const Value& a, const Value& b) {
  return a.type == b.type && a.i == b.i &&
         std::equal(a.x.begin(), a.x.end(), b.x.begin(), [](double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); });
}

TEST(EmbeddedRewriter, KeptLabelShortcutGivesTheWalksResultIndexForIndex) {
  std::mt19937 rng(43);
  std::size_t applied = 0, refused = 0, taken = 0, failed = 0;
  for (const Catalog* catalog : {&embedding_catalog(), &subdivision_catalog()})
    for (const auto& r : catalog->rules) {
      if (r.terms->instantiation != Instantiation::extended) continue;
      for (int round = 0; round < 60; ++round) {
        EmbeddedMap with = embed_randomly(build_random_map(r.rule.model(), draw_recipe(rng, 1 + round % 8, 2)), catalog->signatures, rng);
        if (round % 3 == 1) {  // one pool entry per labeled dart
          for (Embedding& e : with.embeddings)
            for (std::uint32_t& k : e.slot)
              if (k != Embedding::none) k = e.store(Value(e.pool[k]));
        } else if (round % 3 == 2) {  // one dart relabeled
          Embedding& e = with.embeddings[std::uniform_int_distribution<std::size_t>(0, with.embeddings.size() - 1)(rng)];
          e.set(std::uniform_int_distribution<Dart>(0, static_cast<Dart>(with.map.size() - 1))(rng), random_value(e.signature.type, rng));
        }
        EmbeddedMap without = with;
        Applier a(r, {Evaluation::one_per_orbit});
        Applier b(r, {Evaluation::one_per_orbit, false});
        for (int step = 0; step < 3; ++step) {
          std::vector<Dart> hooks;
          for (std::size_t h = 0; h < r.rule.hooks().size(); ++h)
            hooks.push_back(std::uniform_int_distribution<Dart>(0, static_cast<Dart>(with.map.size() - 1))(rng));
          const auto x = a.apply(with, hooks), y = b.apply(without, hooks);
          ASSERT_EQ(x.refusal, y.refusal) << r.rule.name() << ": " << x.why << " / " << y.why;
          ASSERT_EQ(x.why, y.why) << r.rule.name();
          if (!x.ok()) {
            ++refused;
            continue;
          }
          ++applied;
          ASSERT_EQ(with.map, without.map) << r.rule.name();
          for (std::size_t k = 0; k < with.embeddings.size(); ++k) {
            const Embedding &e = with.embeddings[k], &f = without.embeddings[k];
            ASSERT_EQ(e.slot, f.slot) << r.rule.name() << ": the pool indices of " << e.signature.name;
            ASSERT_EQ(e.pool.size(), f.pool.size()) << r.rule.name();
            for (std::size_t i = 0; i < e.pool.size(); ++i) ASSERT_TRUE(same_bits(e.pool[i], f.pool[i])) << r.rule.name() << ": pool entry " << i;
          }
          ASSERT_EQ(x.value->conflicts, y.value->conflicts) << r.rule.name();
          ASSERT_EQ(x.value->written.size(), y.value->written.size()) << r.rule.name();
          for (std::size_t k = 0; k < x.value->written.size(); ++k) {
            ASSERT_EQ(x.value->written[k].dart, y.value->written[k].dart) << r.rule.name();
            ASSERT_TRUE(same_bits(x.value->written[k].value, y.value->written[k].value)) << r.rule.name();
          }
        }
        taken += a.kept_label_shortcuts().taken;
        failed += a.kept_label_shortcuts().refused;
        EXPECT_EQ(b.kept_label_shortcuts().taken + b.kept_label_shortcuts().refused, 0u) << r.rule.name();
      }
    }
  std::printf("kept-label shortcut: %zu applications and %zu refusals agree; taken %zu times, its check failed %zu times\n", applied, refused,
              taken, failed);
  EXPECT_GT(applied, 1000u);
  EXPECT_GT(taken, 500u);
  EXPECT_GT(failed, 100u);
}

// 003 Lemma 3 by its definition: an extended application is refused for
// overlap exactly when two instances of L in different pi-orbits of the
// instantiated L (classes by one union-find over every instance) match
// darts of one pi-orbit of G (orbits walked from each matched dart), for
// some embedding the rule labels. Every extended rule of the embedding and
// subdivision catalogs, consistent or not, on random embedded maps;
// applications refused before the check (no match, L's labels) are
// skipped.
TEST(EmbeddedRewriter, OverlapRefusalIsLemma3ByBruteForce) {
  std::mt19937 rng(29);
  std::size_t checked = 0, overlaps = 0;
  for (const Catalog* catalog : {&embedding_catalog(), &subdivision_catalog()})
    for (const auto& r : catalog->rules) {
      if (r.terms->instantiation != Instantiation::extended) continue;
      const TopoGraph& L = r.rule.left();
      for (int round = 0; round < 60; ++round) {
        EmbeddedMap g = embed_randomly(build_random_map(r.rule.model(), draw_recipe(rng, 1 + round % 8, 2)), catalog->signatures, rng);
        std::vector<Dart> hooks;
        for (std::size_t h = 0; h < r.rule.hooks().size(); ++h)
          hooks.push_back(std::uniform_int_distribution<Dart>(0, static_cast<Dart>(g.map.size() - 1))(rng));
        // The instances: dart[x][p], and the pattern of a scheme.
        std::vector<std::vector<Dart>> dart;
        std::optional<SchemeMatch> sm;
        if (r.words.scheme) {
          auto m = match_scheme(r.rule, r.words, g.map, hooks);
          if (!m.ok()) continue;
          sm = std::move(*m.value);
          dart = sm->node;
        } else {
          const auto m = match_from_hooks(r.rule, g.map, hooks);
          if (!m.ok()) continue;
          for (Dart d : m.value->node) dart.push_back({d});
        }
        const std::size_t np = dart[0].size();
        bool expected = false;
        OrbitWalker walker(g.map);
        InstantiatedClasses classes;
        for (const EmbeddingSignature* sig : r.terms->used()) {
          instantiated_classes_by_instance(L, r.words.left, sm ? &sm->pattern : nullptr, sig->orbit, classes);
          for (NodeId x = 0; x < L.node_count() && !expected; ++x)
            for (std::size_t p = 0; p < np && !expected; ++p) {
              const std::vector<Dart> orbit = walker.orbit(dart[x][p], dims_generators(sig->orbit));
              for (NodeId z = 0; z < L.node_count(); ++z)
                for (std::size_t q = 0; q < np; ++q)
                  expected = expected || (classes.of(x, p) != classes.of(z, q) && std::find(orbit.begin(), orbit.end(), dart[z][q]) != orbit.end());
            }
        }
        const auto a = Applier(r).apply(g, hooks, false);
        if (a.refusal == Refusal::label_mismatch || a.refusal == Refusal::no_value) continue;
        ASSERT_EQ(a.refusal == Refusal::overlap, expected) << r.rule.name() << ": " << a.why;
        ++checked;
        overlaps += expected;
      }
    }
  EXPECT_GT(checked, 300u);
  EXPECT_GT(overlaps, 20u);
  std::printf("%zu extended applications, %zu refused for overlap, as Lemma 3 says\n", checked, overlaps);
}

TEST(EmbeddingCatalog, FaceStretchingOverlapsOnATriangle) {
  // Fig. 33-34: on a square the two opposite half-edges are four vertices;
  // on a triangle two of their ends are one vertex (Lemma 3).
  const Operation& r = *embedding_catalog().find_rule("fig32-face-stretching");
  std::mt19937 rng(1);
  for (int n : {3, 4}) {
    Map m(Model::gmap(2), 2 * static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      m.sew(0, 2 * k, 2 * k + 1);
      m.sew(1, 2 * k + 1, (2 * k + 2) % (2 * n));
    }
    for (Dart d = 0; d < m.size(); ++d) m.sew(2, d, d);
    EmbeddedMap g = embed_randomly(std::move(m), {signatures[0]}, rng);
    const std::vector<Dart> hooks{0, 4};  // edges 0 and 2
    const auto d = Applier(r).apply(g, hooks);
    if (n == 3) {
      EXPECT_EQ(d.refusal, Refusal::overlap) << d.why;
    } else {
      ASSERT_TRUE(d.ok()) << d.why;
      EXPECT_TRUE(check_embedding(g.map, g.embeddings[0], true).consistent());
    }
  }
}

// --- Triangulation of a mesh ---------------------------------------------

TEST(EmbeddingApplication, TriangulatingAMeshPutsEachCentreAtItsFaceBarycenter) {
  const Operation& r = *embedding_catalog().find_rule("triangulation-jerboa-pos");
  for (const char* file : {"unit-square.off", "cube.off"}) {
    const Mesh mesh = read_mesh(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/meshes/" + file);
    EmbeddedMap g = mesh_with_positions(Model::gmap(2), mesh, signatures[0]);
    // The first dart of face f is the sum of the sizes of the faces before
    // it, doubled (build_surface); triangulation adds darts at the end, so
    // these numbers survive.
    Dart first = 0;
    for (const auto& f : mesh.faces) {
      std::array<double, 2> centre{};
      for (auto v : f)
        for (std::size_t k = 0; k < 2; ++k) centre[k] += mesh.positions[v][k] / static_cast<double>(f.size());
      const std::vector<Dart> hook{first};
      const auto d = Applier(r).apply(g, hook);
      ASSERT_TRUE(d.ok()) << d.why;
      std::size_t centres = 0;
      for (const auto& w : d.value->written) {
        if (w.node.rfind("n2@", 0) != 0) continue;
        EXPECT_NEAR(w.value.x[0], centre[0], 1e-12);
        EXPECT_NEAR(w.value.x[1], centre[1], 1e-12);
        ++centres;
      }
      EXPECT_EQ(centres, 2 * f.size());
      first += static_cast<Dart>(2 * f.size());
    }
    EXPECT_TRUE(check_map(g.map).valid());
    EXPECT_TRUE(check_embedding(g.map, g.embeddings[0], true).consistent());
    std::size_t triangles = 0;
    for (const auto& f : mesh.faces) triangles += f.size();
    EXPECT_EQ(count_cells(g.map).cells[2], triangles) << file;
  }
}

}  // namespace
}  // namespace dartcheck
