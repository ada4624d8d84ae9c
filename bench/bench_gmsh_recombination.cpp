// Tet -> hex recombination, dartcheck against gmsh's recombinator side by
// side on the same tetrahedral meshes at the same quality thresholds.
//
// The peer: gmsh's `Recombinator` (contrib/domhex/yamakawa.h, the patterns
// of Yamakawa and Shimada 2003 that 001 compares with), from Debian's
// libgmsh 4.8.4; its header is not packaged, scripts/install-gmsh-peer.sh
// fetches it from the gmsh source package. It keeps the potential hexes
// whose quality (the minimum over the 8 corners of the scaled Jacobian) is
// at least its threshold and adds them greedily, best first, when their
// tetrahedra are free and they conform to the hexes already chosen.
// dartcheck runs its default (`dartcheck recombine`: the vertex search and
// the global strategy) with the same threshold as `--min-quality` (which
// keeps hexes strictly above it), and again with `--conforming` (hexes
// meet only in a vertex, an edge or a face of both, as gmsh's do).
//
// Both outputs are measured by the same code here, not by either tool's
// own report: hexes; tetrahedra and volume consumed (from the input
// tetrahedra left over, as fractions of the input); min and mean scaled
// Jacobian of the hexes (hex_quality.hpp's floating-point estimate over
// the corners as each tool orders them); hexes with a corner whose exact
// orientation (orientation.hpp) is flat or against the others; pairs of
// hexes that meet in 3 vertices or in 4 that are not a face of both (a
// non-conforming contact); and wall-clock seconds of the recombination
// alone (gmsh from its region of tetrahedra, dartcheck from the mesh's
// tetrahedra: the tet map, the search, the selection, the merges). Each
// run is a child process: Debian builds gmsh with assertions, which abort
// on some inputs (grids of 5-tet cubes); such a run is reported, not
// hidden.
//
// With --cells, the hex-dominant modes side by side instead: gmsh's
// Recombinator, then its Supplementary (prisms; its threshold is fixed at
// 0.6 of its own prism quality) and PostOp at level 2 without its
// conformity steps (pyramids1: a pyramid on a hex or prism quad whose two
// tetrahedra share their fourth vertex), against `dartcheck recombine
// --cells hex,prism,pyramid`; measured alike: cells of each kind, the
// tetrahedra and volume in cells, cells with a corner that is flat or
// against the others by the exact predicate, quads of cells facing
// triangles, seconds.
//
//   build/bench/bench_gmsh_recombination [--thresholds 0,0.3,0.6] [--cells] MESH.ele|MESH.mesh...
#include <GModel.h>
#include <GRegion.h>
#include <MHexahedron.h>
#include <MPrism.h>
#include <MPyramid.h>
#include <MTetrahedron.h>
#include <fmt/format.h>
#include <gmsh.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yamakawa.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "hex_contacts_check.hpp"
#include "querymodify/cell_search.hpp"
#include "querymodify/cell_subdivisions.hpp"
#include "querymodify/hex_subdivisions.hpp"
#include "io/tet_mesh_io.hpp"
#include "querymodify/hex_quality.hpp"
#include "querymodify/orientation.hpp"
#include "querymodify/recombination.hpp"
#include "querymodify/tet_map.hpp"

using namespace dartcheck;
using namespace dartcheck::querymodify;

namespace {

using Clock = std::chrono::steady_clock;
using Corners = std::array<std::uint32_t, 8>;  // mesh vertex at cube corner x + 2y + 4z

// What one tool produced: its hexes and the input tetrahedra it left.
struct Output {
  std::vector<Corners> hexes;
  std::vector<std::array<std::uint32_t, 6>> prisms;  // --cells: a triangle, then the one above it
  std::vector<std::array<std::uint32_t, 5>> pyramids;  // --cells: the base cycle, then the apex
  std::vector<std::uint32_t> remaining_tets;
  double seconds = 0;
  std::size_t skipped = 0;  // gmsh: hexes its assertion would abort on
};

// gmsh's recombinator with its threshold set (a protected member) and its
// final step, Recombinator::merge, restated with one change. merge sorts
// the potential hexes by quality, best first, and until the threshold
// adds each whose tetrahedra (those on its 8 vertices, one set apart if
// its 4 vertices are a hex face: a "sliver") are free, whose 6 faces are
// each two triangles of them, and that conforms to the hexes added
// (conformityA/B/C); it then asserts that 5 or 6 tetrahedra are left,
// which Debian's build (assertions on) turns into an abort on hexes of
// other counts, tetgen's meshes included. Here such a hex is skipped and
// counted. Everything else (the patterns, the quality, the conformity
// checks, the bookkeeping) is gmsh's own code.
class BenchRecombinator : public Recombinator {
 public:
  explicit BenchRecombinator(double threshold) { hex_threshold_quality = threshold; }
  std::size_t skipped = 0;  // hexes gmsh's assertion would abort on

