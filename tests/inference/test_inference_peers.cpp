// Peers as independent oracles (issue 23): CGAL's Subdivision_method_3
// and OpenMesh's uniform subdividers produce the after meshes. dartcheck
// infers a rule from the peer's result on a small mesh, applies it to
// other meshes (CGAL's data archive), and compares the result with the
// peer's output on those meshes, by a BFS code rooted at dart 0 and its
// image. CGAL and OpenMesh headers live in this one translation unit.
//
// κ comes from the peers' own bookkeeping: they keep the old vertices
// (same indices, moved points) and add the new ones after them, so an old
// dart (face f, at v, towards w) is found in the after mesh as the dart at
// v in the face that holds v's two new neighbours on the sides v-w and
// v-u of f (Catmull-Clark, Loop: the edge points; sqrt3: the centres of
// f and of the face across v-w).
// Not covered: Doo-Sabin (CGAL) and OpenMesh's midpoint subdivider, which
// keep no old vertex, so κ would have to come from the geometry.
#include <gtest/gtest.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>

#include <set>

#include "checkers/map_validity.hpp"
#include "core/isomorphism.hpp"
#include "inference_support.hpp"
#include "io/mesh_io.hpp"
#include "soup_subdivision.hpp"

namespace dartcheck::inference::test {
namespace {

struct Soup {
  std::vector<std::array<double, 3>> points;
  std::vector<Polygon> faces;
};

Soup mesh(const std::string& name) {
  const Mesh m = read_mesh(std::string(DARTCHECK_MESH_DIR) + "/" + name);
  return {m.positions, m.faces};
}

// ---- CGAL ----------------------------------------------------------------
using Kernel = CGAL::Simple_cartesian<double>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

enum class Method { catmull_clark, loop, sqrt3 };

Soup cgal(const Soup& in, Method method) {
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> v;
  for (const auto& p : in.points) v.push_back(sm.add_vertex({p[0], p[1], p[2]}));
  for (const auto& f : in.faces) {
    std::vector<SurfaceMesh::Vertex_index> h;
    for (auto i : f) h.push_back(v[i]);
    if (sm.add_face(h) == SurfaceMesh::null_face()) throw std::runtime_error("CGAL refused a face");
  }
  namespace sub = CGAL::Subdivision_method_3;
  if (method == Method::catmull_clark) sub::CatmullClark_subdivision(sm, CGAL::parameters::number_of_iterations(1));
  if (method == Method::loop) sub::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(1));
  if (method == Method::sqrt3) sub::Sqrt3_subdivision(sm, CGAL::parameters::number_of_iterations(1));
  // sqrt3 flips edges by removing and adding faces: compact the face and
  // halfedge arrays (no vertex is removed, so vertex indices stay).
  const std::size_t vertices = sm.number_of_vertices();
  sm.collect_garbage();
  if (sm.number_of_vertices() != vertices) throw std::runtime_error("CGAL removed a vertex");
  Soup out;
  for (auto vi : sm.vertices()) {
    const auto& p = sm.point(vi);
    if (vi.idx() != out.points.size()) throw std::runtime_error("CGAL vertex indices are not dense");
    out.points.push_back({p.x(), p.y(), p.z()});
  }
  for (auto f : sm.faces()) {
    Polygon poly;
    for (auto vi : CGAL::vertices_around_face(sm.halfedge(f), sm)) poly.push_back(static_cast<std::uint32_t>(vi.idx()));
    out.faces.push_back(poly);
  }
  return out;
}

// ---- OpenMesh ------------------------------------------------------------
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

template <class M>
M openmesh_from(const Soup& in) {
  M m;
  std::vector<typename M::VertexHandle> v;
  for (const auto& p : in.points)
    v.push_back(m.add_vertex(typename M::Point(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]))));
  for (const auto& f : in.faces) {
    std::vector<typename M::VertexHandle> h;
    for (auto i : f) h.push_back(v[i]);
    if (!m.add_face(h).is_valid()) throw std::runtime_error("OpenMesh refused a face");
  }
  return m;
}

template <class M>
Soup soup_of(M& m) {
  m.garbage_collection();
  Soup out;
  for (auto vh : m.vertices()) {
    const auto p = m.point(vh);
    out.points.push_back({p[0], p[1], p[2]});
  }
  for (auto fh : m.faces()) {
    Polygon poly;
    for (auto vh : m.fv_range(fh)) poly.push_back(static_cast<std::uint32_t>(vh.idx()));
    out.faces.push_back(poly);
  }
  return out;
}

Soup openmesh(const Soup& in, Method method) {
  if (method == Method::catmull_clark) {
    PolyMesh m = openmesh_from<PolyMesh>(in);
    OpenMesh::Subdivider::Uniform::CatmullClarkT<PolyMesh> s;
    s.attach(m);
    s(1);
    s.detach();
    return soup_of(m);
  }
  TriMesh m = openmesh_from<TriMesh>(in);
  if (method == Method::loop) {
    OpenMesh::Subdivider::Uniform::LoopT<TriMesh> s;
    s.attach(m);
    s(1);
    s.detach();
  } else {
    OpenMesh::Subdivider::Uniform::Sqrt3T<TriMesh> s;
    s.attach(m);
    s(1);
    s.detach();
  }
  return soup_of(m);
}

