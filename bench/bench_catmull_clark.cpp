// Catmull-Clark subdivision with positions (issue 22) on a real mesh (by
// default CGAL's ChineseDragon-10kv: 19,994 triangles) or on a quad torus
// (--grid RxC), one iteration, in one program:
//   - dartcheck: the subdivision catalog's two schemes with their position
//     terms, each applied once per connected component (hook orbit
//     <0,1,2>): catmull-clark-points stores face points and edge
//     midpoints, catmull-clark subdivides and places every point; with
//     every instance evaluated (the dynamic check) and with one evaluation
//     per orbit (allowed: both rules pass (A)); and the topology alone
//     (the Applier on the map, catmull-clark, no terms), the floor of the rows;
//   - CGAL: Subdivision_method_3::CatmullClark_subdivision on a
//     Surface_mesh (PQQ refinement with CatmullClark_mask_3);
//   - OpenMesh: Subdivider::Uniform::CatmullClarkT on a PolyMesh with
//     double points, built from the parsed file.
// Each peer runs in a child process ("peak MiB" is its own growth of the
// peak RSS while subdividing once), all on one CPU (peer_bench.hpp's
// pin_to_one_cpu); times are medians of --runs
// subdivisions of a fresh copy (copy not timed). Every result is checked:
// a valid map or mesh with one quad per old edge side, and the same points
// as CGAL's (computed once in the parent) within 1e-9 of the input's
// bounding-box diagonal. Points on the boundary are counted, not compared:
// CGAL places an old boundary vertex at (A + 6V + B) / 8, OpenMesh at
// (4V + A + B) / 6, and the scheme has no boundary rule (a boundary edge
// reads its one face); the dragon has 6 boundary edges.
//
//   build/bench/bench_catmull_clark [--runs N] [--mesh FILE.off | --grid RxC] [--only TEXT]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include <fmt/format.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>

#include "bench/peer_bench.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include "core/orbit.hpp"
#include "generators/mesh_map.hpp"
#include "io/catalog.hpp"
#include "io/mesh_io.hpp"
#include "rewriting/application.hpp"

#include DARTCHECK_COMPILED_SUBDIVISION

