// Renumbering: the darts of G against those of H, and composition. The
// expected images are written out by hand for two small rewrites.
#include <gtest/gtest.h>

#include <vector>

#include "core/renumbering.hpp"

using namespace dartcheck;

namespace {

// G has darts 0..5. Step 1 deletes 1 and 4, keeps 0, 2, 3 in place and
// moves 5 into the hole at 1 (H dense: 0..4), and creates dart 4 of H.
Renumbering first_step() {
  Renumbering r(6, 5, 4);
  r.deleted(1);
  r.deleted(4);
  r.map(5, 1);
  r.created(4);
  return r;
}

// H has darts 0..4. Step 2 deletes 0, moves 4 into 0 (K: 0..3).
Renumbering second_step() {
  Renumbering r(5, 4, 2);
  r.deleted(0);
  r.map(4, 0);
  return r;
}

}  // namespace

TEST(Renumbering, ImagesAndPreimagesOfOneRewrite) {
  const Renumbering r = first_step();
  const std::vector<Dart> to_h = {0, no_dart, 2, 3, no_dart, 1};
  for (Dart g = 0; g < 6; ++g) EXPECT_EQ(r.to_h(g), to_h[g]) << "dart " << g;
  const std::vector<Dart> to_g = {0, 5, 2, 3, no_dart};
  for (Dart h = 0; h < 5; ++h) EXPECT_EQ(r.to_g(h), to_g[h]) << "dart " << h;
}

TEST(Renumbering, CompositionIsTheTwoStepsInTurn) {
  // G -> K by hand: 0 -> deleted (kept by step 1, deleted by step 2);
  // 1, 4 deleted; 2 -> 2; 3 -> 3; 5 -> 1 -> 1. K's dart 0 is H's created
  // dart 4, so it has no preimage in G.
  const Renumbering gk = first_step().then(second_step());
  const std::vector<Dart> to_k = {no_dart, no_dart, 2, 3, no_dart, 1};
  for (Dart g = 0; g < 6; ++g) EXPECT_EQ(gk.to_h(g), to_k[g]) << "dart " << g;
  const std::vector<Dart> to_g = {no_dart, 5, 2, 3};
  for (Dart k = 0; k < 4; ++k) EXPECT_EQ(gk.to_g(k), to_g[k]) << "dart " << k;
  EXPECT_EQ(gk.g_size(), 6u);
  EXPECT_EQ(gk.h_size(), 4u);
}

TEST(Renumbering, CarriesPerDartDataToH) {
  const std::vector<int> g_data = {10, 11, 12, 13, 14, 15};
  const auto h_data = first_step().carry<int>(g_data, -1);
  EXPECT_EQ(h_data, (std::vector<int>{10, 15, 12, 13, -1}));
}
