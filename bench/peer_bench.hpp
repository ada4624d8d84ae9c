// Shared by the programs that time dartcheck against a peer library on
// one OFF input (bench_quad_subdivision, bench_triangulation,
// bench_catmull_clark): the input torus, resident-memory probes, medians,
// one child process per peer so that each peak RSS is its own, and the
// machine line that pins every peer to one CPU.
#pragma once

#include <sched.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "core/orbit.hpp"

namespace {

// One dart of every <dims>-orbit of g (a hook per face, per component...),
// found before a clock starts.
[[maybe_unused]] std::vector<dartcheck::Dart> orbit_hooks(const dartcheck::Map& g, const std::vector<dartcheck::Dim>& dims) {
  using namespace dartcheck;
  std::vector<Dart> hooks;
  OrbitWalker walker(g);
  const auto gens = dims_generators(dims);
  std::vector<bool> seen(g.size());
  for (Dart d = 0; d < g.size(); ++d)
    if (!seen[d]) {
      hooks.push_back(d);
      for (Dart x : walker.orbit(d, gens)) seen[x] = true;
    }
  return hooks;
}

// A closed quad torus of r x c faces: V = rc, E = 2rc, F = rc; 8rc darts in
// a 2-G-map, 4rc in a 2-O-map.
[[maybe_unused]] void write_torus_off(const std::string& path, int r, int c) {
  std::ofstream out(path);
  out << "OFF\n" << r * c << " " << r * c << " 0\n";
  const double pi = 3.14159265358979;
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < c; ++j) {
      const double u = 2 * pi * i / r, v = 2 * pi * j / c;
      out << (3 + std::cos(v)) * std::cos(u) << " " << (3 + std::cos(v)) * std::sin(u) << " " << std::sin(v) << "\n";
    }
  auto id = [&](int i, int j) { return ((i + r) % r) * c + (j + c) % c; };
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < c; ++j) out << "4 " << id(i, j) << " " << id(i + 1, j) << " " << id(i + 1, j + 1) << " " << id(i, j + 1) << "\n";
}

// The input of the mesh benchmarks (bench_triangulation,
// bench_catmull_clark): [--runs N] [--mesh FILE.off | --grid RxC]
// [--only TEXT]. A grid is written to a temporary OFF file, removed by
// the destructor.
struct MeshInput {
  int runs = 5;
  std::string off, only, temporary;
  MeshInput(const MeshInput&) = delete;
  MeshInput& operator=(const MeshInput&) = delete;
  MeshInput() = default;
  ~MeshInput() {
    if (!temporary.empty()) std::remove(temporary.c_str());
  }
  // False (after the usage line) on anything else.
  bool parse(int argc, char** argv, const std::string& default_mesh, const std::string& program) {
    int r = 0, c = 0;
    off = default_mesh;
    for (int k = 1; k < argc; ++k) {
      if (!std::strcmp(argv[k], "--runs") && k + 1 < argc)
        runs = std::atoi(argv[++k]);
      else if (!std::strcmp(argv[k], "--mesh") && k + 1 < argc)
        off = argv[++k];
      else if (!std::strcmp(argv[k], "--only") && k + 1 < argc)
        only = argv[++k];
      else if (!std::strcmp(argv[k], "--grid") && k + 1 < argc && std::sscanf(argv[++k], "%dx%d", &r, &c) == 2)
        continue;
      else {
        std::fprintf(stderr, "usage: %s [--runs N] [--mesh FILE.off | --grid RxC] [--only TEXT]\n", argv[0]);
        return false;
      }
    }
    if (r > 0) {
      off = temporary = "/tmp/dartcheck-bench-" + program + "-" + std::to_string(getpid()) + ".off";
      write_torus_off(off, r, c);
    }
    return true;
  }
};

long rss_kib() {
  long pages = 0, resident = 0;
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (f) {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    std::fclose(f);
  }
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}
long peak_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

// The cost of a first touch of a page (a fault that maps a zeroed page),
// in microseconds: the median of 5 probes of 64 MiB. It varies by a factor
// of 40 between the VMs these benches ran on (0.25 to 11 us), and peers
// that take fresh memory on every run (CGAL's Compact_container, OpenMesh's
// vectors, growing tables) pay it per page, so every run prints it beside
// whether glibc keeps freed memory in the process (GLIBC_TUNABLES, see
// BENCHMARKS.md).
inline double page_fault_us() {
  constexpr std::size_t bytes = std::size_t{64} << 20;
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  std::vector<double> probes;
  for (int k = 0; k < 5; ++k) {
    void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) return 0;
    volatile char* c = static_cast<char*>(p);
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < bytes; i += page) c[i] = 1;
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
    munmap(p, bytes);
    probes.push_back(us / static_cast<double>(bytes / page));
  }
  std::sort(probes.begin(), probes.end());
  return probes[probes.size() / 2];
}

