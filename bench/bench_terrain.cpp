// 001 Sec. 7.4, Table 2: a 128 x 128 voxel terrain (diamond-square
// heights, one voxel per cell, bottoms split into two triangles), 50 flat
// spots by a query-apply, 50 houses by a query-extend with created
// vertices placed by mean value coordinates (Sec. 6.5). Prints each step's
// volumes, darts and times (medians of --runs, each run from scratch)
// next to 001's figures, and the peak resident memory of the process.
// Every run is checked: the counts Table 2 gives (houses: ours are 192
// darts, 001's 234), a valid 3-map, and each roof's apex above its spot.
//
//   build/bench/bench_terrain [--runs 5] [--seed 2025]
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "peer_bench.hpp"
#include "querymodify/map_checks.hpp"
#include "querymodify/terrain.hpp"

using namespace dartcheck::querymodify;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

bool checked(const terrain::Experiment& x) {
  bool ok = x.grid.volumes == 16384 && x.grid.darts == 425984 && x.flattened.volumes == 15984 && x.flattened.darts == 419984 &&
            x.housed.volumes == 16134 && x.housed.darts == 419984 + 50 * 192 && x.houses.size() == 50 && check_3map(x.mesh.map).valid();
  for (const auto& h : x.houses)
    ok = ok && std::abs(h.apex[0] - h.spot_centre[0]) < 1e-9 && std::abs(h.apex[1] - h.spot_centre[1]) < 1e-9 &&
         std::abs(h.apex[2] - 4.5 * h.spot_centre[2]) < 1e-9;
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  std::uint64_t seed = 2025;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--runs"))
      runs = std::max(1, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--seed"))
      seed = std::strtoull(argv[i + 1], nullptr, 10);
    else {
      fmt::print(stderr, "usage: bench_terrain [--runs N] [--seed S]\n");
      return 2;
    }
  }
  const long base = rss_kib();
  std::vector<double> grid, query2, apply2, query3, extend3;
  terrain::Experiment last;
  for (int r = 0; r < runs; ++r) {
    last = terrain::run_experiment(7, 50, seed + static_cast<std::uint64_t>(r));
    if (!checked(last)) {
      fmt::print(stderr, "run {}: the terrain does not have Table 2's counts or is not a valid 3-map\n", r);
      return 1;
    }
    grid.push_back(last.grid.modify_seconds);
    query2.push_back(last.flattened.query_seconds);
    apply2.push_back(last.flattened.modify_seconds);
    query3.push_back(last.housed.query_seconds);
    extend3.push_back(last.housed.modify_seconds);
  }
  const double peak = static_cast<double>(std::max(0L, peak_kib() - base)) / 1024.0;
  fmt::print("Terrain with houses (001 Table 2), 128 x 128 voxels, {} runs (medians), every run checked\n\n", runs);
  fmt::print("| step | volumes | darts | 001 volumes / darts | time (s) | 001 time (s) |\n|---|---:|---:|---|---|---|\n");
  fmt::print("| (1) voxel grid | {} | {} | 16,384 / 425,984 | {:.3f} | 0.028 |\n", last.grid.volumes, last.grid.darts, median(grid));
  fmt::print("| (2) 50 query-apply | {} | {} | 15,984 / 419,984 | {:.3f} ({:.3f} query, {:.3f} apply) | 0.012 (0.008, 0.004) |\n",
             last.flattened.volumes, last.flattened.darts, median(query2) + median(apply2), median(query2), median(apply2));
  fmt::print("| (3) 50 query-extend | {} | {} | 16,134 / 431,684 | {:.3f} ({:.3f} query, {:.3f} extend) | 0.68 (0.62, 0.06) |\n", last.housed.volumes,
             last.housed.darts, median(query3) + median(extend3), median(query3), median(extend3));
  fmt::print("\nmatches: step (2) {} raw, {} distinct; step (3) {} raw, {} distinct; peak memory {:.1f} MiB ({:.0f} B per dart of step (3))\n",
             last.flattened.raw_matches, last.flattened.distinct_matches, last.housed.raw_matches, last.housed.distinct_matches, peak,
             peak * 1024 * 1024 / static_cast<double>(last.housed.darts));
  return 0;
}
