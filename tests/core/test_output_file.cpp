// Outputs written atomically (core/output_file, issue 62 item 1): a writer
// stopped part way, by a failure or by SIGKILL, leaves the previous file
// as it was and no temporary beside it; links, devices and permissions.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/output_file.hpp"

using namespace dartcheck;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh directory holding one file, `name`, with `content`.
fs::path directory_with(const std::string& name, const std::string& content) {
  static int n = 0;
  const fs::path dir = fs::temp_directory_path() / ("dartcheck-output-" + std::to_string(::getpid()) + "-" + std::to_string(n++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << content;
  return dir;
}

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

const std::string big(3 << 16, 'x');  // three chunks of the writer

}  // namespace

TEST(OutputFile, AFailureMidWriteLeavesThePreviousFileAndNoTemporary) {
  const fs::path dir = directory_with("report.json", "previous");
  detail::write_hook = [](std::size_t written) {
    if (written >= (1 << 16)) throw OutputError("report.json", "the test's failure after one chunk");
  };
  EXPECT_THROW(write_file((dir / "report.json").string(), big), OutputError);
  detail::write_hook = nullptr;
  EXPECT_EQ(slurp(dir / "report.json"), "previous");
  EXPECT_EQ(entries(dir), 1U);
  write_file((dir / "report.json").string(), big);
  EXPECT_EQ(slurp(dir / "report.json"), big);
  EXPECT_EQ(entries(dir), 1U);
  fs::remove_all(dir);
}

// SIGKILL after the first chunk, in a child: nothing can run after it, so
// only an unnamed temporary (O_TMPFILE) leaves the directory clean.
TEST(OutputFile, AWriterKilledMidWriteLeavesThePreviousFile) {
  const fs::path dir = directory_with("index.html", "<p>the previous report</p>");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    detail::write_hook = [](std::size_t written) {
      if (written >= (1 << 16)) ::kill(::getpid(), SIGKILL);
    };
    write_file((dir / "index.html").string(), big);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  EXPECT_EQ(slurp(dir / "index.html"), "<p>the previous report</p>");
  EXPECT_EQ(entries(dir), 1U) << "a temporary was left behind";
  fs::remove_all(dir);
}

TEST(OutputFile, ALinkKeepsPointingAtTheReplacedFile) {
  const fs::path dir = directory_with("real.yaml", "old");
  fs::create_symlink(dir / "real.yaml", dir / "link.yaml");
  write_file((dir / "link.yaml").string(), "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.yaml"));
  EXPECT_EQ(slurp(dir / "real.yaml"), "new");
  EXPECT_EQ(entries(dir), 2U);
  fs::remove_all(dir);
}

TEST(OutputFile, PermissionsOfTheTargetAreKept) {
  const fs::path dir = directory_with("out.hpp", "old");
  fs::permissions(dir / "out.hpp", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_file((dir / "out.hpp").string(), "new");
  EXPECT_EQ(fs::status(dir / "out.hpp").permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  fs::remove_all(dir);
}

TEST(OutputFile, ADeviceIsWrittenInPlace) {
  write_file("/dev/null", big);
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_THROW(write_file("/dev/full", "x"), OutputError);
}
