// Quad subdivision of a ~100,000-dart closed quad surface (002 Sec. 3.4,
// Example 25: 100,680 darts become 402,720), dartcheck's rule schemes
// against what a user would pick instead, on the same OFF input in one
// program:
//   - dartcheck: the seed catalog's quad-subdivision-gmap and -omap schemes
//     (an Applier at dart 0), topology only, interpreted and compiled by
//     `dartcheck compile` (issue 41; the header is generated at build time);
//   - CGAL: Linear_cell_complex_for_combinatorial_map<2,3>, the topological
//     part of the libcgal-demo's subdivide_lcc_pqq (insert_barycenter_in_cell
//     <1> on every edge, insert_barycenter_in_cell<2> on every face, then
//     remove_cell<1> on the spokes to the old vertices); the barycenters'
//     points come with it, the smoothing passes are left out;
//   - OpenMesh: Subdivider::Uniform::CatmullClarkT on a PolyMesh, which
//     cannot be split into topology and geometry (it moves every point).
// Each peer runs in its own child process (fork), so its peak resident
// memory is its own: "peak MiB" is the growth of the peak RSS while
// subdividing once, over the RSS with the input loaded. Times are medians of
// `--runs` subdivisions of a fresh copy of the input (copy not timed).
//
//   build/bench/bench_quad_subdivision [--runs N] [--grid RxC]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <CGAL/Linear_cell_complex_constructors.h>
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>

#include "checkers/map_validity.hpp"
#include "io/catalog.hpp"
#include "core/orbit.hpp"
#include "rewriting/application.hpp"
#include "generators/mesh_map.hpp"
#include "bench/peer_bench.hpp"
#include DARTCHECK_COMPILED_SEED

namespace {

// [--runs N] [--grid RxC]; false (after the usage line) on anything else.
bool torus_arguments(int argc, char** argv, int& runs, int& r, int& c) {
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--runs") && k + 1 < argc)
      runs = std::atoi(argv[++k]);
    else if (!std::strcmp(argv[k], "--grid") && k + 1 < argc)
      std::sscanf(argv[++k], "%dx%d", &r, &c);
    else {
      std::fprintf(stderr, "usage: %s [--runs N] [--grid RxC]\n", argv[0]);
      return false;
    }
  }
  return true;
}

using LCC = CGAL::Linear_cell_complex_for_combinatorial_map<2, 3>;
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

Result run_dartcheck(const std::string& off, const dartcheck::Model& model, const char* scheme, int runs) {
  using namespace dartcheck;
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  const CatalogRule& s = *catalog.find_rule(scheme);
  const Map input = load_mesh(model, off);
  return measure(runs, [&](double& ms, std::size_t& out) {
    Map g = input;
    const Dart hook = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const auto r = Applier(s).apply(g, std::span(&hook, 1));
    ms = since(t0);
    out = g.size();
    return r.ok() && check_map(g).valid();
  });
}

// The same scheme through its compiled function (a fresh Workspace per
// run, as a fresh Applier builds its tables per call).
template <class Compiled>
Result run_compiled(const std::string& off, const dartcheck::Model& model, Compiled apply, int runs) {
  using namespace dartcheck;
  const Map input = load_mesh(model, off);
  return measure(runs, [&](double& ms, std::size_t& out) {
    Map g = input;
    const Dart hook = 0;
    compiled::Workspace ws;
    const auto t0 = std::chrono::steady_clock::now();
    const Refusal r = apply(g, std::span(&hook, 1), ws);
    ms = since(t0);
    out = g.size();
    return r == Refusal::none && check_map(g).valid();
  });
}

