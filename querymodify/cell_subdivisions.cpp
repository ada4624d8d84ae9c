#include "querymodify/cell_subdivisions.hpp"

#include <algorithm>
#include <bit>
#include <numeric>
#include <set>

namespace dartcheck::querymodify {

namespace {

unsigned mask_of(const std::vector<int>& corners) {
  unsigned m = 0;
  for (int c : corners) m |= 1u << c;
  return m;
}

// The corner permutations that map the faces (as corner sets) onto faces.
std::vector<std::vector<int>> symmetries_of(int corners, const std::vector<std::vector<int>>& faces) {
  std::set<unsigned> face_masks;
  for (const auto& f : faces) face_masks.insert(mask_of(f));
  std::vector<int> p(static_cast<std::size_t>(corners));
  std::iota(p.begin(), p.end(), 0);
  std::vector<std::vector<int>> out;
  do {
    bool ok = true;
    for (const auto& f : faces) {
      unsigned image = 0;
      for (int c : f) image |= 1u << p[static_cast<std::size_t>(c)];
      ok = ok && face_masks.count(image);
    }
    if (ok) out.push_back(p);
  } while (std::next_permutation(p.begin(), p.end()));
  return out;
}

CellShape make_shape(std::string_view name, int corners, std::vector<std::vector<int>> faces) {
  CellShape s{name, corners, std::move(faces), {}};
  s.symmetries = symmetries_of(corners, s.faces);
  return s;
}

// The tetrahedra a subdivision may use: 4 corners not all on one face.
std::vector<CellTet> candidate_tets(const CellShape& cell) {
  std::vector<CellTet> out;
  for (unsigned m = 0; m < (1u << cell.corners); ++m) {
    if (std::popcount(m) != 4) continue;
    const bool on_a_face = std::any_of(cell.faces.begin(), cell.faces.end(), [&](const auto& f) { return (m & ~mask_of(f)) == 0; });
    if (!on_a_face) out.push_back(static_cast<CellTet>(m));
  }
  return out;
}

// The boundary triangles of the cell's surface when quad q is split by
// its corners 1-3 for bit q of `diagonals` (0-2 otherwise).
std::vector<unsigned> boundary_triangles(const CellShape& cell, unsigned diagonals) {
  std::vector<unsigned> out;
  unsigned q = 0;
  for (const auto& f : cell.faces) {
    if (f.size() == 3) {
      out.push_back(mask_of(f));
      continue;
    }
    auto bit = [&](std::size_t k) { return 1u << f[k]; };
    if ((diagonals >> q++) & 1)
      out.insert(out.end(), {bit(0) | bit(1) | bit(3), bit(1) | bit(2) | bit(3)});
    else
      out.insert(out.end(), {bit(0) | bit(1) | bit(2), bit(0) | bit(2) | bit(3)});
  }
  return out;
}

unsigned quads_of(const CellShape& cell) {
  return static_cast<unsigned>(std::count_if(cell.faces.begin(), cell.faces.end(), [](const auto& f) { return f.size() == 4; }));
}

// Every mask reached from the first by steps between masks that share
// `shared` bits (triangles sharing an edge, tetrahedra sharing a face).
template <class Mask>
bool connected(const std::vector<Mask>& masks, int shared) {
  std::vector<bool> reached(masks.size(), false);
  reached[0] = true;
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t a = 0; a < masks.size(); ++a)
      for (std::size_t b = 0; b < masks.size(); ++b)
        if (reached[a] && !reached[b] && std::popcount(static_cast<unsigned>(masks[a] & masks[b])) == shared) reached[b] = grew = true;
  }
  return std::find(reached.begin(), reached.end(), false) == reached.end();
}

// Each corner's link (the triangles opposite it in its tetrahedra) is a
// disk: connected, every edge in one or two of its triangles, Euler
// characteristic 1. With the boundary the cell's surface, the complex is
// then a 3-manifold bounded by a sphere: a ball.
bool links_are_disks(const CellShape& cell, const std::vector<CellTet>& tets) {
  for (int v = 0; v < cell.corners; ++v) {
    std::vector<unsigned> triangles;
    for (CellTet t : tets)
      if (t & (1u << v)) triangles.push_back(t & ~(1u << v));
    if (triangles.empty()) return false;
    std::vector<int> edge_uses(64, 0);
    unsigned vertices = 0;
    for (unsigned t : triangles) {
      vertices |= t;
      for (unsigned x = t; x; x &= x - 1) ++edge_uses[t & ~(x & -x)];
    }
    int edges = 0;
    for (int uses : edge_uses) {
      if (uses > 2) return false;
      edges += uses > 0;
    }
    if (std::popcount(vertices) - edges + static_cast<int>(triangles.size()) != 1) return false;
    if (!connected(triangles, 2)) return false;  // across shared edges
  }
  return true;
}

