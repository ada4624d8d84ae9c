#include "querymodify/terrain.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <random>
#include <stdexcept>

#include "core/error.hpp"
#include "core/orbit.hpp"
#include "querymodify/overlap.hpp"

namespace dartcheck::querymodify::terrain {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Lower and upper grid vertices of an n x n voxel grid.
struct GridIds {
  std::uint32_t n;
  std::uint32_t lower(std::uint32_t i, std::uint32_t j) const { return i + (n + 1) * j; }
  std::uint32_t upper(std::uint32_t i, std::uint32_t j) const { return (n + 1) * (n + 1) + lower(i, j); }
};

// The boundary of a 3 x 3 square, counter-clockwise seen from above.
constexpr std::uint32_t ring[12][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}, {2, 3}, {1, 3}, {0, 3}, {0, 2}, {0, 1}};

// Kept darts through a renumbering (a deleted one would become no_dart).
void renumber(std::vector<Dart>& darts, const Renumbering& r) {
  for (Dart& d : darts) d = r.to_h(d);
}

std::size_t volumes(const Map& m) {
  OrbitWalker w(m);
  return w.count_orbits(dims_generators({1, 2}));
}

}  // namespace

std::vector<double> diamond_square(unsigned k, std::uint64_t seed, double low, double high) {
  const std::size_t s = (std::size_t{1} << k) + 1;
  std::vector<double> h(s * s, 0.0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  auto at = [&](std::size_t x, std::size_t y) -> double& { return h[x + s * y]; };
  for (std::size_t y : {std::size_t{0}, s - 1})
    for (std::size_t x : {std::size_t{0}, s - 1}) at(x, y) = noise(rng);
  double scale = 1.0;
  for (std::size_t step = s - 1; step > 1; step /= 2, scale *= 0.55) {
    const std::size_t half = step / 2;
    for (std::size_t y = half; y < s; y += step)  // diamond: square centres
      for (std::size_t x = half; x < s; x += step)
        at(x, y) = (at(x - half, y - half) + at(x + half, y - half) + at(x - half, y + half) + at(x + half, y + half)) / 4 + scale * noise(rng);
    for (std::size_t y = 0; y < s; y += half)  // square: edge midpoints
      for (std::size_t x = (y / half) % 2 == 0 ? half : 0; x < s; x += step) {
        double sum = 0;
        int count = 0;
        if (x >= half) sum += at(x - half, y), ++count;
        if (x + half < s) sum += at(x + half, y), ++count;
        if (y >= half) sum += at(x, y - half), ++count;
        if (y + half < s) sum += at(x, y + half), ++count;
        at(x, y) = sum / count + scale * noise(rng);
      }
  }
  const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
  const double from = *lo, span = *hi - *lo;
  for (double& v : h) v = span > 0 ? low + (high - low) * (v - from) / span : low;
  return h;
}

std::vector<Polyhedron> voxel_cells(std::uint32_t n) {
  const GridIds g{n};
  std::vector<Polyhedron> cells;
  cells.reserve(std::size_t{n} * n);
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t b00 = g.lower(i, j), b10 = g.lower(i + 1, j), b11 = g.lower(i + 1, j + 1), b01 = g.lower(i, j + 1);
      const std::uint32_t t00 = g.upper(i, j), t10 = g.upper(i + 1, j), t11 = g.upper(i + 1, j + 1), t01 = g.upper(i, j + 1);
      cells.push_back({{t00, t10, t11, t01},  // upper face first: darts 26c .. 26c+3
                       {b00, b11, b10},
                       {b00, b01, b11},  // bottom, split by (i, j)-(i+1, j+1)
                       {b00, b10, t10, t00},
                       {b10, b11, t11, t10},  // sides -y, +x
                       {b11, b01, t01, t11},
                       {b01, b00, t00, t01}});  // sides +y, -x
    }
  return cells;
}

std::vector<Point3> voxel_points(std::uint32_t n, const std::vector<double>& heights) {
  if (heights.size() != std::size_t{n + 1} * (n + 1))
    throw ValueError(fmt::format("a {0} x {0} voxel grid needs {1} heights, not {2}", n, (n + 1) * (n + 1), heights.size()));
  std::vector<Point3> p(2 * heights.size());
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i) {
      const std::size_t at = i + std::size_t{n + 1} * j;
      p[at] = {double(i), double(j), 0.0};
      p[heights.size() + at] = {double(i), double(j), heights[at]};
    }
  return p;
}

Mesh voxel_grid(std::uint32_t n, const std::vector<double>& heights) {
  const auto points = voxel_points(n, heights);
  GluedCells c = glue_cells(CellComplex::of(voxel_cells(n)));
  return {std::move(c.map), dart_points(c.vertex, points)};
}

