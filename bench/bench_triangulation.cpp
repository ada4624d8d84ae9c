// Face triangulation with barycentric positions (003 Fig. 20, issue 8) on a
// ~100,000-dart closed quad torus read from an OFF file, in one program:
//   - dartcheck: the embedding catalog's triangulation-jerboa-pos scheme
//     (n2 labeled center(pos<0,1>(n0))) applied by apply_embedded at one
//     dart of every face: match, term evaluation, non-overlap check,
//     rewrite, propagation of the new positions;
//   - CGAL: Linear_cell_complex_for_combinatorial_map<2,3>,
//     insert_barycenter_in_cell<2> on every face (topology + barycenter
//     point).
// Each peer runs in a child process ("peak MiB" is its own growth of the
// peak RSS while triangulating once); times are medians of --runs
// triangulations of a fresh copy (copy not timed). Both results are
// checked: dartcheck's map valid with a consistent pos embedding, CGAL's
// is_valid(), and both with four triangles per quad.
//
//   build/bench/bench_triangulation [--runs N] [--grid RxC]
#include <cstring>

#include <CGAL/Linear_cell_complex_constructors.h>
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>

#include "bench/peer_bench.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include "core/catalog.hpp"
#include "core/embedded_application.hpp"
#include "core/orbit.hpp"
#include "generators/mesh_map.hpp"

namespace {

using LCC = CGAL::Linear_cell_complex_for_combinatorial_map<2, 3>;

Result run_dartcheck(const std::string& off, int runs, std::size_t faces) {
  using namespace dartcheck;
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  const CatalogRule& s = *catalog.find_rule("triangulation-jerboa-pos");
  const EmbeddedMap input = mesh_with_positions(Model::gmap(2), read_mesh(off), s.terms->embeddings[0]);
  // One hook per face; triangulation only appends darts, so they stay valid.
  std::vector<Dart> hooks;
  {
    OrbitWalker walker(input.map);
    std::vector<bool> seen(input.map.size());
    const auto gens = dims_generators({0, 1});
    for (Dart d = 0; d < input.map.size(); ++d)
      if (!seen[d]) {
        hooks.push_back(d);
        for (Dart x : walker.orbit(d, gens)) seen[x] = true;
      }
  }
  return measure(runs, [&](double& ms, std::size_t& out) {
    EmbeddedMap g = input;
    bool ok = true;
    const auto t0 = std::chrono::steady_clock::now();
    for (Dart h : hooks) ok &= apply_embedded(s.rule, s.words, *s.terms, g, std::span(&h, 1), false).ok();
    ms = since(t0);
    out = g.map.size();
    return ok && count_cells(g.map).cells[2] == faces && check_map(g.map).valid() && check_embedding(g.map, g.embeddings[0], true).consistent();
  });
}

Result run_cgal(const std::string& off, int runs, std::size_t faces) {
  LCC input;
  std::ifstream in(off);
  CGAL::load_off(input, in);
  return measure(runs, [&](double& ms, std::size_t& out) {
    LCC m(input);
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<LCC::Dart_handle> one_per_face;
    for (auto it = m.one_dart_per_cell<2>().begin(); it != m.one_dart_per_cell<2>().end(); ++it) one_per_face.push_back(it);
    for (auto d : one_per_face) m.insert_barycenter_in_cell<2>(d);
    ms = since(t0);
    out = m.number_of_darts();
    return m.is_valid() && m.one_dart_per_cell<2>().size() == faces;
  });
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5, r = 148, c = 85;  // 148 x 85 quads: 100,640 G-map darts
  if (!torus_arguments(argc, argv, runs, r, c)) return 2;
  const std::string off = "/tmp/dartcheck-bench-triangulation-" + std::to_string(getpid()) + ".off";
  write_torus_off(off, r, c);
  std::printf("input: quad torus %dx%d: F=%d, %d G-map darts, %d CGAL darts; median of %d runs\n\n", r, c, r * c, 8 * r * c, 4 * r * c, runs);
  const std::size_t triangles = 4 * static_cast<std::size_t>(r * c);  // each quad becomes four triangles
  const Result d = run_in_child([&] { return run_dartcheck(off, runs, triangles); });
  const Result g = run_in_child([&] { return run_cgal(off, runs, triangles); });
  std::remove(off.c_str());
  std::printf("| peer | output darts | median ms | peak MiB | ms / CGAL | MiB / CGAL | result valid |\n|---|---|---|---|---|---|---|\n");
  for (const auto& [name, x] : {std::pair{"dartcheck triangulation-jerboa-pos (2-G-map, pos terms)", d}, std::pair{"CGAL LCC insert_barycenter_in_cell<2>", g}})
    std::printf("| %s | %zu | %.1f | %.1f | %.2fx | %.2fx | %s |\n", name, x.out_elements, x.median_ms, x.peak_mib, x.median_ms / g.median_ms,
                g.peak_mib > 0 ? x.peak_mib / g.peak_mib : 0.0, x.ok ? "yes" : "NO");
  return d.ok && g.ok ? 0 : 1;
}