// ---- κ from the peers' vertex bookkeeping ----------------------------------
struct Adjacency {
  std::vector<std::set<std::uint32_t>> next;
  explicit Adjacency(const Soup& s) : next(s.points.size()) {
    for (const auto& f : s.faces)
      for (std::size_t i = 0; i < f.size(); ++i) {
        next[f[i]].insert(f[(i + 1) % f.size()]);
        next[f[(i + 1) % f.size()]].insert(f[i]);
      }
  }
};

// The new vertex adjacent to every vertex of `near` (and unique so).
std::uint32_t new_vertex_adjacent(const Adjacency& a, std::uint32_t old_count, const std::vector<std::uint32_t>& near) {
  std::uint32_t found = no_dart;
  for (auto x : a.next[near[0]]) {
    if (x < old_count) continue;
    bool all = true;
    for (auto y : near) all = all && a.next[y].count(x);
    if (all) {
      if (found != no_dart) throw std::runtime_error("two new vertices qualify");
      found = x;
    }
  }
  if (found == no_dart) throw std::runtime_error("no new vertex qualifies: the peer renumbered the old vertices");
  return found;
}

// The face of `s` that has v between x and y (in either order).
std::uint32_t face_with_corner(const Soup& s, std::uint32_t v, std::uint32_t x, std::uint32_t y) {
  for (std::uint32_t f = 0; f < s.faces.size(); ++f) {
    const auto& p = s.faces[f];
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p[i] == v) {
        const auto a = p[(i + 1) % p.size()], b = p[(i + p.size() - 1) % p.size()];
        if ((a == x && b == y) || (a == y && b == x)) return f;
      }
  }
  throw std::runtime_error("no face has that corner");
}

// κ: before dart (f, v -> w) to after dart; u is v's other neighbour in f.
std::vector<std::pair<SoupDart, SoupDart>> peer_kappa(const Soup& before, const Soup& after, Method method) {
  const Adjacency adj(after);
  const auto old = static_cast<std::uint32_t>(before.points.size());
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> across;  // directed side -> face
  for (std::uint32_t f = 0; f < before.faces.size(); ++f)
    for (std::size_t i = 0; i < before.faces[f].size(); ++i) across[{before.faces[f][i], before.faces[f][(i + 1) % before.faces[f].size()]}] = f;
  std::vector<std::pair<SoupDart, SoupDart>> out;
  for (std::uint32_t f = 0; f < before.faces.size(); ++f) {
    const auto& p = before.faces[f];
    const std::size_t k = p.size();
    for (std::size_t i = 0; i < k; ++i)
      for (int dir = 0; dir < 2; ++dir) {
        const auto v = p[i], w = p[dir ? (i + k - 1) % k : (i + 1) % k], u = p[dir ? (i + 1) % k : (i + k - 1) % k];
        std::uint32_t xw, xu;
        if (method == Method::sqrt3) {
          xw = new_vertex_adjacent(adj, old, p);  // the centre of f
          const auto g = across.at({w, v}) == f ? across.at({v, w}) : across.at({w, v});
          xu = new_vertex_adjacent(adj, old, before.faces[g]);  // the centre across v-w
        } else {
          xw = new_vertex_adjacent(adj, old, {v, w});
          xu = new_vertex_adjacent(adj, old, {v, u});
        }
        out.push_back({{f, v, w}, {face_with_corner(after, v, xw, xu), v, xw}});
      }
  }
  return out;
}

// The number of faces a method must give, by hand: Catmull-Clark one quad
// per face corner, Loop four triangles per triangle, sqrt3 three.
std::size_t expected_faces(const Soup& s, Method method) {
  std::size_t corners = 0;
  for (const auto& f : s.faces) corners += f.size();
  return method == Method::catmull_clark ? corners : method == Method::loop ? 4 * s.faces.size() : 3 * s.faces.size();
}

// And vertices, on a closed mesh (E = corners / 2): Catmull-Clark
// V + E + F, Loop V + E, sqrt3 V + F.
std::size_t expected_vertices(const Soup& s, Method method) {
  std::size_t corners = 0;
  for (const auto& f : s.faces) corners += f.size();
  const std::size_t v = s.points.size(), e = corners / 2, f = s.faces.size();
  return method == Method::catmull_clark ? v + e + f : method == Method::loop ? v + e : v + f;
}

Attempt infer_from_peer(const Soup& small, const Soup& after, Method method) {
  EXPECT_EQ(after.faces.size(), expected_faces(small, method));
  EXPECT_EQ(after.points.size(), expected_vertices(small, method));
  KappaSpec k;
  for (const auto& [b, a] : peer_kappa(small, after, method)) k.pairs.emplace_back(soup_dart(small.faces, b), soup_dart(after.faces, a));
  const Model m = Model::gmap(2);
  const auto graph = make_kappa_graph(build_surface(m, small.faces), build_surface(m, after.faces), k);
  auto attempts = infer(graph, {0, 1, 2}, {});
  for (auto& a : attempts)
    if (a.inferred()) return std::move(a);
  ADD_FAILURE() << "nothing inferred: " << (attempts.back().failure ? attempts.back().failure->text : attempts.back().not_a_rule);
  return {};
}

