// OFF/OBJ meshes: real meshes made elsewhere, and malformed files.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <algorithm>

#include <fmt/format.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checkers/map_validity.hpp"
#include "io/catalog.hpp"
#include "core/input_error.hpp"
#include "io/map_io.hpp"
#include "io/detail/yaml_util.hpp"
#include "core/orbit.hpp"
#include "generators/mesh_map.hpp"
#include "io/mesh_io.hpp"
#include "io/mesh_writer.hpp"
#include "generators/polygon_soup.hpp"
#include "core/isomorphism.hpp"
#include "generators/random_maps.hpp"

#include "tests/io/io_support.hpp"

using namespace dartcheck;
using namespace dartcheck::testing_support;

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

// The mesh writer inverts read_mesh + mesh_with_positions: written as OFF
// and as OBJ and read back, a mesh gives an isomorphic 2-G-map, the same
// vertex positions and as many faces. Meshes: the catalog's cube, the unit
// square (a boundary) and a Moebius band (non-orientable). An O-map has no
// positions to write: refused.
TEST(MeshWriter, RoundTripsThroughOffAndObj) {
  const std::string root = DARTCHECK_SOURCE_DIR;
  const EmbeddingSignature pos{"pos", ValueType::point3, {1, 2}};
  for (const std::string& file : {root + "/catalogs/meshes/cube.off", root + "/catalogs/meshes/unit-square.off", data("moebius.off")}) {
    const Mesh mesh = read_mesh(file);
    const EmbeddedMap m = mesh_with_positions(Model::gmap(2), mesh, pos);
    for (const char* ext : {".off", ".obj"}) {
      std::ostringstream out;
      write_mesh(out, m, "pos", std::string("x") + ext);
      const std::string path = (std::filesystem::temp_directory_path() / (fmt::format("dartcheck-mesh-{}", ::getpid()) + ext)).string();
      std::ofstream(path) << out.str();
      const Mesh back = read_mesh(path);
      std::filesystem::remove(path);
      const EmbeddedMap n = mesh_with_positions(Model::gmap(2), back, pos);
      EXPECT_TRUE(isomorphic(m.map, n.map)) << file << ext;
      auto sorted = [](std::vector<std::array<double, 3>> p) {
        std::sort(p.begin(), p.end());
        return p;
      };
      EXPECT_EQ(sorted(back.positions), sorted(mesh.positions)) << file << ext;
      EXPECT_EQ(back.faces.size(), mesh.faces.size()) << file << ext;
    }
  }
  EmbeddedMap o(build_surface(Model::omap(2), {{0, 1, 2, 3}}));
  std::ostringstream sink;
  EXPECT_THROW(write_mesh(sink, o, "pos", "o.off"), InputError);
  EmbeddedMap bare(build_surface(Model::gmap(2), {{0, 1, 2, 3}}));
  EXPECT_THROW(write_mesh(sink, bare, "pos", "bare.off"), InputError);  // no positions
}
