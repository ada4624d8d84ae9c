#include "analysis/run_stages.hpp"

#include "analysis/fuzz_targets.hpp"
#include "analysis/interrupt.hpp"
#include "analysis/stage_progress.hpp"

#include <fmt/format.h>

namespace dartcheck::analysis {

void fuzz_all(std::vector<RuleResult>& rows, const Catalog& catalog, const std::string& rule, double seconds, std::uint64_t seed,
              const std::string& out_dir, const std::string& catalog_file, bool progress) {
  FuzzOptions options;
  options.seed = seed;
  options.runs = SIZE_MAX;  // the time decides
  const FuzzTargets targets = fuzz_targets(catalog, rule, {});
  auto found = fuzz_rules(targets.rules, targets.seeds, options, seconds, progress);
  for (std::size_t k = 0; k < found.size() && k < rows.size(); ++k)  // fewer than rows if interrupted
    add_fuzz(rows[k], std::move(found[k]), seed, out_dir, catalog_file, ".fuzz");
}

void prove_all(std::vector<RuleResult>& rows, std::size_t max_darts, std::size_t scheme_darts, const std::string& out_dir,
               const std::string& catalog_file, bool terminal) {
  proofs::ProveOptions options;
  options.max_darts = max_darts;
  options.scheme_darts = scheme_darts;
  options.stop = [] { return interrupted(); };
  StageProgress progress(rows.size(), terminal);
  for (std::size_t k = 0; k < rows.size() && !interrupted(); ++k) {
    progress.start(k, fmt::format("{}: asking Z3 for a host", rows[k].name()));
    run_proof(rows[k], options, out_dir, catalog_file, ".prove");
    if (rows[k].proof) progress.finished(k, proof_line(*rows[k].proof));
  }
}

}  // namespace dartcheck::analysis
