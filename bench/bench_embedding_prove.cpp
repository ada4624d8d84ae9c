// The solver on embeddings (proofs/embedding_prover), for BENCHMARKS.md:
// per catalog and per host bound K = |L| + d, the rules' time (total and
// the slowest), the hosts enumerated, the Z3 queries asked after the
// cache and Z3's own time per query.
//   build/bench/bench_embedding_prove [CATALOG...] [--extra 2,3,4,5]
// Default catalogs: the embedding catalog, tests/data/embedding-readings.yaml
// and JerboaRebuilt2.jme (when ../shared is beside the repository).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/catalog.hpp"
#include "proofs/embedding_prover.hpp"

using namespace dartcheck;
using namespace dartcheck::proofs;

int main(int argc, char** argv) {
  std::vector<std::string> catalogs;
  std::vector<std::size_t> extra{2, 3, 4, 5};
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--extra" && a + 1 < argc) {
      extra.clear();
      std::stringstream list(argv[++a]);
      for (std::string x; std::getline(list, x, ',');) extra.push_back(std::stoul(x));
    } else {
      catalogs.push_back(arg);
    }
  }
  const std::string root = DARTCHECK_SOURCE_DIR;
  if (catalogs.empty()) {
    catalogs = {root + "/catalogs/embedding-operations.yaml", root + "/tests/data/embedding-readings.yaml"};
    if (std::filesystem::exists(root + "/../shared/jerboa-samples/JerboaRebuilt2.jme"))
      catalogs.push_back(root + "/../shared/jerboa-samples/JerboaRebuilt2.jme");
  }
  fmt::print("{:<28} {:>6} {:>6} {:>9} {:>9} {:>10} {:>8} {:>9} {:>9}\n", "catalog", "K", "rules", "total s", "max s", "hosts", "queries", "Z3 s",
             "ms/query");
  for (const auto& file : catalogs) {
    const Catalog catalog = read_catalog(file);
    for (std::size_t d : extra) {
      double total = 0, worst = 0, z3 = 0;
      std::size_t rules = 0, hosts = 0, queries = 0;
      for (const auto& e : catalog.rules) {
        if (!e.terms) continue;
        EmbeddingProveOptions o;
        o.max_darts = e.rule.left().node_count() + d;
        const EmbeddingProof p = prove_embeddings(e, o);
        ++rules;
        total += p.seconds;
        worst = std::max(worst, p.seconds);
        hosts += p.hosts;
        queries += p.queries;
        z3 += p.z3_seconds;
      }
      fmt::print("{:<28} {:>6} {:>6} {:>9.2f} {:>9.2f} {:>10} {:>8} {:>9.3f} {:>9.3f}\n", std::filesystem::path(file).filename().string(),
                 fmt::format("|L|+{}", d), rules, total, worst, hosts, queries, z3, queries ? 1000 * z3 / static_cast<double>(queries) : 0.0);
    }
  }
}