 protected:
  void merge() override {
    clear_hash_tables();
    std::sort(potential.begin(), potential.end(), [](const Hex* a, const Hex* b) { return a->get_quality() > b->get_quality(); });
    bool any = false;
    for (const Hex* hex : potential) {
      if (hex->get_quality() < hex_threshold_quality) break;
      std::set<MElement*> tets, slivers;
      for (MVertex* v : hex->vertices())
        for (MElement* t : tet_mesh.tets_around_vertex(v))
          if (hex->contains(t->getVertex(0)) && hex->contains(t->getVertex(1)) && hex->contains(t->getVertex(2)) && hex->contains(t->getVertex(3)))
            tets.insert(t);
      for (MElement* t : tets)
        if (on_one_face(*hex, t)) {
          slivers.insert(t);
          tets.erase(t);
          break;
        }
      if (tets.size() < 5 || tets.size() > 6) {
        ++skipped;
        continue;
      }
      if (are_all_tets_free(tets) && faces_of(*hex, tets) && is_potential_hex_conform(*hex)) {
        current_region->addHexahedron(new MHexahedron(hex->vertices()));
        mark_tets(tets);
        mark_tets(slivers);
        build_hash_tableA(*hex);
        build_hash_tableB(*hex);
        build_hash_tableC(*hex);
        any = true;
      }
    }
    if (any) delete_marked_tets_in_region();
  }

 private:
  static bool on_one_face(const Hex& hex, const MElement* t) {
    for (unsigned f = 0; f < 6; ++f) {
      int in = 0;
      for (int k = 0; k < 4; ++k)
        for (unsigned c = 0; c < 4; ++c) in += t->getVertex(k) == hex.vertex_in_facet(f, c);
      if (in == 4) return true;
    }
    return false;
  }
  // Some tetrahedron of `tets` has the 3 vertices.
  static bool has_triangle(const std::set<MElement*>& tets, MVertex* a, MVertex* b, MVertex* c) {
    for (const MElement* t : tets) {
      int in = 0;
      for (int k = 0; k < 4; ++k) in += t->getVertex(k) == a || t->getVertex(k) == b || t->getVertex(k) == c;
      if (in == 3) return true;
    }
    return false;
  }
  // Each face is two triangles of `tets` along one of its diagonals.
  static bool faces_of(const Hex& hex, const std::set<MElement*>& tets) {
    for (unsigned f = 0; f < 6; ++f) {
      MVertex* q[4];
      for (unsigned c = 0; c < 4; ++c) q[c] = hex.vertex_in_facet(f, c);
      const bool ok = (has_triangle(tets, q[0], q[1], q[2]) && has_triangle(tets, q[0], q[2], q[3])) ||
                      (has_triangle(tets, q[0], q[1], q[3]) && has_triangle(tets, q[1], q[2], q[3]));
      if (!ok) return false;
    }
    return true;
  }
};

Output run_gmsh_with(const TetMesh& mesh, double threshold, bool cells) {
  gmsh::option::setNumber("General.Verbosity", 1);
  gmsh::model::add("input");
  const int region_tag = gmsh::model::addDiscreteEntity(3);
  std::vector<std::size_t> node_tags(mesh.points.size());
  std::vector<double> coords;
  coords.reserve(3 * mesh.points.size());
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    node_tags[v] = v + 1;
    coords.insert(coords.end(), mesh.points[v].begin(), mesh.points[v].end());
  }
  gmsh::model::mesh::addNodes(3, region_tag, node_tags, coords);
  std::vector<std::size_t> tet_tags(mesh.tets.size()), tet_nodes;
  tet_nodes.reserve(4 * mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    tet_tags[t] = t + 1;
    for (std::uint32_t v : mesh.tets[t]) tet_nodes.push_back(v + 1);
  }
  gmsh::model::mesh::addElementsByType(region_tag, 4, tet_tags, tet_nodes);
  GRegion* region = GModel::current()->getRegionByTag(region_tag);

