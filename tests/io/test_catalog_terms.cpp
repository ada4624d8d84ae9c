// Embedding terms in YAML catalogs: errors at the offending token.
#include <algorithm>
#include <fstream>
#include <numeric>
#include <optional>
#include <random>
#include <set>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "checkers/embedding_conditions.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include "checkers/rule_conditions.hpp"
#include "analysis/embedded_fuzz.hpp"
#include "io/catalog.hpp"
#include "rewriting/application.hpp"
#include "core/input_error.hpp"
#include "io/mesh_io.hpp"
#include "core/orbit.hpp"
#include "rewriting/term_eval.hpp"
#include "generators/mesh_map.hpp"
#include "generators/random_embedding.hpp"
#include "generators/random_maps.hpp"
#include "generators/random_rules.hpp"
#include "tests/embedding_support.hpp"

namespace dartcheck {
namespace {

using namespace testing_support;

TEST(Catalog, BadTermsAreReportedAtTheirToken) {
  const std::string file = ::testing::TempDir() + "bad-terms.yaml";
  std::ofstream(file) << "model: 2-gmap\n"
                         "embeddings: [{name: pos, type: point2, orbit: \"<1,2>\"}]\n"
                         "rules:\n"
                         "  - name: r\n"
                         "    hooks: [a]\n"
                         "    left: {nodes: [a]}\n"
                         "    right: {nodes: [a]}\n"
                         "    labels: {right: {a: {pos: \"a.pos + * 2\"}}}\n";
  try {
    read_catalog(file);
    FAIL() << "accepted a malformed term";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 8);
    EXPECT_EQ(e.column(), 40);  // the '*': the quote is column 31, the term starts at 32, offset 8
    EXPECT_NE(std::string(e.what()).find("'*'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dartcheck
