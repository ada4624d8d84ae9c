#include "querymodify/recombination.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>
#include <tuple>

#include "core/error.hpp"
#include "querymodify/cell_contacts.hpp"
#include "querymodify/cell_quality.hpp"
#include "querymodify/cell_subdivisions.hpp"
#include "querymodify/hex_contacts.hpp"
#include "querymodify/hex_search.hpp"
#include "querymodify/hex_subdivisions.hpp"
#include "querymodify/modify.hpp"
#include "querymodify/overlap.hpp"

namespace dartcheck::querymodify {

std::vector<std::uint32_t> query_corners(const HexQuery& q) {
  // Rebuild the query's tetrahedral map to read its darts' corners: the
  // construction is deterministic, so the darts are the query's.
  auto tets = subdivision_tets(q.subdivision);
  if (q.mirrored)
    for (auto& t : tets) std::swap(t[2], t[3]);
  return build_tet_map(tets).vertex;
}

std::array<std::uint32_t, 8> match_corners(const HexQuery& q, const std::vector<std::uint32_t>& corners, const QueryMatch& m,
                                           const std::vector<std::uint32_t>& vertex_of_dart) {
  const Labeling l = bfs_labeling(q.map, 0);
  std::array<std::uint32_t, 8> out{};
  for (std::size_t k = 0; k < l.darts.size(); ++k) out[corners[l.darts[k]]] = vertex_of_dart[m.darts[k]];
  return out;
}

namespace {

using Clock = std::chrono::steady_clock;
using Corners = std::array<std::array<double, 3>, 8>;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The best reading of a match as a hexahedron: a pattern whose triangles
// pair into quads in several ways is read by the pairing that fits the
// geometry. Without points, the first reading and NaN.
std::pair<std::array<std::uint32_t, 8>, double> best_reading(const HexQuery& q, const std::array<std::uint32_t, 8>& c,
                                                             const std::vector<std::array<double, 3>>* points) {
  std::array<std::uint32_t, 8> best_corners{};
  double best = -2;
  // The best reading by the floating-point value, then its sign made exact;
  // only if that fails (numerically flat) is every reading judged exactly.
  auto choose = [&](bool exact) {
    best = -2;
    for (const auto& reading : q.readings) {
      std::array<std::uint32_t, 8> corners{};
      for (int v = 0; v < 8; ++v) corners[reading[static_cast<std::size_t>(v)]] = c[static_cast<std::size_t>(v)];
      const Corners p = corner_points(corners, *points);
      const double j = exact ? scaled_jacobian(p) : scaled_jacobian_estimate(p);
      if (j > best) best = j, best_corners = corners;
    }
  };
  if (!points) {
    if (q.readings.empty()) return {best_corners, best};
    std::array<std::uint32_t, 8> corners{};
    for (int v = 0; v < 8; ++v) corners[q.readings.front()[static_cast<std::size_t>(v)]] = c[static_cast<std::size_t>(v)];
    return {corners, std::nan("")};
  }
  choose(false);
  if (best > 0 && scaled_jacobian(corner_points(best_corners, *points)) != best) choose(true);
  return {best_corners, best};
}

}  // namespace

namespace {

// A hex to merge: its tetrahedra (sorted), corners and quality.
struct Chosen {
  std::vector<std::uint32_t> tets;
  std::array<std::uint32_t, 8> corners{};
  double quality = 0;
};

// 8 distinct corners and, with points, a quality above the threshold.
bool acceptable(const std::array<std::uint32_t, 8>& c, double quality, bool scored, double min_quality) {
  auto sorted = c;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
  return !scored || quality > min_quality;
}

// 001's search: every query word matched from every dart, then the
// greedy walk or the global order on the distinct matches.
std::vector<Chosen> by_words(const TetMap& mesh, const std::vector<HexQuery>& queries, Strategy strategy,
                             const std::vector<std::array<double, 3>>* points, double min_quality, Recombination& r) {
  QueryTrie trie;
  for (std::size_t k = 0; k < queries.size(); ++k) trie.add(queries[k].word, static_cast<int>(k));
  std::vector<std::vector<std::uint32_t>> corners;
  for (const auto& q : queries) corners.push_back(query_corners(q));
  auto reading = [&](const QueryMatch& m) {
    const HexQuery& q = queries[static_cast<std::size_t>(m.query)];
    return best_reading(q, match_corners(q, corners[static_cast<std::size_t>(m.query)], m, mesh.vertex), points);
  };
  auto fits = [&](const std::array<std::uint32_t, 8>& c, double quality) { return acceptable(c, quality, points != nullptr, min_quality); };
  // A hex spans 8 mesh vertices: the search abandons larger partial matches.
  std::uint32_t vertices = 0;
  for (auto v : mesh.vertex) vertices = std::max(vertices, v + 1);
  std::vector<std::uint32_t> per_vertex(vertices, 0);
  const ClassBound bound{&mesh.vertex, 8, &per_vertex};
  auto t = Clock::now();
  const auto all = all_matches(mesh.map, trie, &bound);
  r.raw_matches = all.raw;
  r.distinct_matches = all.distinct.size();
  r.match_seconds = since(t);
  t = Clock::now();
  std::vector<QueryMatch> selected;
  if (strategy == Strategy::greedy) {
    selected = greedy_matches(mesh.map, trie, &bound, [&](const QueryMatch& m) {
      const auto [c, quality] = reading(m);
      return fits(c, quality);
    });
    for (const auto& m : all.distinct) {
      const auto [c, quality] = reading(m);
      r.acceptable += fits(c, quality);
    }
  } else {
    // Each candidate read once: its best reading scores it.
    AllMatches candidates;
    std::vector<double> scores;
    for (const auto& m : all.distinct) {
      const auto [c, quality] = reading(m);
      if (!fits(c, quality)) continue;
      candidates.distinct.push_back(m);
      scores.push_back(points ? quality : -static_cast<double>(m.darts.size()));  // without points: fewer tetrahedra first
    }
    r.acceptable = candidates.distinct.size();
    selected = global_matches(candidates, mesh.map.size(), scores);
  }
  r.select_seconds = since(t);
  std::vector<Chosen> out;
  for (const auto& m : selected) {
    Chosen h;
    for (Dart d : m.darts) h.tets.push_back(d / 12);
    std::sort(h.tets.begin(), h.tets.end());
    h.tets.erase(std::unique(h.tets.begin(), h.tets.end()), h.tets.end());
    std::tie(h.corners, h.quality) = reading(m);
    out.push_back(std::move(h));
  }
  return out;
}

// The vertex search (hex_search.hpp) and the global order: best quality
// first (without points, fewer tetrahedra first), ties in the order found,
// each taken unless it shares a tetrahedron with one taken before (or,
// with Contacts::conforming, meets one in more than a vertex, an edge or a
// face of both).
std::vector<Chosen> by_vertices(const TetMap& mesh, const std::vector<std::array<double, 3>>* points, double min_quality, Contacts contacts,
                                Recombination& r, const Progress& progress) {
  auto t = Clock::now();
  HexCandidates found = find_hex_candidates(mesh.tets, points, min_quality, progress);
  if (progress) progress("selecting hexes", 0, 0);
  r.readings = found.readings;
  r.candidates = found.found;
  r.match_seconds = since(t);
  t = Clock::now();
  // The search keeps only acceptable candidates: 8 distinct corners by
  // construction, and (with points) a quality above the threshold.
  r.acceptable = found.list.size();
  std::vector<double> score;
  for (const HexCandidate& c : found.list) score.push_back(points ? c.quality : -static_cast<double>(c.count));
  std::vector<std::uint32_t> rank(found.list.size());
  for (std::uint32_t k = 0; k < rank.size(); ++k) rank[k] = k;
  std::stable_sort(rank.begin(), rank.end(), [&](std::uint32_t a, std::uint32_t b) { return score[a] > score[b]; });
  std::vector<bool> used(mesh.tets.size(), false);
  std::vector<Chosen> out;
  // The selected hexes (indices into out) at each mesh vertex.
  std::uint32_t vertices = 0;
  if (contacts == Contacts::conforming)
    for (const auto& tet : mesh.tets) vertices = std::max(vertices, *std::max_element(tet.begin(), tet.end()) + 1);
  std::vector<std::vector<std::uint32_t>> at_vertex(vertices);
  auto conforms = [&](const HexCandidate& c) {
    for (std::uint32_t v : c.corners)
      for (std::uint32_t h : at_vertex[v])
        if (!conforming_contact(c.corners, out[h].corners)) return false;
    return true;
  };
  for (std::uint32_t k : rank) {
    const HexCandidate& c = found.list[k];
    const auto tets = found.tets_of(c);
    if (std::any_of(tets.begin(), tets.end(), [&](std::uint32_t x) { return used[x]; })) continue;
    if (contacts == Contacts::conforming) {
      if (!conforms(c)) {
        ++r.nonconforming;
        continue;
      }
      for (std::uint32_t v : c.corners) at_vertex[v].push_back(static_cast<std::uint32_t>(out.size()));
    }
    for (auto x : tets) used[x] = true;
    out.push_back({{tets.begin(), tets.end()}, c.corners, c.quality});
  }
  r.select_seconds = since(t);
  return out;
}

// The cells selected so far at each mesh vertex (Contacts::conforming):
// a new cell must meet each of them in nothing, a vertex, an edge of both
// or a face of both (cell_contacts.hpp).
class Placed {
 public:
  explicit Placed(std::size_t vertices) : at_(vertices) {}
  void add(std::span<const std::uint32_t> corners, const CellShape& shape) {
    Cell c{{}, corners.size(), &shape};
    std::copy(corners.begin(), corners.end(), c.corners.begin());
    for (std::uint32_t v : corners) at_[v].push_back(static_cast<std::uint32_t>(cells_.size()));
    cells_.push_back(c);
  }
  bool conforms(std::span<const std::uint32_t> corners, const CellShape& shape) const {
    for (std::uint32_t v : corners)
      for (std::uint32_t k : at_[v]) {
        const Cell& c = cells_[k];
        if (!conforming_contact(corners, shape, {c.corners.data(), c.count}, *c.shape)) return false;
      }
    return true;
  }