  Output out;
  BenchRecombinator recombinator(threshold);
  const auto start = Clock::now();
  recombinator.execute(region);
  if (cells) {
    Supplementary prisms;
    prisms.execute(region);
    PostOp pyramids;
    pyramids.execute(region, 2, 0);  // level 2: pyramids1; conformity 0: no trihedra, no splits
  }
  out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  auto index = [](const MElement* e, int k) { return static_cast<std::uint32_t>(e->getVertex(k)->getNum() - 1); };
  for (const MPrism* p : region->prisms) out.prisms.push_back({index(p, 0), index(p, 1), index(p, 2), index(p, 3), index(p, 4), index(p, 5)});
  for (const MPyramid* p : region->pyramids) out.pyramids.push_back({index(p, 0), index(p, 1), index(p, 2), index(p, 3), index(p, 4)});
  // gmsh's order: the bottom quad, then the top quad vertex above vertex.
  for (const MHexahedron* h : region->hexahedra) {
    std::array<std::uint32_t, 8> ring{};
    for (int k = 0; k < 8; ++k) ring[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(h->getVertex(k)->getNum() - 1);
    out.hexes.push_back({ring[0], ring[1], ring[3], ring[2], ring[4], ring[5], ring[7], ring[6]});
  }
  for (const MTetrahedron* t : region->tetrahedra) out.remaining_tets.push_back(static_cast<std::uint32_t>(t->getNum() - 1));
  out.skipped = recombinator.skipped;
  return out;
}
Output run_gmsh(const TetMesh& mesh, double threshold) { return run_gmsh_with(mesh, threshold, false); }
Output run_gmsh_cells(const TetMesh& mesh, double threshold) { return run_gmsh_with(mesh, threshold, true); }

Output run_dartcheck(const TetMesh& mesh, double threshold, Contacts contacts, Cells cells = {}) {
  Output out;
  const auto start = Clock::now();
  TetMap map = build_tet_map(mesh.tets, &mesh.points);
  const Recombination r = recombine(map, {}, Strategy::global, &mesh.points, threshold, Search::vertices, contacts, cells);
  out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  out.hexes = r.hex_corners;
  for (const auto& c : r.prisms.cells) out.prisms.push_back(c.corners);
  for (const auto& c : r.pyramids.cells) out.pyramids.push_back({c.corners[0], c.corners[1], c.corners[2], c.corners[3], c.corners[4]});
  for (std::size_t t : r.remaining_tets) out.remaining_tets.push_back(static_cast<std::uint32_t>(t));
  return out;
}
Output run_dartcheck_any(const TetMesh& mesh, double threshold) { return run_dartcheck(mesh, threshold, Contacts::any); }
Output run_dartcheck_conforming(const TetMesh& mesh, double threshold) { return run_dartcheck(mesh, threshold, Contacts::conforming); }
Output run_dartcheck_cells(const TetMesh& mesh, double threshold) { return run_dartcheck(mesh, threshold, Contacts::any, Cells{true, true}); }
Output run_dartcheck_cells_conforming(const TetMesh& mesh, double threshold) {
  return run_dartcheck(mesh, threshold, Contacts::conforming, Cells{true, true});
}

double tet_volume(const TetMesh& m, const std::array<std::uint32_t, 4>& t) {
  const auto& a = m.points[t[0]];
  double e[3][3];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) e[k][c] = m.points[t[static_cast<std::size_t>(k + 1)]][static_cast<std::size_t>(c)] - a[static_cast<std::size_t>(c)];
  return std::abs(e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                  e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
         6;
}

// The figures of one output, computed alike for both tools.
struct Figures {
  std::size_t hexes = 0;
  double tet_share = 0, volume_share = 0;
  double min_quality = 0, mean_quality = 0;  // scaled Jacobian (dartcheck's threshold)
  double min_ige = 0, mean_ige = 0;          // gmsh's IGE measure (gmsh's threshold)
  std::size_t skipped = 0;
  std::size_t bad_corner_hexes = 0;  // a corner exactly flat or against the others
  std::size_t nonconforming_pairs = 0;
  double seconds = 0;
  // --cells
  std::size_t prisms = 0, pyramids = 0;
  std::size_t bad_corner_prisms = 0, bad_corner_pyramids = 0;
  std::size_t quads_facing_triangles = 0;
  std::size_t nonconforming_cell_pairs = 0;  // among all cells
};

// A cell whose corners (each with its three edges, `corners`) are not all
// of one exact sign, or has one flat: either handedness passes.
template <std::size_t N, std::size_t M>
bool bad_corners(const TetMesh& mesh, const std::array<std::uint32_t, N>& cell, const std::array<std::array<int, 4>, M>& corners) {
  int first = 0;
  for (const auto& [v, a, b, c] : corners) {
    auto at = [&](int k) { return mesh.points[cell[static_cast<std::size_t>(k)]]; };
    const int s = orientation_sign(at(v), at(a), at(b), at(c));
    if (s == 0 || (first != 0 && s != first)) return true;
    first = s;
  }
  return false;
}

Figures measure(const TetMesh& mesh, const Output& out) {
  Figures f;
  f.hexes = out.hexes.size();
  f.seconds = out.seconds;
  f.skipped = out.skipped;
  double total = 0, left = 0;
  for (const auto& t : mesh.tets) total += tet_volume(mesh, t);
  for (std::uint32_t t : out.remaining_tets) left += tet_volume(mesh, mesh.tets[t]);
  f.tet_share = 1.0 - double(out.remaining_tets.size()) / double(mesh.tets.size());
  f.volume_share = 1.0 - left / total;
  f.min_quality = f.min_ige = out.hexes.empty() ? 0 : 1;
  for (const Corners& h : out.hexes) {
    const auto p = corner_points(h, mesh.points);
    const double q = scaled_jacobian_estimate(p);
    f.min_quality = std::min(f.min_quality, q);
    f.mean_quality += q / double(out.hexes.size());
    // gmsh's quality of a hex (yamakawa.h's Hex::compute_quality), on
    // vertices of their own.
    std::vector<MVertex> own;
    own.reserve(8);
    for (int c : {0, 1, 3, 2, 4, 5, 7, 6})
      own.emplace_back(p[static_cast<std::size_t>(c)][0], p[static_cast<std::size_t>(c)][1], p[static_cast<std::size_t>(c)][2]);
    std::vector<MVertex*> ring;
    for (MVertex& v : own) ring.push_back(&v);
    MHexahedron element(ring);
    const double ige = jacobianBasedQuality::minIGEMeasure(&element, false, true);
    f.min_ige = std::min(f.min_ige, ige);
    f.mean_ige += ige / double(out.hexes.size());
    // Corner v's edges towards +x, +y, +z, reversed on the high side: all 8
    // signs equal in a valid hex of either handedness.
    int first = 0;
    bool bad = false;
    for (int v = 0; v < 8 && !bad; ++v) {
      int flip = 1;
      for (int axis = 0; axis < 3; ++axis) flip *= (v >> axis) & 1 ? -1 : 1;
      auto at = [&](int c) { return p[static_cast<std::size_t>(c)]; };
      const int s = orientation_sign(at(v), at(v ^ 1), at(v ^ 2), at(v ^ 4)) * flip;
      if (s == 0 || (first != 0 && s != first)) bad = true;
      first = s;
    }
    f.bad_corner_hexes += bad;
  }
  // Contacts between hexes, by the check check_hex_corners uses.
  std::vector<MeditHex> rings;
  for (const Corners& h : out.hexes) rings.push_back({h[0], h[1], h[3], h[2], h[4], h[5], h[7], h[6]});
  f.nonconforming_pairs = nonconforming_pairs(rings, mesh.points.size());
  f.prisms = out.prisms.size();
  f.pyramids = out.pyramids.size();
  // Each corner with its two edges along its triangle (base) and its third
  // edge, as medit orders prisms and pyramids.
  const std::array<std::array<int, 4>, 6> prism_corners{{{0, 1, 2, 3}, {1, 2, 0, 4}, {2, 0, 1, 5}, {3, 5, 4, 0}, {4, 3, 5, 1}, {5, 4, 3, 2}}};
  const std::array<std::array<int, 4>, 4> pyramid_corners{{{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}}};
  for (const auto& p : out.prisms) f.bad_corner_prisms += bad_corners(mesh, p, prism_corners);
  for (const auto& p : out.pyramids) f.bad_corner_pyramids += bad_corners(mesh, p, pyramid_corners);
  // Quads of cells that face neither the boundary nor another cell's quad
  // (the cells are unions of input tetrahedra, so the input's triangles
  // tell the boundary).
  if (!out.prisms.empty() || !out.pyramids.empty()) {
    std::vector<std::array<std::uint32_t, 4>> quads;
    for (const Corners& h : out.hexes)
      for (const auto& q : hex_faces()) quads.push_back({h[static_cast<std::size_t>(q[0])], h[static_cast<std::size_t>(q[1])], h[static_cast<std::size_t>(q[2])], h[static_cast<std::size_t>(q[3])]});
    for (const auto& p : out.prisms) quads.insert(quads.end(), {{p[0], p[1], p[4], p[3]}, {p[1], p[2], p[5], p[4]}, {p[2], p[0], p[3], p[5]}});
    for (const auto& p : out.pyramids) quads.push_back({p[0], p[1], p[2], p[3]});
    f.quads_facing_triangles = querymodify::quads_facing_triangles(quads, TetFaces(mesh.tets));
    std::vector<MeditCell> all;
    for (const auto& r : rings) all.emplace_back(r.begin(), r.end());
    for (const auto& p : out.prisms) all.emplace_back(p.begin(), p.end());
    for (const auto& p : out.pyramids) all.emplace_back(p.begin(), p.end());
    f.nonconforming_cell_pairs = nonconforming_pairs(all, mesh.points.size());
  }
  return f;
}

// Runs `tool` in a child process; false with the reason if it did not
// finish.
bool in_child(const TetMesh& mesh, double threshold, Output (*tool)(const TetMesh&, double), Figures& figures, std::string& why) {
  int fd[2];
  if (pipe(fd) != 0) {
    why = "no pipe";
    return false;
  }
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    gmsh::initialize();
    const Figures f = measure(mesh, tool(mesh, threshold));
    const ssize_t n = write(fd[1], &f, sizeof f);
    _exit(n == static_cast<ssize_t>(sizeof f) ? 0 : 3);
  }
  close(fd[1]);
  Figures f;
  const ssize_t n = read(fd[0], &f, sizeof f);
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) {
    why = fmt::format("killed by signal {} ({})", WTERMSIG(status), strsignal(WTERMSIG(status)));
    return false;
  }
  if (n != static_cast<ssize_t>(sizeof f) || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    why = "exited without a result";
    return false;
  }
  figures = f;
  return true;
}

