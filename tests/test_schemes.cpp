// Rule scheme application (002 Sec. 6.3) on dense maps, checked against
// what the operation must give. Quad subdivision of a mesh with V vertices,
// E edges, F faces and face degrees summing to S: a vertex per vertex, edge
// and face (V + E + F); every edge split in two plus one inner edge per
// face corner (2E + S); a quad per face corner (S); 4 darts per dart. On a
// quad mesh S = 4F: 2E + 4F edges and 4F faces, the figures.
#include <gtest/gtest.h>

#include "checkers/map_validity.hpp"
#include "core/catalog.hpp"
#include "core/orbit.hpp"
#include "core/scheme_application.hpp"
#include "generators/mesh_map.hpp"
#include "generators/shapes.hpp"

using namespace dartcheck;

namespace {
const CatalogRule& entry(const std::string& name) {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  return *c.find_rule(name);
}

void expect_quad_subdivision(const std::string& scheme, Map g) {
  const auto before = count_cells(g);
  const std::size_t darts = g.size();
  const std::size_t V = before.cells[0], E = before.cells[1], F = before.cells[2];
  // A face of degree k has 2k darts in a G-map, k in an O-map.
  const std::size_t S = g.model().is_generalized() ? darts / 2 : darts;
  const auto& s = entry(scheme);
  const Dart hook = 0;
  auto out = apply_scheme(s.rule, s.words, g, std::span(&hook, 1));
  ASSERT_TRUE(out.ok()) << out.why;
  EXPECT_EQ(out.value->pattern_nodes, darts) << "a connected map: P_v is every dart";
  EXPECT_EQ(g.size(), 4 * darts);
  const auto report = check_map(g);
  EXPECT_TRUE(report.valid()) << report.violations.size() << " violations";
  const auto after = count_cells(g);
  EXPECT_EQ(after.cells, (std::vector<std::size_t>{V + E + F, 2 * E + S, S}));
  if (S == 4 * F) {
    EXPECT_EQ(after.cells, (std::vector<std::size_t>{V + E + F, 2 * E + 4 * F, 4 * F}));
  }
  EXPECT_EQ(after.components, before.components);
}
}  // namespace

TEST(QuadSubdivision, GmapCube) { expect_quad_subdivision("quad-subdivision-gmap", build_shape(Model::gmap(2), {"cube", {}})); }
TEST(QuadSubdivision, GmapGridWithBoundary) {
  // An open grid: the boundary edges are free (2-loops); the counts still
  // hold for V, E, F of the open surface.
  expect_quad_subdivision("quad-subdivision-gmap", build_shape(Model::gmap(2), {"grid", {2, 3}}));
}
TEST(QuadSubdivision, GmapTriangleMesh) {
  expect_quad_subdivision("quad-subdivision-gmap", build_shape(Model::gmap(2), {"tetrahedron", {}}));
}
TEST(QuadSubdivision, OmapCube) { expect_quad_subdivision("quad-subdivision-omap", build_shape(Model::omap(2), {"cube", {}})); }
TEST(QuadSubdivision, OmapPrism) { expect_quad_subdivision("quad-subdivision-omap", build_shape(Model::omap(2), {"prism", {5}})); }
TEST(QuadSubdivision, OmapMesh) {
  expect_quad_subdivision("quad-subdivision-omap",
                          load_mesh(Model::omap(2), std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/meshes/cube.off"));
}

// The broken variants are refused or produce invalid maps, as their
// failing conditions predict.
TEST(QuadSubdivision, BrokenWordBreaksTheCycleConstraint) {
  Map g = build_shape(Model::gmap(2), {"cube", {}});
  const auto& s = entry("quad-subdivision-gmap-broken-word");
  const Dart hook = 0;
  auto out = apply_scheme(s.rule, s.words, g, std::span(&hook, 1));
  ASSERT_TRUE(out.ok()) << out.why;
  const auto report = check_map(g);
  ASSERT_FALSE(report.valid());
  for (const auto& v : report.violations) EXPECT_EQ(v.constraint, Constraint::cycle) << "only C(0,2) is predicted to fail";
}

// Cone extrusion of an isolated k-gon (002 Sec. 10.2): a pyramid, closed:
// k + 1 vertices, 2k edges, k + 1 faces; 4 darts per edge in a G-map (8k),
// 2 in an O-map (4k).
void expect_cone(const std::string& scheme, const Model& model, int k) {
  Map g = build_shape(model, {"polygon", {k}});
  const auto& s = entry(scheme);
  const Dart hook = 0;
  auto out = apply_scheme(s.rule, s.words, g, std::span(&hook, 1));
  ASSERT_TRUE(out.ok()) << out.why;
  const auto n = static_cast<std::size_t>(k);
  EXPECT_EQ(g.size(), (model.is_generalized() ? 8 : 4) * n);
  const auto report = check_map(g);
  EXPECT_TRUE(report.valid()) << report.violations.size() << " violations";
  const auto cells = count_cells(g);
  EXPECT_EQ(cells.cells, (std::vector<std::size_t>{n + 1, 2 * n, n + 1}));
  EXPECT_EQ(cells.euler(), 2);
}
TEST(ConeExtrusion, Gmap) {
  for (int k : {3, 4, 6}) expect_cone("cone-extrusion-gmap", Model::gmap(2), k);
}
TEST(ConeExtrusion, Omap) {
  for (int k : {3, 4, 6}) expect_cone("cone-extrusion-omap", Model::omap(2), k);
}
