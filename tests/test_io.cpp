// YAML maps, catalogs and meshes: round trips and error positions.
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checkers/map_validity.hpp"
#include "core/catalog.hpp"
#include "core/input_error.hpp"
#include "core/map_io.hpp"
#include "core/orbit.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_maps.hpp"

using namespace dartcheck;

namespace {
std::string data(const std::string& f) { return std::string(DARTCHECK_SOURCE_DIR) + "/tests/data/" + f; }

// Parses YAML text as if it were a file, returning the InputError position.
std::string error_of(const std::string& text, bool catalog = false) {
  // ctest runs each test in its own process, in parallel: one file per test.
  const auto path = std::filesystem::temp_directory_path() /
                    (std::string(catalog ? "dartcheck-test-catalog-" : "dartcheck-test-map-") + ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                     "-" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(path) << text;
  try {
    if (catalog)
      read_catalog(path.string());
    else
      read_map(path.string(), load_yaml_file(path.string()));
  } catch (const InputError& e) {
    return std::to_string(e.line()) + ":" + std::to_string(e.column()) + " " + e.what();
  }
  return "no error";
}
}  // namespace

// Issue 2: a map written to YAML and read back is identical, including
// corrupted maps whose predecessor records disagree with their links.
RC_GTEST_PROP(MapYaml, WriteThenReadIsIdentity, ()) {
  const auto model = *rc::gen::element(Model::gmap(2), Model::gmap(3), Model::omap(2), Model::omap(3));
  Map m = build_random_map(model, *gen_map_recipe(1, 20));
  for (const auto& c : *rc::gen::container<std::vector<LinkCorruption>>(rc::gen::arbitrary<LinkCorruption>())) apply_corruption(m, c);
  const Map back = read_map("<memory>", YAML::Load(map_to_yaml(m)));
  RC_ASSERT(back == m);
}

TEST(MapYaml, CompactFormsMeanTheSameAsArrays) {
  const Map compact = read_map("<memory>", YAML::Load("model: 2-omap\ndarts: 3\nlinks:\n  1: {cycles: [[0, 1, 2]]}\n  2: {pairs: [[0, 1]], loops: [2]}\n"));
  const Map raw = read_map("<memory>", YAML::Load("model: 2-omap\ndarts: 3\nlinks:\n  1: [1, 2, 0]\n  2: [1, 0, 2]\n"));
  EXPECT_EQ(compact, raw);
  EXPECT_EQ(raw.inverse_link(1, 0), 2u);
}

TEST(MapYaml, ErrorsNameLineAndColumn) {
  EXPECT_EQ(error_of("model: 2-gmap\ndarts: 2\nlinks:\n  0: [1, 5]\n").substr(0, 4), "4:10") << "dart 5 is out of range";
  EXPECT_EQ(error_of("model: 2-gmap\ndarts: 2\nlinks:\n  7: [1, 0]\n").substr(0, 3), "4:3") << "no dimension 7 in a 2-G-map";
  EXPECT_EQ(error_of("model: 9-cmap\ndarts: 2\nlinks: {}\n").substr(0, 3), "1:8");
  EXPECT_EQ(error_of("model: 2-gmap\ndarts: 2\nlinks:\n  0: [1]\n").substr(0, 3), "4:6") << "one entry per dart";
  EXPECT_EQ(error_of("model: 2-gmap\ndarts: 2\nlinkz: {}\n").substr(0, 3), "3:1") << "typos are not ignored";
  EXPECT_EQ(error_of("model: 2-gmap\ndarts: [\n").substr(0, 1), "3") << "malformed YAML";
}

TEST(Catalog, SeedCatalogLoads) {
  const Catalog c = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  EXPECT_NE(c.find_rule("insert-vertex-sewn-edge"), nullptr);
  EXPECT_NE(c.find_map("cube-mesh"), nullptr);
}

TEST(Catalog, DanglingNameIsReportedAtTheArc) {
  try {
    read_catalog(data("bad-catalog.yaml"));
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 9);
    EXPECT_EQ(e.column(), 25);  // the opening quote of "x -2- z"
    EXPECT_NE(std::string(e.what()).find("node 'z' is not declared"), std::string::npos) << e.what();
  }
}

TEST(Catalog, OtherErrors) {
  const std::string head = "rules:\n  - name: r\n    model: 2-gmap\n    hooks: [x]\n    left: {nodes: [x], arcs: [";
  EXPECT_NE(error_of(head + "\"x -0-> \"]}\n    right: {nodes: [x]}\n", true).find("5:"), std::string::npos);
  EXPECT_NE(error_of(head + "\"x -0- x\"]}\n    right: {nodes: [x]}\n    examples: [{map: nowhere, hooks: [0], expect: valid}]\n", true).find("no map named 'nowhere'"),
            std::string::npos);
  EXPECT_NE(error_of("rules:\n  - name: r\n    model: 2-gmap\n    hooks: [y]\n    left: {nodes: [x]}\n    right: {nodes: [x]}\n", true).find("4:12"), std::string::npos);
  EXPECT_NE(error_of("maps:\n  m: {model: 2-gmap, shape: cube, file: x.off}\n", true).find("exactly one"), std::string::npos);
}

