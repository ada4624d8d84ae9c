// Face triangulation with barycentric positions (003 Fig. 20, issue 8) on
// a real OFF mesh (by default CGAL's ChineseDragon-10kv: 19,994 triangles,
// 119,964 2-G-map darts) or on a quad torus (--grid), in one program:
//   - dartcheck, the embedding catalog's schemes with pos terms
//     (n2 labeled center(pos<0,1>(n0)), extended instantiation):
//       per face: triangulation-jerboa-pos applied at one dart of every
//         face by one Applier (match, evaluation, non-overlap,
//         rewrite, propagation, per application);
//       all faces: triangulation-all-faces-pos applied once (hook orbit
//         <0,1,2>, as Jerboa applies a scheme to a whole orbit);
//     each with every instance evaluated (the dynamic check) and with one
//     evaluation per orbit (allowed because the rule passes (A));
//   - the compiled rows (`dartcheck compile`, issue 41) and the floors:
//     a generic scheme engine's, a fused pass keeping the compiled row's
//     checks and canonical collects (and two ablations of it that say
//     what it is made of), and the same triangulation written by hand on
//     dartcheck's Map (one pass over the old darts), with and without
//     barycenters;
//   - CGAL: Linear_cell_complex_for_combinatorial_map<2,3>,
//     insert_barycenter_in_cell<2> on every face (topology + barycenter),
//     and insert_cell_0_in_cell_2 on a plain Combinatorial_map<2>
//     (topology only).
// Each peer runs in a child process ("peak MiB" is its own growth of the
// peak RSS while triangulating once), all on one CPU (peer_bench.hpp's
// pin_to_one_cpu); times are medians of --runs
// triangulations of a fresh copy (copy not timed). Every result is
// checked: dartcheck's map valid with a consistent, total pos embedding
// and every new vertex at its face's barycenter; CGAL's is_valid(); both
// with one triangle per old edge side.
//
//   build/bench/bench_triangulation [--runs N] [--mesh FILE.off | --grid RxC]
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>

#include <CGAL/Combinatorial_map.h>
#include <CGAL/Linear_cell_complex_constructors.h>
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>

#include "bench/peer_bench.hpp"
#include "checkers/embedding_consistency.hpp"
#include "checkers/map_validity.hpp"
#include "core/dart_table.hpp"
#include "io/catalog.hpp"
#include "rewriting/algebra.hpp"
#include "core/orbit.hpp"
#include "rewriting/application.hpp"
#include "io/mesh_io.hpp"
#include "generators/mesh_map.hpp"

#include DARTCHECK_COMPILED_EMBEDDING

