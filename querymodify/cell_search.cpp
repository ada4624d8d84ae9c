#include "querymodify/cell_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "querymodify/cell_quality.hpp"
#include "querymodify/cell_subdivisions.hpp"

namespace dartcheck::querymodify {

namespace {

using Tet = std::array<std::uint32_t, 4>;
using Triangle = std::array<std::uint32_t, 3>;

Triangle sorted(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  Triangle t{a, b, c};
  std::sort(t.begin(), t.end());
  return t;
}

// The vertex of tetrahedron t that is not on the triangle tri.
std::uint32_t opposite(const Tet& t, const Triangle& tri) {
  for (auto v : t)
    if (std::find(tri.begin(), tri.end(), v) == tri.end()) return v;
  return t[0];
}

// The best reading of tetrahedra on k vertices as a cell of `readings`,
// filled into c (corners, quality); false if they are no such cell. Only
// readings whose corner `fixed` is at vertex `at` count, when fixed >= 0.
template <std::size_t K>
bool read_cell(const std::vector<Tet>& tets, const CellReadings& readings, CellCandidate& c, const std::vector<std::array<double, 3>>* points,
               int fixed = -1, std::uint32_t at = 0) {
  // The whole array sorted, unused slots last (a sort of a prefix of
  // variable length trips GCC 12's -Warray-bounds).
  std::array<std::uint32_t, 12> all;
  all.fill(std::numeric_limits<std::uint32_t>::max());
  std::size_t n = 0;
  for (std::uint32_t t : c.tets_of())
    for (auto v : tets[t]) all[n++] = v;
  std::sort(all.begin(), all.end());
  const auto end = std::unique(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(n));
  if (end - all.begin() != static_cast<std::ptrdiff_t>(K)) return false;
  std::array<CellTet, 3> local{};
  for (std::size_t k = 0; k < c.count; ++k) {
    unsigned m = 0;
    for (auto v : tets[c.tets[k]]) m |= 1u << (std::lower_bound(all.begin(), end, v) - all.begin());
    local[k] = static_cast<CellTet>(m);
  }
  bool any = false;
  for (const auto& r : readings.of({local.data(), c.count})) {
    std::array<std::uint32_t, 6> corners{};
    for (std::size_t k = 0; k < K; ++k) corners[k] = all[r[k]];
    if (fixed >= 0 && corners[static_cast<std::size_t>(fixed)] != at) continue;
    double q = std::nan("");
    if (points) {
      std::array<std::array<double, 3>, K> p{};
      for (std::size_t k = 0; k < K; ++k) p[k] = (*points)[corners[k]];
      if constexpr (K == 6)
        q = prism_quality(p);
      else
        q = pyramid_quality(p);
    }
    // The first reading without points; the best one with them.
    if (!any || q > c.quality) c.corners = corners, c.quality = q;
    any = true;
  }
  return any;
}

void keep(CellCandidates& out, const CellCandidate& c, const std::vector<std::array<double, 3>>* points, double min_quality) {
  ++out.found;
  if (!points || c.quality > min_quality) out.list.push_back(c);
}

}  // namespace

TetFaces::TetFaces(const std::vector<Tet>& tets) {
  std::vector<std::pair<Triangle, std::uint32_t>> all;
  all.reserve(4 * tets.size());
  for (std::uint32_t t = 0; t < tets.size(); ++t) {
    const Tet& x = tets[t];
    for (std::size_t k = 0; k < 4; ++k) all.push_back({sorted(x[(k + 1) % 4], x[(k + 2) % 4], x[(k + 3) % 4]), t});
  }
  std::sort(all.begin(), all.end());
  for (const auto& [tri, t] : all) triangles_.push_back(tri), tet_.push_back(t);
}

std::span<const std::uint32_t> TetFaces::on(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
  const auto [lo, hi] = std::equal_range(triangles_.begin(), triangles_.end(), sorted(a, b, c));
  return {tet_.data() + (lo - triangles_.begin()), static_cast<std::size_t>(hi - lo)};
}

bool TetFaces::quad_on_boundary(const std::array<std::uint32_t, 4>& q) const {
  // The diagonal whose triangles the mesh has (a quad of a cell is split
  // by exactly one).
  for (const auto& [x, y] : {std::pair{on(q[0], q[1], q[2]), on(q[0], q[2], q[3])}, std::pair{on(q[0], q[1], q[3]), on(q[1], q[2], q[3])}})
    if (!x.empty() && !y.empty()) return x.size() == 1 && y.size() == 1;
  return false;
}

CellCandidates find_prism_candidates(const std::vector<Tet>& tets, const TetFaces& faces, const std::vector<bool>& used,
                                     const std::vector<std::array<double, 3>>* points, double min_quality) {
  CellCandidates out;
  std::array<std::uint32_t, 4> across{};  // the free neighbour across each face, or the tetrahedron itself
  for (std::uint32_t m = 0; m < tets.size(); ++m) {
    if (used[m]) continue;
    const Tet& t = tets[m];
    for (std::size_t k = 0; k < 4; ++k) {
      across[k] = m;
      for (std::uint32_t n : faces.on(t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]))
        if (n != m && !used[n]) across[k] = n;
    }
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j) {
        if (across[i] == m || across[j] == m || across[i] == across[j]) continue;
        CellCandidate c;
        c.tets = {across[i], m, across[j]};
        c.count = 3;
        if (read_cell<6>(tets, prism_readings(), c, points)) keep(out, c, points, min_quality);
      }
  }
  return out;
}

