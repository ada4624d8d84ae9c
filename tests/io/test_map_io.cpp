// YAML map files: round trips and error positions.
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
#include "tests/map_recipe_gen.hpp"

#include "tests/io/io_support.hpp"

using namespace dartcheck;
using namespace dartcheck::testing_support;

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
  const Map compact =
      read_map("<memory>", YAML::Load("model: 2-omap\ndarts: 3\nlinks:\n  1: {cycles: [[0, 1, 2]]}\n  2: {pairs: [[0, 1]], loops: [2]}\n"));
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
  // An unclosed [ is named at the bracket (yaml-cpp stops at the end, line 3).
  EXPECT_EQ(error_of("model: 2-gmap\ndarts: [\n").substr(0, 3), "2:8") << "malformed YAML";
}
