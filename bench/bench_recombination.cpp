// Tet -> hex recombination (001 Sec. 7.1) side by side with a vertex-based
// hex search written for this benchmark (the approach of HXT, Pellerin et
// al. 2018, whose code is not in Debian: 8 nested loops over mesh vertices
// joined by edges, then a look-up of the tetrahedra inside as a labeled
// subdivision of the hexahedron). dartcheck runs both of its searches: the
// word search of 001 (every query word from every dart, the definition)
// and its vertex search (hex_search.hpp, the default).
//
// Inputs: the paper's synthetic set-up (hexes cut into 5 tetrahedra, no new
// points), a 31^3 grid of 148,955 tetrahedra, the size of 001's Armadillo
// (149,675); and any TetGen/medit mesh given with --mesh (e.g. CGAL's
// elephant tetrahedralized by tetgen). Each row runs in its own child
// process (peak MiB is its own growth); times are medians of --runs.
// Every row is checked: each finds what an untimed reference finds, every
// peer hex is a dartcheck match and every other dartcheck match is
// explained (a further tetrahedron on its 8 vertices, or fewer than 8
// vertices), the vertex search finds exactly the word matches on 8
// distinct vertices, the recombined map has 36 darts per hex and 12 per
// tetrahedron, and the grid's recombination gives back every hex and no
// tetrahedron.
//
//   build/bench/bench_recombination [--runs 3] [--grid 31] [--mesh FILE.ele]
#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "io/tet_mesh_io.hpp"
#include "peer_bench.hpp"
#include "querymodify/hex_queries.hpp"
#include "querymodify/hex_search.hpp"
#include "querymodify/hex_subdivisions.hpp"
#include "querymodify/overlap.hpp"
#include "querymodify/recombination.hpp"

using namespace dartcheck;
using namespace dartcheck::querymodify;

