#include "campaign/jobs.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/terminal.hpp"
#include "analysis/exit_status.hpp"
#include "analysis/interrupt.hpp"
#include "core/input_error.hpp"
#include "io/input_file.hpp"

extern char** environ;

namespace dartcheck::campaign {

namespace {

std::vector<std::string>& command_line() {
  static std::vector<std::string> args;
  return args;
}

// The arguments of shard k: the command line without --jobs and --format
// (both spellings), with the shard, its lines and the shared seed.
std::vector<std::string> shard_arguments(std::size_t k, std::size_t shards, const JobsRun& run, std::optional<double> budget) {
  std::vector<std::string> out;
  const auto& args = command_line();
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--jobs" || a == "--format") {
      ++i;  // and its value
      continue;
    }
    if (a.starts_with("--jobs=") || a.starts_with("--format=")) continue;
    out.push_back(a);
  }
  for (std::string a : {std::string("--shard"), fmt::format("{}/{}", k, shards), std::string("--format"), std::string("jsonl")}) out.push_back(a);
  if (run.seed) {
    out.push_back("--seed");
    out.push_back(std::to_string(*run.seed));
  }
  if (budget) {
    out.push_back("--shard-budget");
    out.push_back(fmt::format("{}", *budget));
  }
  return out;
}

pid_t spawn(const std::vector<std::string>& args, const std::string& out, const std::string& err) {
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, "/proc/self/exe", &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (rc != 0) throw Error(fmt::format("--jobs: cannot start a shard process: {}", std::strerror(rc)));
  return pid;
}

// The shards' files: in $TMPDIR (or /tmp), in a directory of this run's
// own, removed with what it holds when the run ends.
class JobsDirectory {
 public:
  JobsDirectory() {
    const char* tmp = std::getenv("TMPDIR");
    const std::string parent = tmp && *tmp ? tmp : "/tmp";
    std::string dir_template = parent + "/dartcheck-jobs-XXXXXX";
    if (!mkdtemp(dir_template.data()))
      throw Error(fmt::format("--jobs: cannot create a directory in {}: {}", printable(parent), std::strerror(errno)));
    path_ = dir_template;
  }
  JobsDirectory(const JobsDirectory&) = delete;
  JobsDirectory& operator=(const JobsDirectory&) = delete;
  ~JobsDirectory() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// A second signal: every shard killed and reaped.
void kill_shards(std::map<pid_t, std::size_t>& running) {
  for (const auto& [pid, k] : running) ::kill(pid, SIGKILL);
  for (int status = 0; !running.empty();) {
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid > 0)
      running.erase(pid);
    else if (errno != EINTR)
      running.clear();  // no child left to wait for
  }
}

// A shard's exit status if it stops the run, else 0: 0, 1 and 3 are
// verdicts, which the merge reports; 130 and SIGTERM after a signal are
// the stop this run asked for; anything else stops it.
int shard_failure(int status) {
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  const bool stopped = analysis::interrupted() && (code == analysis::interrupted_exit || code == 128 + SIGTERM);
  if (code == exit_status::ok || code == exit_status::violation || code == exit_status::soundness_bug || stopped) return 0;
  return code;
}

}  // namespace

void set_command_line(int argc, char** argv) { command_line().assign(argv, argv + argc); }

int run_jobs(const JobsRun& run) {
  if (!run.shard.empty()) throw UsageError("--jobs with --shard: run a shard on one job, or the whole run on several");
  if (command_line().empty()) throw InternalError("run_jobs: the command line was not saved");
  analysis::catch_interrupts();  // Ctrl-C reaches the shards too (one process group); they stop and say so
  analysis::count_second_interrupt();  // a second signal kills the shards before the parent goes
  const JobsDirectory jobs_dir;
  const std::string& dir = jobs_dir.path();

  // Four shards per job, started as jobs finish: a rule hashes to a shard
  // whatever its cost, so finer shards even out the processes' loads.
  const std::size_t shards = run.jobs * 4;
  if (!terminal().quiet)
    fmt::print(stderr, "dartcheck: {} shards on {} processes{}\n", shards, run.jobs,
               run.seed ? fmt::format(", seed {} (replay with --seed {})", *run.seed, *run.seed) : "");
  MergeRequest merge = run.merge;
  std::map<pid_t, std::size_t> running;
  int failed = 0;
  bool forwarded = false;
  const auto start = std::chrono::steady_clock::now();
  const auto signal_shards = [&](int signal) {
    for (const auto& [pid, k] : running) ::kill(pid, signal);
  };
  for (std::size_t next = 0; (next < shards && !analysis::interrupted()) || !running.empty();) {
    if (analysis::interrupted_twice()) {
      kill_shards(running);
      fmt::print(stderr, "interrupted again: the shards were killed; nothing is merged\n");
      return analysis::interrupted_exit;
    }
    // A signal to the parent alone (SIGTERM from a scheduler) reaches the shards too.
    if (analysis::interrupted() && !forwarded) {
      signal_shards(SIGTERM);
      forwarded = true;
    }
    if (!analysis::interrupted() && next < shards && running.size() < run.jobs) {
      std::optional<double> budget;
      if (run.budget_seconds) {
        const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::size_t waves = (shards - next + run.jobs - 1) / run.jobs;
        budget = std::max(0.001, (*run.budget_seconds - spent) / static_cast<double>(waves));
      }
      merge.shards.push_back(fmt::format("{}/{}.jsonl", dir, next));
      running[spawn(shard_arguments(next, shards, run, budget), merge.shards.back(), fmt::format("{}/{}.err", dir, next))] = next;
      ++next;
      continue;
    }
    // Polled, not blocking: a signal must be seen while every shard runs.
    int status = 0;
    const pid_t pid = waitpid(-1, &status, WNOHANG);
    if (pid == 0) {
      const timespec pause{0, 20'000'000};  // 20 ms
      ::nanosleep(&pause, nullptr);
      continue;
    }
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw Error(fmt::format("--jobs: waiting for the shards: {}", std::strerror(errno)));
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const std::size_t k = it->second;
    running.erase(it);
    if (const int code = shard_failure(status); code != 0) {
      fmt::print(stderr, "shard {}/{} exited with {}:\n{}", k, shards, code, read_input(fmt::format("{}/{}.err", dir, k)));
      if (!failed) failed = code;
    }
  }
  if (failed) return failed;
  // After a signal: the finished shards' rules, and the interrupted shards' finished ones.
  merge.incomplete = analysis::interrupted();
  merge.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return merge_shards(merge);
}

}  // namespace dartcheck::campaign
