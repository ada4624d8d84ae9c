// Shard files of a campaign (campaign/shard_stream, result_record), as
// `dartcheck merge` reads them: every line parsed, and every rule line's
// record restored onto its rule of the seed catalog (the seeds are shards
// of that catalog, so the records get past the static comparison and
// into the maps, graphs and proofs they hold). Inputs of odd size are read
// as merge --incomplete reads them (interrupted and unfinished shards).
#include <map>

#include "analysis/rule_result.hpp"
#include "campaign/detail/result_record.hpp"
#include "campaign/detail/shard_stream.hpp"
#include "core/input_error.hpp"
#include "fuzz/harness.hpp"
#include "io/catalog.hpp"

namespace {

using namespace dartcheck;

const Catalog& seed_catalog() {
  static const Catalog catalog = read_catalog(DARTCHECK_SOURCE_DIR "/catalogs/seed-operations.yaml");
  return catalog;
}

// The static stage of a rule, computed once.
const analysis::RuleResult* static_result(const std::string& name) {
  static std::map<std::string, analysis::RuleResult> cache;
  if (const auto it = cache.find(name); it != cache.end()) return &it->second;
  const CatalogRule* entry = seed_catalog().find_rule(name);
  if (!entry) return nullptr;
  return &cache.emplace(name, analysis::analyse_static(seed_catalog(), *entry, 0)).first->second;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const campaign::ShardFile f = campaign::read_shard_file(fuzzing::input_file(data, size, ".jsonl"), (size & 1) != 0);
    for (const auto& rule : f.rules) {
      const analysis::RuleResult* base = static_result(rule.name);
      if (!base) continue;
      analysis::RuleResult r = *base;
      try {
        campaign::restore_record(r, rule.record);
      } catch (const campaign::RecordError&) {
      }
    }
  } catch (const InputError&) {
  }
  return 0;
}
