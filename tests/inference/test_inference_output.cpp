// What `dartcheck infer -o` writes reads back as the same rules: the .jme
// writer against dartcheck's own .jme reader (every Jerboa scheme of the
// seed catalog and of JerboaRebuilt2.jme, compared by canonical form), and
// the YAML catalog against the catalog reader (maps bit for bit).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "inference_support.hpp"
#include "io/catalog_writer.hpp"
#include "io/jerboa_modeler.hpp"
#include "io/jerboa_modeler_writer.hpp"

namespace dartcheck::inference::test {
namespace {

std::string temp_path(const std::string& name) { return (std::filesystem::temp_directory_path() / name).string(); }

// Every explicit arc has its reverse: what a .jme file can say.
bool non_oriented(const Operation& op) {
  for (const auto* side : {&op.rule.left(), &op.rule.right()}) {
    const auto& words = side == &op.rule.left() ? op.words.left : op.words.right;
    for (ArcId e = 0; e < side->arc_count(); ++e) {
      if (!arc_word(words, e).empty()) continue;
      const auto& a = side->arc(e);
      bool reverse = false;
      for (ArcId f = 0; f < side->arc_count() && !reverse; ++f)
        reverse = arc_word(words, f).empty() && side->arc(f).label == a.label && side->arc(f).source == a.target && side->arc(f).target == a.source;
      if (!reverse) return false;
    }
  }
  return true;
}

void jme_round_trip(const Catalog& source, int dimension, const std::string& file) {
  std::vector<const Operation*> ops;
  for (const auto& r : source.rules)
    if (r.jerboa && r.rule.model() == Model::gmap(dimension)) {
      if (non_oriented(r)) {
        ops.push_back(&r);
      } else {
        std::ostringstream sink;
        EXPECT_THROW(write_jme(sink, "m", dimension, {&r}), ValueError) << r.rule.name();
      }
    }
  ASSERT_FALSE(ops.empty());
  {
    std::ofstream out(file);
    write_jme(out, "round-trip", dimension, ops);
  }
  const Catalog back = read_jme(file);
  ASSERT_EQ(back.rules.size(), ops.size()) << (back.skipped.empty() ? "" : back.skipped[0].why);
  for (std::size_t k = 0; k < ops.size(); ++k) {
    EXPECT_EQ(back.rules[k].rule.name(), ops[k]->rule.name());
    const auto a = canonical_form(*ops[k]), b = canonical_form(back.rules[k]);
    if (a) {
      EXPECT_EQ(a, b) << ops[k]->rule.name();
    }
    // Rules with several hooks have no canonical form: compare the labels.
    EXPECT_EQ(back.rules[k].jerboa->left, ops[k]->jerboa->left) << ops[k]->rule.name();
    EXPECT_EQ(back.rules[k].jerboa->right, ops[k]->jerboa->right) << ops[k]->rule.name();
    EXPECT_EQ(back.rules[k].rule.left().arc_count(), ops[k]->rule.left().arc_count()) << ops[k]->rule.name();
    EXPECT_EQ(back.rules[k].rule.right().arc_count(), ops[k]->rule.right().arc_count()) << ops[k]->rule.name();
  }
}

TEST(InferenceOutput, JmeWriterReadsBackSeedSchemes) { jme_round_trip(seed_catalog(), 2, temp_path("dartcheck-seed-round-trip.jme")); }

TEST(InferenceOutput, JmeWriterReadsBackJerboaRebuilt2) {
  const Catalog c = read_jme(std::string(DARTCHECK_SOURCE_DIR) + "/../shared/jerboa-samples/JerboaRebuilt2.jme");
  jme_round_trip(c, 3, temp_path("dartcheck-rebuilt-round-trip.jme"));
}

// The inferred catalog: maps read back bit for bit, the rule keeps its
// scheme, and the example names both maps.
TEST(InferenceOutput, CatalogWithMapsAndExampleReadsBack) {
  const Map cube = shape("cube");
  const Map after = applied(*seed_catalog().find_rule("quad-subdivision-jerboa"), cube, 0);
  KappaSpec k;
  k.identity = true;
  const auto graph = make_kappa_graph(cube, after, k);
  InferOptions o;
  const auto attempts = infer(graph, {0, 1, 2}, o);
  ASSERT_TRUE(attempts.at(0).inferred());
  Catalog c;
  c.maps.push_back({"before", cube.model(), cube, {}, {}, {}});
  c.maps.push_back({"after", after.model(), after, {}, {}, {}});
  CatalogRule r{attempts[0].rule->operation, "note", {}, {}, std::vector<std::string>{}, {}, std::nullopt, {}};
  r.examples.push_back({"before", {0}, "valid", std::nullopt, "after", {}});
  c.rules.push_back(r);
  const std::string file = temp_path("dartcheck-inferred.yaml");
  {
    std::ofstream out(file);
    out << catalog_yaml(c, "test");
  }
  const Catalog back = read_catalog(file);
  ASSERT_EQ(back.maps.size(), 2u);
  EXPECT_TRUE(*back.maps[0].map == cube);
  EXPECT_TRUE(*back.maps[1].map == after);
  ASSERT_EQ(back.rules.size(), 1u);
  EXPECT_EQ(canonical_form(back.rules[0]), canonical_form(attempts[0].rule->operation));
  ASSERT_TRUE(back.rules[0].expected_failures);
  EXPECT_TRUE(back.rules[0].expected_failures->empty());
  ASSERT_EQ(back.rules[0].examples.size(), 1u);
  EXPECT_EQ(back.rules[0].examples[0].isomorphic_to, "after");
}

}  // namespace
}  // namespace dartcheck::inference::test