struct Result {
  double median_ms = 0;
  double peak_mib = 0;
  std::size_t out_elements = 0;  // darts (dartcheck, CGAL) or halfedges (OpenMesh)
  bool ok = false;
};

// Runs `subdivide` (which copies its input untimed and returns the
// subdivision time and the output size) once for memory, then `runs` times.
template <class F>
Result measure(int runs, F subdivide) {
  Result r;
  const long base = rss_kib();
  double ms = 0;
  r.ok = subdivide(ms, r.out_elements);
  r.peak_mib = static_cast<double>(std::max(0L, peak_kib() - base)) / 1024.0;
  std::vector<double> times;
  for (int k = 0; k < runs; ++k) {
    std::size_t n = 0;
    subdivide(ms, n);
    times.push_back(ms);
  }
  std::sort(times.begin(), times.end());
  r.median_ms = times[times.size() / 2];
  return r;
}

[[maybe_unused]] double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Runs `run` in a forked child and reads its result (a trivially copyable
// T, a Result by default) back through a pipe.
template <class T = Result>
T run_in_child(const std::function<T()>& run) {
  int pipefd[2];
  if (pipe(pipefd) != 0) return {};
  const pid_t pid = fork();
  if (pid == 0) {
    close(pipefd[0]);
    const T res = run();
    if (write(pipefd[1], &res, sizeof res) != sizeof res) _exit(1);
    _exit(0);
  }
  close(pipefd[1]);
  T res{};
  if (read(pipefd[0], &res, sizeof res) != sizeof res) res = {};
  close(pipefd[0]);
  waitpid(pid, nullptr, 0);
  return res;
}

// Milliseconds of a chase of dependent loads through a random cycle over
// 8 MiB (beyond a core's own caches, as the rows' maps are) on the calling
// thread: the best of 3, so a CPU's speed as these benches use it.
inline double cpu_probe_ms() {
  constexpr std::size_t slots = (std::size_t{8} << 20) / sizeof(std::uint32_t);
  std::vector<std::uint32_t> order(slots), next(slots);
  for (std::size_t k = 0; k < slots; ++k) order[k] = static_cast<std::uint32_t>(k);
  std::uint64_t x = 88172645463325252ULL;  // xorshift64: the same cycle on every CPU
  for (std::size_t k = slots - 1; k > 0; --k) {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    std::swap(order[k], order[x % (k + 1)]);
  }
  for (std::size_t k = 0; k < slots; ++k) next[order[k]] = order[(k + 1) % slots];
  double best = 1e300;
  for (int round = 0; round < 3; ++round) {
    std::uint32_t at = order[0];
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < 300'000; ++k) at = next[at];
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    volatile std::uint32_t sink = at;
    (void)sink;
  }
  return best;
}

// The vCPUs of a VM need not run at one speed: on the 2-core machines of
// these benches one ran 1.5x slower than the other for hours (2026-11-28),
// and the scheduler moves a process, and each forked row, between them, so
// two rows of one run could be timed on different CPUs and their ratio be
// off by that factor. Pins the process (and so every row it forks) to the
// fastest CPU it may use, by cpu_probe_ms on each, and says so with every
// CPU's probe time. DARTCHECK_BENCH_CPU=k pins to CPU k instead.
inline std::string pin_to_one_cpu() {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return "not pinned (sched_getaffinity failed)";
  std::string probes;
  int best = -1;
  double best_ms = 1e300;
  const char* forced = std::getenv("DARTCHECK_BENCH_CPU");
  for (int c = 0; c < CPU_SETSIZE; ++c) {
    if (!CPU_ISSET(c, &allowed)) continue;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(c, &one);
    if (sched_setaffinity(0, sizeof one, &one) != 0) continue;
    // In a child: the probe's 16 MiB must not raise the peak RSS that
    // the rows' children inherit from this process.
    const double ms = run_in_child<double>(std::function<double()>(cpu_probe_ms));
    char probe[64];
    std::snprintf(probe, sizeof probe, "%sCPU %d %.2f ms", probes.empty() ? "" : ", ", c, ms);
    probes += probe;
    if (forced ? std::atoi(forced) == c : ms < best_ms) {
      best = c;
      best_ms = ms;
    }
  }
  if (best < 0) {
    sched_setaffinity(0, sizeof allowed, &allowed);
    return "not pinned (no usable CPU" + std::string(forced ? " matches DARTCHECK_BENCH_CPU" : "") + "); probes: " + probes;
  }
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(best, &one);
  sched_setaffinity(0, sizeof one, &one);
  return "every row on CPU " + std::to_string(best) + (forced ? " (DARTCHECK_BENCH_CPU)" : " (the fastest)") + "; probes: " + probes;
}

inline void print_machine_line() {
  const std::string pinned = pin_to_one_cpu();
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::printf("machine: a page's first touch costs %.2f us; GLIBC_TUNABLES=%s; %s\n", page_fault_us(), tunables ? tunables : "(unset)",
              pinned.c_str());
}

}  // namespace
