// Hostile and mistaken input to every reader (issue 21): each defect found
// by hand and by the fuzzer gets a clear error at its position, never a
// crash, an allocation of what the file merely announces, or raw bytes.
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/input_error.hpp"
#include "core/limits.hpp"
#include "io/catalog.hpp"
#include "io/jerboa_jba.hpp"
#include "io/mesh_io.hpp"
#include "tests/io/io_support.hpp"

using namespace dartcheck;
using namespace dartcheck::testing_support;

namespace {

std::string temp_path(const std::string& ext) {
  return (std::filesystem::temp_directory_path() /
          fmt::format("dartcheck-hostile-{}-{}{}", ::testing::UnitTest::GetInstance()->current_test_info()->name(), ::getpid(), ext))
      .string();
}

bool has_control_bytes(const std::string& s) {
  for (unsigned char c : s)
    if (c < 0x20 || c == 0x7f) return true;
  return false;
}

}  // namespace

TEST(HostileInput, NullDartInLoopsAndCyclesIsAnErrorNotAWrite) {
  // Both crashed validate-map with SIGSEGV: '~' became dart 2^32 - 1.
  EXPECT_EQ(error_of("model: 2-gmap\ndarts: 1\nlinks:\n  0: {loops: [~]}\n").substr(0, 5), "4:15 ");
  EXPECT_EQ(error_of("model: 2-omap\ndarts: 1\nlinks:\n  1: {cycles: [[~, 0]]}\n").substr(0, 5), "4:17 ");
  EXPECT_EQ(error_of("model: 2-omap\ndarts: 1\nlinks:\n  1: {cycles: [[0, ~]]}\n").substr(0, 5), "4:20 ");
  EXPECT_NE(error_of("model: 2-gmap\ndarts: 2\nlinks:\n  0: {pairs: [[0, ~]]}\n").find("expected a dart"), std::string::npos);
  // The same map inline in a catalog.
  EXPECT_NE(error_of("maps:\n  m: {model: 2-gmap, darts: 1, links: {0: {loops: [~]}}}\n", true).find("2:52"), std::string::npos);
}

TEST(HostileInput, DartCountsAreBoundedBeforeAllocation) {
  const auto yaml = error_of("model: 2-gmap\ndarts: 2147483648\nlinks: {}\n");
  EXPECT_EQ(yaml.substr(0, 4), "2:8 ") << yaml;
  EXPECT_NE(yaml.find("over the limit of 33554432"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("--limit-darts"), std::string::npos) << yaml;
  // The limit can be raised, and lowered for this test.
  const Limits saved = limits();
  limits().darts = 3;
  EXPECT_NE(error_of("model: 2-gmap\ndarts: 4\nlinks: {}\n").find("over the limit of 3"), std::string::npos);
  EXPECT_EQ(error_of("model: 2-gmap\ndarts: 3\nlinks: {}\n"), "no error");
  limits() = saved;

  // A .jba count line: an error at its line, not bad_alloc; and a count the
  // file does not back with dart lines ends at the missing line, having
  // allocated nothing for it.
  const std::string head = "Jerboa JBA Generic Format\nversion 1\nname x\ndimension 2\nnbebd 0\n";
  const auto write = [&](const std::string& text) {
    const auto p = temp_path(".jba");
    std::ofstream(p, std::ios::binary) << text;
    return p;
  };
  const auto huge = message_of([&] { read_jba(write(head + "2147483648 0\n")); });
  EXPECT_NE(huge.find(":6:"), std::string::npos) << huge;
  EXPECT_NE(huge.find("over the limit"), std::string::npos) << huge;
  const auto unbacked = message_of([&] { read_jba(write(head + "33554432 0\n0 0 0 0\n")); });
  EXPECT_NE(unbacked.find("the file ends where dart 2 of 33554432 was expected"), std::string::npos) << unbacked;
}

TEST(HostileInput, ScalarWhereARuleSideBelongsNamesTheFile) {
  // Was: "operator[] call on a scalar (key: "nodes")", with no file.
  const auto e = error_of("rules:\n  - name: r\n    model: 2-gmap\n    hooks: [a]\n    left: 5\n    right: {nodes: [a]}\n", true);
  EXPECT_EQ(e.substr(0, 5), "5:11 ") << e;
  EXPECT_NE(e.find("left: expected a mapping"), std::string::npos) << e;
}

TEST(HostileInput, DirectoriesAndBinaryFilesAreNamedAndPrintable) {
  const std::string dir = std::filesystem::temp_directory_path().string();
  const auto catalog = message_of([&] { read_catalog(dir); });
  EXPECT_EQ(catalog, dir + ": is a directory, not a file");
  const auto jba = message_of([&] { read_jba(dir); });
  EXPECT_EQ(jba, dir + ": is a directory, not a file");
  const auto mesh = message_of([&] { read_mesh(dir + "/x.off"); });
  EXPECT_NE(mesh.find("no such file"), std::string::npos) << mesh;

  const auto binary = temp_path(".yaml");
  std::ofstream(binary, std::ios::binary) << std::string("a: \"\\\0\x01\x7f\xff\"\n", 10);
  const auto m = message_of([&] { read_catalog(binary); });
  EXPECT_EQ(m.rfind(binary, 0), 0U) << m;
  EXPECT_FALSE(has_control_bytes(m)) << m;
  EXPECT_EQ(printable(std::string("a\x01\xff\xc3\xa9\t\n\x1b", 8)), "a\\x01\\xffé\t\n\\x1b");
}
