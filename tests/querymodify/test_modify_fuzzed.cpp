// The modify operations of 001 Sec. 6 on fuzzed hosts (RapidCheck, 100
// cases each): random tetrahedral complexes, a random part of a grid of
// unit cubes cut into 5 tetrahedra, each as an open 3-O-map oriented by
// volume. Theorem tested: every modify result is a valid 3-map
// (check_3map), with the dart and volume counts its operation implies
// (12 darts per tetrahedron): delete removes its volumes, extend adds the
// target's new tetrahedron glued to the matched face, and replace (the
// 2-3 flip: two tetrahedra sharing a face -> three around the edge of
// their apexes, the same 6 boundary triangles) trades 2 volumes for 3.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "core/orbit.hpp"
#include "querymodify/map_checks.hpp"
#include "map_counts.hpp"
#include "querymodify/modify.hpp"
#include "querymodify/overlap.hpp"
#include "querymodify/tet_map.hpp"

namespace dartcheck::querymodify {
namespace {

using test::free3;
using test::volumes;

// An n^3 grid of unit cubes cut into 5 tetrahedra (the corner-cut pattern,
// mirrored on odd cells), each tetrahedron kept with probability 3/4.
// Drawn from a seed: RapidCheck's small sizes would keep none.
TetMap random_host(std::uint32_t n, std::mt19937& rng) {
  std::vector<std::array<double, 3>> points;
  const std::uint32_t s = n + 1;
  for (std::uint32_t k = 0; k <= n; ++k)
    for (std::uint32_t j = 0; j <= n; ++j)
      for (std::uint32_t i = 0; i <= n; ++i) points.push_back({double(i), double(j), double(k)});
  const int pattern[5][4] = {{0, 3, 5, 6}, {1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}};
  std::vector<std::array<std::uint32_t, 4>> tets;
  for (std::uint32_t k = 0; k < n; ++k)
    for (std::uint32_t j = 0; j < n; ++j)
      for (std::uint32_t i = 0; i < n; ++i)
        for (const auto& t : pattern) {
          if (rng() % 4 == 0) continue;
          const int flip = static_cast<int>((i + j + k) & 1);
          std::array<std::uint32_t, 4> tet{};
          for (int a = 0; a < 4; ++a) {
            const int c = t[a] ^ flip;
            tet[static_cast<std::size_t>(a)] = (i + (c & 1)) + s * ((j + ((c >> 1) & 1)) + s * (k + ((c >> 2) & 1)));
          }
          tets.push_back(tet);
        }
  if (tets.empty()) tets.push_back({0, 1, s, s * s});
  return build_tet_map(tets, &points);
}

std::vector<QueryMatch> matches_of(const Map& host, const QueryWord& w) {
  QueryTrie trie;
  trie.add(w, 0);
  return all_matches(host, trie, nullptr, 1).distinct;
}

RC_GTEST_PROP(ModifyOnFuzzedHosts, DeleteLeavesAValidMap, ()) {
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  TetMap host = random_host(2, rng);
  const std::size_t n = host.tets.size();
  std::vector<Dart> gone;
  std::size_t deleted = 0;
  for (std::size_t t = 0; t < n; ++t)
    if (rng() & 1) {
      ++deleted;
      for (Dart d = 0; d < 12; ++d) gone.push_back(static_cast<Dart>(12 * t + d));
    }
  delete_volumes(host.map, gone);
  RC_ASSERT(check_3map(host.map).valid());
  RC_ASSERT(host.map.size() == 12 * (n - deleted));
  RC_ASSERT(volumes(host.map) == n - deleted);
}

RC_GTEST_PROP(ModifyOnFuzzedHosts, ExtendGluesTheNewTetrahedron, ()) {
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  TetMap host = random_host(2, rng);
  const std::size_t before = host.map.size(), before_volumes = volumes(host.map);
  // Q: one tetrahedron; T: Q and a second one on its face 1 2 3. Built
  // alike, T's first tetrahedron is Q dart for dart (m_QT = identity).
  const std::vector<std::array<double, 3>> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  const TetMap q = build_tet_map({{0, 1, 2, 3}}, &p), t = build_tet_map({{0, 1, 2, 3}, {1, 2, 3, 4}}, &p);
  std::vector<Dart> q_to_t(q.map.size());
  std::vector<BoundaryOverride> free_face;
  for (Dart d = 0; d < q.map.size(); ++d) {
    q_to_t[d] = d;
    if (t.map.link(3, d) != no_dart) free_face.push_back({d, 3, BoundaryCondition::boundary});  // ε: the face must be free in the host
  }
  RC_ASSERT(free_face.size() == 3u);
  const Dart start = static_cast<Dart>(rng() % 12);
  const std::size_t before_free = free3(host.map);
  const auto matches = matches_of(host.map, query_word(q.map, start, BoundaryCondition::any, free_face));
  RC_PRE(!matches.empty());  // every host with a boundary face has one
  const QueryMatch& m = matches[rng() % matches.size()];
  const auto q_to_m = query_to_input(q.map, start, m);
  const auto t_to_m = extend(host.map, q.map, t.map, q_to_t, q_to_m);
  RC_ASSERT(check_3map(host.map).valid());
  RC_ASSERT(host.map.size() == before + 12);
  RC_ASSERT(volumes(host.map) == before_volumes + 1);
  RC_ASSERT(free3(host.map) == before_free - 3 + 9);  // the glued face, the new tetrahedron's other three
  for (Dart d = 0; d < 12; ++d)
    if (t.map.link(3, d) != no_dart) RC_ASSERT(host.map.link(3, q_to_m[d]) == t_to_m[t.map.link(3, d)]);
}

RC_GTEST_PROP(ModifyOnFuzzedHosts, ReplaceFlipsTwoTetrahedraIntoThree, ()) {
  std::mt19937 rng(*rc::gen::arbitrary<std::uint32_t>());
  TetMap host = random_host(2, rng);
  const std::size_t before = host.map.size(), before_volumes = volumes(host.map);
  // a b c the shared triangle, d and e the apexes; T: three tetrahedra
  // around d-e. Both oriented by the same points, so a boundary dart u -> v
  // of Q is the boundary dart u -> v of T.
  const std::vector<std::array<double, 3>> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1}, {0.3, 0.3, -1}};
  const TetMap q = build_tet_map({{0, 1, 2, 3}, {0, 1, 2, 4}}, &p);
  const TetMap t = build_tet_map({{0, 1, 3, 4}, {1, 2, 3, 4}, {2, 0, 3, 4}}, &p);
  std::map<std::pair<std::uint32_t, std::uint32_t>, Dart> t_boundary;
  for (Dart d = 0; d < t.map.size(); ++d)
    if (t.map.link(3, d) == no_dart) t_boundary[{t.vertex[d], t.vertex[t.map.link(1, d)]}] = d;
  RC_ASSERT(t_boundary.size() == 18u);  // 6 triangles
  std::vector<Dart> q_to_t(q.map.size(), 0);
  for (Dart d = 0; d < q.map.size(); ++d)
    if (q.map.link(3, d) == no_dart) q_to_t[d] = t_boundary.at({q.vertex[d], q.vertex[q.map.link(1, d)]});
  const Dart start = static_cast<Dart>(rng() % 24);
  const std::size_t before_free = free3(host.map);
  const auto matches = matches_of(host.map, query_word(q.map, start, BoundaryCondition::any));
  RC_PRE(!matches.empty());
  const QueryMatch& m = matches[rng() % matches.size()];
  replace(host.map, q.map, t.map, q_to_t, query_to_input(q.map, start, m));
  RC_ASSERT(check_3map(host.map).valid());
  RC_ASSERT(free3(host.map) == before_free);  // the boundary is kept, links to the outside too
  RC_ASSERT(host.map.size() == before + 12);
  RC_ASSERT(volumes(host.map) == before_volumes + 1);
}

// Extending at a face that is not free is refused before anything changes
// (001: the darts receiving a new volume must be 3-free).
TEST(Modify, ExtendRefusesASewnFace) {
  const std::vector<std::array<double, 3>> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  TetMap host = build_tet_map({{0, 1, 2, 3}, {1, 2, 3, 4}}, &p);
  const Map before = host.map;
  const TetMap q = build_tet_map({{0, 1, 2, 3}}, &p), t = build_tet_map({{0, 1, 2, 3}, {1, 2, 3, 4}}, &p);
  std::vector<Dart> identity(12);
  for (Dart d = 0; d < 12; ++d) identity[d] = d;
  EXPECT_THROW(extend(host.map, q.map, t.map, identity, identity), ValueError);
  EXPECT_EQ(host.map, before);
}

}  // namespace
}  // namespace dartcheck::querymodify
