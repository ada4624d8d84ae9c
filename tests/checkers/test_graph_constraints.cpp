// The per-node constraints of 002 Def. 9 on the graph of Example 4
// (Figure 6, rebuilt from the example's text: the figure is missing).
#include <gtest/gtest.h>

#include "checkers/graph_constraints.hpp"

using namespace dartcheck;

namespace {
// Example 4 states: b has exactly one outgoing and one incoming 2-arc; c has
// no outgoing 3-arc; d -3-> f and f -3-> d; f has a 2-loop; the 3-arc between
// a and c has no reverse; c is the source of a 1313-cycle; a is the source
// of a 3131-cycle. One graph with those facts:
struct Example4 {
  TopoGraph g;
  NodeId a, b, c, d, f;
  Example4() {
    a = g.add_node("a"), b = g.add_node("b"), c = g.add_node("c"), d = g.add_node("d"), f = g.add_node("f");
    g.add_arc(a, b, 2);
    g.add_arc(b, a, 2);
    g.add_arc(d, f, 3);
    g.add_arc(f, d, 3);
    g.add_arc(f, f, 2);
    g.add_arc(a, c, 3);  // no reverse
    // c -1-> a -3-> c -1-> a -3-> c is a 1313-cycle from c (with a c 1-loop
    // it would also be one); a -3-> c -1-> a -3-> c -1-> a a 3131-cycle from a.
    g.add_arc(c, a, 1);
  }
};
}  // namespace

TEST(GraphConstraints, Example4Incidence) {
  Example4 e;
  std::vector<Violation> out;
  check_incidence(e.g, e.b, 2, false, out);
  EXPECT_TRUE(out.empty()) << "b is the source and target of a unique 2-arc";
  check_incidence(e.g, e.c, 3, false, out);
  ASSERT_EQ(out.size(), 1u) << "c is not the source of a 3-arc (but is the target of one)";
  EXPECT_EQ(out[0].constraint, Constraint::incident_out);
  EXPECT_EQ(out[0].count, 0u);
}

TEST(GraphConstraints, Example4NonOrientation) {
  Example4 e;
  EXPECT_TRUE(non_oriented_at(e.g, e.f, 3));
  EXPECT_TRUE(non_oriented_at(e.g, e.f, 2)) << "the only 2-arc at f is a loop";
  EXPECT_FALSE(non_oriented_at(e.g, e.a, 3)) << "a -3-> c has no reverse";
  EXPECT_TRUE(non_oriented_at(e.g, e.d, 2)) << "no 2-arc is incident to d";
}

TEST(GraphConstraints, Example4Cycles) {
  Example4 e;
  EXPECT_TRUE(cycle_at(e.g, e.c, 1, 3));
  EXPECT_TRUE(cycle_at(e.g, e.a, 3, 1));
  EXPECT_FALSE(cycle_at(e.g, e.b, 1, 3));
}

// 002 Example 5 / Figure 7: a triangle on top of a square. As a 2-O-map:
// three 1-cycles (the two faces and the outer face), 2-arcs pairing the
// half-edges of each edge.
TEST(GraphConstraints, Example5TriangleOnSquareOMap) {
  // Square A: 0->1->2->3 (edges 01, 12, 23, 30); triangle B on edge 23:
  // 3->2 is B's copy of edge 23, then 2->4, 4->3.
  TopoGraph g;
  for (const char* n : {"s0", "s1", "s2", "s3", "t0", "t1", "t2", "o0", "o1", "o2", "o3", "o4"}) g.add_node(n);
  auto cyc = [&](std::vector<NodeId> c) {
    for (std::size_t k = 0; k < c.size(); ++k) g.add_arc(c[k], c[(k + 1) % c.size()], 1);
  };
  auto pair = [&](NodeId x, NodeId y) {
    g.add_arc(x, y, 2);
    g.add_arc(y, x, 2);
  };
  cyc({0, 1, 2, 3});       // square darts: s0 = 0->1, s1 = 1->2, s2 = 2->3, s3 = 3->0
  cyc({4, 5, 6});          // triangle: t0 = 3->2, t1 = 2->4, t2 = 4->3
  cyc({7, 8, 9, 10, 11});  // outer face, 5 boundary edges
  pair(2, 4);              // edge 23
  pair(0, 7), pair(1, 8), pair(5, 9), pair(6, 10), pair(3, 11);
  EXPECT_TRUE(check_graph(g, Model::omap(2)).valid());
  // Orienting one 2-arc breaks O(2) at both of its ends, only there.
  TopoGraph broken;
  for (const auto& n : g.names()) broken.add_node(n);
  bool dropped = false;
  for (const auto& a : g.arcs())
    if (!dropped && a.label == 2 && a.source == 2 && a.target == 4)
      dropped = true;
    else
      broken.add_arc(a.source, a.target, a.label);
  auto report = check_graph(broken, Model::omap(2));
  std::vector<std::pair<Constraint, std::uint32_t>> got;
  for (const auto& v : report.violations) got.emplace_back(v.constraint, v.element);
  EXPECT_EQ(got,
            (std::vector<std::pair<Constraint, std::uint32_t>>{
                {Constraint::incident_out, 2}, {Constraint::non_orientation, 2}, {Constraint::incident_in, 4}, {Constraint::non_orientation, 4}}));
}