 private:
  struct Cell {
    std::array<std::uint32_t, 8> corners;
    std::size_t count;
    const CellShape* shape;
  };
  std::vector<Cell> cells_;
  std::vector<std::vector<std::uint32_t>> at_;
};

// The global order on prism or pyramid candidates: best quality first
// (ties, and every candidate without points, in the order found), each
// taken unless it shares a tetrahedron with a cell taken before or (with
// `placed`) does not conform to one.
void select_cells(CellCandidates found, const CellShape& shape, std::vector<bool>& used, const std::vector<std::array<double, 3>>* points,
                  Placed* placed, CellSelection& out) {
  out.candidates += found.found;
  out.acceptable += found.list.size();
  if (points)
    std::stable_sort(found.list.begin(), found.list.end(), [](const CellCandidate& a, const CellCandidate& b) { return a.quality > b.quality; });
  const auto n = static_cast<std::size_t>(shape.corners);
  for (const CellCandidate& c : found.list) {
    const auto tets = c.tets_of();
    if (std::any_of(tets.begin(), tets.end(), [&](std::uint32_t x) { return used[x]; })) continue;
    if (placed) {
      if (!placed->conforms({c.corners.data(), n}, shape)) {
        ++out.nonconforming;
        continue;
      }
      placed->add({c.corners.data(), n}, shape);
    }
    for (auto x : tets) used[x] = true;
    out.cells.push_back(c);
  }
}

// The quad faces (cycles of corners among `faces`) of a cell as cycles of
// mesh vertices.
template <class Corners, class Faces>
void add_quads(const Corners& c, const Faces& faces, std::vector<std::array<std::uint32_t, 4>>& quads) {
  for (const auto& f : faces)
    if (f.size() == 4) {
      std::array<std::uint32_t, 4> q{};
      for (std::size_t k = 0; k < 4; ++k) q[k] = c[static_cast<std::size_t>(f[k])];
      quads.push_back(q);
    }
}

// Merges the chosen hexes' and the cells' tetrahedra into volumes (the
// vertex table follows the darts); each merge's renumbering shifts the
// darts of later cells.
void merge_cells(TetMap& mesh, const std::vector<Chosen>& chosen, Recombination& r, const Progress& progress) {
  if (progress) progress("merging the cells' tetrahedra", 0, 0);
  const auto t = Clock::now();
  std::vector<Dart> where(mesh.map.size());
  for (Dart d = 0; d < where.size(); ++d) where[d] = d;
  std::vector<Dart> at(mesh.map.size());  // current dart -> original
  for (Dart d = 0; d < at.size(); ++d) at[d] = d;
  std::vector<std::span<const std::uint32_t>> merged;
  for (const auto& h : chosen) merged.push_back(h.tets);
  for (const auto& c : r.prisms.cells) merged.push_back(c.tets_of());
  for (const auto& c : r.pyramids.cells) merged.push_back(c.tets_of());
  for (const auto tets : merged) {
    std::vector<Dart> darts;
    for (auto x : tets)
      for (Dart d = 12 * x; d < 12 * x + 12; ++d) darts.push_back(where[d]);
    merge_volumes(mesh.map, darts).for_each_moved([&](Dart from, Dart to) {
      const Dart original = at[from];
      where[original] = to;
      at[to] = original;
      mesh.vertex[to] = mesh.vertex[from];
    });
  }
  mesh.vertex.resize(mesh.map.size());
  r.merge_seconds = since(t);
}

// For conforming contacts: the hexes placed, so that a prism or pyramid
// only joins them face to face.
std::optional<Placed> conforming_placement(const TetMap& mesh, const Recombination& r) {
  std::uint32_t vertices = 0;
  for (const auto& tet : mesh.tets) vertices = std::max(vertices, *std::max_element(tet.begin(), tet.end()) + 1);
  std::optional<Placed> placed(std::in_place, vertices);
  for (const auto& h : r.hex_corners) placed->add(h, hex_shape());
  return placed;
}

}  // namespace

Recombination recombine(TetMap& mesh, const std::vector<HexQuery>& queries, Strategy strategy, const std::vector<std::array<double, 3>>* points,
                        double min_quality, Search search, Contacts contacts, Cells cells, const Progress& progress) {
  Recombination r;
  r.search = strategy == Strategy::greedy ? Search::words : search;
  r.contacts = contacts;
  if (contacts == Contacts::conforming && r.search == Search::words)
    throw ValueError("recombine: conforming contacts need the global strategy's vertex search");
  if (progress && r.search == Search::words) progress("matching the hex queries' words", 0, 0);
  const std::vector<Chosen> chosen = r.search == Search::words ? by_words(mesh, queries, strategy, points, min_quality, r)
                                                               : by_vertices(mesh, points, min_quality, contacts, r, progress);
  std::vector<bool> used(mesh.tets.size(), false);
  for (const auto& h : chosen) {
    r.hex_tets.push_back(h.tets);
    r.hex_corners.push_back(points ? right_handed(h.corners, *points) : h.corners);
    r.quality.push_back(h.quality);
    for (auto x : h.tets) used[x] = true;
  }
  // Pyramids, prisms, pyramids, on the tetrahedra still free; the quads of
  // the cells say where the mesh is not conforming.
  const TetFaces faces(mesh.tets);
  std::vector<std::array<std::uint32_t, 4>> quads;
  for (const auto& h : r.hex_corners) add_quads(h, hex_faces(), quads);
  std::optional<Placed> placed;
  if (contacts == Contacts::conforming && (cells.prisms || cells.pyramids)) placed = conforming_placement(mesh, r);
  Placed* const conforming = placed ? &*placed : nullptr;
  std::vector<std::array<std::uint32_t, 4>> bases;  // the pyramids' bases (each also a quad of a hex or prism)
  // Pyramids on the quads so far that face two free tetrahedra with one
  // apex.
  auto pyramids_on_quads = [&](const std::vector<std::array<std::uint32_t, 4>>& on) {
    if (progress) progress("selecting pyramids", 0, 0);
    const auto t = Clock::now();
    const std::size_t before = r.pyramids.cells.size();
    select_cells(find_pyramid_candidates(mesh.tets, faces, used, on, points, min_quality), pyramid_shape(), used, points, conforming, r.pyramids);
    for (std::size_t k = before; k < r.pyramids.cells.size(); ++k) {
      auto& c = r.pyramids.cells[k];
      if (points) {
        const auto p = right_handed_pyramid({c.corners[0], c.corners[1], c.corners[2], c.corners[3], c.corners[4]}, *points);
        std::copy(p.begin(), p.end(), c.corners.begin());
      }
      add_quads(c.corners, pyramid_shape().faces, bases);
    }
    r.pyramids.seconds += since(t);
  };
  // Pyramids on the hexes' quads before the prisms take their tetrahedra,
  // then on the prisms' quads: on tetgen's elephant (-pqQ) that leaves
  // 11,907 quads against triangles instead of 13,245 with prisms first
  // (gmsh's order), and makes 5,682 cells instead of 5,397.
  // The second pass looks at the prisms' quads only: the hexes' quads
  // lost free tetrahedra since the first, and gained none (each candidate
  // is counted once).
  if (cells.pyramids) pyramids_on_quads(quads);
  std::vector<std::array<std::uint32_t, 4>> prism_quads;
  if (cells.prisms) {
    if (progress) progress("selecting prisms", 0, 0);
    const auto t = Clock::now();
    select_cells(find_prism_candidates(mesh.tets, faces, used, points, min_quality), prism_shape(), used, points, conforming, r.prisms);
    for (auto& c : r.prisms.cells) {
      if (points) c.corners = right_handed_prism(c.corners, *points);
      add_quads(c.corners, prism_shape().faces, prism_quads);
    }
    r.prisms.seconds = since(t);
  }
  if (cells.pyramids && !prism_quads.empty()) pyramids_on_quads(prism_quads);
  quads.insert(quads.end(), prism_quads.begin(), prism_quads.end());
  if (cells.pyramids) {
    // Without the pyramids their bases would face two tetrahedra.
    r.quads_facing_triangles_before_pyramids = quads_facing_triangles(quads, faces);
  }
  quads.insert(quads.end(), bases.begin(), bases.end());
  r.quads_facing_triangles = quads_facing_triangles(quads, faces);
  for (std::size_t k = 0; k < used.size(); ++k)
    if (!used[k]) r.remaining_tets.push_back(k);
  merge_cells(mesh, chosen, r, progress);
  r.hexes = chosen.size();
  r.tets = r.remaining_tets.size();
  return r;
}

}  // namespace dartcheck::querymodify
