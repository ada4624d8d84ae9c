#include "querymodify/hex_queries.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "querymodify/hex_subdivisions.hpp"

namespace dartcheck::querymodify {

std::vector<std::array<std::uint32_t, 4>> subdivision_tets(std::uint64_t subdivision) {
  std::vector<std::array<std::uint32_t, 4>> out;
  for (TetMask t : tets_of(subdivision)) {
    std::array<std::uint32_t, 4> v{};
    std::size_t k = 0;
    for (std::uint32_t i = 0; i < 8; ++i)
      if (t & (1u << i)) v[k++] = i;
    out.push_back(v);
  }
  return out;
}

int subdivision_diagonals(std::uint64_t subdivision) {
  const auto tets = tets_of(subdivision);
  int bits = 0;
  for (int f = 0; f < 6; ++f) {
    const auto& q = hex_faces()[static_cast<std::size_t>(f)];
    // a-c splits the face iff triangle abc is a boundary triangle: in
    // exactly one tetrahedron (the other diagonal's triangles may be
    // interior, in two).
    const unsigned abc = (1u << q[0]) | (1u << q[1]) | (1u << q[2]);
    int uses = 0;
    for (TetMask t : tets) uses += (t & abc) == abc;
    if (uses != 1) bits |= 1 << f;
  }
  return bits;
}

std::vector<std::uint32_t> canonical_word(const Map& m) {
  std::vector<std::uint32_t> best;
  for (Dart d = 0; d < m.size(); ++d) {
    auto w = word(m, bfs_labeling(m, d));
    if (best.empty() || w < best) best = std::move(w);
  }
  return best;
}

// Readings of subdivision s: vertex permutations p such that p(tets) is
// again a labeled subdivision. Assigned vertex by vertex; a boundary
// triangle (in one tetrahedron) must land on 3 corners of one face, which
// leaves a few hundred of the 8! candidates.
static std::vector<std::array<std::uint8_t, 8>> readings(std::uint64_t s) {
  const auto tets = tets_of(s);
  std::vector<unsigned> boundary;
  for (TetMask t : tets)
    for (int v = 0; v < 8; ++v) {
      if (!(t & (1u << v))) continue;
      const unsigned tri = t & ~(1u << v);
      int uses = 0;
      for (TetMask u : tets) uses += (u & tri) == tri;
      if (uses == 1) boundary.push_back(tri);
    }
  auto on_a_face = [](unsigned m) {
    for (const auto& f : hex_faces()) {
      unsigned fm = 0;
      for (int v : f) fm |= 1u << v;
      if ((m & fm) == m) return true;
    }
    return false;
  };
  std::vector<std::array<std::uint8_t, 8>> out;
  std::array<std::uint8_t, 8> p{};
  auto image = [&](unsigned m) {
    unsigned r = 0;
    for (int v = 0; v < 8; ++v)
      if (m & (1u << v)) r |= 1u << p[static_cast<std::size_t>(v)];
    return r;
  };
  auto assign = [&](auto&& self, int v, unsigned used) -> void {
    if (v == 8) {
      std::uint64_t mapped = 0;
      for (TetMask t : tets) {
        const auto it = std::lower_bound(candidate_tets().begin(), candidate_tets().end(), static_cast<TetMask>(image(t)));
        if (it == candidate_tets().end() || *it != image(t)) return;
        mapped |= std::uint64_t{1} << (it - candidate_tets().begin());
      }
      if (std::binary_search(labeled_hex_subdivisions().begin(), labeled_hex_subdivisions().end(), mapped)) out.push_back(p);
      return;
    }
    const unsigned upto = (2u << v) - 1;  // vertices 0..v assigned
    for (std::uint8_t w = 0; w < 8; ++w) {
      if (used & (1u << w)) continue;
      p[static_cast<std::size_t>(v)] = w;
      bool ok = true;
      for (unsigned tri : boundary)
        if ((tri & (1u << v)) && (tri & ~upto) == 0 && !on_a_face(image(tri))) ok = false;
      if (ok) self(self, v + 1, used | (1u << w));
    }
  };
  assign(assign, 0, 0);
  return out;
}

const std::vector<HexQuery>& hex_queries() {
  static const std::vector<HexQuery> all = [] {
    std::set<std::uint64_t> classes;
    for (auto s : labeled_hex_subdivisions()) classes.insert(canonical_subdivision(s));
    std::vector<HexQuery> out;
    std::set<std::vector<std::uint32_t>> seen;
    for (std::uint64_t s : classes)
      for (bool mirror : {false, true}) {
        auto tets = subdivision_tets(s);
        // Without points, build_tet_map keeps the first tetrahedron's
        // orientation as given and propagates it: reflecting every
        // tetrahedron gives the mirror image.
        if (mirror)
          for (auto& t : tets) std::swap(t[2], t[3]);
        TetMap tm = build_tet_map(tets);
        auto key = canonical_word(tm.map);
        if (!seen.insert(key).second) continue;
        HexQuery q;
        q.readings = readings(s);
        q.subdivision = s;
        q.mirrored = mirror;
        q.tets = tm.tets.size();
        q.word = query_word(tm.map, 0, BoundaryCondition::no_connection);
        q.map = std::move(tm.map);
        out.push_back(std::move(q));
      }
    return out;
  }();
  return all;
}

}  // namespace dartcheck::querymodify