// The inferred rule on `mesh` against the peer's output on it.
void expect_like_peer(const Attempt& a, const Soup& mesh, const Soup& peer_after, Method method, const std::string& what) {
  ASSERT_TRUE(a.rule) << what;
  ASSERT_EQ(peer_after.faces.size(), expected_faces(mesh, method)) << what;
  ASSERT_EQ(peer_after.points.size(), expected_vertices(mesh, method)) << what;
  const Model m = Model::gmap(2);
  const Map h = applied(a.rule->operation, build_surface(m, mesh.faces), 0);
  ASSERT_TRUE(check_map(h).valid()) << what;
  const Map peer = build_surface(m, peer_after.faces);
  ASSERT_EQ(h.size(), peer.size()) << what;
  Dart root = no_dart;
  const SoupDart zero{0, mesh.faces[0][0], mesh.faces[0][1]};
  for (const auto& [b, after] : peer_kappa(mesh, peer_after, method))
    if (b.face == zero.face && b.at == zero.at && b.to == zero.to) root = soup_dart(peer_after.faces, after);
  ASSERT_NE(root, no_dart) << what;
  EXPECT_EQ(component_code(h, 0), component_code(peer, root)) << what;
}

Soup tetrahedron() { return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, tetrahedron_faces()}; }

TEST(InferencePeers, CgalCatmullClark) {
  const Soup small = mesh("cube_quad.off");
  const Attempt a = infer_from_peer(small, cgal(small, Method::catmull_clark), Method::catmull_clark);
  const Soup torus = mesh("torus_quad.off");
  expect_like_peer(a, torus, cgal(torus, Method::catmull_clark), Method::catmull_clark, "torus_quad.off");
  const Soup elephant = mesh("elephant.off");  // triangles: Catmull-Clark makes quads of any face
  expect_like_peer(a, elephant, cgal(elephant, Method::catmull_clark), Method::catmull_clark, "elephant.off");
}

TEST(InferencePeers, CgalLoop) {
  const Soup small = tetrahedron();
  const Attempt a = infer_from_peer(small, cgal(small, Method::loop), Method::loop);
  const Soup elephant = mesh("elephant.off");
  expect_like_peer(a, elephant, cgal(elephant, Method::loop), Method::loop, "elephant.off");
}

TEST(InferencePeers, CgalSqrt3) {
  const Soup small = tetrahedron();
  const Attempt a = infer_from_peer(small, cgal(small, Method::sqrt3), Method::sqrt3);
  const Soup elephant = mesh("elephant.off");
  expect_like_peer(a, elephant, cgal(elephant, Method::sqrt3), Method::sqrt3, "elephant.off");
}

TEST(InferencePeers, OpenMeshCatmullClark) {
  const Soup small = mesh("cube_quad.off");
  const Attempt a = infer_from_peer(small, openmesh(small, Method::catmull_clark), Method::catmull_clark);
  const Soup torus = mesh("torus_quad.off");
  expect_like_peer(a, torus, openmesh(torus, Method::catmull_clark), Method::catmull_clark, "torus_quad.off");
}

TEST(InferencePeers, OpenMeshLoop) {
  const Soup small = tetrahedron();
  const Attempt a = infer_from_peer(small, openmesh(small, Method::loop), Method::loop);
  const Soup elephant = mesh("elephant.off");
  expect_like_peer(a, elephant, openmesh(elephant, Method::loop), Method::loop, "elephant.off");
}

TEST(InferencePeers, OpenMeshSqrt3) {
  const Soup small = tetrahedron();
  const Attempt a = infer_from_peer(small, openmesh(small, Method::sqrt3), Method::sqrt3);
  const Soup elephant = mesh("elephant.off");
  expect_like_peer(a, elephant, openmesh(elephant, Method::sqrt3), Method::sqrt3, "elephant.off");
}

// The peers agree with dartcheck's own polygon-level oracle on the
// topology (a check of the oracle the other inference tests use).
TEST(InferencePeers, PeersAgreeWithTheFaceLevelOracle) {
  const Soup t = tetrahedron();
  const Model m = Model::gmap(2);
  EXPECT_TRUE(isomorphic(build_surface(m, cgal(t, Method::loop).faces), build_surface(m, loop_subdivision(t.faces).faces)));
  EXPECT_TRUE(isomorphic(build_surface(m, cgal(t, Method::sqrt3).faces), build_surface(m, sqrt3(t.faces).faces)));
  EXPECT_TRUE(isomorphic(build_surface(m, cgal(t, Method::catmull_clark).faces), build_surface(m, quad_subdivision(t.faces).faces)));
}

}  // namespace
}  // namespace dartcheck::inference::test