SpotQuery spot_query() {
  SpotQuery q{voxel_grid(3, std::vector<double>(16, 1.0)), {}};
  for (Dart c = 0; c < 9; ++c)
    for (Dart j = 0; j < 4; ++j) q.upper.push_back(26 * c + j);
  return q;
}

Renumbering flatten_spot(Mesh& m, const SpotQuery& q, const std::vector<Dart>& q_to_m) {
  std::vector<Dart> upper;
  for (Dart x : q.upper) upper.push_back(q_to_m[x]);
  // The mean height of the 16 upper points (by position: they are grid
  // points, distinct in x and y).
  std::map<std::pair<double, double>, double> height;
  for (Dart d : upper) height[{m.points[d][0], m.points[d][1]}] = m.points[d][2];
  double mean = 0;
  for (const auto& [xy, z] : height) mean += z;
  mean /= static_cast<double>(height.size());
  const Renumbering first = merge_volumes(m.map, q_to_m);
  follow(m.points, first);
  renumber(upper, first);
  std::vector<Dart> kept;  // the merged face's darts: not on an edge between two upper faces
  for (Dart d : upper)
    if (std::find(upper.begin(), upper.end(), m.map.link(2, d)) == upper.end()) kept.push_back(d);
  const Renumbering second = merge_faces(m.map, upper);
  follow(m.points, second);
  renumber(kept, second);
  OrbitWalker walker(m.map);
  const auto vertex = cell_generators(m.map.model(), 0);
  for (Dart d : kept)
    for (Dart e : walker.orbit(d, vertex)) m.points[e][2] = mean;
  return first.then(second);
}

HouseRule house_rule() {
  // Points by name: lower grid points, then the rings at z = 1, 2, 3, apex.
  std::vector<Point3> points;
  std::uint32_t lower[4][4];
  for (std::uint32_t j = 0; j < 4; ++j)
    for (std::uint32_t i = 0; i < 4; ++i) {
      lower[i][j] = static_cast<std::uint32_t>(points.size());
      points.push_back({double(i), double(j), 0.0});
    }
  auto level = [&](double z) {
    std::vector<std::uint32_t> r;
    for (const auto& p : ring) {
      r.push_back(static_cast<std::uint32_t>(points.size()));
      points.push_back({double(p[0]), double(p[1]), z});
    }
    return r;
  };
  const auto top = level(1), second = level(2), eaves = level(3);
  const auto apex = static_cast<std::uint32_t>(points.size());
  points.push_back({1.5, 1.5, 4.5});
  auto reversed = [](std::vector<std::uint32_t> r) {
    std::reverse(r.begin(), r.end());
    return r;
  };
  Polyhedron spot{top};
  for (std::size_t k = 0; k < 12; ++k) {
    const auto& p = ring[k];
    const auto& q = ring[(k + 1) % 12];
    spot.push_back({lower[p[0]][p[1]], lower[q[0]][q[1]], top[(k + 1) % 12], top[k]});
  }
  for (std::uint32_t j = 0; j < 3; ++j)
    for (std::uint32_t i = 0; i < 3; ++i) {
      spot.push_back({lower[i][j], lower[i + 1][j + 1], lower[i + 1][j]});
      spot.push_back({lower[i][j], lower[i][j + 1], lower[i + 1][j + 1]});
    }
  auto storey = [&](const std::vector<std::uint32_t>& floor, const std::vector<std::uint32_t>& ceiling) {
    Polyhedron p{reversed(floor), ceiling};
    for (std::size_t k = 0; k < 12; ++k) p.push_back({floor[k], floor[(k + 1) % 12], ceiling[(k + 1) % 12], ceiling[k]});
    return p;
  };
  Polyhedron roof{reversed(eaves)};
  for (std::size_t k = 0; k < 12; ++k) roof.push_back({eaves[k], eaves[(k + 1) % 12], apex});
  HouseRule r;
  GluedCells q = glue_cells(CellComplex::of({spot}));
  GluedCells t = glue_cells(CellComplex::of({spot, storey(top, second), storey(second, eaves), roof}));
  r.query = {std::move(q.map), dart_points(q.vertex, points)};
  r.target = {std::move(t.map), dart_points(t.vertex, points)};
  for (Dart d = 0; d < 12; ++d) r.upper.push_back(d);
  return r;
}

