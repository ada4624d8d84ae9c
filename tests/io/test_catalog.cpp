// YAML catalogs: the seed catalog, custom models, the arc notation, and
// errors at their position.
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checkers/map_validity.hpp"
#include "io/catalog.hpp"
#include "io/detail/yaml_readers.hpp"
#include "core/input_error.hpp"
#include "io/map_io.hpp"
#include "io/detail/yaml_util.hpp"
#include "core/orbit.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_maps.hpp"

#include "tests/io/io_support.hpp"

using namespace dartcheck;
using namespace dartcheck::testing_support;

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
  EXPECT_NE(error_of(head + "\"x -0- x\"]}\n    right: {nodes: [x]}\n    examples: [{map: nowhere, hooks: [0], expect: valid}]\n", true)
                .find("no map named 'nowhere'"),
            std::string::npos);
  EXPECT_NE(error_of("rules:\n  - name: r\n    model: 2-gmap\n    hooks: [y]\n    left: {nodes: [x]}\n    right: {nodes: [x]}\n", true).find("4:12"),
            std::string::npos);
  EXPECT_NE(error_of("maps:\n  m: {model: 2-gmap, shape: cube, file: x.off}\n", true).find("exactly one"), std::string::npos);
}

// A custom model (D, N, E) written in the catalog: dimension 1 oriented, so
// a 1-cycle of three darts is fine where a 2-G-map would need pairs.
TEST(Catalog, CustomModel) {
  const auto path = std::filesystem::temp_directory_path() / "dartcheck-custom-model.yaml";
  std::ofstream(path) << "models:\n  half-oriented: {dims: [0, 1, 2], non_oriented: [0, 2], exchangeable: [[0, 2]]}\n"
                         "maps:\n  m:\n    model: half-oriented\n    darts: 3\n    links:\n      0: {loops: all}\n      1: {cycles: [[0, 1, 2]]}\n   "
                         "   2: {loops: all}\n";
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
