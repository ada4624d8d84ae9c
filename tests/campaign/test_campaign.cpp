// Campaigns: the shard partition, and the records a shard writes, which
// merge must read back into the very results the shard had.
#include <gtest/gtest.h>

#include <set>

#include "analysis/fuzz.hpp"
#include "analysis/map_sources.hpp"
#include "analysis/rule_result.hpp"
#include "campaign/detail/result_record.hpp"
#include "campaign/shard.hpp"
#include "campaign/detail/shard_stream.hpp"
#include "core/input_error.hpp"
#include "io/catalog.hpp"
#include "reports/rule_result_json.hpp"

namespace dartcheck {
namespace {

using analysis::RuleResult;
using campaign::Shard;
using reports::Json;

TEST(Shard, ParsesKOfNAndRefusesTheRest) {
  EXPECT_EQ(campaign::parse_shard("0/1"), (Shard{0, 1}));
  EXPECT_EQ(campaign::parse_shard("3/4"), (Shard{3, 4}));
  for (const char* bad : {"4/4", "-1/4", "1/0", "a/b", "1/", "/2", "1/2/3", " 1/2", "1/2 ", "", "0/1000001", "18446744073709551616/2"})
    EXPECT_THROW(campaign::parse_shard(bad), InputError) << bad;
}

// The partition must not depend on the platform or the standard library:
// FNV-1a's published test vectors (Fowler, Noll, Vo).
TEST(Shard, StableHashIsFnv1a64) {
  EXPECT_EQ(campaign::stable_hash(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(campaign::stable_hash("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(campaign::stable_hash("foobar"), 0x85944171f73967e8ULL);
}

// Every rule of a catalog is in exactly one shard of N, and keep_shard
// keeps exactly the rules in_shard names, in catalog order.
TEST(Shard, ShardsPartitionTheCatalog) {
  const Catalog full = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  for (std::size_t n = 1; n <= 7; ++n) {
    std::multiset<std::string> seen;
    for (std::size_t k = 0; k < n; ++k) {
      Catalog part = read_catalog(full.file);
      campaign::keep_shard(part, {k, n});
      std::vector<std::string> expected;
      for (const auto& e : full.rules)
        if (campaign::stable_hash(e.rule.name()) % n == k) expected.push_back(e.rule.name());
      std::vector<std::string> kept;
      for (const auto& e : part.rules) kept.push_back(e.rule.name()), seen.insert(e.rule.name());
      EXPECT_EQ(kept, expected);
      EXPECT_EQ(part.skipped.size(), full.skipped.size());
    }
    EXPECT_EQ(seen.size(), full.rules.size());
    for (const auto& e : full.rules) EXPECT_EQ(seen.count(e.rule.name()), 1U) << e.rule.name();
  }
}

// A record read back gives the result that was written: the same JSON
// for the rule (every stage, times included) and the same record again.
// Results from real runs: check's confirmation, fuzz counterexamples (maps
// with predecessor records, embedded values) and Z3 proofs.
void expect_round_trip(const Catalog& catalog, const RuleResult& original) {
  const std::string text = reports::json_text(campaign::result_record(original));
  RuleResult back = analysis::analyse_static(catalog, *original.entry, 0);
  campaign::restore_record(back, Json::parse(text));
  EXPECT_EQ(reports::rule_result_json(back), reports::rule_result_json(original)) << original.name();
  EXPECT_EQ(reports::json_text(campaign::result_record(back)), text) << original.name();
}

// A header records each option with the JSON type of its value (shards
// merge only when these are equal): the largest seed stays unsigned, an
// unset optional is null, a name with a quote is escaped, the order kept.
TEST(RunHeader, ParametersKeepTheirTypesAndOrder) {
  const std::optional<std::uint64_t> unset;
  const auto h = campaign::make_header("fuzz", "no-such-catalog.yaml", "", "", Shard{},
                                       {{"seed", std::numeric_limits<std::uint64_t>::max()},
                                        {"runs", unset},
                                        {"offset", -3},
                                        {"min_quality", 0.5},
                                        {"event_checks", true},
                                        {"maps", std::vector<std::string>{"a", "b\"c"}},
                                        {"time", "30s"}});
  EXPECT_EQ(h.parameters.dump(),
            R"({"seed":18446744073709551615,"runs":null,"offset":-3,"min_quality":0.5,"event_checks":true,"maps":["a","b\"c"],"time":"30s"})");
  EXPECT_EQ(h.catalog_digest, "");  // no such file
}

TEST(ResultRecord, CheckFuzzAndProofResultsReadBackUnchanged) {
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  std::vector<Map> maps;
  for (const auto& s : catalog.maps) maps.push_back(analysis::build_source(s));
  analysis::FuzzOptions fo;
  fo.seed = 5;
  fo.runs = 200;
  proofs::ProveOptions po;
  po.max_darts = 3;
  po.scheme_darts = 3;
  std::size_t fuzz_cx = 0, proofs = 0, confirmations = 0;
  for (std::size_t k = 0; k < catalog.rules.size(); ++k) {
    const auto& e = catalog.rules[k];
    RuleResult r = analysis::analyse_static(catalog, e, 2, maps);
    confirmations += r.host_search.has_value() || r.scheme_search.has_value();
    analysis::add_fuzz(r, analysis::fuzz_rule(e, maps, fo), fo.seed, "", catalog.file);
    fuzz_cx += r.fuzz->counterexample.has_value();
    if (k % 5 == 0) run_proof(r, po, "", catalog.file), ++proofs;
    expect_round_trip(catalog, r);
  }
  // The runs above must have produced what the records are for.
  EXPECT_GT(confirmations, 20U);
  EXPECT_GT(fuzz_cx, 20U);
  EXPECT_GT(proofs, 10U);
}

TEST(ResultRecord, EmbeddedCounterexamplesReadBackUnchanged) {
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  analysis::FuzzOptions fo;
  fo.seed = 3;
  fo.runs = 100;
  std::size_t values = 0;
  for (const auto& e : catalog.rules) {
    RuleResult r = analysis::analyse_static(catalog, e, 0);
    analysis::add_fuzz(r, analysis::fuzz_rule(e, {}, fo), fo.seed, "", catalog.file);
    if (r.fuzz->counterexample) values += !r.fuzz->counterexample->orbit_values.empty();
    expect_round_trip(catalog, r);
  }
  EXPECT_GT(values, 0U);
}

// The solver's embedding answers and decided potential events (prove on
// embedded rules and on the event catalog) read back as written.
TEST(ResultRecord, EmbeddingAnswersAndPotentialEventsReadBackUnchanged) {
  proofs::ProveOptions po;
  po.max_darts = 5;
  po.embedding_darts = 5;  // small hosts: the records, not the answers, are under test
  std::size_t answers = 0, events = 0;
  for (const char* file : {"/catalogs/embedding-operations.yaml", "/catalogs/event-operations.yaml"}) {
    const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + file);
    for (std::size_t k = 0; k < catalog.rules.size(); k += 3) {
      RuleResult r = analysis::analyse_static(catalog, catalog.rules[k], 0);
      run_proof(r, po, "", catalog.file);
      if (r.proof->embedding) answers += r.proof->embedding->answers.size();
      if (r.potential_events) events += r.potential_events->events.size();
      expect_round_trip(catalog, r);
    }
  }
  EXPECT_GT(answers, 10U);
  EXPECT_GT(events, 5U);
}

// A damaged record is refused with the path of the damage, never read as
// a result: a dart beyond the map, a missing key, a wrong type, an enum
// out of range, and static failures that the catalog no longer gives.
TEST(ResultRecord, DamagedRecordsNameWhere) {
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/seed-operations.yaml");
  const CatalogRule* entry = catalog.find_rule("insert-vertex-free-edge/oriented-1");
  ASSERT_NE(entry, nullptr);
  analysis::FuzzOptions fo;
  fo.runs = 200;
  RuleResult r = analysis::analyse_static(catalog, *entry, 0);
  analysis::add_fuzz(r, analysis::fuzz_rule(*entry, {}, fo), fo.seed, "", catalog.file);
  ASSERT_TRUE(r.fuzz->counterexample);
  const Json good = campaign::result_record(r);
  const auto refused = [&](const std::function<void(Json&)>& damage, const std::string& where) {
    Json bad = good;
    damage(bad);
    RuleResult back = analysis::analyse_static(catalog, *entry, 0);
    try {
      campaign::restore_record(back, bad);
      ADD_FAILURE() << "accepted: " << where;
    } catch (const campaign::RecordError& e) {
      EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
    }
  };
  refused([](Json& j) { j["fuzz"]["counterexample"]["host"]["dims"][0]["links"][0] = 1000; }, "record.fuzz.counterexample.host.dims[0].links[0]");
  refused([](Json& j) { j["fuzz"].erase("hosts"); }, "record.fuzz: no key \"hosts\"");
  refused([](Json& j) { j["fuzz"]["applications"] = -3; }, "record.fuzz.applications");
  refused([](Json& j) { j["fuzz"]["class"] = "nine"; }, "record.fuzz.class");
  refused([](Json& j) { j["fuzz"]["counterexample"]["hooks"] = "0"; }, "record.fuzz.counterexample.hooks");
  refused([](Json& j) { j["failures"] = Json::array(); }, "did the catalog change?");
}

}  // namespace
}  // namespace dartcheck
