// Silent acceptance (issue 62): what a reader used to take without a word,
// the first value winning or the data cut at a count, is refused at its
// line and column. Each expected position is the offending byte's, counted
// by hand in the literal.
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/input_error.hpp"
#include "io/catalog.hpp"
#include "io/jerboa_jba.hpp"
#include "io/jerboa_modeler.hpp"
#include "io/jerboa_modeler_writer.hpp"
#include "io/mesh_io.hpp"
#include "io/tet_mesh_io.hpp"
#include "tests/io/io_support.hpp"

using namespace dartcheck;
using namespace dartcheck::testing_support;

namespace {

// A file of this test's own holding `text` (bytes as given, NULs included).
std::string file_with(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() /
                   fmt::format("dartcheck-silent-{}-{}", ::testing::UnitTest::GetInstance()->current_test_info()->name(), ::getpid());
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

const std::string rule_text =
    "rules:\n"
    "  - name: r\n"
    "    model: 2-gmap\n"
    "    verdict: consistent\n"
    "    hooks: [x]\n"
    "    left: {nodes: [x], arcs: [\"x -0- x\", \"x -1- x\", \"x -2- x\"]}\n"
    "    right: {nodes: [x], arcs: [\"x -0- x\", \"x -1- x\", \"x -2- x\"]}\n";

}  // namespace

TEST(HostileInputSilent, YamlDuplicateKeysAreRefusedAtTheSecond) {
  // The first value used to win: a catalog recorded `consistent` and was read as failing.
  const auto verdict = error_of(rule_text + "    verdict: [\"I(1)\"]\n", true);
  EXPECT_EQ(verdict.substr(0, 4), "8:5 ") << verdict;
  EXPECT_NE(verdict.find("duplicate key 'verdict' (first at line 4, column 5)"), std::string::npos) << verdict;
  const auto rules = error_of(rule_text + "rules: []\n", true);
  EXPECT_EQ(rules.substr(0, 4), "8:1 ") << rules;
  const auto darts = error_of("model: 2-gmap\ndarts: 1\ndarts: 2\nlinks: {}\n");
  EXPECT_EQ(darts.substr(0, 4), "3:1 ") << darts;
  EXPECT_NE(darts.find("duplicate key 'darts'"), std::string::npos) << darts;
  // A flow mapping: the second 0 is at column 26.
  EXPECT_NE(error_of("model: 2-gmap\ndarts: 1\nlinks: {0: {loops: all}, 0: {loops: all}}\n").find(":3:26: duplicate key '0'"), std::string::npos);
  // Equal values, distinct keys: accepted.
  EXPECT_EQ(error_of("model: 2-gmap\ndarts: 1\nlinks: {0: {loops: all}, 1: {loops: all}, 2: {loops: all}}\n"), "no error");
}

TEST(HostileInputSilent, NulBytesAreRefusedInEveryTextFormat) {
  const auto raw = message_of([] { read_catalog(file_with("raw.yaml", std::string("rules:\n  - name: a\0b\n", 21))); });
  EXPECT_NE(raw.find(":2:12: a NUL byte: a YAML file is text"), std::string::npos) << raw;
  const auto escaped = error_of("rules:\n  - name: \"a\\0b\"\n", true);
  EXPECT_EQ(escaped.substr(0, 5), "2:11 ") << escaped;
  EXPECT_NE(escaped.find("a NUL character"), std::string::npos) << escaped;
  const auto jba = message_of([] { read_jba(file_with("x.jba", std::string("Jerboa JBA Generic Format\nversion\0 1\n", 38))); });
  EXPECT_NE(jba.find(":2:8: a NUL byte: a .jba file is text"), std::string::npos) << jba;
  const auto jme = message_of([] { read_jme(file_with("x.jme", std::string("<?xml version=\"1.0\"?>\n<m\0/>\n", 28))); });
  EXPECT_NE(jme.find(":2:3: a NUL byte: a .jme file is text"), std::string::npos) << jme;
}

TEST(HostileInputSilent, CountsSmallerThanTheDataAreRefused) {
  // OFF: 3 vertices announced, a fourth vertex line read as the face line
  // fails; here the count of faces is 1 and a second face follows.
  const std::string off = "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n";
  const auto o = message_of([&] { read_mesh(file_with("x.off", off)); });
  EXPECT_NE(o.find(":8:1: data after the 4 vertices and 1 faces the counts announce (line 2)"), std::string::npos) << o;
  EXPECT_EQ(message_of([&] { read_mesh(file_with("y.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n")); }), "no error");

  // TetGen: one point too many in .node, one tetrahedron too many in .ele.
  const std::string node = "# points\n4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n";
  const std::string ele = "1 4 0\n0 0 1 2 3\n";
  file_with("t.ele", ele);
  const auto n = message_of([&] { read_tetgen(file_with("t.node", node + "4 1 1 1\n")); });
  EXPECT_NE(n.find("t.node:7:1: data after the 4 points the header announces (line 2)"), std::string::npos) << n;
  file_with("t.node", node);
  EXPECT_EQ(message_of([&] { read_tetgen(file_with("t.ele", ele)); }), "no error");
  const auto e = message_of([&] { read_tetgen(file_with("t.ele", ele + "1 0 1 3 2\n")); });
  EXPECT_NE(e.find("t.ele:3:1: data after the 1 tetrahedra the header announces (line 1)"), std::string::npos) << e;

  // medit: Vertices says 4 and five lines follow.
  const std::string medit =
      "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n";
  const auto m = message_of([&] { read_medit(file_with("x.mesh", medit)); });
  EXPECT_NE(m.find(":9:1: '1' where a section name"), std::string::npos) << m;

  // .jba: a dart count of 1 and two dart lines.
  const std::string jba = "Jerboa JBA Generic Format\nversion 1\nname x\ndimension 1\nnbebd 0\n1 0\n0 0 0\n1 1 1\n";
  const auto j = message_of([&] { read_jba(file_with("c.jba", jba)); });
  EXPECT_NE(j.find(":8:1: a dart line after the 1 darts the dart count announces"), std::string::npos) << j;
}

TEST(HostileInputSilent, MessagesNameWhatIsWrong) {
  // 600 nested lists: yaml-cpp's limit, which it words "bad file".
  const auto deep = error_of("a: " + std::string(600, '[') + std::string(600, ']') + "\n", true);
  EXPECT_NE(deep.find("collections nested deeper than"), std::string::npos) << deep;
  // A null where an integer is expected: not "a collection".
  const auto null = error_of("model: 2-gmap\ndarts: ~\nlinks: {}\n");
  EXPECT_NE(null.find("got nothing (a null)"), std::string::npos) << null;
  // A loop of symbolic links: not "no such file".
  const auto dir = std::filesystem::path(file_with("anchor", "")).parent_path();
  std::filesystem::remove(dir / "loop1");
  std::filesystem::remove(dir / "loop2");
  std::filesystem::create_symlink(dir / "loop2", dir / "loop1");
  std::filesystem::create_symlink(dir / "loop1", dir / "loop2");
  const auto loop = message_of([&] { read_catalog((dir / "loop1").string()); });
  EXPECT_NE(loop.find("a loop of symbolic links"), std::string::npos) << loop;
}

TEST(HostileInputSilent, NamesXmlCannotHoldAreNamed) {
  // infer --name "a\x01b" -o x.jme wrote "&#1;", which no XML 1.0 reader accepts.
  EXPECT_EQ(xml_name_problem("a\x01" "b"), "a control character (\\x01)");
  EXPECT_EQ(xml_name_problem("\x7f"), std::nullopt);  // DEL is a character XML 1.0 allows
  EXPECT_EQ(xml_name_problem("tab\tand line\nend\r"), std::nullopt);
  EXPECT_EQ(xml_name_problem("Kaleidoscope \xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80"), std::nullopt);  // é, €, an emoji
  EXPECT_EQ(xml_name_problem("\xef\xbf\xbe"), "the non-character U+FFFE");
  EXPECT_EQ(xml_name_problem("\xef\xbf\xbf"), "the non-character U+FFFF");
  for (const char* bad : {"\xff", "\xc3", "\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "\xe2\x82"})
    EXPECT_EQ(xml_name_problem(bad), "invalid UTF-8") << printable(bad);
}
