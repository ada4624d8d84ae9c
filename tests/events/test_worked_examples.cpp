// The worked examples of 004, rebuilt from the prose, with every expected
// event derived by hand from the definitions (Def. 3.1.1-3.4.2) on the
// maps of catalogs/event-operations.yaml, not read from the tool.
#include <gmock/gmock.h>

#include "events_support.hpp"
#include "generators/polygon_soup.hpp"

namespace dartcheck::events::test {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;
using ::testing::UnorderedElementsAre;

// Fig. 4 on the house of Fig. 5 (Table 1, corrected). The square face is
// darts 0-7; nothing is deleted, so its darts keep their numbers in H and
// the new darts are 14-29.
TEST(WorkedExamples, TriangulationOfTheHouseStatic) {
  const Applied a = apply_catalog_rule("triangulate-face", "house", {0});
  // Rule orbits: the face L<0,1>(n0) is complete and splits implicitly
  // along position 1 (its 1-links become 2-links or vanish in every node of
  // R<0,1>(n0,n1,n2)): conditional (Prop. 3.2.1).
  EXPECT_THAT(claim_texts(a, "<0,1>"), ElementsAre("split conditional implicit L<0,1>(n0)", "modification conditional L<0,1>(n0)"));
  // <0,2>: n0 has no 2-link (incomplete), its 0-links are kept, and it is
  // the only incomplete orbit: the map's orbit meets no changed link, a
  // certain non-modification (the sharpening of static_events, not the
  // paper's 'potential'); R<0,2>(n1,n2) is created (Sec. 3.1's example).
  EXPECT_THAT(claim_texts(a, "<0,2>"), ElementsAre("creation certain R<0,2>(n1,n2)", "no-modification certain L<0,2>(n0)"));
  // <0>: n0 keeps its 0-links, complete: certain non-modification (Sec. 3.4.2's example).
  EXPECT_THAT(claim_texts(a, "<0>"), ElementsAre("creation certain R<0>(n1,n2)", "no-modification certain L<0>(n0)"));
  // <1,2>: vertices gain n1 (Sec. 3.4.3's example); incomplete (no 2), but
  // no incomplete orbit splits, merges or is deleted and R<1,2>(n0,n1)
  // gains created darts: a certain modification, as Table 1 lists it.
  EXPECT_THAT(claim_texts(a, "<1,2>"), ElementsAre("creation certain R<1,2>(n2)", "modification certain L<1,2>(n0)"));
}

TEST(WorkedExamples, TriangulationOfTheHouseLog) {
  const Applied a = apply_catalog_rule("triangulate-face", "house", {0});
  ASSERT_EQ(a.after.size(), 30U);
  expect_no_contradiction(a);
  // <0>: the 4 edges of the square keep their 0-links; each of the 8 new
  // n1 darts is 0-linked to its n2 copy: 8 created <0>-orbits.
  EXPECT_EQ(a.counts("<0>"), (std::map<Event, int>{{Event::creation, 8}, {Event::non_modification, 4}}));
  // <1>: the square's 1-orbits {1,2}, {3,4}, {5,6}, {7,0} each split in
  // two (every dart is 1-linked to its own n1 copy); the n2 copies of
  // 0-linked darts form 4 new 1-orbits. Table 1: split G<1>(a0) ->
  // {H<1>(a0), H<1>(h0)}, with a0 = 0 and h0 = 7.
  auto split = [](const char* g, int x, int y) { return fmt::format("split G<1>({}) -> {{H<1>({}), H<1>({})}}", g, x, y); };
  std::vector<std::string> splits;
  for (const auto& l : a.lines("<1>"))
    if (l.rfind("split", 0) == 0) splits.push_back(l);
  EXPECT_THAT(splits, UnorderedElementsAre(split("0", 0, 7), split("1", 1, 2), split("3", 3, 4), split("5", 5, 6)));
  EXPECT_EQ(a.counts("<1>"), (std::map<Event, int>{{Event::creation, 4}, {Event::split, 4}}));
  // <2>: the square's darts keep their 2-links ({4,9}, {5,8} and six
  // loops): 8 unchanged; n1 and n2 darts are 2-linked in pairs: 8 created.
  EXPECT_EQ(a.counts("<2>"), (std::map<Event, int>{{Event::creation, 8}, {Event::non_modification, 8}}));
  // <0,1>: the square splits into four triangles, one per square edge.
  EXPECT_THAT(a.lines("<0,1>"), ElementsAre("split G<0,1>(0) -> {H<0,1>(0), H<0,1>(2), H<0,1>(4), H<0,1>(6)}"));
  // <0,2>: the 4 square edges unchanged (the top one is still sewn to the
  // roof), 4 new inner edges.
  EXPECT_EQ(a.counts("<0,2>"), (std::map<Event, int>{{Event::creation, 4}, {Event::non_modification, 4}}));
  // <1,2>: the 4 corners gain two darts each: modified (Table 1 says
  // "Creation H<1,2>(a0)": a0 is a preserved dart, so its vertex cannot be
  // created; corrected); the centre vertex is created.
  EXPECT_THAT(a.lines("<1,2>"), ElementsAre("creation H<1,2>(22)", "modification G<1,2>(0) -> H<1,2>(0)", "modification G<1,2>(1) -> H<1,2>(1)",
                                            "modification G<1,2>(3) -> H<1,2>(3)", "modification G<1,2>(5) -> H<1,2>(5)"));
  // <0,1,2>: the whole surface is modified.
  EXPECT_THAT(a.lines("<0,1,2>"), ElementsAre("modification G<0,1,2>(0) -> H<0,1,2>(0)"));
}

// Fig. 6 and 7(a)-(c): unsewing a 2-x-2 grid. Any interior edge of the grid
// separates two of its four faces, whose adjacency is a 4-cycle: removing
// one adjacency leaves a path (connected), removing a second one cuts it.
std::vector<Dart> interior_edge_darts(const Map& m) {
  std::vector<Dart> out;
  for (Dart d = 0; d < m.size(); ++d)
    if (m.link(2, d) != d) out.push_back(d);
  return out;
}

TEST(WorkedExamples, UnsewSplitsTheEdgeAndTheSurfaceOnlyTheSecondTime) {
  const Map grid = catalog_map("grid-2x2");
  const Dart first = interior_edge_darts(grid).at(0);
  const Applied a = apply_catalog_rule("unsew2", "grid-2x2", {first});
  expect_no_contradiction(a);
  EXPECT_THAT(claim_texts(a, "<0,2>"), ElementsAre("split certain L<0,2>(n0,n1)"));
  EXPECT_THAT(claim_texts(a, "<0,1,2>"), ElementsAre("split potential L<0,1,2>(n0,n1)", "modification potential L<0,1,2>(n0,n1)"));
  EXPECT_EQ(a.counts("<0,2>"), (std::map<Event, int>{{Event::split, 1}}));
  EXPECT_EQ(a.counts("<0,1,2>"), (std::map<Event, int>{{Event::modification, 1}}));
  // Second unsew on another interior edge of the result.
  Dart second = no_dart;
  const Dart twin = grid.link(2, first);
  for (Dart d : interior_edge_darts(a.after))
    if (d != first && d != grid.link(0, first) && d != twin && d != grid.link(0, twin)) {
      second = d;
      break;
    }
  ASSERT_NE(second, no_dart);
  const Applied b = apply_with_events(*event_catalog().find_rule("unsew2"), a.after, {second});
  expect_no_contradiction(b);
  EXPECT_EQ(b.counts("<0,1,2>"), (std::map<Event, int>{{Event::split, 1}}));
  EXPECT_EQ(count_cells(b.after).components, 2U);
}

// Fig. 8: sewing two free edges merges two edges (certain, explicit).
TEST(WorkedExamples, SewMergesTwoEdges) {
  // Unsew an interior edge of the grid, then sew it back: the two hooks are
  // the unsewn darts.
  const Map grid = catalog_map("grid-2x2");
  const Dart d = interior_edge_darts(grid).at(0), e = grid.link(2, d);
  const Applied cut = apply_catalog_rule("unsew2", "grid-2x2", {d});
  const Applied a = apply_with_events(*event_catalog().find_rule("sew2"), cut.after, {d, e});
  expect_no_contradiction(a);
  EXPECT_THAT(claim_texts(a, "<0,2>"), ElementsAre("merge certain L<0,2>(n0)", "merge certain L<0,2>(n1)"));
  const Dart lo = std::min({d, e, grid.link(0, d), grid.link(0, e)});
  const Dart lo_d = std::min(d, grid.link(0, d)), lo_e = std::min(e, grid.link(0, e));
  EXPECT_THAT(a.lines("<0,2>"),
              ElementsAre(fmt::format("merge {{G<0,2>({}), G<0,2>({})}} -> H<0,2>({})", std::min(lo_d, lo_e), std::max(lo_d, lo_e), lo)));
}

// Fig. 9 and 7(d): deleting an interior edge of the grid merges its two
// faces (a potential merge of L<0,1>, confirmed) and deletes the edge
// (certain).
TEST(WorkedExamples, EdgeDeletionMergesTwoFaces) {
  const Map grid = catalog_map("grid-2x2");
  const Applied a = apply_catalog_rule("delete-edge", "grid-2x2", {interior_edge_darts(grid).at(0)});
  expect_no_contradiction(a);
  EXPECT_THAT(claim_texts(a, "<0,2>"), ::testing::Contains("deletion certain L<0,2>(n0)"));
  EXPECT_THAT(claim_texts(a, "<0,1>"), ::testing::Contains("merge potential implicit L<0,1>(n0,n1)"));
  // <1>: L<1>(n0,n1) is complete and merges implicitly (Sec. 3.3's example).
  EXPECT_THAT(claim_texts(a, "<1>"), ::testing::Contains("merge conditional implicit L<1>(n0,n1)"));
  // <0,2>: the edge is deleted; the 4 edges of n1 (the darts 1-linked to
  // it) keep their 0- and 2-links.
  EXPECT_EQ(a.counts("<0,2>"), (std::map<Event, int>{{Event::deletion, 1}, {Event::non_modification, 4}}));
  EXPECT_EQ(a.counts("<0,1>"), (std::map<Event, int>{{Event::merge, 1}}));
  // Two face-vertices merge on each side of the edge (the edge's two ends).
  EXPECT_EQ(a.counts("<1>")[Event::merge], 2);
  // V 9, E 12 - 1, F 4 - 1: an interior edge joins the centre to a
  // boundary midpoint, which both keep other edges.
  EXPECT_EQ(count_cells(a.after).cells, (std::vector<std::size_t>{9, 11, 3}));
}

// Fig. 10 and 11: collapsing an edge merges its two vertices (potential:
// L<1,2>(n0,n1) is incomplete).
TEST(WorkedExamples, EdgeCollapseMergesItsEndsAndIsBothSplitAndMergeOnTheSecondCollapse) {
  const Map grid = catalog_map("grid-2x2");
  const Applied a = apply_catalog_rule("collapse-edge", "grid-2x2", {interior_edge_darts(grid).at(0)});
  expect_no_contradiction(a);
  // Position 0 (letter 0) becomes a 1-link of n1 (merge), position 1
  // (letter 2, a 2-link of n0 in L) leaves the orbit with n0 (split).
  EXPECT_THAT(claim_texts(a, "<1,2>"), ElementsAre("merge potential implicit L<1,2>(n0,n1)", "split potential implicit L<1,2>(n0,n1)",
                                                   "modification potential L<1,2>(n0,n1)"));
  // Fig. 11(b): the centre and the boundary midpoint become one vertex.
  EXPECT_EQ(a.counts("<1,2>"), (std::map<Event, int>{{Event::merge, 1}}));
  EXPECT_EQ(count_cells(a.after).cells, (std::vector<std::size_t>{8, 11, 4}));
  // Fig. 1(c), 11(c): the merged vertex is on the boundary now, as are the
  // three other midpoints, so each remaining interior edge joins two
  // boundary vertices, whose fans it cuts in two. Collapsing it joins the
  // upper halves into one vertex and the lower halves into another: each
  // end splits in two and each new vertex merges two: split 2, merge 2.
  const std::vector<Dart> inner = interior_edge_darts(a.after);
  ASSERT_EQ(inner.size(), 12U);  // three edges of four darts
  for (Dart d : inner) {
    const Applied b = apply_with_events(*event_catalog().find_rule("collapse-edge"), a.after, {d});
    expect_no_contradiction(b);
    EXPECT_EQ(b.counts("<1,2>"), (std::map<Event, int>{{Event::split, 2}, {Event::merge, 2}})) << "hook " << d;
  }
}

// A ring of four quads between an outer and an inner square: its interior
// edges are the four radial ones. Deleting three merges the faces two by
// two (each deletion joins two different faces of the ring's path); the
// fourth radial edge then has the one remaining face on both sides (a
// bridge between the two boundary cycles): deleting it does not merge
// anything but splits the face's <0,1>-orbit into the outer and the inner
// cycle. The potential merge and the potential split of L<0,1>(n0,n1)
// (Sec. 3.3) resolve in opposite ways.
TEST(WorkedExamples, EdgeDeletionMergesTwoFacesOrSplitsOneAtABridge) {
  const std::vector<Polygon> ring{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  Map m = build_surface(Model::gmap(2), ring);
  const Operation& del = *event_catalog().find_rule("delete-edge");
  for (int k = 0; k < 3; ++k) {
    const Applied a = apply_with_events(del, m, {interior_edge_darts(m).at(0)});
    expect_no_contradiction(a);
    EXPECT_EQ(a.counts("<0,1>"), (std::map<Event, int>{{Event::merge, 1}})) << "deletion " << k;
    m = a.after;
  }
  ASSERT_EQ(interior_edge_darts(m).size(), 4U);  // one edge left inside
  const Applied a = apply_with_events(del, m, {interior_edge_darts(m).at(0)});
  expect_no_contradiction(a);
  EXPECT_EQ(a.counts("<0,1>"), (std::map<Event, int>{{Event::split, 1}}));
  // 8 vertices, 8 boundary edges, and the two cycles.
  EXPECT_EQ(count_cells(a.after).cells, (std::vector<std::size_t>{8, 8, 2}));
}

// Jerboa's own rules (../shared/jerboa-samples/JerboaRebuilt2.jme, a
// 3-G-map modeler): UnSewA2 and SewA2 are Fig. 6 and 8 in 3D. Expected
// from the paper's prose: unsewing splits the edge <0,2> for certain and
// the surface <0,1,2> only potentially (its nodes have no 1-link);
// sewing merges two edges for certain.
TEST(WorkedExamples, JerboaSewAndUnsew) {
  const Catalog jerboa = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/../shared/jerboa-samples/JerboaRebuilt2.jme");
  auto claims = [&](const char* rule, const char* kind) {
    const Operation& op = *jerboa.find_rule(rule);
    const EventRule view = *event_rule(op).rule;
    const KindEvents k = static_events(view, parse_orbit_kind(kind, op.rule.model()));
    std::vector<std::string> out;
    for (const auto& c : k.claims)
      out.push_back(fmt::format("{} {} {}", name_of(c.event), name_of(c.certainty), rule_orbit_name(view, k, c.event != Event::creation, c.orbit)));
    return out;
  };
  EXPECT_THAT(claims("UnSewA2", "<0,2>"), ElementsAre("split certain L<0,2>(n0,n1)"));
  EXPECT_THAT(claims("UnSewA2", "<0,1,2>"), ElementsAre("split potential L<0,1,2>(n0,n1)", "modification potential L<0,1,2>(n0,n1)"));
  EXPECT_THAT(claims("SewA2", "<0,2>"), ElementsAre("merge certain L<0,2>(n0)", "merge certain L<0,2>(n1)"));
  // The 3-links of SewA2's nodes are implicit (<0,3>) and untouched: the
  // <3> orbits are not modified.
  EXPECT_THAT(claims("SewA2", "<3>"), ElementsAre("no-modification certain L<3>(n0)", "no-modification certain L<3>(n1)"));
}

}  // namespace
}  // namespace dartcheck::events::test