// The topological part of CGAL's demo subdivide_lcc_pqq.
void cgal_pqq_topology(LCC& m) {
  LCC::size_type old = m.get_new_mark();
  LCC::size_type treated = m.get_new_mark();
  m.negate_mark(old);
  m.negate_mark(treated);
  for (auto it = m.darts().begin(); m.number_of_marked_darts(treated) > 0; ++it)
    if (m.is_marked(it, treated)) {
      CGAL::unmark_cell<LCC, 1>(m, it, treated);
      m.insert_barycenter_in_cell<1>(it);
    }
  std::vector<LCC::Dart_handle> remove;
  m.negate_mark(treated);
  for (auto it = m.darts().begin(); m.number_of_marked_darts(treated) > 0; ++it)
    if (m.is_marked(it, treated)) {
      CGAL::unmark_cell<LCC, 2>(m, it, treated);
      LCC::Dart_handle dc = m.insert_barycenter_in_cell<2>(it);
      for (auto it2 = m.one_dart_per_incident_cell<1, 0>(dc).begin(); it2 != m.one_dart_per_incident_cell<1, 0>(dc).end(); ++it2)
        if (m.is_marked(m.beta(it2, 1), old)) remove.push_back(it2);
      for (auto d : remove) m.remove_cell<1>(d);
      remove.clear();
    }
  m.negate_mark(treated);
  m.free_mark(treated);
  m.unmark_all(old);
  m.free_mark(old);
}

Result run_cgal(const std::string& off, int runs) {
  LCC input;
  std::ifstream in(off);
  CGAL::load_off(input, in);
  return measure(runs, [&](double& ms, std::size_t& out) {
    LCC m(input);
    const auto t0 = std::chrono::steady_clock::now();
    cgal_pqq_topology(m);
    ms = since(t0);
    out = m.number_of_darts();
    return m.is_valid();
  });
}

Result run_openmesh(const std::string& off, int runs) {
  PolyMesh input;
  if (!OpenMesh::IO::read_mesh(input, off)) return {};
  return measure(runs, [&](double& ms, std::size_t& out) {
    PolyMesh m(input);
    OpenMesh::Subdivider::Uniform::CatmullClarkT<PolyMesh> cc;
    const auto t0 = std::chrono::steady_clock::now();
    cc.attach(m);
    cc(1);
    cc.detach();
    ms = since(t0);
    out = m.n_halfedges();
    return m.n_faces() == 4 * input.n_faces();
  });
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5, r = 148, c = 85;  // 148 x 85 quads: 100,640 G-map darts
  if (!torus_arguments(argc, argv, runs, r, c)) return 2;
  const std::string off = "/tmp/dartcheck-bench-torus-" + std::to_string(getpid()) + ".off";
  write_torus_off(off, r, c);
  std::printf("input: quad torus %dx%d: V=%d E=%d F=%d, %d G-map darts, %d O-map darts; median of %d runs\n\n", r, c, r * c, 2 * r * c, r * c,
              8 * r * c, 4 * r * c, runs);

  struct Peer {
    const char* name;
    const char* unit;
    std::function<Result()> run;
  };
  const std::vector<Peer> peers{
      {"dartcheck 2-G-map scheme", "darts", [&] { return run_dartcheck(off, dartcheck::Model::gmap(2), "quad-subdivision-gmap", runs); }},
      {"dartcheck 2-O-map scheme", "darts", [&] { return run_dartcheck(off, dartcheck::Model::omap(2), "quad-subdivision-omap", runs); }},
      {"dartcheck 2-G-map scheme, compiled", "darts",
       [&] { return run_compiled(off, dartcheck::Model::gmap(2), &compiled_seed_operations::quad_subdivision_gmap, runs); }},
      {"dartcheck 2-O-map scheme, compiled", "darts",
       [&] { return run_compiled(off, dartcheck::Model::omap(2), &compiled_seed_operations::quad_subdivision_omap, runs); }},
      {"CGAL LCC pqq topology", "darts", [&] { return run_cgal(off, runs); }},
      {"OpenMesh Catmull-Clark", "halfedges", [&] { return run_openmesh(off, runs); }},
  };
  std::vector<Result> results;
  for (const auto& p : peers) results.push_back(run_in_child(p.run));
  std::remove(off.c_str());

  std::printf("| peer | output | median ms | peak MiB | ms / dartcheck 2-G | MiB / dartcheck 2-G | result valid |\n|---|---|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < peers.size(); ++k) {
    const auto& x = results[k];
    std::printf("| %s | %zu %s | %.1f | %.1f | %.2fx | %.2fx | %s |\n", peers[k].name, x.out_elements, peers[k].unit, x.median_ms, x.peak_mib,
                x.median_ms / results[0].median_ms, results[0].peak_mib > 0 ? x.peak_mib / results[0].peak_mib : 0.0, x.ok ? "yes" : "NO");
  }
  return std::all_of(results.begin(), results.end(), [](const Result& x) { return x.ok; }) ? 0 : 1;
}
