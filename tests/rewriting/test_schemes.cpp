// Rule scheme application (002 Sec. 6.3) on dense maps, checked against
// what the operation must give. Quad subdivision of a mesh with V vertices,
// E edges, F faces and face degrees summing to S: a vertex per vertex, edge
// and face (V + E + F); every edge split in two plus one inner edge per
// face corner (2E + S); a quad per face corner (S); 4 darts per dart. On a
// quad mesh S = 4F: 2E + 4F edges and 4F faces, the issue's figures.
#include <algorithm>
#include <map>
#include <random>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checkers/map_validity.hpp"
#include "io/catalog.hpp"
#include "rewriting/detail/derivation.hpp"
#include "rewriting/jerboa_scheme.hpp"
#include "core/isomorphism.hpp"
#include "core/orbit.hpp"
#include "rewriting/instantiated_classes.hpp"
#include "rewriting/detail/scheme_rewriter.hpp"
#include "rewriting/scheme_instantiation.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_maps.hpp"
#include "tests/map_recipe_gen.hpp"
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
TEST(QuadSubdivision, GmapTriangleMesh) { expect_quad_subdivision("quad-subdivision-gmap", build_shape(Model::gmap(2), {"tetrahedron", {}})); }
TEST(QuadSubdivision, OmapCube) { expect_quad_subdivision("quad-subdivision-omap", build_shape(Model::omap(2), {"cube", {}})); }
TEST(QuadSubdivision, OmapPrism) { expect_quad_subdivision("quad-subdivision-omap", build_shape(Model::omap(2), {"prism", {5}})); }
TEST(QuadSubdivision, OmapMesh) {
  expect_quad_subdivision("quad-subdivision-omap", load_mesh(Model::omap(2), std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/meshes/cube.off"));
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

// ---- Jerboa notation (000 Sec. 4.3, 002 Sec. 10.1) ------------------------

namespace {
// The arcs of one side as (source, target, dimension, word), with node
// names renamed, sorted: two sides are the same scheme side iff equal.
std::vector<std::string> arcs_of(const TopoGraph& g, const std::vector<ConjWord>& words, const std::map<std::string, std::string>& rename) {
  std::vector<std::string> out;
  for (ArcId e = 0; e < g.arc_count(); ++e) {
    auto name = [&](NodeId v) {
      auto it = rename.find(g.name(v));
      return it == rename.end() ? g.name(v) : it->second;
    };
    out.push_back(name(g.arc(e).source) + " -(" + words[e].str() + "," + std::to_string(g.arc(e).label) + ")-> " + name(g.arc(e).target));
  }
  std::sort(out.begin(), out.end());
  return out;
}
Map apply_at(const CatalogRule& s, Map g, Dart hook) {
  auto out = s.words.scheme ? apply_scheme(s.rule, s.words, g, std::span(&hook, 1)).refusal : apply_rule(s.rule, g, std::span(&hook, 1)).refusal;
  EXPECT_EQ(out, Refusal::none) << s.rule.name();
  return g;
}
}  // namespace

// 002 Sec. 10.1: "we can write the rule scheme of Figure 29 in Jerboa".
// The Jerboa entry, translated, is the (W,D) entry arc for arc.
TEST(JerboaNotation, QuadSubdivisionTranslatesToFigure29) {
  const auto& j = entry("quad-subdivision-jerboa");
  const auto& w = entry("quad-subdivision-gmap");
  const std::map<std::string, std::string> rename{{"n0", "a"}, {"n1", "b"}, {"n2", "c"}, {"n3", "d"}};
  EXPECT_EQ(arcs_of(j.rule.left(), j.words.left, rename), arcs_of(w.rule.left(), w.words.left, {}));
  EXPECT_EQ(arcs_of(j.rule.right(), j.words.right, rename), arcs_of(w.rule.right(), w.words.right, {}));
}

// 000 Sec. 4.3.2: the folded vertex insertion (Fig. 8(b), parameter <0,2>)
// unfolds on a free edge into Fig. 7(a) and on a sewn edge into Fig. 7(c);
// so does Fig. 8(a) (parameter <2>). Applied at the same dart, the scheme
// and the DPO rule give isomorphic maps.
TEST(JerboaNotation, FoldedVertexInsertionUnfoldsToFigure7) {
  const Map square = build_shape(Model::gmap(2), {"polygon", {4}});
  const Map cube = build_shape(Model::gmap(2), {"cube", {}});
  const Map grid = build_shape(Model::gmap(2), {"grid", {2, 2}});
  for (const char* folded : {"insert-vertex-jerboa", "insert-vertex-jerboa-2"}) {
    EXPECT_TRUE(isomorphic(apply_at(entry(folded), square, 0), apply_at(entry("insert-vertex-free-edge"), square, 0))) << folded;
    EXPECT_TRUE(isomorphic(apply_at(entry(folded), cube, 0), apply_at(entry("insert-vertex-sewn-edge"), cube, 0))) << folded;
    for (Dart d = 0; d < grid.size(); ++d) {
      const bool free = grid.link(2, d) == d;
      const Map folded_result = apply_at(entry(folded), grid, d);
      const Map dpo_result = apply_at(entry(free ? "insert-vertex-free-edge" : "insert-vertex-sewn-edge"), grid, d);
      EXPECT_TRUE(isomorphic(folded_result, dpo_result)) << folded << " at dart " << d;
      EXPECT_TRUE(check_map(folded_result).valid());
    }
  }
}

// ---- Edge rounding (002 Sec. 10.2, Fig. 34) -------------------------------
// On a closed surface every edge and every vertex becomes a face: V' = 2E
// (one vertex per corner, and corners number 2E), E' = 4E, F' = V + E + F,
// 4 darts per dart; Euler characteristic unchanged.
void expect_edge_rounding(const std::string& scheme, Map g) {
  const auto before = count_cells(g);
  const std::size_t darts = g.size(), V = before.cells[0], E = before.cells[1], F = before.cells[2];
  const auto& s = entry(scheme);
  const Dart hook = 0;
  auto out = apply_scheme(s.rule, s.words, g, std::span(&hook, 1));
  ASSERT_TRUE(out.ok()) << out.why;
  EXPECT_EQ(g.size(), 4 * darts);
  const auto report = check_map(g);
  EXPECT_TRUE(report.valid()) << report.violations.size() << " violations";
  const auto after = count_cells(g);
  EXPECT_EQ(after.cells, (std::vector<std::size_t>{2 * E, 4 * E, V + E + F}));
  EXPECT_EQ(after.euler(), before.euler());
}
TEST(EdgeRounding, Gmap) {
  expect_edge_rounding("edge-rounding-gmap", build_shape(Model::gmap(2), {"cube", {}}));
  expect_edge_rounding("edge-rounding-gmap", build_shape(Model::gmap(2), {"tetrahedron", {}}));
  expect_edge_rounding("edge-rounding-gmap", build_shape(Model::gmap(2), {"prism", {5}}));
  expect_edge_rounding("edge-rounding-gmap", load_mesh(Model::gmap(2), std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/meshes/cube.off"));
}
TEST(EdgeRounding, Omap) {
  expect_edge_rounding("edge-rounding-omap", build_shape(Model::omap(2), {"cube", {}}));
  expect_edge_rounding("edge-rounding-omap", build_shape(Model::omap(2), {"tetrahedron", {}}));
  expect_edge_rounding("edge-rounding-omap", build_shape(Model::omap(2), {"prism", {5}}));
  expect_edge_rounding("edge-rounding-omap", load_mesh(Model::omap(2), std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/meshes/cube.off"));
}
// The pyramid of Fig. 35 is the cone extrusion of a square (Fig. 31 (1),
// (2)): 5 vertices, 8 edges, 5 faces become 16, 32, 18.
TEST(EdgeRounding, PyramidOfFigure35) {
  Map g = apply_at(entry("cone-extrusion-gmap"), build_shape(Model::gmap(2), {"polygon", {4}}), 0);
  g = apply_at(entry("edge-rounding-gmap"), g, 0);
  EXPECT_TRUE(check_map(g).valid());
  EXPECT_EQ(count_cells(g).cells, (std::vector<std::size_t>{16, 32, 18}));
}

// ---- Face extrusion (002 Sec. 10.2, Fig. 36, 37) --------------------------
// Extruding a face of degree k adds a prism: k vertices, 2k edges, k + 1
// faces (top and k sides; the base is shared), one volume. New darts per
// dart of the face: 6 in a 3-G-map (b..g), 10 in a 3-O-map (d..o).
void expect_face_extrusion(const std::string& scheme, Map g, Dart hook) {
  const auto before = count_cells(g);
  const auto& s = entry(scheme);
  auto out = apply_scheme(s.rule, s.words, g, std::span(&hook, 1));
  ASSERT_TRUE(out.ok()) << out.why;
  const bool gmap = g.model().is_generalized();
  // A face of degree k has 2k darts (G) or k darts (O) on one side.
  // P_v holds the face's darts (G: 2k, the pattern of the single node a).
  const std::size_t k = gmap ? out.value->pattern_nodes / 2 : out.value->added_darts / 10;
  EXPECT_EQ(out.value->added_darts, gmap ? 12 * k : 10 * k);
  const auto report = check_map(g);
  ASSERT_TRUE(report.valid()) << report.violations.size() << " violations";
  const auto after = count_cells(g);
  ASSERT_EQ(after.cells.size(), 4u);
  EXPECT_EQ(after.cells, (std::vector<std::size_t>{before.cells[0] + k, before.cells[1] + 2 * k, before.cells[2] + k + 1, before.cells[3] + 1}));
}
TEST(FaceExtrusion, GmapCubeAndStackedCubes) {
  expect_face_extrusion("face-extrusion-gmap", build_shape(Model::gmap(3), {"cube", {}}), 0);
  expect_face_extrusion("face-extrusion-gmap", build_shape(Model::gmap(3), {"prism", {5}}), 0);
  const Map stacked = build_shape(Model::gmap(3), {"stacked-cubes", {}});
  for (Dart d = 0; d < stacked.size(); ++d)
    if (stacked.link(3, d) == d) expect_face_extrusion("face-extrusion-gmap", stacked, d);
}
// On random 3-O-maps (every face is 3-sewn): the L of Fig. 37 matches every
// face, and the result is a valid 3-O-map with one more volume.
RC_GTEST_PROP(FaceExtrusion, OmapOnRandomMaps, ()) {
  const auto recipe = *gen_map_recipe(1, 6);
  const Map g = build_random_map(Model::omap(3), recipe);
  const auto before = count_cells(g);
  const auto& s = entry("face-extrusion-omap");
  std::size_t applied = 0;
  for (Dart hook = 0; hook < g.size(); ++hook) {
    Map h = g;
    auto out = apply_scheme(s.rule, s.words, h, std::span(&hook, 1));
    // L's nodes a, b = a·3 and c = b·2 must match distinct darts: a face
    // whose far side is 2-sewn to itself (2-loops) is refused, and only so.
    if (!out.ok()) {
      RC_ASSERT(out.refusal == Refusal::not_injective);
      continue;
    }
    ++applied;
    RC_ASSERT(check_map(h).valid());
    const auto after = count_cells(h);
    const std::size_t k = out.value->added_darts / 10;
    RC_ASSERT(out.value->added_darts % 10 == 0u);
    RC_ASSERT(after.cells == (std::vector<std::size_t>{before.cells[0] + k, before.cells[1] + 2 * k, before.cells[2] + k + 1, before.cells[3] + 1}));
  }
  RC_CLASSIFY(applied > 0, "applied somewhere");
}

// Jerboa orbit types (000 Sec. 4.3): hand-read parses, and the overflow
// fuzz_word found ("09999999999" multiplied past INT_MAX: UBSan).
TEST(OrbitType, ParsesAndRefusesLargeDimensions) {
  const OrbitType t = parse_orbit_type("<0, _, 2>");
  ASSERT_EQ(t.size(), 3U);
  EXPECT_EQ(t[0], std::optional<Dim>(0));
  EXPECT_FALSE(t[1].has_value());
  EXPECT_EQ(t[2], std::optional<Dim>(2));
  EXPECT_TRUE(parse_orbit_type("<>").empty());
  try {
    parse_orbit_type("<09999999999,_,@");
    FAIL() << "accepted a dimension above 15";
  } catch (const ValueError& e) {
    EXPECT_NE(std::string(e.what()).find("dimension 09999999999 is above 15"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_orbit_type("<16>"), ValueError);
}

// A SchemeRewriter kept across applications (its tables reused, and left
// by refusals) acts as a fresh apply_scheme at every step: same refusal,
// same H dart for dart, same comatch and renumbering. Every scheme of the
// seed catalog, three applications in a row on random maps of its model.
TEST(SchemeRewriter, KeptAcrossApplicationsActsAsFresh) {
  static const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  std::mt19937 rng(5);
  std::size_t schemes = 0, applied = 0, refused = 0;
  for (const CatalogRule& r : c.rules) {
    if (!r.words.scheme || !has_random_generator(r.rule.model())) continue;
    ++schemes;
    SchemeRewriter kept(r.rule, r.words);
    for (int round = 0; round < 40; ++round) {
      Map fresh = build_random_map(r.rule.model(), draw_recipe(rng, 1 + round % 6, r.rule.model().dimension()));
      Map reused = fresh;
      for (int step = 0; step < 3 && fresh.size() < 4000; ++step) {
        std::vector<Dart> hooks;
        for (std::size_t h = 0; h < r.rule.hooks().size(); ++h)
          hooks.push_back(std::uniform_int_distribution<Dart>(0, static_cast<Dart>(fresh.size() - 1))(rng));
        const auto a = apply_scheme(r.rule, r.words, fresh, hooks);
        auto b = kept.apply(reused, hooks);
        ASSERT_EQ(a.refusal, b.refusal) << r.rule.name() << ": " << a.why << " / " << b.why;
        ASSERT_EQ(a.why, b.why) << r.rule.name();
        ASSERT_EQ(fresh, reused) << r.rule.name();
        if (!a.ok()) {
          ++refused;
          continue;
        }
        ++applied;
        ASSERT_EQ(a.value->comatch, b.value->comatch) << r.rule.name();
        ASSERT_EQ(a.value->moved, b.value->moved) << r.rule.name();
        ASSERT_EQ(a.value->added_darts, b.value->added_darts) << r.rule.name();
        kept.recycle(std::move(*b.value));
      }
    }
  }
  EXPECT_GE(schemes, 10u);
  EXPECT_GT(applied, 100u);
  EXPECT_GT(refused, 100u);
}

// 002 Def. 19-21: applying a scheme S at hook v is the direct derivation
// of its instantiated rule ι(S, P_v) at the match (p, hook) -> the p-th
// dart of P_v. The instantiated rule is built as an explicit DPO rule
// (rewriting/scheme_instantiation) and applied by the graph engine
// (apply_rule: match_from_hooks and the DPO derivation), which shares no
// code with the scheme engine's match and rewrite; both must apply or
// refuse together and give isomorphic maps, and each arc of R must be a
// link of H between the comatched darts. P_v itself is checked against
// its definition: the hook's closure under W's words and their
// conjugates, each shift table the word's path. Every scheme of the three
// catalogs whose L is the hook alone, on random maps of its model.
TEST(SchemeApplication, IsTheDerivationOfTheInstantiatedRule) {
  std::vector<Catalog> catalogs;
  for (const char* f : {"seed-operations", "embedding-operations", "subdivision-operations"})
    catalogs.push_back(read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/" + f + ".yaml"));
  std::mt19937 rng(23);
  std::size_t schemes = 0, applied = 0, refused = 0;
  for (const Catalog& c : catalogs)
    for (const CatalogRule& r : c.rules) {
      if (!r.words.scheme || r.rule.left().node_count() != 1 || !has_random_generator(r.rule.model())) continue;
      ++schemes;
      SchemeRewriter kept(r.rule, r.words);
      for (int round = 0; round < 30; ++round) {
        const Map g = build_random_map(r.rule.model(), draw_recipe(rng, 1 + round % 6, r.rule.model().dimension()));
        const Dart v = std::uniform_int_distribution<Dart>(0, static_cast<Dart>(g.size() - 1))(rng);
        Map by_scheme = g;
        auto s = kept.apply(by_scheme, std::span(&v, 1));
        const auto pattern = pattern_graphs(r.rule.model(), r.words, g, std::span(&v, 1));
        if (!pattern.ok()) {
          ASSERT_FALSE(s.ok()) << r.rule.name();
          ++refused;
          continue;
        }
        // P_v by its definition.
        const PatternGraphs& pv = *pattern.value;
        const std::vector<Dart>& darts = pv.darts[0];
        ASSERT_EQ(darts[0], v);
        std::vector<Dart> sorted = darts;
        std::sort(sorted.begin(), sorted.end());
        ASSERT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << r.rule.name() << ": a dart twice in P_v";
        for (std::size_t w = 0; w < pv.gens.size(); ++w)
          for (std::size_t p = 0; p < darts.size(); ++p) {
            Dart d = darts[p];
            for (std::size_t k = 0; k < pv.gens[w].size() && d != no_dart; ++k)
              d = pv.gens[w].bar(k) ? g.inverse_link(pv.gens[w].dim(k), d) : g.link(pv.gens[w].dim(k), d);
            ASSERT_EQ(d, darts[pv.shift[w][p]]) << r.rule.name() << ": shift of " << pv.gens[w].str();
          }
        Map by_rule = g;
        bool rule_ok = false;
        try {
          const Rule inst = instantiate(r.rule, r.words, pv);
          // Each component of ι(L, P_v) is hooked at its first node, "x@d".
          std::vector<Dart> hooks;
          for (NodeId h : inst.hooks()) {
            const std::string& name = inst.left().name(h);
            hooks.push_back(static_cast<Dart>(std::stoul(name.substr(name.find('@') + 1))));
          }
          rule_ok = apply_rule(inst, by_rule, hooks).ok();
        } catch (const ValueError&) {
          rule_ok = false;  // ι(S, P_v) is not a rule: no derivation
        }
        ASSERT_EQ(s.ok(), rule_ok) << r.rule.name() << " at dart " << v << ": " << s.why;
        if (!s.ok()) {
          ASSERT_EQ(by_scheme, g) << r.rule.name() << ": a refusal changed the map";
          ++refused;
          continue;
        }
        ++applied;
        ASSERT_TRUE(isomorphic(by_scheme, by_rule)) << r.rule.name() << " at dart " << v;
        // Every arc of R is a link of H between the comatched darts (the
        // embedded rewriter writes the classes of a closed R on this).
        const TopoGraph& R = r.rule.right();
        const auto& comatch = s.value->comatch;
        for (ArcId a = 0; a < R.arc_count(); ++a) {
          const int w = pv.generator(arc_word(r.words.right, a));
          for (std::size_t p = 0; p < darts.size(); ++p)
            ASSERT_EQ(by_scheme.link(R.arc(a).label, comatch[R.arc(a).source][p]), comatch[R.arc(a).target][pv.step(p, w)])
                << r.rule.name() << ": arc " << a;
        }
        kept.recycle(std::move(*s.value));
      }
    }
  EXPECT_GE(schemes, 20u);
  EXPECT_GT(applied, 300u);
  EXPECT_GT(refused, 50u);
  std::printf("%zu schemes: %zu applications, %zu refusals agree with ι(S, P_v)\n", schemes, applied, refused);
}

// Whether two class tables of one side on np pattern copies are the same
// partition of the instances (numbers may differ): a bijection of numbers.
::testing::AssertionResult same_partition(const InstantiatedClasses& a, const InstantiatedClasses& b, std::size_t nodes, std::size_t np) {
  if (a.count != b.count) return ::testing::AssertionFailure() << a.count << " classes against " << b.count;
  std::vector<std::uint32_t> to(a.count, ~0U), from(b.count, ~0U);
  for (NodeId x = 0; x < nodes; ++x)
    for (std::size_t p = 0; p < np; ++p) {
      const std::uint32_t i = a.of(x, p), j = b.of(x, p);
      if (i >= a.count || j >= b.count) return ::testing::AssertionFailure() << "a class number out of range";
      if (to[i] == ~0U) to[i] = j;
      if (from[j] == ~0U) from[j] = i;
      if (to[i] != j) return ::testing::AssertionFailure() << "a class of the first spans two classes of the second";
      if (from[j] != i) return ::testing::AssertionFailure() << "a class of the second spans two classes of the first";
    }
  return ::testing::AssertionSuccess();
}

// The classes of an instantiated side computed per pattern copy (one walk
// over the pattern per group of nodes) are the classes of the definition
// (one union-find over every instance (x, p), joined to (y, p·w) by each
// arc x -(w, i)-> y with i in <o>): the same partition. Every scheme of
// the three catalogs, both sides, every orbit type of its model, on the
// pattern of matches on random maps, and on the same pattern with random
// shift tables: steps that are not permutations (an invalid host), where
// a forward walk alone would split an orbit of the symmetric closure.
TEST(InstantiatedClasses, PerPatternCopyEqualsTheDefinition) {
  std::vector<Catalog> catalogs;
  for (const char* f : {"seed-operations", "embedding-operations", "subdivision-operations"})
    catalogs.push_back(read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/" + f + ".yaml"));
  std::mt19937 rng(17);
  std::size_t compared = 0, by_pattern = 0, by_instance = 0, scrambled = 0;
  InstantiatedClasses fast, reference;
  for (const Catalog& c : catalogs)
    for (const CatalogRule& r : c.rules) {
      if (!r.words.scheme || !has_random_generator(r.rule.model())) continue;
      const std::vector<Dim>& dims = r.rule.model().dims;
      for (int round = 0; round < 12; ++round) {
        const Map g = build_random_map(r.rule.model(), draw_recipe(rng, 1 + round % 6, r.rule.model().dimension()));
        std::vector<Dart> hooks;
        for (std::size_t h = 0; h < r.rule.hooks().size(); ++h)
          hooks.push_back(std::uniform_int_distribution<Dart>(0, static_cast<Dart>(g.size() - 1))(rng));
        const auto m = match_scheme(r.rule, r.words, g, hooks);
        if (!m.ok()) continue;
        const std::size_t np = m.value->pattern.darts[0].size();
        PatternGraphs random_steps = m.value->pattern;
        for (auto& column : random_steps.shift)
          for (std::uint32_t& q : column) q = std::uniform_int_distribution<std::uint32_t>(0, static_cast<std::uint32_t>(np - 1))(rng);
        const PatternGraphs* const patterns[] = {&m.value->pattern, &random_steps};
        for (unsigned mask = 1; mask < (1U << dims.size()); ++mask) {
          std::vector<Dim> orbit;
          for (std::size_t k = 0; k < dims.size(); ++k)
            if (mask >> k & 1U) orbit.push_back(dims[k]);
          for (bool right : {false, true}) {
            const TopoGraph& side = right ? r.rule.right() : r.rule.left();
            const auto& words = right ? r.words.right : r.words.left;
            for (const PatternGraphs* pattern : patterns) {
              instantiated_classes(side, words, pattern, orbit, fast);
              instantiated_classes_by_instance(side, words, pattern, orbit, reference);
              ASSERT_TRUE(same_partition(fast, reference, side.node_count(), np))
                  << r.rule.name() << (pattern == &random_steps ? " (random steps)" : "");
              (fast.by_pattern ? by_pattern : by_instance) += 1;
              scrambled += pattern == &random_steps;
              ++compared;
            }
          }
        }
      }
    }
  EXPECT_GT(compared, 2000u);
  EXPECT_GT(by_pattern, 1000u);
  EXPECT_GT(by_instance, 40u);  // (W, D) schemes with a word on an arc between two nodes
  EXPECT_GT(scrambled, 1000u);
  std::printf("%zu partitions compared (%zu on random steps): %zu per pattern copy, %zu by the definition\n", compared, scrambled, by_pattern,
              by_instance);
}
