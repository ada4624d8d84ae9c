// Words, query words and matching (001 Sec. 3.3, 5). Oracles: dartcheck's
// isomorphism test (core/isomorphism, BFS codes tried from every dart) and
// a brute-force search over injective dart maps, which shares nothing with
// Algorithm 1's rigid propagation.
//
// Properties, on random 2-O-maps, open 3-O-maps (random 3-O-maps whose
// 3-fixed points become free links) and 2-G-maps:
//  - words: two connected maps are isomorphic iff some labelings give the
//    same word (001 Def. 4, after [17]);
//  - matching = isomorphism: a query whose free links all say ε matches a
//    connected map of its size from some dart iff the two are isomorphic;
//  - matching = brute force: from every start dart, Algorithm 1 finds a
//    match iff an injective map respecting every letter of the query word
//    exists, and then it is that map;
//  - trie = single queries: the prefix tree finds from each dart exactly
//    the matches of the queries taken one by one.
// RC_PARAMS="max_success=N" raises the number of cases (default 100).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <set>

#include "checkers/map_validity.hpp"
#include "core/isomorphism.hpp"
#include "generators/random_maps.hpp"
#include "tests/map_recipe_gen.hpp"
#include "querymodify/annotation.hpp"
#include "querymodify/overlap.hpp"