bool is_subdivision(const CellShape& cell, const std::vector<CellTet>& tets) {
  if (tets.empty()) return false;
  std::vector<int> uses(64, 0);
  for (CellTet t : tets)
    for (unsigned x = t; x; x &= x - 1) ++uses[t & ~(x & -x)];
  // Some choice of diagonals makes every boundary triangle used once and
  // every other triangle twice or never.
  bool fits = false;
  for (unsigned d = 0; d < (1u << quads_of(cell)) && !fits; ++d) {
    std::vector<bool> boundary(64, false);
    for (unsigned t : boundary_triangles(cell, d)) boundary[t] = true;
    fits = true;
    for (unsigned t = 0; t < 64 && fits; ++t) fits = boundary[t] ? uses[t] == 1 : uses[t] != 1 && uses[t] <= 2;
  }
  if (!fits) return false;
  return connected(tets, 3) && links_are_disks(cell, tets);  // connected across shared triangles
}

}  // namespace

const CellShape& prism_shape() {
  static const CellShape s = make_shape("prism", 6, {{0, 1, 2}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}});
  return s;
}

const CellShape& pyramid_shape() {
  static const CellShape s = make_shape("pyramid", 5, {{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  return s;
}

std::vector<std::vector<CellTet>> enumerate_cell_subdivisions(const CellShape& cell) {
  const auto candidates = candidate_tets(cell);
  std::vector<std::vector<CellTet>> out;
  for (std::uint32_t set = 1; set < (1u << candidates.size()); ++set) {
    std::vector<CellTet> tets;
    for (std::uint32_t s = set; s; s &= s - 1) tets.push_back(candidates[static_cast<std::size_t>(std::countr_zero(s))]);
    if (is_subdivision(cell, tets)) out.push_back(std::move(tets));
  }
  return out;
}

unsigned cell_subdivision_diagonals(const CellShape& cell, std::span<const CellTet> subdivision) {
  unsigned out = 0, q = 0;
  for (const auto& f : cell.faces) {
    if (f.size() != 4) continue;
    // Split by 1-3: exactly one tetrahedron holds the triangle (0, 1, 3)
    // (two hold it when 1-3 passes inside, the quad split by 0-2).
    const unsigned t = (1u << f[0]) | (1u << f[1]) | (1u << f[3]);
    if (std::count_if(subdivision.begin(), subdivision.end(), [&](CellTet x) { return (x & t) == t; }) == 1) out |= 1u << q;
    ++q;
  }
  return out;
}

CellReadings::CellReadings(const CellShape& cell) : cell_(&cell) {
  const auto k = static_cast<std::size_t>(cell.corners);
  std::vector<std::pair<std::uint64_t, std::array<std::uint8_t, 6>>> all;
  std::vector<int> perm(k);
  for (const auto& s : enumerate_cell_subdivisions(cell)) {
    std::iota(perm.begin(), perm.end(), 0);
    do {  // corner c read at local vertex perm[c]
      std::uint64_t key = 0;
      for (CellTet t : s) {
        unsigned image = 0;
        for (std::size_t c = 0; c < k; ++c)
          if (t & (1u << c)) image |= 1u << perm[c];
        key |= std::uint64_t{1} << image;
      }
      // The smallest reading of its class under the cell's symmetries.
      std::array<std::uint8_t, 6> best{255, 255, 255, 255, 255, 255};
      for (const auto& sigma : cell.symmetries) {
        std::array<std::uint8_t, 6> r{255, 255, 255, 255, 255, 255};
        for (std::size_t c = 0; c < k; ++c) r[c] = static_cast<std::uint8_t>(perm[static_cast<std::size_t>(sigma[c])]);
        best = std::min(best, r);
      }
      all.push_back({key, best});
    } while (std::next_permutation(perm.begin(), perm.end()));
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  for (const auto& [key, reading] : all) {
    keys_.push_back(key);
    readings_.push_back(reading);
  }
}

std::span<const std::array<std::uint8_t, 6>> CellReadings::of(std::span<const CellTet> tets) const {
  std::uint64_t key = 0;
  for (CellTet t : tets) key |= std::uint64_t{1} << (t & 63u);
  const auto [lo, hi] = std::equal_range(keys_.begin(), keys_.end(), key);
  return {readings_.data() + (lo - keys_.begin()), static_cast<std::size_t>(hi - lo)};
}

const CellReadings& prism_readings() {
  static const CellReadings r(prism_shape());
  return r;
}

const CellReadings& pyramid_readings() {
  static const CellReadings r(pyramid_shape());
  return r;
}

}  // namespace dartcheck::querymodify