namespace {

using LCC = CGAL::Linear_cell_complex_for_combinatorial_map<2, 3>;

// Each new vertex must sit at the barycenter of its old face, computed
// here from the input's positions. In H, an old dart d keeps its number
// (n0), its 1-neighbour is its new edge dart (n1) and that dart's
// 0-neighbour a copy of the centre (n2). The mean over the face's darts is
// the mean of its corners: both darts of a corner carry its position.
bool centres_are_barycenters(const dartcheck::EmbeddedMap& input, const dartcheck::EmbeddedMap& g) {
  using namespace dartcheck;
  OrbitWalker walker(input.map);
  const Embedding &before = input.embeddings[0], &after = g.embeddings[0];
  std::vector<bool> seen(input.map.size());
  for (Dart d = 0; d < input.map.size(); ++d) {
    if (seen[d]) continue;
    std::array<double, 3> sum{};
    const auto& face = walker.orbit(d, dims_generators({0, 1}));
    for (Dart x : face) {
      seen[x] = true;
      for (std::size_t k = 0; k < 3; ++k) sum[k] += before.value(x)->x[k];
    }
    const Value* v = after.value(g.map.link(0, g.map.link(1, d)));
    if (!v) return false;
    for (std::size_t k = 0; k < 3; ++k)
      if (std::abs(v->x[k] - sum[k] / static_cast<double>(face.size())) > 1e-9) return false;
  }
  return true;
}

enum class Scope { per_face, all_faces, everywhere };

Result run_dartcheck(const std::string& off, int runs, std::size_t triangles, Scope scope, dartcheck::Evaluation evaluation) {
  using namespace dartcheck;
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  const CatalogRule& s = *catalog.find_rule(scope == Scope::per_face ? "triangulation-jerboa-pos" : "triangulation-all-faces-pos");
  const Mesh mesh = read_mesh(off);
  const EmbeddedMap input = mesh_with_positions(Model::gmap(2), mesh, s.terms->embeddings[0]);
  // One hook per face (triangulation only appends darts, so they stay
  // valid), or one per connected component.
  const std::vector<Dart> hooks = orbit_hooks(input.map, scope == Scope::per_face ? std::vector<Dim>{0, 1} : std::vector<Dim>{0, 1, 2});
  return measure(runs, [&](double& ms, std::size_t& out) {
    EmbeddedMap g = input;
    bool ok = true;
    const auto t0 = std::chrono::steady_clock::now();
    {
      Applier rewriter(s, {evaluation});
      for (Dart h : hooks) ok &= rewriter.apply(g, std::span(&h, 1), false).ok();
    }
    ms = since(t0);
    out = g.map.size();
    return ok && count_cells(g.map).cells[2] == triangles && check_map(g.map).valid() && check_embedding(g.map, g.embeddings[0], true).consistent() &&
           centres_are_barycenters(input, g);
  });
}

// The same schemes compiled by `dartcheck compile` (issue 41): one
// evaluation per class, as the interpreter's one-per-orbit rows, the same
// checks.
using CompiledRule = dartcheck::Refusal (*)(dartcheck::EmbeddedMap&, std::span<const dartcheck::Dart>, dartcheck::compiled::Workspace&);
Result run_compiled(const std::string& off, int runs, std::size_t triangles, Scope scope) {
  using namespace dartcheck;
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  const CatalogRule& s = *catalog.find_rule("triangulation-all-faces-pos");
  const CompiledRule rule = scope == Scope::per_face ? &compiled_embedding_operations::triangulation_jerboa_pos
                                                     : &compiled_embedding_operations::triangulation_all_faces_pos;
  const EmbeddedMap input = mesh_with_positions(Model::gmap(2), read_mesh(off), s.terms->embeddings[0]);
  const std::vector<Dart> hooks = orbit_hooks(input.map, scope == Scope::per_face ? std::vector<Dim>{0, 1} : std::vector<Dim>{0, 1, 2});
  return measure(runs, [&](double& ms, std::size_t& out) {
    EmbeddedMap g = input;
    bool ok = true;
    const auto t0 = std::chrono::steady_clock::now();
    {
      compiled::Workspace ws;
      if (scope == Scope::everywhere)  // positions are darts: no P_v walk, no hooks
        ok = compiled_embedding_operations::triangulation_all_faces_pos_everywhere(g, ws) == Refusal::none;
      else
        for (Dart h : hooks) ok &= rule(g, std::span(&h, 1), ws) == Refusal::none;
    }
    ms = since(t0);
    out = g.map.size();
    return ok && count_cells(g.map).cells[2] == triangles && check_map(g.map).valid() && check_embedding(g.map, g.embeddings[0], true).consistent() &&
           centres_are_barycenters(input, g);
  });
}

// The floor of the all-faces rows: the same scheme's topology alone.
Result run_topology(const std::string& off, int runs, std::size_t triangles) {
  using namespace dartcheck;
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  const CatalogRule& s = *catalog.find_rule("triangulation-all-faces-pos");
  const Map input = build_mesh(Model::gmap(2), read_mesh(off));
  // One hook per connected component, found before the clock starts (as
  // for the rows with positions).
  const std::vector<Dart> hooks = orbit_hooks(input, {0, 1, 2});
  return measure(runs, [&](double& ms, std::size_t& out) {
    Map g = input;
    const auto t0 = std::chrono::steady_clock::now();
    bool ok = true;
    for (Dart h : hooks) ok &= Applier(s).apply(g, std::span(&h, 1)).ok();
    ms = since(t0);
    out = g.size();
    return ok && count_cells(g).cells[2] == triangles && check_map(g).valid();
  });
}

// The floor of a fused everywhere function (issue 41): what a generator
// that emits one pass per class, instead of one pass per step of the
// interpreter, would write for triangulation-all-faces-pos, with every
// check and every semantic choice of the compiled row kept: each dart's
// three links (whole_map_patterns' refusal), every dart labeled (L's
// term), the kept-label check along 1 and 2, the faces walked as
// alternating 0/1 links with their involutions checked, a face's
// vertices as 1-pairs valued at their smaller labeled dart, the multiset
// sorted canonically before its center (so the values are the compiled
// row's bit for bit), and a refusal that leaves the map as it was (the
// slots and pool entries written so far are dropped). What it changes
// against the compiled row: no tables (pattern, shifts, match, classes,
// sources, comatch, pool indices), each rewritten link being read before
// its position writes it, which holds because the rule changes only the
// 1-link of a position's own dart; the multiset sorted as pointers, not
// 40-byte values; the pool reserved before the centers; and a position's
// two new darts numbered side by side (n1 at n + 2p, n2 at n + 2p + 1, as
// the by-hand row), so that its links are written in one cache line. A kept-label check
// that fails would need the compiled row's walk: this row reports it
// invalid instead (a mesh's positions are shared per vertex, so it does
// not fail here).
//
// Its two ablations say what the floor is made of (issue 41): `checks`
// false drops the three check passes (each dart's links, L's labels, the
// kept-label check), `canonical` false sums each face's values in walk
// order instead of the sorted order. Neither is a valid compiled row: the
// first would apply the rule to hosts the interpreter refuses, the second
// gives centers that differ in the last bits between isomorphic numberings
// of one mesh (and from the interpreter's).
Result run_fused_floor(const std::string& off, int runs, std::size_t triangles, bool checks = true, bool canonical = true) {
  using namespace dartcheck;
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  const CatalogRule& s = *catalog.find_rule("triangulation-all-faces-pos");
  const EmbeddedMap input = mesh_with_positions(Model::gmap(2), read_mesh(off), s.terms->embeddings[0]);
  std::vector<Dart> face;
  std::vector<const Value*> bag;
  return measure(runs, [&](double& ms, std::size_t& out) {
    EmbeddedMap g = input;
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = [&] {
      Map& m = g.map;
      Embedding* const e = g.find("pos");
      if (!e) return false;
      const auto n = static_cast<Dart>(m.size());
      if (checks) {
        for (Dart d = 0; d < n; ++d)
          if (m.link(0, d) == no_dart || m.link(1, d) == no_dart || m.link(2, d) == no_dart) return false;  // not combinatorial
        for (Dart d = 0; d < n; ++d)
          if (!e->value(d)) return false;  // L: n0.pos has no value
        for (Dart d = 0; d < n; ++d)
          if (e->slot[m.link(1, d)] != e->slot[d] || e->slot[m.link(2, d)] != e->slot[d]) return false;  // the shortcut's check
      }
      const std::size_t pool0 = e->pool.size();
      e->pool.reserve(pool0 + n / 3);  // room for a center per face of 3 or more darts
      e->slot.resize(3 * static_cast<std::size_t>(n), Embedding::none);
      auto undo = [&] {
        e->slot.resize(n);
        e->pool.resize(pool0);
        return false;
      };
      for (Dart p0 = 0; p0 < n; ++p0) {  // n2: center(pos<0,1>(n0)), once per face
        if (e->slot[n + 2 * p0 + 1] != Embedding::none) continue;
        face.assign(1, p0);
        bool closed = false;
        for (int half = 0; half < 2 && !closed; ++half) {
          Dim i = half == 0 ? 0 : 1;
          for (Dart x = p0;; i = 1 - i) {
            const Dart y = m.link(i, x);
            if (m.link(i, y) != x) return undo();  // not an involution: the compiled row walks with a stack
            if (y == x) break;
            if (y == p0) {
              closed = true;
              break;
            }
            face.push_back(y);
            x = y;
          }
        }
        bag.clear();  // the pi-orbits' values, as pointers sorted by value_less (the multiset's canonical order)
        for (const Dart x : face) {
          const Dart y = m.link(1, x);
          if (y < x) continue;
          const Value* v = e->value(x);
          if (!v && y != x) v = e->value(y);
          if (!v) return undo();
          bag.push_back(v);
        }
        if (canonical) std::sort(bag.begin(), bag.end(), [](const Value* a, const Value* b) { return value_less(*a, *b); });
        std::array<double, 3> sum{};  // algebra::average's sum, in the same order
        for (const Value* v : bag)
          for (std::size_t k = 0; k < 3; ++k) sum[k] += v->x[k];
        for (double& x : sum) x /= static_cast<double>(bag.size());
        const std::uint32_t centre = e->store(Value::coords(e->signature.type, sum));
        for (const Dart x : face) e->slot[n + 2 * x + 1] = centre;
      }
      for (Dart p = 0; p < n; ++p) e->slot[n + 2 * p] = e->slot[p];  // n1: n0.pos, kept
      m.add_darts(2 * static_cast<std::size_t>(n));
      for (Dart p = 0; p < n; ++p) {
        const Dart a0 = m.link(0, p), a1 = m.link(1, p), n1 = n + 2 * p, n2 = n + 2 * p + 1;
        m.set_link(1, p, n1);
        m.set_link(1, n1, p);
        m.set_link(0, n1, n2);
        m.set_link(0, n2, n1);
        m.set_link(2, n1, n + 2 * a1);
        m.set_link(1, n2, n + 2 * a0 + 1);
        m.set_link(2, n2, n + 2 * a1 + 1);
      }
      return true;
    }();
    ms = since(t0);
    out = g.map.size();
    return ok && count_cells(g.map).cells[2] == triangles && check_map(g.map).valid() && check_embedding(g.map, g.embeddings[0], true).consistent() &&
           centres_are_barycenters(input, g);
  });
}

// The like-for-like floor of the dartcheck rows: the same triangulation
// written by hand on dartcheck's own Map (and Embedding), no rule engine.
// Old dart d keeps its number; its new darts are e(d) = n + 2d (node n1 of
// the scheme, on the new corner-to-centre edge) and c(d) = n + 2d + 1
// (node n2, at the centre). In the face of d, with a0 = alpha0(d) and
// a1 = alpha1(d) read before the write:
//   alpha1(d) = e(d); e(d): alpha0 c(d), alpha2 e(a1);
//   c(d): alpha1 c(a0), alpha2 c(a1).
// Only d's own alpha1 slot changes among the old darts, so one pass over
// the old darts writes every link. The checks are those of the scheme rows.
Result run_by_hand(const std::string& off, int runs, std::size_t triangles, bool positions) {
  using namespace dartcheck;
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  const CatalogRule& s = *catalog.find_rule("triangulation-all-faces-pos");
  const EmbeddedMap input = mesh_with_positions(Model::gmap(2), read_mesh(off), s.terms->embeddings[0]);
  return measure(runs, [&](double& ms, std::size_t& out) {
    EmbeddedMap g = input;
    Map& m = g.map;
    Embedding& pos = g.embeddings[0];
    const auto t0 = std::chrono::steady_clock::now();
    const auto n = static_cast<Dart>(m.size());
    m.add_darts(2 * static_cast<std::size_t>(n));
    if (positions) {
      // One barycenter per face, shared by its centre darts; e(d) shares
      // d's vertex value.
      pos.slot.resize(3 * static_cast<std::size_t>(n), Embedding::none);
      for (Dart d = 0; d < n; ++d) {
        if (pos.slot[n + 2 * d + 1] != Embedding::none) continue;
        std::array<double, 3> sum{};
        std::size_t corners = 0;
        Dart x = d;
        do {
          for (std::size_t k = 0; k < 3; ++k) sum[k] += pos.pool[pos.slot[x]].x[k];
          ++corners;
          x = m.link(1, m.link(0, x));
        } while (x != d);
        for (double& v : sum) v /= static_cast<double>(corners);
        const std::uint32_t centre = pos.store(Value::coords(ValueType::point3, sum));
        x = d;
        do {
          pos.slot[n + 2 * x + 1] = centre;
          pos.slot[n + 2 * m.link(0, x) + 1] = centre;
          x = m.link(1, m.link(0, x));
        } while (x != d);
      }
      for (Dart d = 0; d < n; ++d) pos.slot[n + 2 * d] = pos.slot[d];
    }
    for (Dart d = 0; d < n; ++d) {
      const Dart a0 = m.link(0, d), a1 = m.link(1, d), e = n + 2 * d, c = e + 1;
      m.set_link(1, d, e);
      m.set_link(0, e, c);
      m.set_link(1, e, d);
      m.set_link(2, e, n + 2 * a1);
      m.set_link(0, c, e);
      m.set_link(1, c, n + 2 * a0 + 1);
      m.set_link(2, c, n + 2 * a1 + 1);
    }
    ms = since(t0);
    out = m.size();
    return count_cells(m).cells[2] == triangles && check_map(m).valid() &&
           (!positions || (check_embedding(m, pos, true).consistent() && centres_are_barycenters(input, g)));
  });
}

// The floor of a generic scheme engine: what 002's instantiation and
// 003's extended labels make any implementation do, written by hand for
// this one rule (no rule is read or interpreted). For each hook:
//   1. P_v (002 Def. 20): a BFS of the hook orbit with a dart -> position
//      table and one shift table per generator (alpha0, alpha1, and
//      alpha2 for all faces), as a scheme engine must, not knowing the
//      orbit's shape;
//   2. the classes of pos <1,2> in the instantiated L and R: per face,
//      Lemma 3's check walks the <1,2>-orbit in G of each corner (L has
//      no 2-loop, so its classes are not whole orbits of G); for all
//      faces, L is closed and the classes are walks over P_v;
//   3. one barycenter per face (one evaluation per class);
//   4. the links of the new darts through the shift tables;
//   5. the labels: per face, Def. 12's walk of each corner's vertex orbit
//      in H (R has no 2-arc at n0, so the class is not a whole orbit);
//      for all faces, one write per instance from its class (R closed).
// Checked as the scheme rows. New darts of copy p: n1 = base + p, n2 =
// base + np + p.
Result run_generic_floor(const std::string& off, int runs, std::size_t triangles, Scope scope) {
  using namespace dartcheck;
  constexpr std::uint32_t none = DartTable::none;
  const Catalog catalog = read_catalog(std::string(DARTCHECK_SOURCE_DIR) + "/catalogs/embedding-operations.yaml");
  const EmbeddedMap input =
      mesh_with_positions(Model::gmap(2), read_mesh(off), catalog.find_rule("triangulation-all-faces-pos")->terms->embeddings[0]);
  const bool per_face = scope == Scope::per_face;
  const std::vector<Dart> hooks = orbit_hooks(input.map, per_face ? std::vector<Dim>{0, 1} : std::vector<Dim>{0, 1, 2});
  const Dim generators = per_face ? 2 : 3;
  return measure(runs, [&](double& ms, std::size_t& out) {
    EmbeddedMap g = input;
    Map& m = g.map;
    Embedding& pos = g.embeddings[0];
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::uint32_t> position(m.size(), none), face, vertex, stack;
    std::vector<Dart> pattern;
    std::array<std::vector<std::uint32_t>, 3> shift;
    DartTable corner_of;
    OrbitWalker walker(m);
    const std::vector<OrbitWord> vertex_gens = dims_generators({1, 2});
    // Classes of P_v under two generators, by a walk along the shifts.
    auto classes = [&](int a, int b, std::vector<std::uint32_t>& cls) {
      cls.assign(pattern.size(), none);
      std::uint32_t count = 0;
      for (std::uint32_t p = 0; p < pattern.size(); ++p) {
        if (cls[p] != none) continue;
        cls[p] = count;
        stack.push_back(p);
        while (!stack.empty()) {
          const std::uint32_t q = stack.back();
          stack.pop_back();
          for (int w : {a, b})
            if (const std::uint32_t r = shift[w][q]; cls[r] == none) {
              cls[r] = count;
              stack.push_back(r);
            }
        }
        ++count;
      }
      return count;
    };
    bool ok = true;
    for (Dart h : hooks) {
      // 1. P_v.
      pattern.assign(1, h);
      for (auto& t : shift) t.clear();
      position[h] = 0;
      for (std::size_t k = 0; k < pattern.size(); ++k)
        for (Dim i = 0; i < generators; ++i) {
          const Dart t = m.link(i, pattern[k]);
          if (position[t] == none) {
            position[t] = static_cast<std::uint32_t>(pattern.size());
            pattern.push_back(t);
          }
          shift[i].push_back(position[t]);
        }
      for (Dart d : pattern) position[d] = none;
      const auto np = static_cast<std::uint32_t>(pattern.size());
      // 2. Classes: faces (alpha0, alpha1) for n2; per face, Lemma 3 on the
      //    corners {p, p.alpha1}, each walked in G once.
      const std::uint32_t faces = classes(0, 1, face);
      if (per_face) {
        for (std::uint32_t p = 0; p < np; ++p) corner_of.set(pattern[p], std::min(p, shift[1][p]));
        for (std::uint32_t p = 0; p < np; ++p) {
          if (shift[1][p] < p) continue;
          for (Dart y : walker.orbit(pattern[p], vertex_gens))
            if (const std::uint32_t c = corner_of.get(y); c != none && c != p) ok = false;  // overlap
        }
        corner_of.clear();
      } else {
        classes(1, 2, vertex);
      }
      // 3. One barycenter per face class: its corners' mean.
      std::vector<std::array<double, 3>> sum(faces, {0, 0, 0});
      std::vector<int> corners(faces, 0);
      for (std::uint32_t p = 0; p < np; ++p) {
        if (shift[1][p] < p) continue;
        const Value& v = pos.pool[pos.slot[pattern[p]]];
        for (std::size_t k = 0; k < 3; ++k) sum[face[p]][k] += v.x[k];
        ++corners[face[p]];
      }
      std::vector<std::uint32_t> centre(faces);
      for (std::uint32_t c = 0; c < faces; ++c) {
        for (double& x : sum[c]) x /= corners[c];
        centre[c] = pos.store(Value::coords(ValueType::point3, sum[c]));
      }
      // 4. The rewrite: n0 -1- n1 -0- n2, n1's 2-loop along alpha1, n2's
      //    1- and 2-loops along alpha0 and alpha1.
      const Dart base = m.add_darts(2 * std::size_t{np});
      for (std::uint32_t p = 0; p < np; ++p) {
        const Dart n0 = pattern[p], n1 = base + p, n2 = base + np + p;
        m.set_link(1, n0, n1);
        m.set_link(1, n1, n0);
        m.set_link(0, n1, n2);
        m.set_link(0, n2, n1);
        m.set_link(2, n1, base + shift[1][p]);
        m.set_link(1, n2, base + np + shift[0][p]);
        m.set_link(2, n2, base + np + shift[1][p]);
      }
      // 5. Labels: n2 from its face class; n0 keeps its value and n1 takes
      //    it, through Def. 12's walk per corner, or per instance.
      for (std::uint32_t p = 0; p < np; ++p) pos.set_index(base + np + p, centre[face[p]]);
      for (std::uint32_t p = 0; p < np; ++p) {
        const std::uint32_t v = pos.slot[pattern[p]];
        if (!per_face)
          pos.set_index(base + p, v);
        else if (shift[1][p] > p)
          for (Dart y : walker.orbit(pattern[p], vertex_gens)) pos.set_index(y, v);
      }
    }
    ms = since(t0);
    out = m.size();
    return ok && count_cells(m).cells[2] == triangles && check_map(m).valid() && check_embedding(m, pos, true).consistent() &&
           centres_are_barycenters(input, g);
  });
}

// CGAL's topology-only floor: the same insertion on a plain
// Combinatorial_map<2> (no point attributes), copied from the LCC.
Result run_cgal_topology(const std::string& off, int runs, std::size_t faces) {
  using CMap = CGAL::Combinatorial_map<2>;
  LCC read;
  std::ifstream in(off);
  CGAL::load_off(read, in);
  const CMap input(read);
  return measure(runs, [&](double& ms, std::size_t& out) {
    CMap m(input);
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<CMap::Dart_handle> one_per_face;
    for (auto it = m.one_dart_per_cell<2>().begin(); it != m.one_dart_per_cell<2>().end(); ++it) one_per_face.push_back(it);
    for (auto d : one_per_face) m.insert_cell_0_in_cell_2(d);
    ms = since(t0);
    out = m.number_of_darts();
    return m.is_valid() && m.one_dart_per_cell<2>().size() == faces;
  });
}

Result run_cgal(const std::string& off, int runs, std::size_t faces) {
  LCC input;
  std::ifstream in(off);
  CGAL::load_off(input, in);
  return measure(runs, [&](double& ms, std::size_t& out) {
    LCC m(input);
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<LCC::Dart_handle> one_per_face;
    for (auto it = m.one_dart_per_cell<2>().begin(); it != m.one_dart_per_cell<2>().end(); ++it) one_per_face.push_back(it);
    for (auto d : one_per_face) m.insert_barycenter_in_cell<2>(d);
    ms = since(t0);
    out = m.number_of_darts();
    return m.is_valid() && m.one_dart_per_cell<2>().size() == faces;
  });
}

}  // namespace