namespace dartcheck::querymodify {
namespace {

// The connected component of `start`, renumbered in BFS order.
Map component(const Map& g, Dart start) {
  const Labeling l = bfs_labeling(g, start);
  Map out(g.model(), l.darts.size());
  for (std::size_t k = 0; k < l.darts.size(); ++k)
    for (Dim i : g.model().dims) {
      const Dart e = g.link(i, l.darts[k]);
      if (e != no_dart) out.set_link(i, static_cast<Dart>(k), l.label[e] - 1);
    }
  return out;
}

// A random 3-O-map with its 3-fixed points made free: an open 3-O-map.
Map open_3omap(const MapRecipe& r) {
  const Map g = build_random_map(Model::omap(3), r);
  Map out(Model::open_omap(3), g.size());
  for (Dart d = 0; d < g.size(); ++d)
    for (Dim i : g.model().dims)
      if (const Dart e = g.link(i, d); !(i == 3 && e == d)) out.set_link(i, d, e);
  return out;
}

Map random_map(int kind, const MapRecipe& r) {
  if (kind == 0) return build_random_map(Model::omap(2), r);
  if (kind == 1) return open_3omap(r);
  return build_random_map(Model::gmap(2), r);
}

// The map with its darts renamed by a random permutation.
Map shuffled(const Map& g, std::vector<Dart>& perm, std::mt19937& rng) {
  perm.resize(g.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  Map out(g.model(), g.size());
  for (Dart d = 0; d < g.size(); ++d)
    for (Dim i : g.model().dims)
      if (const Dart e = g.link(i, d); e != no_dart) out.set_link(i, perm[d], perm[e]);
  return out;
}

// Brute force: every injective f from query labels to input darts with
// f(1) = start that respects every letter (labels: the input link is f of
// the query link; ε: free; ε̄: not free; ↔: free or outside the image;
// '*': anything), found by trying darts in index order.
std::vector<std::vector<Dart>> brute_force(const Map& input, const QueryWord& w, Dart start) {
  std::vector<std::vector<Dart>> found;
  std::vector<Dart> f(w.darts + 1, no_dart);
  std::vector<bool> used(input.size(), false);
  auto consistent = [&](bool complete) {
    for (std::uint32_t k = 1; k <= w.darts; ++k) {
      if (f[k] == no_dart) continue;
      for (std::size_t i = 0; i < w.dims.size(); ++i) {
        const std::uint32_t c = w.at(k, i);
        const bool free = is_free(input, w.dims[i], f[k]);
        const Dart e = free ? no_dart : input.link(w.dims[i], f[k]);
        if (c == static_cast<std::uint32_t>(BoundaryCondition::any)) continue;
        if (c == static_cast<std::uint32_t>(BoundaryCondition::boundary) && !free) return false;
        if (c == static_cast<std::uint32_t>(BoundaryCondition::interior) && free) return false;
        if (c == static_cast<std::uint32_t>(BoundaryCondition::no_connection)) {
          if (complete && !free && used[e]) return false;
          continue;
        }
        if (is_boundary_condition(c)) continue;
        if (free) return false;
        if (f[c] != no_dart && f[c] != e) return false;
      }
    }
    return true;
  };
  std::function<void(std::uint32_t)> place = [&](std::uint32_t k) {
    if (k > w.darts) {
      if (consistent(true)) found.emplace_back(f.begin() + 1, f.end());
      return;
    }
    for (Dart d = 0; d < input.size(); ++d) {
      if (used[d] || (k == 1 && d != start)) continue;
      f[k] = d;
      used[d] = true;
      if (consistent(false)) place(k + 1);
      used[d] = false;
      f[k] = no_dart;
    }
  };
  place(1);
  return found;
}

BoundaryCondition random_boundary_condition(std::mt19937& rng) {
  static const BoundaryCondition all[] = {BoundaryCondition::any, BoundaryCondition::boundary, BoundaryCondition::interior,
                                          BoundaryCondition::no_connection};
  return all[std::uniform_int_distribution<int>(0, 3)(rng)];
}

// A query: a random connected map with a random boundary condition on each free link.
QueryWord random_query(const Map& q, std::mt19937& rng) {
  std::vector<BoundaryOverride> o;
  for (Dart d = 0; d < q.size(); ++d)
    for (Dim i : q.model().dims)
      if (is_free(q, i, d)) o.push_back({d, i, random_boundary_condition(rng)});
  return query_word(q, 0, BoundaryCondition::any, o);
}

RC_GTEST_PROP(QueryWords, EqualWordsIffIsomorphic, ()) {
  const int kind = *rc::gen::inRange(0, 3);
  const auto ra = *gen_map_recipe(1, 3), rb = *gen_map_recipe(1, 3);
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  const Map a = component(random_map(kind, ra), 0);
  // b: a shuffled copy of a, or an unrelated map.
  std::vector<Dart> perm;
  const bool same = *rc::gen::arbitrary<bool>();
  const Map b = same ? shuffled(a, perm, rng) : component(random_map(kind, rb), 0);
  const auto wa = word(a, bfs_labeling(a, 0));
  bool equal = false;
  for (Dart d = 0; d < b.size() && !equal; ++d) equal = b.size() == a.size() && word(b, bfs_labeling(b, d)) == wa;
  RC_ASSERT(equal == isomorphic(a, b));
  if (same) RC_ASSERT(word(b, bfs_labeling(b, perm[0])) == wa);
  RC_CLASSIFY(equal, "isomorphic");
}

RC_GTEST_PROP(QueryMatching, BoundaryQueryMatchesIffIsomorphic, ()) {
  const int kind = *rc::gen::inRange(0, 3);
  const auto ra = *gen_map_recipe(1, 3), rb = *gen_map_recipe(1, 3);
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  const Map q = component(random_map(kind, ra), 0);
  const QueryWord w = query_word(q, 0, BoundaryCondition::boundary);
  std::vector<Dart> perm;
  const bool same = *rc::gen::arbitrary<bool>();
  const Map m = same ? shuffled(q, perm, rng) : component(random_map(kind, rb), 0);
  bool matched = false;
  for (Dart d = 0; d < m.size() && !matched; ++d) matched = m.size() == q.size() && annotate(m, w, d).has_value();
  RC_ASSERT(matched == isomorphic(q, m));
  RC_CLASSIFY(matched, "matched");
  if (same) {
    const auto found = annotate(m, w, perm[0]);
    RC_ASSERT(found.has_value());
    const Labeling l = bfs_labeling(q, 0);
    for (std::size_t k = 0; k < l.darts.size(); ++k) RC_ASSERT(found->darts[k] == perm[l.darts[k]]);
  }
}

RC_GTEST_PROP(QueryMatching, AlgorithmOneIsTheBruteForceMatch, ()) {
  const int kind = *rc::gen::inRange(0, 3);
  const auto rq = *gen_map_recipe(1, 2), rm = *gen_map_recipe(1, 3);
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  Map q = component(random_map(kind, rq), 0);
  RC_PRE(q.size() <= 8);
  const Map m = random_map(kind, rm);
  RC_PRE(m.size() <= 24);
  const QueryWord w = random_query(q, rng);
  std::size_t hits = 0;
  for (Dart d = 0; d < m.size(); ++d) {
    const auto alg = annotate(m, w, d);
    const auto brute = brute_force(m, w, d);
    RC_ASSERT(brute.size() <= 1u);  // maps are rigid: one dart fixes the match
    RC_ASSERT(alg.has_value() == !brute.empty());
    if (alg) {
      RC_ASSERT(alg->darts == brute[0]);
      ++hits;
    }
  }
  RC_CLASSIFY(hits > 0, "matched somewhere");
}

RC_GTEST_PROP(QueryTrie, TrieFindsWhatSingleQueriesFind, ()) {
  const int kind = *rc::gen::inRange(0, 3);
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  QueryTrie trie;
  std::vector<QueryWord> words;
  std::vector<Map> maps;
  const int count = *rc::gen::inRange(1, 6);
  for (int k = 0; k < count; ++k) {
    const Map q = component(random_map(kind, *gen_map_recipe(1, 2)), 0);
    maps.push_back(q);
    words.push_back(random_query(q, rng));
    trie.add(words.back(), k);
    if (*rc::gen::arbitrary<bool>()) {  // the same word twice: a terminal with two queries
      words.push_back(words.back());
      trie.add(words.back(), static_cast<int>(words.size()) - 1);
      ++k;
    }
  }
  // Half the inputs are a query's own map, renumbered: matches exist.
  std::vector<Dart> perm;
  const Map m = *rc::gen::arbitrary<bool>() ? shuffled(maps[0], perm, rng) : random_map(kind, *gen_map_recipe(1, 4));
  std::vector<bool> blocked(m.size(), false);
  for (Dart d = 0; d < m.size(); d += 5) blocked[d] = *rc::gen::arbitrary<bool>();
  std::size_t matches = 0;
  for (Dart d = 0; d < m.size(); ++d) {
    std::set<std::pair<int, std::vector<Dart>>> single, tree;
    for (std::size_t k = 0; k < words.size(); ++k)
      if (auto a = annotate(m, words[k], d, &blocked)) single.emplace(static_cast<int>(k), a->darts);
    for (auto& x : trie.match(m, d, &blocked)) tree.emplace(x.query, x.darts);
    RC_ASSERT(single == tree);
    matches += tree.size();
  }
  RC_CLASSIFY(matches > 0, "matches");
}

// The two strategies never select conflicting matches, and the global one
// always keeps the best-scored match.
RC_GTEST_PROP(QueryOverlap, StrategiesSelectDisjointMatches, ()) {
  const int kind = *rc::gen::inRange(0, 3);
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  QueryTrie trie;
  for (int k = 0; k < 3; ++k) trie.add(query_word(component(random_map(kind, *gen_map_recipe(1, 2)), 0), 0, BoundaryCondition::any), k);
  const Map m = random_map(kind, *gen_map_recipe(2, 6));
  for (const auto& chosen :
       {greedy_matches(m, trie), global_matches(m, trie, [](const QueryMatch& x) { return static_cast<double>(x.darts[0] % 7); })})
    for (std::size_t a = 0; a < chosen.size(); ++a)
      for (std::size_t b = a + 1; b < chosen.size(); ++b) RC_ASSERT(!conflict(chosen[a], chosen[b]));
  const auto all = all_matches(m, trie);
  if (!all.distinct.empty()) {
    const auto score = [](const QueryMatch& x) { return static_cast<double>(x.darts.size() * 100 + x.darts[0] % 7); };
    const auto best =
        *std::max_element(all.distinct.begin(), all.distinct.end(), [&](const QueryMatch& a, const QueryMatch& b) { return score(a) < score(b); });
    const auto chosen = global_matches(m, trie, score);
    RC_ASSERT(!chosen.empty());
    RC_ASSERT(score(chosen[0]) == score(best));
  }
  RC_CLASSIFY(!all.distinct.empty(), "matches");
}

// The boundary conditions of Fig. 3 on a triangle query whose 2-links are
// free, against a hand-made input: two triangles 2-sewn along all three
// sides (a closed surface), and one triangle whose darts 0 and 1 are
// 2-sewn to each other (so matching it would 2-link two matched darts).
TEST(QueryMatching, BoundaryConditionsOnATriangle) {
  Map q(Model::open_omap(2), 3);
  for (Dart d = 0; d < 3; ++d) q.sew(1, d, (d + 1) % 3);
  Map two(Model::open_omap(2), 6);
  for (Dart d = 0; d < 3; ++d) {
    two.sew(1, d, (d + 1) % 3);
    two.sew(1, 3 + d, 3 + (d + 2) % 3);
    two.sew(2, d, 3 + d);
  }
  ASSERT_TRUE(check_map(two).valid());
  EXPECT_TRUE(annotate(two, query_word(q, 0, BoundaryCondition::any), 0).has_value());
  EXPECT_TRUE(annotate(two, query_word(q, 0, BoundaryCondition::no_connection), 0).has_value());  // the other triangle is not matched
  EXPECT_FALSE(annotate(two, query_word(q, 0, BoundaryCondition::boundary), 0).has_value());      // the links are not free
  EXPECT_TRUE(annotate(two, query_word(q, 0, BoundaryCondition::interior), 0).has_value());
  // Darts blocked by an earlier greedy selection are annotated ∅: fine for
  // '↔' and '*', and never matched.
  const std::vector<bool> blocked{false, false, false, true, true, true};
  EXPECT_TRUE(annotate(two, query_word(q, 0, BoundaryCondition::no_connection), 0, &blocked).has_value());
  EXPECT_FALSE(annotate(two, query_word(q, 0, BoundaryCondition::any), 3, &blocked).has_value());

  Map folded(Model::open_omap(2), 3);
  for (Dart d = 0; d < 3; ++d) folded.sew(1, d, (d + 1) % 3);
  folded.sew(2, 0, 1);
  ASSERT_TRUE(check_map(folded).valid());
  EXPECT_TRUE(annotate(folded, query_word(q, 0, BoundaryCondition::any), 0).has_value());
  EXPECT_FALSE(annotate(folded, query_word(q, 0, BoundaryCondition::no_connection), 0).has_value());  // 0 -2- 1, both matched
  // Dart 2 is 2-free: 'ε' holds there only.
  const std::vector<BoundaryOverride> only2{{2, 2, BoundaryCondition::boundary}};
  EXPECT_FALSE(annotate(folded, query_word(q, 0, BoundaryCondition::boundary), 0).has_value());
  EXPECT_TRUE(annotate(folded, query_word(q, 0, BoundaryCondition::any, only2), 0).has_value());
}

}  // namespace
}  // namespace dartcheck::querymodify