const char* const kHeader = "  {:<10} {:>6} {:>7} {:>7} {:>6} {:>6} {:>6} {:>6} {:>6} {:>6} {:>7} {:>8}";

std::string row(const char* tool, const Figures& f) {
  return fmt::format("  {:<10} {:>6} {:>6.1f}% {:>6.1f}% {:>6.3f} {:>6.3f} {:>6.3f} {:>6.3f} {:>6} {:>6} {:>7} {:>8.2f}", tool, f.hexes,
                     100 * f.tet_share, 100 * f.volume_share, f.min_quality, f.mean_quality, f.min_ige, f.mean_ige, f.bad_corner_hexes,
                     f.nonconforming_pairs, f.skipped, f.seconds);
}

const char* const kCellsHeader = "  {:<10} {:>6} {:>6} {:>6} {:>7} {:>7} {:>6} {:>6} {:>9} {:>8}";

std::string cells_row(const char* tool, const Figures& f) {
  return fmt::format("  {:<10} {:>6} {:>6} {:>6} {:>6.1f}% {:>6.1f}% {:>6} {:>6} {:>9} {:>8.2f}", tool, f.hexes, f.prisms, f.pyramids,
                     100 * f.tet_share, 100 * f.volume_share, f.bad_corner_hexes + f.bad_corner_prisms + f.bad_corner_pyramids,
                     f.nonconforming_cell_pairs, f.quads_facing_triangles, f.seconds);
}

