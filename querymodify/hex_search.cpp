#include "querymodify/hex_search.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "querymodify/hex_quality.hpp"
#include "querymodify/hex_queries.hpp"
#include "querymodify/hex_subdivisions.hpp"

namespace dartcheck::querymodify {

namespace {

using Tet = std::array<std::uint32_t, 4>;

// Compressed lists: the items of key k are items[start[k], start[k + 1]).
struct Lists {
  std::vector<std::uint32_t> start, items;
  std::span<const std::uint32_t> operator[](std::uint32_t k) const { return {items.data() + start[k], start[k + 1] - start[k]}; }
};

// Counting sort of (key, item) pairs into lists.
template <class Each>
Lists lists(std::size_t keys, Each each) {
  Lists l;
  l.start.assign(keys + 1, 0);
  each([&](std::uint32_t k, std::uint32_t) { ++l.start[k + 1]; });
  for (std::size_t k = 0; k < keys; ++k) l.start[k + 1] += l.start[k];
  l.items.resize(l.start[keys]);
  std::vector<std::uint32_t> at(l.start.begin(), l.start.end() - 1);
  each([&](std::uint32_t k, std::uint32_t item) { l.items[at[k]++] = item; });
  return l;
}

// The labeled subdivisions by their face diagonals (bit f: face f split
// by b-d, as subdivision_diagonals), and each face's two triangles under
// each diagonal, as vertex masks.
struct ByDiagonals {
  std::array<std::vector<std::uint64_t>, 64> subdivisions;
  std::array<std::array<std::array<unsigned, 2>, 2>, 6> triangles{};
  ByDiagonals() {
    for (auto s : labeled_hex_subdivisions()) subdivisions[static_cast<std::size_t>(subdivision_diagonals(s))].push_back(s);
    for (std::size_t f = 0; f < 6; ++f) {
      const auto& q = hex_faces()[f];
      auto bit = [&](int k) { return 1u << q[static_cast<std::size_t>(k)]; };
      triangles[f][0] = {bit(0) | bit(1) | bit(2), bit(0) | bit(2) | bit(3)};  // split by a-c
      triangles[f][1] = {bit(0) | bit(1) | bit(3), bit(1) | bit(2) | bit(3)};  // split by b-d
    }
  }
};
const ByDiagonals& by_diagonals() {
  static const ByDiagonals b;
  return b;
}

// A quad face at corner 0: the cycle (corner 0, p, q, r), p < r.
struct Quad {
  std::uint32_t p, q, r;
  auto operator<=>(const Quad&) const = default;
};

class Search {
 public:
  Search(const std::vector<Tet>& tets, const std::vector<std::array<double, 3>>* points, double min_quality)
      : tets_(tets), points_(points), min_quality_(min_quality) {
    std::uint32_t vertices = 0;
    for (const auto& t : tets)
      for (auto v : t) vertices = std::max(vertices, v + 1);
    vertices_ = vertices;
    low_ = std::vector<std::uint32_t>(tets.size());
    for (std::size_t t = 0; t < tets.size(); ++t) low_[t] = *std::min_element(tets[t].begin(), tets[t].end());
    // Each tetrahedron listed once, under its smallest vertex, and under
    // each of its vertices.
    by_low_ = lists(vertices, [&](auto add) {
      for (std::uint32_t t = 0; t < tets.size(); ++t) add(low_[t], t);
    });
    around_ = lists(vertices, [&](auto add) {
      for (std::uint32_t t = 0; t < tets.size(); ++t)
        for (auto v : tets[t]) add(v, t);
    });
    // Edges, both ways, sorted: around each vertex its neighbours.
    std::vector<std::uint64_t> edges;
    edges.reserve(tets.size() * 12);
    for (const auto& t : tets)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          if (a != b) edges.push_back(std::uint64_t{t[static_cast<std::size_t>(a)]} << 32 | t[static_cast<std::size_t>(b)]);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    adjacent_ = lists(vertices, [&](auto add) {
      for (auto e : edges) add(static_cast<std::uint32_t>(e >> 32), static_cast<std::uint32_t>(e));
    });
    corner_of_.assign(vertices, 0);
    candidate_index_.fill(-1);
    for (std::size_t k = 0; k < candidate_tets().size(); ++k) candidate_index_[candidate_tets()[k]] = static_cast<int>(k);
  }

  HexCandidates run(const Progress& progress) {
    for (std::uint32_t v0 = 0; v0 < vertices_; ++v0) {
      if (progress && v0 % 16384 == 0) progress("searching hex candidates", v0, vertices_);
      from_corner(v0);
    }
    return std::move(out_);
  }

 private:
  bool linked(std::uint32_t a, std::uint32_t b) const {
    const auto n = adjacent_[a];
    return std::binary_search(n.begin(), n.end(), b);
  }
  bool holds(std::uint32_t t, std::uint32_t v) const { return std::find(tets_[t].begin(), tets_[t].end(), v) != tets_[t].end(); }

