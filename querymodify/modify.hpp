// Modify operations on matched volumes (001 Sec. 6): deleting volumes
// (Alg. 3, corrected), merging them into one (Alg. 4's first step, the
// replace used by the tet -> hex recombination), extending a match by a
// target that contains the query (Alg. 2) and replacing a match by a
// target with the same boundary (Alg. 4). Delete and merge take the darts
// of whole volumes (closed under β1 and β2); all keep the map a valid
// 3-map and renumber darts to keep it dense.
#pragma once

#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/map.hpp"
#include "core/renumbering.hpp"

namespace dartcheck::querymodify {

/// Deletes the volumes made of `darts`. Every β3 link between a deleted
/// dart and a kept one is unsewn first, whether or not the kept dart was
/// matched: 001's Alg. 3 unsews only the 3-links inside the query, which
/// leaves a kept dart 3-sewn to a deleted one when a deleted volume
/// touches the rest of the mesh (tests show it). Throws
/// ValueError if `darts` is not a union of volumes.
Renumbering delete_volumes(Map& m, const std::vector<Dart>& darts);

/// Merges the volumes made of `darts` into one by removing every face
/// between two of them (001 Alg. 4, lines 1-2): each remaining dart's
/// β2 becomes the next remaining dart around its edge, found by turning
/// through the removed faces (β2 then β3); edges and vertices inside the
/// merged volume disappear with their faces. Throws ValueError
/// if `darts` is not a union of volumes.
Renumbering merge_volumes(Map& m, const std::vector<Dart>& darts);

/// Merges the faces made of `darts` (whole faces, every dart 3-free) into
/// one face per connected group by removing every edge between two of
/// them: each remaining dart's β1 becomes the next remaining dart around
/// the merged face, found by turning through the removed edges (β2 then
/// β1), so edges and vertices inside a merged face disappear with them
/// (001 Sec. 7.4 merges the upper faces of flattened terrain volumes this
/// way). Throws ValueError if `darts` is not a union of faces
/// or a dart is 3-sewn.
Renumbering merge_faces(Map& m, const std::vector<Dart>& darts);

/// Carries per-dart data through a renumbering of deleted darts (the
/// slots of removed darts filled by the last ones), in place: O(darts
/// moved), not a copy of the table.
template <class T>
void follow(std::vector<T>& per_dart, const Renumbering& r) {
  r.for_each_moved([&](Dart from, Dart to) { per_dart[to] = per_dart[from]; });
  per_dart.resize(r.h_size());
}

/// Alg. 2: T contains Q (`q_to_t[q]`, m_QT, is the target dart of query
/// dart q) and `q_to_m[q]` (m_QM) is the input dart of q in a match. The
/// darts of T without a pre-image are copied into `m` with their links
/// among themselves, and each that T 3-sews to an image of Q is 3-sewn to
/// that image's input dart. Returns m_TM (the input dart of each target
/// dart: the copies, and the matched darts for images of Q). Throws
/// ValueError, before changing `m`, if m_QT does not keep a
/// link of Q, if a new dart is linked to an image of Q other than by β3,
/// or if the input dart it must be 3-sewn to is not 3-free (001: such
/// darts must be free before the operation; a query marks them ε).
std::vector<Dart> extend(Map& m, const Map& q, const Map& t, const std::vector<Dart>& q_to_t, const std::vector<Dart>& q_to_m);

/// Alg. 4 on a whole match: the matched volumes (the images of all of Q)
/// are removed and T put in their place, each 3-free dart of Q handing
/// its outside neighbour to its image in T (`q_to_t`, defined on Q's
/// 3-free darts at least). T's boundary must be Q's: q_to_t maps Q's
/// 3-free darts one to one onto T's and keeps β1 among them (throws
/// ValueError otherwise, before changing `m`). Returns m_TM;
/// `moved`, if given, receives the renumbering of the input once the
/// match's darts are removed (T's are appended after).
std::vector<Dart> replace(Map& m, const Map& q, const Map& t, const std::vector<Dart>& q_to_t, const std::vector<Dart>& q_to_m,
                          Renumbering* moved = nullptr);

}  // namespace dartcheck::querymodify