namespace {

using Point = std::array<double, 3>;
using SurfaceMesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

// The output vertices' positions: interior ones to compare, boundary ones
// counted.
struct Points {
  std::vector<Point> interior;
  std::size_t boundary = 0;
};

struct Row {
  Result r;
  double deviation = std::numeric_limits<double>::infinity();  // max over matched points, max-norm
  std::size_t boundary = 0;
  bool has_points = true;  // false for the topology row: nothing compared
};

// The largest distance (max-norm) between matched points of a and b, or
// infinity when some point of a has no unused point of b within tol.
double deviation(const std::vector<Point>& a, std::vector<Point> b, double tol) {
  if (a.size() != b.size()) return std::numeric_limits<double>::infinity();
  std::sort(b.begin(), b.end());
  std::vector<bool> used(b.size());
  double worst = 0;
  for (const Point& p : a) {
    auto it = std::lower_bound(b.begin(), b.end(), Point{p[0] - tol, -std::numeric_limits<double>::infinity(), 0});
    bool found = false;
    for (; it != b.end() && (*it)[0] <= p[0] + tol; ++it) {
      const auto k = static_cast<std::size_t>(it - b.begin());
      double d = 0;
      for (std::size_t c = 0; c < 3; ++c) d = std::max(d, std::abs((*it)[c] - p[c]));
      if (used[k] || d > tol) continue;
      used[k] = found = true;
      worst = std::max(worst, d);
      break;
    }
    if (!found) return std::numeric_limits<double>::infinity();
  }
  return worst;
}

Points points_of(const SurfaceMesh& m) {
  Points out;
  for (auto v : m.vertices()) {
    if (m.is_border(v)) {
      ++out.boundary;
      continue;
    }
    const auto& p = m.point(v);
    out.interior.push_back({p.x(), p.y(), p.z()});
  }
  return out;
}

Points points_of(const PolyMesh& m) {
  Points out;
  for (auto v : m.vertices()) {
    if (m.is_boundary(v)) {
      ++out.boundary;
      continue;
    }
    const auto& p = m.point(v);
    out.interior.push_back({p[0], p[1], p[2]});
  }
  return out;
}

// One point per vertex (<1,2>-orbit); a vertex with a free 2-link is on
// the boundary.
Points points_of(const dartcheck::EmbeddedMap& g) {
  using namespace dartcheck;
  Points out;
  OrbitWalker walker(g.map);
  std::vector<bool> seen(g.map.size());
  const auto gens = dims_generators({1, 2});
  for (Dart d = 0; d < g.map.size(); ++d) {
    if (seen[d]) continue;
    bool border = false;
    for (Dart x : walker.orbit(d, gens)) {
      seen[x] = true;
      border |= g.map.link(2, x) == x;
    }
    const Value* v = g.embeddings[0].value(d);
    if (border)
      ++out.boundary;
    else if (v)
      out.interior.push_back(v->x);
  }
  return out;
}

const dartcheck::Catalog& subdivision_catalog() {
  static const dartcheck::Catalog c = dartcheck::read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/subdivision-operations.yaml");
  return c;
}

// The mesh with its positions and the two other embeddings, unlabeled.
dartcheck::EmbeddedMap subdivision_input(const std::string& off) {
  using namespace dartcheck;
  const Catalog& catalog = subdivision_catalog();
  EmbeddedMap input = mesh_with_positions(Model::gmap(2), read_mesh(off), catalog.signatures[0]);
  for (std::size_t k = 1; k < catalog.signatures.size(); ++k) input.add_embedding(catalog.signatures[k]);
  return input;
}

// The checks of a dartcheck row: a valid map of `quads` faces, positions
// consistent and total, the interior points CGAL's within tol.
bool subdivided(const dartcheck::EmbeddedMap& g, std::size_t quads, const Points& ref, double tol, Row& row) {
  using namespace dartcheck;
  if (count_cells(g.map).cells[2] != quads || !check_map(g.map).valid() || !check_embedding(g.map, g.embeddings[0], true).consistent()) return false;
  const Points p = points_of(g);
  row.deviation = deviation(p.interior, ref.interior, tol);
  row.boundary = p.boundary;
  return row.deviation <= tol && p.boundary == ref.boundary;
}

Row run_dartcheck(const std::string& off, int runs, std::size_t quads, dartcheck::Evaluation evaluation, const Points& ref, double tol) {
  using namespace dartcheck;
  const Catalog& catalog = subdivision_catalog();
  const CatalogRule &points = *catalog.find_rule("catmull-clark-points"), &cc = *catalog.find_rule("catmull-clark");
  const EmbeddedMap input = subdivision_input(off);
  const std::vector<Dart> hooks = orbit_hooks(input.map, {0, 1, 2});
  Row row;
  row.r = measure(runs, [&](double& ms, std::size_t& out) {
    EmbeddedMap g = input;
    bool ok = true;
    const auto t0 = std::chrono::steady_clock::now();
    // One rewriter per rule, each gone (with the tables it keeps for
    // further applications) before the next rule runs.
    {
      Applier first(points, {evaluation});
      for (Dart h : hooks) ok &= first.apply(g, std::span(&h, 1), false).ok();
    }
    {
      Applier second(cc, {evaluation});
      for (Dart h : hooks) ok &= second.apply(g, std::span(&h, 1), false).ok();
    }
    ms = since(t0);
    out = g.map.size();
    return ok && subdivided(g, quads, ref, tol, row);
  });
  return row;
}

// The two schemes compiled by `dartcheck compile` (issue 41): one
// evaluation per class, the same checks as the interpreter's rows.
Row run_compiled(const std::string& off, int runs, std::size_t quads, const Points& ref, double tol, bool everywhere) {
  using namespace dartcheck;
  const EmbeddedMap input = subdivision_input(off);
  const std::vector<Dart> hooks = orbit_hooks(input.map, {0, 1, 2});
  Row row;
  row.r = measure(runs, [&](double& ms, std::size_t& out) {
    EmbeddedMap g = input;
    bool ok = true;
    const auto t0 = std::chrono::steady_clock::now();
    {
      compiled::Workspace ws;
      if (everywhere) {  // positions are darts: no P_v walk, no hooks
        ok &= compiled_subdivision_operations::catmull_clark_points_everywhere(g, ws) == Refusal::none;
        ok &= compiled_subdivision_operations::catmull_clark_everywhere(g, ws) == Refusal::none;
      } else {
        for (Dart h : hooks) ok &= compiled_subdivision_operations::catmull_clark_points(g, std::span(&h, 1), ws) == Refusal::none;
        for (Dart h : hooks) ok &= compiled_subdivision_operations::catmull_clark(g, std::span(&h, 1), ws) == Refusal::none;
      }
    }
    ms = since(t0);
    out = g.map.size();
    return ok && subdivided(g, quads, ref, tol, row);
  });
  return row;
}

// The floor of the dartcheck rows: catmull-clark's topology alone.
Row run_topology(const std::string& off, int runs, std::size_t quads) {
  using namespace dartcheck;
  const CatalogRule& cc = *subdivision_catalog().find_rule("catmull-clark");
  const Map input = build_mesh(Model::gmap(2), read_mesh(off));
  const std::vector<Dart> hooks = orbit_hooks(input, {0, 1, 2});
  Row row;
  row.r = measure(runs, [&](double& ms, std::size_t& out) {
    Map g = input;
    bool ok = true;
    const auto t0 = std::chrono::steady_clock::now();
    {
      Applier rewriter(cc);
      for (Dart h : hooks) ok &= rewriter.apply(g, std::span(&h, 1)).ok();
    }
    ms = since(t0);
    out = g.size();
    return ok && count_cells(g).cells[2] == quads && check_map(g).valid();
  });
  row.has_points = false;
  return row;
}

SurfaceMesh read_surface_mesh(const std::string& off) {
  SurfaceMesh m;
  std::ifstream in(off);
  in >> m;
  return m;
}

void cgal_catmull_clark(SurfaceMesh& m) { CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(1)); }

