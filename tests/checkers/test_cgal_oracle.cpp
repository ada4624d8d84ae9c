// CGAL as an independent oracle (the only translation unit of this target
// that includes CGAL: it compiles for about a minute).
//
// Theorem tested: for every map of the four models, dartcheck's verdict
// "valid n-G-map / n-O-map" (002 Def. 10) equals CGAL's is_valid() on the
// same links, with CGAL's free darts converted as follows.
//  - Generalized_map: a free dart is a fixed point, exactly our loop, and
//    every dart has an alpha_i; corruptions therefore only retarget links.
//  - Combinatorial_map: beta1 = our links of 1, beta0 = our recorded
//    predecessors, beta_i (i >= 2) = our links; our "no arc" is CGAL's null
//    dart. CGAL accepts free darts (boundaries) where our models demand an
//    arc, so the comparison is ours == (CGAL valid and no dart is free).
// CGAL's Generalized_map<1>::is_valid() aborts (an unsigned loop bound
// wraps), so dimensions 0 and 1 are not compared.
#include <CGAL/Combinatorial_map.h>
#include <CGAL/Generalized_map.h>
#include <CGAL/Linear_cell_complex_constructors.h>
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <gtest/gtest.h>
#include <iostream>
#include <rapidcheck/gtest.h>
#include <sstream>

#include "checkers/map_validity.hpp"
#include "io/map_io.hpp"
#include "core/orbit.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_maps.hpp"
#include "tests/map_recipe_gen.hpp"

using namespace dartcheck;

namespace {

// CGAL keeps the one-directional link writes protected; corrupted maps need
// them, so expose them.
template <unsigned n>
struct GMap : CGAL::Generalized_map<n> {
  using CGAL::Generalized_map<n>::dart_link_alpha;
};
template <unsigned n>
struct CMap : CGAL::Combinatorial_map<n> {
  using CGAL::Combinatorial_map<n>::dart_link_beta;
};

// CGAL's Generalized_map::is_valid() prints every bad dart on std::cerr.
struct QuietCerr {
  std::ostringstream sink;
  std::streambuf* old = std::cerr.rdbuf(sink.rdbuf());
  ~QuietCerr() { std::cerr.rdbuf(old); }
};

template <unsigned n>
bool cgal_gmap_valid(const Map& m) {
  GMap<n> g;
  std::vector<typename GMap<n>::Dart_handle> h;
  for (Dart d = 0; d < m.size(); ++d) h.push_back(g.create_dart());
  for (Dim i = 0; i <= static_cast<Dim>(n); ++i)
    for (Dart d = 0; d < m.size(); ++d) g.dart_link_alpha(h[d], h[m.link(i, d)], static_cast<unsigned>(i));
  QuietCerr quiet;
  return g.is_valid();
}

template <unsigned n>
bool cgal_cmap_valid_and_closed(const Map& m) {
  CMap<n> c;
  std::vector<typename CMap<n>::Dart_handle> h;
  for (Dart d = 0; d < m.size(); ++d) h.push_back(c.create_dart());
  auto set = [&](Dart d, Dart e, unsigned i) {
    if (e != no_dart) c.dart_link_beta(h[d], h[e], i);
  };
  for (Dart d = 0; d < m.size(); ++d) {
    set(d, m.link(1, d), 1);
    set(d, m.inverse_link(1, d), 0);
    for (Dim i = 2; i <= static_cast<Dim>(n); ++i) set(d, m.link(i, d), static_cast<unsigned>(i));
  }
  bool closed = true;
  for (auto it = c.darts().begin(); it != c.darts().end(); ++it)
    for (unsigned i = 0; i <= n; ++i) closed &= !c.is_free(it, i);
  return c.is_valid(false) && closed;
}

// Half of the maps are corrupted by random link changes.
Map random_map(const Model& model, bool keep_every_link) {
  Map m = build_random_map(model, *gen_map_recipe(1, 24));
  if (*rc::gen::arbitrary<bool>()) {
    for (auto c : *rc::gen::nonEmpty(rc::gen::container<std::vector<LinkCorruption>>(rc::gen::arbitrary<LinkCorruption>()))) {
      if (keep_every_link) c.target %= static_cast<std::uint32_t>(m.size());  // a G-map dart always has an alpha_i
      apply_corruption(m, c);
    }
    RC_TAG("corrupted");
  }
  RC_CLASSIFY(check_map(m).valid(), "valid");
  RC_LOG() << map_to_yaml(m);
  return m;
}

}  // namespace

RC_GTEST_PROP(CgalOracle, GMap2, ()) {
  const Map m = random_map(Model::gmap(2), true);
  RC_ASSERT(check_map(m).valid() == cgal_gmap_valid<2>(m));
}

RC_GTEST_PROP(CgalOracle, GMap3, ()) {
  const Map m = random_map(Model::gmap(3), true);
  RC_ASSERT(check_map(m).valid() == cgal_gmap_valid<3>(m));
}

RC_GTEST_PROP(CgalOracle, OMap2, ()) {
  const Map m = random_map(Model::omap(2), false);
  RC_ASSERT(check_map(m).valid() == cgal_cmap_valid_and_closed<2>(m));
}

RC_GTEST_PROP(CgalOracle, OMap3, ()) {
  const Map m = random_map(Model::omap(3), false);
  RC_ASSERT(check_map(m).valid() == cgal_cmap_valid_and_closed<3>(m));
}

// Cell counts of real meshes: dartcheck's import and orbits against CGAL's
// own OFF reader and cell iteration (Linear_cell_complex, combinatorial map).
TEST(CgalOracle, MeshCellCountsMatchCgal) {
  using LCC = CGAL::Linear_cell_complex_for_combinatorial_map<2, 3>;
  const std::string dir = std::string(DARTCHECK_MESH_DIR) + "/";
  for (const char* name : {"cube_quad.off", "torus_quad.off", "3torus.off", "elephant.off"}) {
    SCOPED_TRACE(name);
    LCC lcc;
    // A 2-map has no beta3: sew3_same_facets(), called here before, failed
    // CGAL's assertion i <= dimension in the Debug (sanitizer) build; the
    // Release build skips the assertion, so the call went unnoticed.
    ASSERT_TRUE(CGAL::load_off(lcc, (dir + name).c_str()));
    const std::vector<std::size_t> cgal{lcc.one_dart_per_cell<0>().size(), lcc.one_dart_per_cell<1>().size(), lcc.one_dart_per_cell<2>().size()};
    for (const Model& model : {Model::gmap(2), Model::omap(2)}) {
      const Map m = load_mesh(model, dir + name);
      EXPECT_TRUE(check_map(m).valid());
      EXPECT_EQ(count_cells(m).cells, cgal) << model.name;
    }
  }
}

// Known Euler characteristics: a cube and a quad torus from CGAL's data,
// and the genus-3 surface 3torus.off: 2 - 2g = -4.
TEST(CgalOracle, EulerCharacteristicOfNamedSurfaces) {
  const std::string dir = std::string(DARTCHECK_MESH_DIR) + "/";
  EXPECT_EQ(count_cells(load_mesh(Model::gmap(2), dir + "cube_quad.off")).euler(), 2);
  EXPECT_EQ(count_cells(load_mesh(Model::gmap(2), dir + "torus_quad.off")).euler(), 0);
  EXPECT_EQ(count_cells(load_mesh(Model::omap(2), dir + "3torus.off")).euler(), -4);
}