// What a run of the benchmark compares: hexes alone, or all cells.
struct Mode {
  std::string header;
  Output (*ours)(const TetMesh&, double);
  Output (*conforming)(const TetMesh&, double);
  Output (*peer)(const TetMesh&, double);
  std::string (*row)(const char*, const Figures&);
  const char* counted;
  double (*count)(const Figures&);
};
const Mode hex_mode{fmt::format(fmt::runtime(kHeader), "tool", "hexes", "tets", "volume", "minSJ", "meanSJ", "minIGE", "mnIGE", "badcrn", "noncnf",
                                "skipped", "seconds"),
                    run_dartcheck_any,
                    run_dartcheck_conforming,
                    run_gmsh,
                    row,
                    "hexes",
                    [](const Figures& f) { return double(f.hexes); }};
const Mode cell_mode{fmt::format(fmt::runtime(kCellsHeader), "tool", "hexes", "prisms", "pyrs", "tets", "volume", "badcrn", "noncnf", "quads/tri",
                                 "seconds"),
                     run_dartcheck_cells,
                     run_dartcheck_cells_conforming,
                     run_gmsh_cells,
                     cells_row,
                     "cells",
                     [](const Figures& f) { return double(f.hexes + f.prisms + f.pyramids); }};

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> thresholds{0.0, 0.3, 0.6};
  std::vector<std::string> meshes;
  bool cells = false;
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--cells")) {
      cells = true;
    } else if (!std::strcmp(argv[k], "--thresholds") && k + 1 < argc) {
      thresholds.clear();
      std::string list = argv[++k];
      for (std::size_t at = 0; at <= list.size();) {
        const std::size_t comma = std::min(list.find(',', at), list.size());
        thresholds.push_back(std::stod(list.substr(at, comma - at)));
        at = comma + 1;
      }
    } else
      meshes.emplace_back(argv[k]);
  }
  if (meshes.empty()) {
    fmt::print(stderr, "usage: {} [--thresholds 0,0.3,0.6] [--cells] MESH.ele|MESH.mesh...\n", argv[0]);
    return 2;
  }
  int status = 0;
  for (const auto& file : meshes) {
    TetMesh mesh;
    try {
      mesh = read_tet_mesh(file);
    } catch (const std::exception& e) {
      fmt::print(stderr, "{}\n", e.what());
      return 1;
    }
    fmt::print("{}: {} points, {} tetrahedra\n", file, mesh.points.size(), mesh.tets.size());
    for (double threshold : thresholds) {
      fmt::print(" threshold {}\n", threshold);
      // The three runs of a mode: dartcheck, dartcheck --conforming, gmsh.
      const auto& m = cells ? cell_mode : hex_mode;
      fmt::print("{}\n", m.header);
      Figures ours, conforming, theirs;
      std::string why;
      const bool ok = in_child(mesh, threshold, m.ours, ours, why);
      fmt::print("{}\n", ok ? m.row("dartcheck", ours) : "  dartcheck  " + why);
      const bool ok_conforming = in_child(mesh, threshold, m.conforming, conforming, why);
      fmt::print("{}\n", ok_conforming ? m.row("conforming", conforming) : "  conforming " + why);
      if (!ok || !ok_conforming) status = 1;
      const bool peer = in_child(mesh, threshold, m.peer, theirs, why);
      fmt::print("{}\n", peer ? m.row("gmsh", theirs) : "  gmsh       " + why);
      if (ok && ok_conforming && peer)
        fmt::print("  {} dartcheck/gmsh {:.2f}, conforming/gmsh {:.2f}; time gmsh/dartcheck {:.1f}, gmsh/conforming {:.1f}\n", m.counted,
                   m.count(ours) / std::max(m.count(theirs), 1.0), m.count(conforming) / std::max(m.count(theirs), 1.0), theirs.seconds / ours.seconds,
                   theirs.seconds / conforming.seconds);
      std::fflush(stdout);
    }
  }
  return status;
}
