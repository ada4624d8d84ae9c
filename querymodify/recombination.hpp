// Tetrahedra to hexahedra (001 Sec. 7.1): every match of the hex queries
// (hex_queries.hpp) in a tetrahedral 3-map, a selection of non-overlapping
// matches (greedy, or global by a quality score), and each selected match
// merged into one volume (modify.hpp). A merged hex keeps its 12 boundary
// triangles (36 darts): neighbouring tetrahedra still see triangles, as in
// 001's intermediate states.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/error.hpp"
#include "querymodify/progress.hpp"
#include "querymodify/annotation.hpp"
#include "querymodify/cell_search.hpp"
#include "querymodify/hex_quality.hpp"
#include "querymodify/hex_queries.hpp"

namespace dartcheck::querymodify {

enum class Strategy { greedy, global };

/// How the global strategy finds its candidates: from mesh vertices
/// (hex_search.hpp, the default) or by matching every query word from
/// every dart (001 Sec. 5, the definition the vertex search is tested
/// against). The greedy strategy is 001's dart-order walk of the word
/// search: it always matches words.
enum class Search { vertices, words };

/// How the selected cells may meet (hex_contacts.hpp, cell_contacts.hpp):
/// in any way their tetrahedra allow (001's recombination, the default), or
/// only in nothing, a vertex, an edge or a face of both (a conforming
/// mesh; the global strategy's vertex search only).
enum class Contacts { any, conforming };

/// The cells besides hexes that the recombination makes (--cells): after
/// the hexes, pyramids on their quad faces that face two tetrahedra with
/// one apex, then prisms from the tetrahedra left, then pyramids on the
/// prisms' quads (cell_search.hpp).
struct Cells {
  bool prisms = false, pyramids = false;
};

/// The prisms or pyramids of a recombination.
struct CellSelection {
  /// Candidates found, those acceptable (quality above the threshold),
  /// and acceptable ones passed over as not conforming to a cell selected
  /// before (Contacts::conforming).
  std::size_t candidates = 0, acceptable = 0, nonconforming = 0;
  /// The selected ones, corners right-handed (cell_quality.hpp) with points.
  std::vector<CellCandidate> cells;
  double seconds = 0;  // search and selection
};

/// The cube corner (0..7, v = x + 2y + 4z) each dart of a query starts at.
std::vector<std::uint32_t> query_corners(const HexQuery& q);

/// The mesh vertex at each cube corner of a match of query `q`.
std::array<std::uint32_t, 8> match_corners(const HexQuery& q, const std::vector<std::uint32_t>& corners, const QueryMatch& m,
                                           const std::vector<std::uint32_t>& vertex_of_dart);

struct Recombination {
  Search search = Search::vertices;  // the search that ran
  Contacts contacts = Contacts::any;
  /// Acceptable candidates passed over because they would not conform to
  /// a hex selected before (Contacts::conforming).
  std::size_t nonconforming = 0;
  /// The word search's matches (raw: from every start dart; distinct: by
  /// query and darts), 0 when the vertex search ran.
  std::size_t raw_matches = 0, distinct_matches = 0;
  /// The vertex search's readings and candidates (hex_search.hpp), 0 when
  /// the word search ran.
  std::size_t readings = 0, candidates = 0;
  std::size_t hexes = 0, tets = 0;
  /// Candidates that may be selected: 8 distinct corners, quality above
  /// the threshold (the same set from either search).
  std::size_t acceptable = 0;
  /// The input tetrahedra (indices into mesh.tets, sorted) of each
  /// selected hex.
  std::vector<std::vector<std::uint32_t>> hex_tets;
  /// Per selected match: the mesh vertex at each cube corner (v = x + 2y +
  /// 4z) under its best reading, right-handed at corner 0 (mirrored in x
  /// if needed), and that reading's scaled Jacobian (NaN without points;
  /// then the first reading, as it comes).
  std::vector<std::array<std::uint32_t, 8>> hex_corners;
  std::vector<double> quality;
  /// The prisms and pyramids, empty unless asked for (Cells).
  CellSelection prisms, pyramids;
  /// Quad faces of the cells (hexes, prisms, pyramids) that face neither
  /// the boundary nor the same quad of another cell (cell_search.hpp), at
  /// the end and (when pyramids are made) as if the pyramids were left as
  /// tetrahedra.
  std::size_t quads_facing_triangles = 0, quads_facing_triangles_before_pyramids = 0;
  /// The input tetrahedra (indices into mesh.tets) left as tetrahedra.
  std::vector<std::size_t> remaining_tets;
  /// Wall-clock seconds: every match (raw and distinct), the selection,
  /// the merges.
  double match_seconds = 0, select_seconds = 0, merge_seconds = 0;
};

/// Finds and selects hexes in `mesh` (points give the global strategy its
/// score; without them the global order is by number of tetrahedra, then
/// found order). Merges the selected matches in `mesh.map`. Either
/// strategy skips a match whose corners are not 8 distinct mesh vertices
/// (a pattern closed on itself: words see darts, not vertices) and, with
/// points, one whose best scaled Jacobian is not above `min_quality`.
/// Contacts::conforming with the greedy strategy or the word search is a
/// ValueError. `cells` adds pyramids, prisms and pyramids
/// after the hexes (Cells), each pass by the global order (best quality
/// first, above `min_quality`) on the tetrahedra still free; with
/// Contacts::conforming each cell conforms to every cell selected before.
/// `progress` hears each stage and the vertex search's count.
Recombination recombine(TetMap& mesh, const std::vector<HexQuery>& queries, Strategy strategy,
                        const std::vector<std::array<double, 3>>* points = nullptr, double min_quality = 0.0, Search search = Search::vertices,
                        Contacts contacts = Contacts::any, Cells cells = {}, const Progress& progress = {});

}  // namespace dartcheck::querymodify