int main(int argc, char** argv) {
  MeshInput input;
  if (!input.parse(argc, argv, DARTCHECK_BENCH_MESH, "triangulation")) return 2;
  const int runs = input.runs;
  const std::string &off = input.off, &only = input.only;
  // A k-gon becomes k triangles: one per side, so as many as the input's
  // G-map darts / 2 (= its CGAL darts).
  std::size_t sides = 0;
  const dartcheck::Mesh mesh = dartcheck::read_mesh(off);
  for (const auto& f : mesh.faces) sides += f.size();
  print_machine_line();
  std::printf("input: %s: V=%zu, F=%zu, %zu G-map darts, %zu CGAL darts; median of %d runs\n\n", off.c_str(), mesh.positions.size(),
              mesh.faces.size(), 2 * sides, sides, runs);
  using dartcheck::Evaluation;
  struct Peer {
    const char* name;
    std::function<Result()> run;
  };
  const std::vector<Peer> all_peers{
      {"dartcheck triangulation-jerboa-pos, per face, every instance evaluated",
       [&] { return run_dartcheck(off, runs, sides, Scope::per_face, Evaluation::every_instance); }},
      {"dartcheck triangulation-jerboa-pos, per face, one evaluation per orbit",
       [&] { return run_dartcheck(off, runs, sides, Scope::per_face, Evaluation::one_per_orbit); }},
      {"dartcheck triangulation-all-faces-pos, once, every instance evaluated",
       [&] { return run_dartcheck(off, runs, sides, Scope::all_faces, Evaluation::every_instance); }},
      {"dartcheck triangulation-all-faces-pos, once, one evaluation per orbit",
       [&] { return run_dartcheck(off, runs, sides, Scope::all_faces, Evaluation::one_per_orbit); }},
      {"dartcheck triangulation-all-faces-pos, topology only (Applier on the map, no terms)", [&] { return run_topology(off, runs, sides); }},
      {"dartcheck compiled triangulation-jerboa-pos, per face", [&] { return run_compiled(off, runs, sides, Scope::per_face); }},
      {"dartcheck compiled triangulation-all-faces-pos, once", [&] { return run_compiled(off, runs, sides, Scope::all_faces); }},
      {"dartcheck compiled triangulation-all-faces-pos, everywhere (positions are darts)",
       [&] { return run_compiled(off, runs, sides, Scope::everywhere); }},
      {"generic scheme floor by hand, per face (P_v, Lemma 3 and Def. 12 walks)",
       [&] { return run_generic_floor(off, runs, sides, Scope::per_face); }},
      {"generic scheme floor by hand, all faces (P_v, classes over P_v)", [&] { return run_generic_floor(off, runs, sides, Scope::all_faces); }},
      {"fused floor by hand: the compiled row's checks and canonical collects, no tables", [&] { return run_fused_floor(off, runs, sides); }},
      {"fused floor without its check passes (ablation: not a valid compiled row)", [&] { return run_fused_floor(off, runs, sides, false, true); }},
      {"fused floor without the canonical order, sums in walk order (ablation: not a valid compiled row)",
       [&] { return run_fused_floor(off, runs, sides, true, false); }},
      {"by hand on dartcheck's Map and Embedding, with barycenters (one pass, no rule)", [&] { return run_by_hand(off, runs, sides, true); }},
      {"by hand on dartcheck's Map, topology only (one pass, no rule)", [&] { return run_by_hand(off, runs, sides, false); }},
      {"CGAL Combinatorial_map<2> insert_cell_0_in_cell_2 on every face (topology only)", [&] { return run_cgal_topology(off, runs, sides); }},
      {"CGAL LCC insert_barycenter_in_cell<2> on every face", [&] { return run_cgal(off, runs, sides); }},
  };
  // --only keeps the peers whose name contains the text, and CGAL (the
  // ratios' base): for profiling one row.
  std::vector<Peer> chosen;
  for (const Peer& p : all_peers)
    if (only.empty() || std::strstr(p.name, only.c_str()) || &p == &all_peers.back()) chosen.push_back(p);
  const std::vector<Peer>& peers = chosen;
  std::vector<Result> results;
  for (const Peer& p : peers) results.push_back(run_in_child(p.run));
  const Result& g = results.back();
  bool ok = true;
  std::printf("| peer | output darts | median ms | peak MiB | ms / CGAL | MiB / CGAL | result valid |\n|---|---|---|---|---|---|---|\n");
  for (std::size_t k = 0; k < peers.size(); ++k) {
    const Result& x = results[k];
    ok &= x.ok;
    std::printf("| %s | %zu | %.1f | %.1f | %.2fx | %.2fx | %s |\n", peers[k].name, x.out_elements, x.median_ms, x.peak_mib,
                x.median_ms / g.median_ms, g.peak_mib > 0 ? x.peak_mib / g.peak_mib : 0.0, x.ok ? "yes" : "NO");
  }
  return ok ? 0 : 1;
}