Row run_cgal(const std::string& off, int runs, std::size_t quads, const Points& ref, double tol) {
  const SurfaceMesh input = read_surface_mesh(off);
  Row row;
  row.r = measure(runs, [&](double& ms, std::size_t& out) {
    SurfaceMesh m(input);
    const auto t0 = std::chrono::steady_clock::now();
    cgal_catmull_clark(m);
    ms = since(t0);
    out = m.number_of_halfedges();
    const Points p = points_of(m);
    row.deviation = deviation(p.interior, ref.interior, tol);
    row.boundary = p.boundary;
    return CGAL::is_valid_polygon_mesh(m) && m.number_of_faces() == quads && row.deviation <= tol && p.boundary == ref.boundary;
  });
  return row;
}

// Built from dartcheck's parse of the file: OpenMesh's OFF reader parses
// coordinates as floats (the torus's vertex points then move by 4e-8).
Row run_openmesh(const std::string& off, int runs, std::size_t quads, const Points& ref, double tol) {
  PolyMesh input;
  {
    const dartcheck::Mesh mesh = dartcheck::read_mesh(off);
    std::vector<PolyMesh::VertexHandle> v;
    for (const Point& p : mesh.positions) v.push_back(input.add_vertex(PolyMesh::Point(p[0], p[1], p[2])));
    for (const auto& f : mesh.faces) {
      std::vector<PolyMesh::VertexHandle> h;
      for (auto k : f) h.push_back(v[k]);
      if (!input.add_face(h).is_valid()) return {};
    }
  }
  Row row;
  row.r = measure(runs, [&](double& ms, std::size_t& out) {
    PolyMesh m(input);
    OpenMesh::Subdivider::Uniform::CatmullClarkT<PolyMesh> cc;
    const auto t0 = std::chrono::steady_clock::now();
    cc.attach(m);
    cc(1);
    cc.detach();
    ms = since(t0);
    out = m.n_halfedges();
    const Points p = points_of(m);
    row.deviation = deviation(p.interior, ref.interior, tol);
    row.boundary = p.boundary;
    return m.n_faces() == quads && row.deviation <= tol && p.boundary == ref.boundary;
  });
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  MeshInput input;
  if (!input.parse(argc, argv, DARTCHECK_BENCH_MESH, "catmull-clark")) return 2;
  const int runs = input.runs;
  const std::string &off = input.off, &only = input.only;
  // A k-gon becomes k quads: one per side (= its CGAL darts).
  std::size_t sides = 0;
  const dartcheck::Mesh mesh = dartcheck::read_mesh(off);
  for (const auto& f : mesh.faces) sides += f.size();
  Point low = mesh.positions.at(0), high = low;
  for (const auto& p : mesh.positions)
    for (std::size_t k = 0; k < 3; ++k) low[k] = std::min(low[k], p[k]), high[k] = std::max(high[k], p[k]);
  const double tol = 1e-9 * std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
  // The reference points: CGAL's, computed here once.
  SurfaceMesh reference_mesh = read_surface_mesh(off);
  cgal_catmull_clark(reference_mesh);
  const Points ref = points_of(reference_mesh);
  reference_mesh.clear();
  print_machine_line();
  std::printf(
      "input: %s: V=%zu, F=%zu, %zu G-map darts, %zu halfedges; output: %zu interior points compared with CGAL's (tolerance %.3g), "
      "%zu boundary points counted; median of %d runs\n\n",
      off.c_str(), mesh.positions.size(), mesh.faces.size(), 2 * sides, sides, ref.interior.size(), tol, ref.boundary, runs);

  using dartcheck::Evaluation;
  struct Peer {
    const char* name;
    const char* unit;
    std::function<Row()> run;
  };
  const std::vector<Peer> all_peers{
      {"dartcheck catmull-clark-points + catmull-clark, every instance evaluated", "darts",
       [&] { return run_dartcheck(off, runs, sides, Evaluation::every_instance, ref, tol); }},
      {"dartcheck catmull-clark-points + catmull-clark, one evaluation per orbit", "darts",
       [&] { return run_dartcheck(off, runs, sides, Evaluation::one_per_orbit, ref, tol); }},
      {"dartcheck catmull-clark, topology only (Applier on the map, no terms)", "darts", [&] { return run_topology(off, runs, sides); }},
      {"dartcheck compiled catmull-clark-points + catmull-clark", "darts", [&] { return run_compiled(off, runs, sides, ref, tol, false); }},
      {"dartcheck compiled, everywhere (positions are darts)", "darts", [&] { return run_compiled(off, runs, sides, ref, tol, true); }},
      {"OpenMesh CatmullClarkT, PolyMesh with double points", "halfedges", [&] { return run_openmesh(off, runs, sides, ref, tol); }},
      {"CGAL Subdivision_method_3::CatmullClark_subdivision, Surface_mesh", "halfedges", [&] { return run_cgal(off, runs, sides, ref, tol); }},
  };
  // --only keeps the peers whose name contains the text, and CGAL (the
  // ratios' base).
  std::vector<Peer> peers;
  for (const Peer& p : all_peers)
    if (only.empty() || std::strstr(p.name, only.c_str()) || &p == &all_peers.back()) peers.push_back(p);
  std::vector<Row> rows;
  for (const Peer& p : peers) rows.push_back(run_in_child<Row>(p.run));
  const Result& base = rows.back().r;
  bool ok = true;
  std::printf(
      "| peer | output | median ms | peak MiB | bytes / output element | ms / CGAL | max deviation | boundary points | result valid |\n"
      "|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < peers.size(); ++k) {
    const Row& x = rows[k];
    ok &= x.r.ok;
    const std::string deviation = x.has_points ? fmt::format("{:.2g}", x.deviation) : "-";
    const std::string boundary = x.has_points ? std::to_string(x.boundary) : "-";
    std::printf("| %s | %zu %s | %.1f | %.1f | %.0f | %.2fx | %s | %s | %s |\n", peers[k].name, x.r.out_elements, peers[k].unit, x.r.median_ms,
                x.r.peak_mib, x.r.out_elements ? x.r.peak_mib * 1048576.0 / static_cast<double>(x.r.out_elements) : 0.0,
                x.r.median_ms / base.median_ms, deviation.c_str(), boundary.c_str(), x.r.ok ? "yes" : "NO");
  }
  return ok ? 0 : 1;
}
