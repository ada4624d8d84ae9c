#include <algorithm>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "checkers/map_validity.hpp"
#include "generators/random_maps.hpp"
#include "tests/map_recipe_gen.hpp"
#include "generators/shapes.hpp"

using namespace dartcheck;

TEST(MapValidity, CubeIsValidInEveryModel) {
  for (const Model& m : {Model::gmap(2), Model::omap(2), Model::gmap(3)}) EXPECT_TRUE(check_map(build_shape(m, {"cube", {}})).valid()) << m.name;
}

TEST(MapValidity, BrokenInvolutionNamesDartAndConstraint) {
  Map m = build_shape(Model::gmap(2), {"polygon", {4}});
  // Dart 0 now points at 2 by its 0-arc, but 2 still points at 3 and 1 at 0.
  const Dart old = m.link(0, 0);
  m.set_link(0, 0, 2);
  auto r = check_map(m);
  ASSERT_FALSE(r.valid());
  auto has = [&](Constraint c, Dart d) {
    for (const auto& v : r.violations)
      if (v.constraint == c && v.i == 0 && v.element == d) return true;
    return false;
  };
  EXPECT_TRUE(has(Constraint::incident_in, 2)) << "2 is the target of two 0-arcs";
  EXPECT_TRUE(has(Constraint::incident_in, old)) << "the old partner is the target of none";
  EXPECT_TRUE(has(Constraint::non_orientation, 0));
  EXPECT_TRUE(has(Constraint::non_orientation, 2));
}

TEST(MapValidity, CycleViolationAlone) {
  // Two squares sewn along one edge by 2-links, with the 2-links crossed:
  // every involution holds, only C(0,2) breaks, at the four sewn darts.
  Map m = build_surface(Model::gmap(2), {{0, 1, 2, 3}, {4, 5, 6, 7}});
  // Face 0 side 0 = darts 0 (at 0), 1 (at 1); face 1 side 0 = darts 8 (at 4), 9 (at 5).
  m.sew(2, 0, 8);
  m.sew(2, 1, 9);
  EXPECT_TRUE(check_map(m).valid());
  m.sew(2, 0, 9);
  m.sew(2, 1, 8);
  EXPECT_TRUE(check_map(m).valid()) << "a half-turn is also a valid sewing";
  m.sew(2, 0, 9);
  m.sew(2, 1, 1);
  m.sew(2, 8, 8);
  auto r = check_map(m);
  std::vector<Dart> cycle_darts;
  for (const auto& v : r.violations) {
    EXPECT_EQ(v.constraint, Constraint::cycle);
    cycle_darts.push_back(v.element);
  }
  // a2 a0 (0) = a2(1) = 1 but a0 a2 (0) = a0(9) = 8: fails at 0, 1, 8, 9.
  EXPECT_EQ(cycle_darts, (std::vector<Dart>{0, 1, 8, 9}));
}

TEST(MapValidity, OrientedPredecessorMismatchIsReported) {
  Map m = build_shape(Model::omap(2), {"polygon", {3}});
  // Face darts 0 -> 1 -> 2 -> 0: the arc into 0 comes from 2. Record 1.
  m.set_inverse_link_raw(1, 0, 1);
  EXPECT_EQ(check_map(m).violations, (std::vector<Violation>{{Constraint::predecessor, 1, 2, 0, 1}}));
  // A predecessor recorded where no arc comes in (0's link removed raw).
  Map lone = build_shape(Model::open_omap(2), {"polygon", {3}});
  lone.set_link_raw(1, 2, no_dart);
  auto r = check_map(lone).violations;
  EXPECT_NE(std::find(r.begin(), r.end(), Violation{Constraint::predecessor, 1, -1, 0, 2}), r.end());
}

TEST(MapValidity, VariantsOfSection3_2) {
  EXPECT_FALSE(check_map(build_shape(Model::closed_gmap(2), {"polygon", {3}})).valid()) << "boundary 2-loops";
  EXPECT_TRUE(check_map(build_shape(Model::closed_gmap(2), {"cube", {}})).valid());
  Map open(Model::open_omap(2), 2);
  open.sew(1, 0, 1);
  open.sew(1, 1, 0);
  EXPECT_TRUE(check_map(open).valid()) << "no 2-arc at all is allowed in an open O-map";
  Map closed(Model::omap(2), 2);
  closed.sew(1, 0, 1);
  closed.sew(1, 1, 0);
  EXPECT_EQ(check_map(closed).violations.size(), 4u) << "I(2) out and in, at both darts";
}

// Two implementations of one definition: the fast pass (bijection
// identities) and the exact pass (arc sets, paths that branch) must report
// the same violations on any map, valid or corrupted, with one thread or
// several.
RC_GTEST_PROP(MapValidity, FastPassEqualsExactDefinition, ()) {
  const auto model = *rc::gen::element(Model::gmap(2), Model::gmap(3), Model::omap(2), Model::omap(3), Model::closed_gmap(2), Model::open_omap(2));
  const auto recipe = *gen_map_recipe(1, 40);
  Map m = build_random_map(model, recipe);
  const auto corruptions = *rc::gen::container<std::vector<LinkCorruption>>(rc::gen::arbitrary<LinkCorruption>());
  for (const auto& c : corruptions) apply_corruption(m, c);
  RC_ASSERT(check_map(m).violations == check_map_exact(m).violations);
  // The dart ranges checked by several threads give the same report (the
  // maps here are below the default threshold, so the split is forced).
  const unsigned threads = *rc::gen::inRange(2U, 6U);
  RC_ASSERT(check_map(m, threads).violations == check_map_exact(m).violations);
}