namespace {

using Tets = std::vector<std::array<std::uint32_t, 4>>;
using HexSet = std::set<std::vector<std::uint32_t>>;  // each hex as its sorted tetrahedra

// n^3 unit hexes, each cut into 5 tetrahedra: the corner-cut pattern,
// reflected in x on odd cells so that shared faces split alike.
TetMesh five_tet_grid(std::uint32_t n) {
  TetMesh m;
  const std::uint32_t s = n + 1;
  for (std::uint32_t k = 0; k <= n; ++k)
    for (std::uint32_t j = 0; j <= n; ++j)
      for (std::uint32_t i = 0; i <= n; ++i) m.points.push_back({double(i), double(j), double(k)});
  // Corner v = x + 2y + 4z: the centre tetrahedron 0 3 5 6 and the four
  // corners it cuts off.
  const int pattern[5][4] = {{0, 3, 5, 6}, {1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}};
  for (std::uint32_t k = 0; k < n; ++k)
    for (std::uint32_t j = 0; j < n; ++j)
      for (std::uint32_t i = 0; i < n; ++i) {
        const int flip = static_cast<int>((i + j + k) & 1);
        for (const auto& t : pattern) {
          std::array<std::uint32_t, 4> tet{};
          for (int a = 0; a < 4; ++a) {
            const int c = t[a] ^ flip;
            tet[static_cast<std::size_t>(a)] = (i + (c & 1)) + s * ((j + ((c >> 1) & 1)) + s * (k + ((c >> 2) & 1)));
          }
          m.tets.push_back(tet);
        }
      }
  return m;
}

// The peer: for each vertex v0 and neighbours v1 < v2 < v4 (the three cube
// edges at corner 0, any assignment being a cube symmetry), corners 3, 5,
// 6 are common neighbours of two of them and 7 of 3, 5 and 6; v0 must be
// the smallest of the 8 so each hex is met once. The tetrahedra on the 8
// vertices must be a labeled subdivision (hex_subdivisions.hpp).
HexSet vertex_based_hexes(const TetMesh& m) {
  const std::size_t nv = m.points.size();
  std::vector<std::vector<std::uint32_t>> adj(nv), around(nv);
  for (std::uint32_t t = 0; t < m.tets.size(); ++t)
    for (int a = 0; a < 4; ++a) {
      around[m.tets[t][static_cast<std::size_t>(a)]].push_back(t);
      for (int b = 0; b < 4; ++b)
        if (a != b) adj[m.tets[t][static_cast<std::size_t>(a)]].push_back(m.tets[t][static_cast<std::size_t>(b)]);
    }
  for (auto& a : adj) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  auto linked = [&](std::uint32_t a, std::uint32_t b) { return std::binary_search(adj[a].begin(), adj[a].end(), b); };
  std::array<int, 256> index{};
  index.fill(-1);
  for (std::size_t k = 0; k < candidate_tets().size(); ++k) index[candidate_tets()[k]] = static_cast<int>(k);
  const auto& labeled = enumerate_hex_subdivisions();
  HexSet found;
  std::array<std::uint32_t, 8> v{};
  std::vector<std::uint32_t> inside;
  for (std::uint32_t v0 = 0; v0 < nv; ++v0) {
    const auto& n0 = adj[v0];
    for (std::size_t a = 0; a < n0.size(); ++a) {
      if (n0[a] < v0) continue;
      for (std::size_t b = a + 1; b < n0.size(); ++b)
        for (std::size_t c = b + 1; c < n0.size(); ++c) {
          v[0] = v0, v[1] = n0[a], v[2] = n0[b], v[4] = n0[c];
          for (std::uint32_t v3 : adj[v[1]]) {
            if (v3 <= v0 || v3 == v[2] || v3 == v[4] || !linked(v3, v[2])) continue;
            for (std::uint32_t v5 : adj[v[1]]) {
              if (v5 <= v0 || v5 == v3 || v5 == v[2] || v5 == v[4] || !linked(v5, v[4])) continue;
              for (std::uint32_t v6 : adj[v[2]]) {
                if (v6 <= v0 || v6 == v3 || v6 == v5 || v6 == v[1] || v6 == v[4] || !linked(v6, v[4])) continue;
                for (std::uint32_t v7 : adj[v3]) {
                  if (v7 <= v0 || v7 == v5 || v7 == v6 || v7 == v[1] || v7 == v[2] || v7 == v[4] || !linked(v7, v5) || !linked(v7, v6)) continue;
                  v[3] = v3, v[5] = v5, v[6] = v6, v[7] = v7;
                  // The tetrahedra on these 8 vertices, as corner masks.
                  std::uint64_t subdivision = 0;
                  bool ok = true;
                  inside.clear();
                  for (int corner = 0; corner < 8 && ok; ++corner)
                    for (std::uint32_t t : around[v[static_cast<std::size_t>(corner)]]) {
                      unsigned mask = 0;
                      for (std::uint32_t x : m.tets[t])
                        for (int q = 0; q < 8; ++q)
                          if (v[static_cast<std::size_t>(q)] == x) mask |= 1u << q;
                      if (std::popcount(mask) != 4) continue;  // not inside
                      if (index[mask] < 0)
                        ok = false;  // the 4 corners of one face
                      else
                        subdivision |= std::uint64_t{1} << index[mask], inside.push_back(t);
                    }
                  if (!ok || !std::binary_search(labeled.begin(), labeled.end(), subdivision)) continue;
                  std::sort(inside.begin(), inside.end());
                  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
                  found.insert(inside);
                }
              }
            }
          }
        }
    }
  }
  return found;
}

HexSet as_tet_sets(const std::vector<QueryMatch>& matches) {
  HexSet out;
  for (const auto& m : matches) {
    std::vector<std::uint32_t> tets;
    for (Dart d : m.darts) tets.push_back(d / 12);
    std::sort(tets.begin(), tets.end());
    tets.erase(std::unique(tets.begin(), tets.end()), tets.end());
    out.insert(tets);
  }
  return out;
}

ClassBound vertex_bound(const TetMap& t, std::vector<std::uint32_t>& counts) {
  counts.assign(*std::max_element(t.vertex.begin(), t.vertex.end()) + 1, 0);
  return {&t.vertex, 8, &counts};
}

QueryTrie hex_trie() {
  QueryTrie trie;
  for (std::size_t k = 0; k < hex_queries().size(); ++k) trie.add(hex_queries()[k].word, static_cast<int>(k));
  return trie;
}

struct Check {
  std::size_t ours = 0, peer = 0, extra_tet = 0, wrapped = 0, unexplained = 0, on_8 = 0, vertex_search = 0;
  bool peer_in_ours = false, searches_agree = false;
};

// The word matches whose query corners are 8 distinct mesh vertices.
HexSet on_8_vertices(const TetMap& t, const std::vector<QueryMatch>& matches) {
  std::vector<std::vector<std::uint32_t>> corners;
  for (const auto& q : hex_queries()) corners.push_back(query_corners(q));
  std::vector<QueryMatch> kept;
  for (const auto& m : matches) {
    const auto& q = hex_queries()[static_cast<std::size_t>(m.query)];
    const auto c = match_corners(q, corners[static_cast<std::size_t>(m.query)], m, t.vertex);
    if (std::set<std::uint32_t>(c.begin(), c.end()).size() == 8) kept.push_back(m);
  }
  return as_tet_sets(kept);
}

HexSet vertex_search_sets(const TetMesh& mesh) {
  const HexCandidates c = find_hex_candidates(mesh.tets, &mesh.points);
  HexSet out;
  for (const auto& h : c.list) {
    const auto t = c.tets_of(h);
    out.insert({t.begin(), t.end()});
  }
  return out;
}

void bench(const std::string& name, const TetMesh& mesh, int runs, bool is_grid) {
  const std::size_t tets = mesh.tets.size();
  // The timed rows first, each in its own child; the parent holds only the
  // mesh and the queries, so each child's peak RSS growth is its own.
  const TetMap reference = build_tet_map(mesh.tets, &mesh.points);
  const QueryTrie trie = hex_trie();
  // all_matches alone; `out` is the number of distinct matches.
  auto matching = [&](unsigned threads) {
    return measure(runs, [&](double& ms, std::size_t& out) {
      std::vector<std::uint32_t> c;
      const auto b = vertex_bound(reference, c);
      const auto t0 = std::chrono::steady_clock::now();
      out = all_matches(reference.map, trie, &b, threads).distinct.size();
      ms = since(t0);
      return true;
    });
  };
  struct Row {
    const char* name;
    std::function<Result()> run;
  };
  // The whole recombination: map, search, global selection, merge.
  auto recombining = [&](Search search) {
    bool ok = true;
    Result r = measure(runs, [&](double& ms, std::size_t& out) {
      const auto t0 = std::chrono::steady_clock::now();
      TetMap t = build_tet_map(mesh.tets, &mesh.points);
      const Recombination rec = recombine(t, hex_queries(), Strategy::global, &mesh.points, 0.0, search);
      ms = since(t0);
      out = rec.hexes;
      ok = ok && t.map.size() == 36 * rec.hexes + 12 * rec.tets && (!is_grid || rec.tets == 0);
      return true;
    });
    r.ok = ok;
    return r;
  };
  const std::vector<Row> rows{
      {"dartcheck word matching, 1 thread", [&] { return matching(1); }},
      {"dartcheck recombine, word search (map, match, global, merge)", [&] { return recombining(Search::words); }},
      {"dartcheck vertex search alone, 1 thread",
       [&] {
         return measure(runs, [&](double& ms, std::size_t& out) {
           const auto t0 = std::chrono::steady_clock::now();
           out = find_hex_candidates(mesh.tets, &mesh.points).list.size();
           ms = since(t0);
           return true;
         });
       }},
      {"dartcheck recombine, vertex search (map, search, global, merge), 1 thread", [&] { return recombining(Search::vertices); }},
      {"vertex-based peer (8 loops), 1 thread",
       [&] {
         std::size_t found = 0;
         Result r = measure(runs, [&](double& ms, std::size_t& out) {
           const auto t0 = std::chrono::steady_clock::now();
           found = vertex_based_hexes(mesh).size();
           ms = since(t0);
           out = found;
           return true;
         });
         r.ok = true;
         return r;
       }},
  };
  std::vector<Result> results;
  for (const auto& row : rows) results.push_back(run_in_child(row.run));
  // Untimed check, in a child too (the parent's peak RSS must stay low for
  // the next mesh's rows): the same hexes from both sides, and each row
  // found what the reference finds.
  const Check check = run_in_child<Check>([&] {
    Check c;
    std::vector<std::uint32_t> counts;
    const ClassBound bound = vertex_bound(reference, counts);
    const auto matches = all_matches(reference.map, trie, &bound).distinct;
    const HexSet ours = as_tet_sets(matches);
    const HexSet on_8 = on_8_vertices(reference, matches), searched = vertex_search_sets(mesh);
    c.on_8 = on_8.size();
    c.vertex_search = searched.size();
    c.searches_agree = on_8 == searched;
    const HexSet peer = vertex_based_hexes(mesh);
    c.ours = ours.size();
    c.peer = peer.size();
    // The two definitions differ: 001's match is a set of tetrahedra
    // isomorphic to a pattern (its boundary darts not 3-linked inside);
    // the peer's hex is 8 vertices whose tetrahedra are exactly a pattern.
    // So every peer hex must be a match, and every other match must have a
    // further mesh tetrahedron on its 8 vertices, or fewer than 8 vertices
    // (the pattern closes on itself: two corners at one mesh vertex, which
    // words cannot see).
    c.peer_in_ours = std::includes(ours.begin(), ours.end(), peer.begin(), peer.end());
    std::vector<std::vector<std::uint32_t>> around(mesh.points.size());
    for (std::uint32_t t = 0; t < tets; ++t)
      for (auto v : mesh.tets[t]) around[v].push_back(t);
    for (const auto& h : ours) {
      if (peer.count(h)) continue;
      std::set<std::uint32_t> vertices;
      for (auto t : h) vertices.insert(mesh.tets[t].begin(), mesh.tets[t].end());
      std::set<std::uint32_t> on_them;
      for (auto v : vertices)
        for (auto t : around[v])
          if (std::all_of(mesh.tets[t].begin(), mesh.tets[t].end(), [&](std::uint32_t x) { return vertices.count(x) > 0; })) on_them.insert(t);
      if (vertices.size() < 8)
        ++c.wrapped;
      else if (on_them.size() > h.size())
        ++c.extra_tet;
      else
        ++c.unexplained;
    }
    return c;
  });
  const bool agree = check.peer_in_ours && check.unexplained == 0 && check.searches_agree;
  results[0].ok = results[0].ok && results[0].out_elements == check.ours;
  results[2].ok = results[2].ok && results[2].out_elements == check.vertex_search;
  results[4].ok = results[4].ok && results[4].out_elements == check.peer;
  std::printf(
      "\n%s: %zu tetrahedra, %zu points; candidate hexes: dartcheck %zu, peer %zu; every peer hex a dartcheck match: %s; "
      "other dartcheck matches: %zu with a further tetrahedron on their 8 vertices, %zu on fewer than 8 vertices, %zu unexplained; "
      "word matches on 8 distinct vertices %zu, vertex-search candidates %zu, the same sets: %s\n\n",
      name.c_str(), tets, mesh.points.size(), check.ours, check.peer, check.peer_in_ours ? "yes" : "NO", check.extra_tet, check.wrapped,
      check.unexplained, check.on_8, check.vertex_search, check.searches_agree ? "yes" : "NO");
  std::printf("| run | found | median ms | tets / s | peak MiB | ms / peer | checked |\n|---|---|---|---|---|---|---|\n");
  const Result& p = results.back();
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Result& x = results[k];
    std::printf("| %s | %zu | %.1f | %.0f | %.1f | %.2fx | %s |\n", rows[k].name, x.out_elements, x.median_ms,
                x.median_ms > 0 ? 1000.0 * static_cast<double>(tets) / x.median_ms : 0.0, x.peak_mib,
                p.median_ms > 0 ? x.median_ms / p.median_ms : 0.0, x.ok && agree ? "yes" : "NO");
  }
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  std::uint32_t grid = 31;
  std::string mesh_file;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--runs"))
      runs = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--grid"))
      grid = static_cast<std::uint32_t>(std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--mesh"))
      mesh_file = argv[i + 1];
  }
  // The 322 queries are built once, before the children fork (about 3 s,
  // a constant of the method, not of the mesh).
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t q = hex_queries().size();
  std::printf("%zu hex queries built in %.1f s (once per process, not in the rows)\n", q, since(t0) / 1000);
  std::printf("001 Table 1, Armadillo (149,675 tetrahedra): Q&M 205.8 s = 727 tets/s; HXT 4.26 s = 35,135 tets/s\n");
  bench(fmt::format("5-tetrahedra grid {}^3", grid), five_tet_grid(grid), runs, true);
  if (!mesh_file.empty()) bench(mesh_file, read_tet_mesh(mesh_file), runs, false);
  return 0;
}