// Real meshes made elsewhere import as valid maps; the Moebius band is a
// valid 2-G-map (G-maps represent non-orientable surfaces) but no 2-O-map.
TEST(Mesh, MoebiusBand) {
  Map g = load_mesh(Model::gmap(2), data("moebius.off"));
  EXPECT_TRUE(check_map(g).valid());
  EXPECT_EQ(count_cells(g).cells, (std::vector<std::size_t>{6, 9, 3}));
  EXPECT_EQ(count_cells(g).euler(), 0);
  try {
    load_mesh(Model::omap(2), data("moebius.off"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 15) << "the third face is the first to repeat the direction of edge (3, 0)";
    EXPECT_NE(std::string(e.what()).find("inconsistent orientation"), std::string::npos);
  }
}

TEST(Mesh, NonManifoldEdgeIsRejected) {
  for (const Model& m : {Model::gmap(2), Model::omap(2)}) {
    try {
      load_mesh(m, data("nonmanifold.off"));
      FAIL() << m.name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("non-manifold"), std::string::npos) << e.what();
    }
  }
}

// assimp-testmodels ships deliberately malformed files: each gets a clear
// error at its position (lines read off the files by hand).
TEST(Mesh, MalformedFilesFromAssimp) {
  const std::string dir = "/usr/share/assimp/models/";
  auto line_of = [&](const std::string& f) {
    try {
      load_mesh(Model::gmap(2), dir + f);
    } catch (const InputError& e) {
      return e.line();
    }
    return -1;
  };
  EXPECT_EQ(line_of("OFF/invalid.off"), 6) << "a face line '0' with no vertex";
  EXPECT_EQ(line_of("invalid/malformed.obj"), 23) << "f 4 12 2 1 with 8 vertices";
  EXPECT_EQ(line_of("invalid/OutOfMemory.off"), 2) << "absurd counts";
  EXPECT_EQ(line_of("invalid/empty.off"), 0) << "empty file";
  EXPECT_NE(line_of("OBJ/box_UTF16BE.obj"), -1) << "UTF-16 is not read as text";
  EXPECT_NE(line_of("OBJ/point_cloud.obj"), -1) << "no face";
}

TEST(Mesh, GoodObjFromAssimp) {
  Map m = load_mesh(Model::omap(2), "/usr/share/assimp/models/OBJ/box.obj");
  EXPECT_TRUE(check_map(m).valid());
  EXPECT_EQ(count_cells(m).cells, (std::vector<std::size_t>{8, 12, 6}));
}

// A custom model (D, N, E) written in the catalog: dimension 1 oriented, so
// a 1-cycle of three darts is fine where a 2-G-map would need pairs.
TEST(Catalog, CustomModel) {
  const auto path = std::filesystem::temp_directory_path() / "dartcheck-custom-model.yaml";
  std::ofstream(path) << "models:\n  half-oriented: {dims: [0, 1, 2], non_oriented: [0, 2], exchangeable: [[0, 2]]}\n"
                         "maps:\n  m:\n    model: half-oriented\n    darts: 3\n    links:\n      0: {loops: all}\n      1: {cycles: [[0, 1, 2]]}\n      2: {loops: all}\n";
  const Catalog c = read_catalog(path.string());
  const Model& m = c.find_map("m")->model;
  EXPECT_TRUE(m.is_oriented(1));
  EXPECT_FALSE(m.is_oriented(0));
  EXPECT_TRUE(check_map(*c.find_map("m")->map).valid());
  EXPECT_NE(error_of("models:\n  x: {dims: [0, 1], non_oriented: [0, 5]}\n", true).find("2:39"), std::string::npos) << "5 is not in dims";
}

// The arc notation of docs/catalog-format.md.
TEST(Catalog, ArcNotation) {
  auto side = [](const std::string& arcs) { return read_side("<memory>", YAML::Load("{nodes: [a, b], arcs: [" + arcs + "]}"), "left"); };
  const TopoGraph pair = side("'a -0- b'");
  ASSERT_EQ(pair.arc_count(), 2u);
  EXPECT_EQ(pair.arc(0), (Arc<int>{0, 1, 0}));
  EXPECT_EQ(pair.arc(1), (Arc<int>{1, 0, 0}));
  EXPECT_EQ(side("'a -12-> b'").arcs(), (std::vector<Arc<int>>{{0, 1, 12}}));
  EXPECT_EQ(side("'b <-1- a'").arcs(), (std::vector<Arc<int>>{{0, 1, 1}}));
  EXPECT_EQ(side("'a -2- a'").arcs(), (std::vector<Arc<int>>{{0, 0, 2}})) << "a non-oriented loop is one arc";
  for (const char* bad : {"'a -0 b'", "'a 0- b'", "'a <-0-> b'", "'a -x- b'", "'a -- b'", "'a -0- b c'", "'a -1234- b'", "'a -0-'"})
    EXPECT_THROW(side(bad), InputError) << bad;
  EXPECT_THROW(side("'a -16- b'"), InputError) << "above the largest dimension";
}