CellCandidates find_pyramid_candidates(const std::vector<Tet>& tets, const TetFaces& faces, const std::vector<bool>& used,
                                       const std::vector<std::array<std::uint32_t, 4>>& quads, const std::vector<std::array<double, 3>>* points,
                                       double min_quality) {
  CellCandidates out;
  auto free_on = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) -> std::int64_t {
    for (std::uint32_t t : faces.on(a, b, c))
      if (!used[t]) return t;
    return -1;
  };
  // Pairs of tetrahedra with their apex; sorted, so a quad two cells share
  // gives its pyramid once.
  std::vector<std::array<std::uint32_t, 3>> pairs;
  for (const auto& q : quads)
    for (const auto& [x, y] : {std::pair{Triangle{q[0], q[1], q[2]}, Triangle{q[0], q[2], q[3]}}, std::pair{Triangle{q[0], q[1], q[3]}, Triangle{q[1], q[2], q[3]}}}) {
      const std::int64_t s = free_on(x[0], x[1], x[2]), t = free_on(y[0], y[1], y[2]);
      if (s < 0 || t < 0 || s == t) continue;
      const std::uint32_t apex = opposite(tets[static_cast<std::size_t>(s)], x);
      if (opposite(tets[static_cast<std::size_t>(t)], y) != apex) continue;
      pairs.push_back({static_cast<std::uint32_t>(std::min(s, t)), static_cast<std::uint32_t>(std::max(s, t)), apex});
    }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (const auto& [s, t, apex] : pairs) {
    CellCandidate c;
    c.tets = {s, t, 0};
    c.count = 2;
    if (read_cell<5>(tets, pyramid_readings(), c, points, 4, apex)) keep(out, c, points, min_quality);
  }
  return out;
}

std::size_t quads_facing_triangles(const std::vector<std::array<std::uint32_t, 4>>& quads, const TetFaces& faces) {
  std::map<std::array<std::uint32_t, 4>, int> cells_with;
  auto key = [](std::array<std::uint32_t, 4> q) {
    std::sort(q.begin(), q.end());
    return q;
  };
  for (const auto& q : quads) ++cells_with[key(q)];
  std::size_t n = 0;
  for (const auto& q : quads) n += cells_with[key(q)] == 1 && !faces.quad_on_boundary(q);
  return n;
}

}  // namespace dartcheck::querymodify