  // The quads at corner v0 made of triangles of tetrahedra above it.
  void quads_at(std::uint32_t v0) {
    link_.clear();
    quads_.clear();
    for (std::uint32_t t : by_low_[v0]) {
      std::array<std::uint32_t, 3> o{};
      std::size_t n = 0;
      for (auto v : tets_[t])
        if (v != v0) o[n++] = v;
      std::sort(o.begin(), o.end());
      link_.push_back({o[0], o[1]});
      link_.push_back({o[0], o[2]});
      link_.push_back({o[1], o[2]});
    }
    std::sort(link_.begin(), link_.end());
    link_.erase(std::unique(link_.begin(), link_.end()), link_.end());
    // Diagonal through corner 0: triangles (v0, p, q) and (v0, q, r).
    for (std::size_t a = 0; a < link_.size(); ++a)
      for (std::size_t b = a + 1; b < link_.size(); ++b) {
        const auto [a0, a1] = link_[a];
        const auto [b0, b1] = link_[b];
        std::uint32_t q, p, r;
        if (a0 == b0)
          q = a0, p = a1, r = b1;
        else if (a0 == b1)
          q = a0, p = a1, r = b0;
        else if (a1 == b0)
          q = a1, p = a0, r = b1;
        else if (a1 == b1)
          q = a1, p = a0, r = b0;
        else
          continue;
        quads_.push_back({std::min(p, r), q, std::max(p, r)});
      }
    // Diagonal p-r: triangle (v0, p, r) and a triangle (p, q, r) of a
    // tetrahedron above corner 0.
    for (const auto& [p, r] : link_)
      for (std::uint32_t t : around_[p]) {
        if (low_[t] < v0 || !holds(t, r)) continue;
        for (auto q : tets_[t])
          if (q != p && q != r && q != v0) quads_.push_back({p, q, r});
      }
    std::sort(quads_.begin(), quads_.end());
    quads_.erase(std::unique(quads_.begin(), quads_.end()), quads_.end());
  }

  void from_corner(std::uint32_t v0) {
    if (by_low_[v0].empty()) return;
    quads_at(v0);
    batch_ = out_.list.size();
    corners_around(v0);
    // Every reading of a candidate has the same 8 corners, so the same
    // corner 0: the candidates from v0 are final. Those not above the
    // threshold go now, so memory holds only what may be selected.
    std::size_t kept = batch_, pool = batch_ < out_.list.size() ? out_.list[batch_].first : out_.tets.size();
    for (std::size_t k = batch_; k < out_.list.size(); ++k) {
      HexCandidate c = out_.list[k];
      ++out_.found;
      if (points_ && !(c.quality > min_quality_)) continue;
      std::copy(out_.tets.begin() + c.first, out_.tets.begin() + c.first + c.count, out_.tets.begin() + static_cast<std::ptrdiff_t>(pool));
      c.first = static_cast<std::uint32_t>(pool);
      pool += c.count;
      out_.list[kept++] = c;
    }
    out_.list.resize(kept);
    out_.tets.resize(pool);
  }

  // The cube labelings with corner 0 at v0 (corners 1 < 2 < 4).
  void corners_around(std::uint32_t v0) {
    auto from = [&](std::uint32_t p) {
      auto lo = std::lower_bound(quads_.begin(), quads_.end(), Quad{p, 0, 0});
      auto hi = lo;
      while (hi != quads_.end() && hi->p == p) ++hi;
      return std::pair{lo, hi};
    };
    std::array<std::uint32_t, 8> v{};
    v[0] = v0;
    for (const Quad& a : quads_) {  // the face (0, 1, 3, 2)
      v[1] = a.p, v[3] = a.q, v[2] = a.r;
      const auto [b_lo, b_hi] = from(v[2]);
      const auto [c_lo, c_hi] = from(v[1]);
      for (auto b = b_lo; b != b_hi; ++b) {  // the face (0, 2, 6, 4)
        v[6] = b->q, v[4] = b->r;
        if (v[6] == v[1] || v[6] == v[3] || v[4] == v[3]) continue;
        for (auto c = c_lo; c != c_hi; ++c) {  // the face (0, 1, 5, 4)
          if (c->r != v[4]) continue;
          v[5] = c->q;
          if (v[5] == v[2] || v[5] == v[3] || v[5] == v[6]) continue;
          for (std::uint32_t v7 : adjacent_[v[3]]) {
            if (v7 <= v0 || v7 == v[1] || v7 == v[2] || v7 == v[4] || v7 == v[5] || v7 == v[6]) continue;
            if (!linked(v7, v[5]) || !linked(v7, v[6])) continue;
            v[7] = v7;
            examine(v);
          }
        }
      }
    }
  }