// (2) flat spots on the n x n grid: query, choose vertex-disjoint
// matches, apply.
void flatten_spots(Experiment& x, std::uint32_t n, std::size_t spots, std::uint64_t seed) {
  const SpotQuery spot = spot_query();
  auto t0 = Clock::now();
  QueryTrie trie;
  trie.add(query_word(spot.mesh.map, 0), 0);
  auto found = all_matches(x.mesh.map, trie, nullptr, 1);
  x.flattened.query_seconds = since(t0);
  x.flattened.raw_matches = found.raw;
  x.flattened.distinct_matches = found.distinct.size();
  t0 = Clock::now();
  std::mt19937_64 rng(seed);
  std::shuffle(found.distinct.begin(), found.distinct.end(), rng);
  OrbitWalker walker(x.mesh.map);
  const auto vertex = cell_generators(x.mesh.map.model(), 0);
  std::vector<bool> used(x.mesh.map.size(), false);  // darts of vertices taken
  std::vector<std::vector<Dart>> chosen;
  for (const QueryMatch& m : found.distinct) {
    if (chosen.size() == spots) break;
    std::vector<Dart> around;
    bool free = true;
    for (Dart d : m.darts)
      for (Dart e : walker.orbit(d, vertex)) {
        free = free && !used[e];
        around.push_back(e);
      }
    if (!free) continue;
    for (Dart e : around) used[e] = true;
    chosen.push_back(query_to_input(spot.mesh.map, 0, m));
  }
  if (chosen.size() < spots) throw Error(fmt::format("only {} vertex-disjoint spots on a {} x {} grid", chosen.size(), n, n));
  for (std::size_t s = 0; s < chosen.size(); ++s) {
    const Renumbering moved = flatten_spot(x.mesh, spot, chosen[s]);
    for (std::size_t later = s + 1; later < chosen.size(); ++later) renumber(chosen[later], moved);
  }
  x.flattened.modify_seconds = since(t0);
  x.flattened.applied = chosen.size();
  x.flattened.volumes = volumes(x.mesh.map);
  x.flattened.darts = x.mesh.map.size();
}

// (3) houses: every distinct match of the flattened spot, its upper face
// required 3-free (ε) to receive the house.
void build_houses(Experiment& x) {
  const HouseRule house = house_rule();
  auto t0 = Clock::now();
  std::vector<BoundaryOverride> upper;
  for (Dart d : house.upper) upper.push_back({d, 3, BoundaryCondition::boundary});
  QueryTrie spot_trie;
  spot_trie.add(query_word(house.query.map, 0, BoundaryCondition::any, upper), 0);
  const auto sites = all_matches(x.mesh.map, spot_trie, nullptr, 1);
  x.housed.query_seconds = since(t0);
  x.housed.raw_matches = sites.raw;
  x.housed.distinct_matches = sites.distinct.size();
  t0 = Clock::now();
  std::vector<Dart> identity(house.query.map.size());
  for (Dart d = 0; d < identity.size(); ++d) identity[d] = d;
  const Dart apex_dart = [&] {
    for (Dart d = 0; d < house.target.map.size(); ++d)
      if (house.target.points[d][2] > 4) return d;
    throw InternalError("the house has no apex");
  }();
  for (const QueryMatch& m : sites.distinct) {
    const auto q_to_m = query_to_input(house.query.map, 0, m);
    std::vector<Point3> matched;
    Point3 centre{0, 0, 0};
    for (Dart d : q_to_m) matched.push_back(x.mesh.points[d]);
    for (Dart d : house.upper)
      for (int c = 0; c < 3; ++c)
        centre[static_cast<std::size_t>(c)] += matched[d][static_cast<std::size_t>(c)] / static_cast<double>(house.upper.size());
    const auto t_to_m = extend(x.mesh.map, house.query.map, house.target.map, identity, q_to_m);
    const auto placed = place_target_points(house.query.map, house.target.map, house.target.points, identity, matched);
    x.mesh.points.resize(x.mesh.map.size());
    for (Dart d = 0; d < t_to_m.size(); ++d) x.mesh.points[t_to_m[d]] = placed[d];
    x.houses.push_back({placed[apex_dart], centre});
  }
  x.housed.modify_seconds = since(t0);
  x.housed.applied = sites.distinct.size();
  x.housed.volumes = volumes(x.mesh.map);
  x.housed.darts = x.mesh.map.size();
}

Experiment run_experiment(unsigned k, std::size_t spots, std::uint64_t seed) {
  Experiment x;
  const std::uint32_t n = 1U << k;
  // (1) the voxel grid.
  auto t0 = Clock::now();
  x.mesh = voxel_grid(n, diamond_square(k, seed, 1.0, 12.0));
  x.grid.modify_seconds = since(t0);
  x.grid.volumes = std::size_t{n} * n;
  x.grid.darts = x.mesh.map.size();
  flatten_spots(x, n, spots, seed);
  build_houses(x);
  return x;
}

}  // namespace dartcheck::querymodify::terrain
