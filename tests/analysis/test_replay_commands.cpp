// Replay commands are pasted into a shell (issue 62, item 3), and per-rule
// file names are shared by every rule of a run (item 2). Property: for
// any rule name and catalog path (any bytes but NUL), the printed replay
// line, run by /bin/sh with `dartcheck` replaced by a function that
// prints its arguments, gives back exactly the argv dartcheck meant; and
// file_stem is injective.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/counterexample_files.hpp"
#include "analysis/embedded_fuzz.hpp"
#include "core/shell_quote.hpp"

using namespace dartcheck;

namespace {

// The arguments /bin/sh gives to `dartcheck` in `line`, NUL-separated.
std::vector<std::string> sh_argv(const std::string& line) {
  const std::string script = "dartcheck() { for a in \"$@\"; do printf '%s\\0' \"$a\"; done; }; " + line;
  // A file of its own: ctest runs the tests of this file in parallel.
  std::string path = (std::filesystem::temp_directory_path() / "dartcheck-replay-XXXXXX").string();
  const int fd = mkstemp(path.data());
  if (fd < 0) return {};
  if (std::FILE* f = fdopen(fd, "wb")) {
    std::fwrite(script.data(), 1, script.size(), f);
    std::fclose(f);
  }
  std::vector<std::string> out;
  std::FILE* p = popen(("/bin/sh " + path).c_str(), "r");
  if (!p) return out;
  std::string current;
  for (int c; (c = std::fgetc(p)) != EOF;) {
    if (c == 0) {
      out.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(c);
    }
  }
  pclose(p);
  std::filesystem::remove(path);
  return out;
}

std::string without_nul(std::string s) {
  for (char& c : s)
    if (c == '\0') c = 'x';
  return s;
}

}  // namespace

RC_GTEST_PROP(ShellQuote, ShReadsBackTheSameWord, (std::string word)) {
  word = without_nul(word);
  const auto argv = sh_argv("dartcheck " + shell_quote(word));
  RC_ASSERT(argv == std::vector<std::string>{word});
}

// The fuzz replay line of a hostile rule name on a hostile catalog path:
// `ok;$(touch PWNED)` stays one argument and runs nothing.
TEST(ReplayCommands, FuzzReplayOfHostileNamesParsesBackIntoItsArgv) {
  for (const std::string name : {"ok;$(touch PWNED)", "a b", "it's", "back\\slash", "new\nline", "$HOME", "`id`", "-rf", "\x1b[31mred"}) {
    analysis::FuzzReport r;
    r.rule = name;
    r.applications = 12;
    const auto argv = sh_argv(analysis::embedded_replay("cat alog's.yaml", r, 7));
    EXPECT_EQ(argv, (std::vector<std::string>{"fuzz", "cat alog's.yaml", "--rule", name, "--seed", "7", "--runs", "12"})) << name;
  }
  EXPECT_FALSE(std::filesystem::exists("PWNED"));
}

// file_stem is injective: names that the old mapping (space and '/' to
// '.') confused get different stems, and a variant's '/' still reads '.'.
TEST(ReplayCommands, FileStemsNeverCollide) {
  EXPECT_NE(analysis::file_stem("a b"), analysis::file_stem("a.b"));
  EXPECT_NE(analysis::file_stem("a/b"), analysis::file_stem("a.b"));
  EXPECT_NE(analysis::file_stem("a%2Eb"), analysis::file_stem("a.b"));
  EXPECT_EQ(analysis::file_stem("fig25a-edge-removal/unlabeled"), "fig25a-edge-removal.unlabeled");
}

RC_GTEST_PROP(ReplayCommands, FileStemIsInjective, (std::string a, std::string b)) {
  RC_PRE(a != b);
  RC_ASSERT(analysis::file_stem(a) != analysis::file_stem(b));
}