  // The mesh tetrahedra on the 8 corners; each labeled subdivision among
  // them is a reading of a candidate.
  void examine(const std::array<std::uint32_t, 8>& v) {
    for (std::uint32_t c = 0; c < 8; ++c) corner_of_[v[c]] = c + 1;
    std::uint64_t present = 0;
    for (std::uint32_t c = 0; c < 8; ++c)
      for (std::uint32_t t : by_low_[v[c]]) {
        unsigned mask = 0;
        for (auto x : tets_[t]) {
          const std::uint32_t at = corner_of_[x];
          if (at == 0) {
            mask = 0;
            break;
          }
          mask |= 1u << (at - 1);
        }
        if (mask == 0) continue;
        const int k = candidate_index_[mask];
        if (k < 0) continue;  // the 4 corners of a face: never in a subdivision
        present |= std::uint64_t{1} << k;
        tet_at_[static_cast<std::size_t>(k)] = t;
      }
    for (std::uint32_t c = 0; c < 8; ++c) corner_of_[v[c]] = 0;
    if (std::popcount(present) < 5) return;
    const auto& labeled = labeled_hex_subdivisions();
    if (std::binary_search(labeled.begin(), labeled.end(), present)) {
      found(v, present);
      return;
    }
    if (std::popcount(present) > 5) within(v, present);
  }

  // Further tetrahedra on the 8 corners (outside the hex): every labeled
  // subdivision among them. Its boundary triangles are triangles of the
  // tetrahedra present, which leaves few diagonals to try.
  void within(const std::array<std::uint32_t, 8>& v, std::uint64_t present) {
    std::array<bool, 256> triangle{};
    for (std::uint64_t s = present; s; s &= s - 1) {
      const unsigned t = candidate_tets()[static_cast<std::size_t>(std::countr_zero(s))];
      for (unsigned x = t; x; x &= x - 1) triangle[t & ~(x & -x)] = true;  // t without one vertex
    }
    const ByDiagonals& b = by_diagonals();
    std::array<unsigned, 6> options{};  // per face, bit o: diagonal o's two triangles are present
    for (std::size_t f = 0; f < 6; ++f) {
      for (std::size_t o = 0; o < 2; ++o)
        if (triangle[b.triangles[f][o][0]] && triangle[b.triangles[f][o][1]]) options[f] |= 1u << o;
      if (options[f] == 0) return;
    }
    for (unsigned d = 0; d < 64; ++d) {
      bool fits = true;
      for (std::size_t f = 0; f < 6 && fits; ++f) fits = (options[f] >> ((d >> f) & 1)) & 1;
      if (!fits) continue;
      for (auto s : b.subdivisions[d])
        if ((s & ~present) == 0) found(v, s);
    }
  }

  void found(const std::array<std::uint32_t, 8>& v, std::uint64_t subdivision) {
    ++out_.readings;
    std::array<std::uint32_t, 15> t{};
    std::uint32_t n = 0;
    for (std::uint64_t s = subdivision; s; s &= s - 1) t[n++] = tet_at_[static_cast<std::size_t>(std::countr_zero(s))];
    std::sort(t.begin(), t.begin() + n);
    const double quality = points_ ? scaled_jacobian(corner_points(v, *points_)) : std::nan("");
    // The same tetrahedra read before (another pairing of their
    // triangles into quads; from this corner 0): keep the better reading.
    for (std::size_t k = batch_; k < out_.list.size(); ++k) {
      HexCandidate& c = out_.list[k];
      if (c.count != n || !std::equal(t.begin(), t.begin() + n, out_.tets.begin() + c.first)) continue;
      if (quality > c.quality) c.quality = quality, c.corners = v;
      return;
    }
    HexCandidate c;
    c.first = static_cast<std::uint32_t>(out_.tets.size());
    c.count = n;
    c.corners = v;
    c.quality = quality;
    out_.tets.insert(out_.tets.end(), t.begin(), t.begin() + n);
    out_.list.push_back(c);
  }

  const std::vector<Tet>& tets_;
  const std::vector<std::array<double, 3>>* points_;
  std::uint32_t vertices_ = 0;
  std::vector<std::uint32_t> low_;  // smallest vertex of each tetrahedron
  Lists by_low_, around_, adjacent_;
  std::vector<std::uint32_t> corner_of_;  // scratch: 1 + the corner of a vertex being examined, 0 otherwise
  std::array<int, 256> candidate_index_{};
  std::array<std::uint32_t, 64> tet_at_{};
  std::vector<std::pair<std::uint32_t, std::uint32_t>> link_;
  std::vector<Quad> quads_;
  double min_quality_;
  std::size_t batch_ = 0;  // the first candidate from the current corner 0
  HexCandidates out_;
};

}  // namespace

HexCandidates find_hex_candidates(const std::vector<Tet>& tets, const std::vector<std::array<double, 3>>* points, double min_quality,
                                  const Progress& progress) {
  if (progress) progress("indexing the tetrahedra", 0, 0);
  return Search(tets, points, min_quality).run(progress);
}

}  // namespace dartcheck::querymodify
