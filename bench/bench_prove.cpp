// Time to the solver's answer per seed DPO rule and constraint, and the
// largest host size answered within a wall-clock cap per query (10 s by
// default), for BENCHMARKS.md:
//   build/bench/bench_prove [CAP_SECONDS] [--rule NAME] [--schemes]
// Sizes tried: 12, 16, 24, 32 darts for DPO rules; with --schemes, the
// in-scope rule schemes instead at 4, 6, 8, 10 darts. A constraint stops
// growing at its first unknown answer or over-cap query.
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/catalog.hpp"
#include "proofs/rule_prover.hpp"

using namespace dartcheck;
using namespace dartcheck::proofs;

int main(int argc, char** argv) {
  double cap = 10;
  std::string only;
  bool schemes = false;
  for (int a = 1; a < argc; ++a) {
    if (std::string(argv[a]) == "--rule" && a + 1 < argc)
      only = argv[++a];
    else if (std::string(argv[a]) == "--schemes")
      schemes = true;
    else
      cap = std::atof(argv[a]);
  }
  const std::vector<std::size_t> sizes = schemes ? std::vector<std::size_t>{4, 6, 8, 10} : std::vector<std::size_t>{12, 16, 24, 32};
  const std::size_t first = sizes.front() == 4 ? 6 : 12;  // the size whose times are listed
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  fmt::print("{:<40} {:<8} {:>12} {:>12} {:>9} {:>9}\n", "rule", "constr.", fmt::format("thm k={} s", first), fmt::format("maps k={} s", first),
             "thm max k", "maps max k");
  double total12 = 0, worst12 = 0;
  for (const auto& e : catalog.rules) {
    if (e.words.scheme != schemes || (!only.empty() && e.rule.name() != only)) continue;
    if (schemes && !scheme_out_of_scope(e.rule).empty()) continue;
    std::map<std::string, std::string> thm_k, map_k;
    std::map<std::string, std::pair<double, double>> at12;
    std::map<std::string, bool> thm_open, map_open;
    for (std::size_t k : sizes) {
      ProveOptions o;
      o.max_darts = o.scheme_darts = k;
      o.timeout_ms = static_cast<unsigned>(cap * 1000);
      o.rlimit = 4'000'000'000U;
      const RuleProof p = prove_rule(e, o);
      bool grew = false;
      for (const auto& c : p.constraints) {
        const std::string n = c.constraint.name();
        if (!thm_open.count(n)) thm_open[n] = map_open[n] = true;
        if (k == first) {
          at12[n] = {c.theorem ? c.theorem->seconds : 0, c.model.seconds};
          worst12 = std::max({worst12, at12[n].first, at12[n].second});
          total12 += at12[n].first + at12[n].second;
        }
        auto grow = [&](const ClassAnswer& a, std::map<std::string, std::string>& best, bool& open) {
          if (!open) return;
          if (a.status == Status::unknown || a.seconds > cap) {
            open = false;
            return;
          }
          best[n] = a.status == Status::counterexample ? fmt::format("cx@{}", a.darts)
                    : a.status == Status::vacuous      ? "vacuous"
                    : a.proved_for_all()               ? fmt::format("all@{}", a.darts)
                                                       : std::to_string(k);
          // A counterexample or a proof for all hosts does not grow with k.
          if (a.status == Status::counterexample || a.proved_for_all()) return;
          grew = true;
        };
        if (c.theorem) grow(*c.theorem, thm_k, thm_open[n]);
        grow(c.model, map_k, map_open[n]);
      }
      if (!grew) break;
    }
    for (const auto& [n, t] : at12)
      fmt::print("{:<40} {:<8} {:>12.4f} {:>12.4f} {:>9} {:>9}\n", e.rule.name(), n, t.first, t.second, thm_k.count(n) ? thm_k[n] : "-",
                 map_k.count(n) ? map_k[n] : "-");
    std::fflush(stdout);
  }
  fmt::print("\nat k = {}: {:.2f} s for all queries, slowest query {:.3f} s (cap {} s)\n", first, total12, worst12, cap);
}
