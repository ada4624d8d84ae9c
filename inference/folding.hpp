// The topological folding algorithm of 000 Sec. 5 on κ(G, H) (Sec. 7):
// from a start dart a of G and an orbit type <o>, the graph scheme S whose
// instantiation on G<o>(a) gives back κ(G, H), or the failure that shows
// none exists from a.
//
// Step 1 builds the orbit G<o>(a) and the hook, labeled <o>. Step 2 is a
// breadth-first traversal of S: for each node m, its explicit arcs (2.1:
// addition, extension, with arc and instantiation failures) on the
// dimensions outside its label and on κ; each new node is labeled at once
// (2.2: relabeling i -> j or deletion i -> _, with relabeling failures).
// Every dart of κ(G, H) is visited once per dimension: O(|G| + |H|)
// (Sec. 8.3), independent of |<o>|.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/formatting.hpp"
#include "core/orbit.hpp"
#include "inference/kappa_graph.hpp"
#include "rewriting/jerboa_scheme.hpp"

namespace dartcheck::inference {

/// The κ "dimension" in arcs and failures: it joins the two copies of a
/// preserved node and never appears in a label.
inline constexpr Dim kappa_arc = -1;

/// A node of the graph scheme: its side and label, and its darts: darts[q]
/// is the dart (b_q, m) of κ(G, H), b_q the q-th dart of G<o>(a) in BFS
/// order (b_0 = a).
struct SchemeNode {
  bool after = false;
  OrbitType label;
  std::vector<Dart> darts;
};

/// An explicit arc (a d-arc, or a κ-arc joining the L and R copies of a
/// preserved node). A loop has a == b.
struct SchemeArc {
  int a = 0, b = 0;
  Dim d = 0;
};

/// A label position the example does not decide: every i-link of G<o>(a)
/// is a loop, so the darts of the node say nothing of what the operation
/// does with a non-loop i-link. `chosen` is the relabeling taken (nullopt:
/// deletion, with explicit loops).
struct UndecidedPosition {
  int node = 0;
  std::size_t position = 0;
  std::optional<Dim> chosen;
};

struct GraphScheme {
  std::vector<Dim> orbit;         // <o>, the hook's label
  std::vector<SchemeNode> nodes;  // nodes[0] is the hook
  std::vector<SchemeArc> arcs;    // each arc once, in creation order
  std::vector<UndecidedPosition> undecided;
};

enum class FailureKind {
  arc,            // (a,m) -d- (b,m') with b != a: not constructible (Sec. 5.2 Step 2.1)
  instantiation,  // the d-links of the darts of m do not all fold into one arc (Step 2.1)
  relabeling,     // no relabeling of position i holds for every dart of m (Step 2.2)
  undecided,      // a position the example does not decide, refused by the caller's policy
  unreached,      // κ(G, H) is not connected: a dart no node owns (Sec. 7)
  shared,         // a node built here was a <o>-node of an earlier failed folding (Sec. 10.3)
};
const char* name_of(FailureKind k);

struct FoldFailure {
  FailureKind kind = FailureKind::arc;
  int node = 0;      // the node being built
  Dim dim = 0;       // the dimension (kappa_arc for κ); for relabeling the orbit dimension i
  Dart dart = 0;     // the dart of κ(G, H) where it fails
  std::string text;  // the sentence, with node, dimension and darts named
};

/// What to do with undecided positions.
enum class UndecidedPolicy {
  keep,  // relabel as the example allows (i -> i first), and report it
  free,  // i -> _, the loops become explicit loop arcs
  fail,  // refuse: the example must be made unambiguous
};

struct FoldOptions {
  /// The paper exactly: one candidate per position (i -> i if it links
  /// (a,m) to (b_i,m), else the smallest such j), checked, no retry.
  /// Otherwise every candidate j is tried in that order and the first that
  /// holds for every dart of the node is kept; if none holds, the position
  /// is deleted (i -> _) and Step 2.1 checks the links as explicit arcs.
  bool strict = false;
  UndecidedPolicy undecided = UndecidedPolicy::keep;
};

struct FoldResult {
  std::optional<GraphScheme> scheme;
  std::optional<FoldFailure> failure;
  /// The darts of the L nodes built with the hook's own label (position p
  /// relabeled o_p -> o_p, nothing deleted), the hook included, on success
  /// and up to a failure; empty in strict mode. Each such node is a
  /// <o>-orbit of G, and a non-strict folding from any of its darts is
  /// this folding hooked at that node: it gives the same scheme re-rooted,
  /// or fails as this one did (docs/inference.md, "Starts that need no
  /// folding"). This is the paper's marking of darts that "would yield an
  /// already found rule or fail to result in a rule" (000 Sec. 10.3).
  std::vector<Dart> hook_like;
};

/// The per-dart tables of the folding, kept across the foldings of one κ
/// graph (multi-start, `infer --all`): each folding clears only the darts
/// it owned, so a folding costs what it visits, not the size of the map
/// (000 Sec. 8.3: linear in the darts it folds).
class FoldScratch {
 public:
  explicit FoldScratch(const KappaGraph& graph);
  OrbitWalker walker;                   // over G
  std::vector<int> owner;               // node of each dart of κ(G, H), -1 if none
  std::vector<std::uint32_t> position;  // its position q in that node
  /// For each dart of G, a start whose non-strict folding failed after
  /// building the dart's <o>-orbit as a node with the hook's label, or
  /// no_dart. A folding that builds such a node fails there (kind
  /// `shared`): hooked at that node it is the failed folding. Set by the
  /// caller (infer) for one orbit type and one policy; empty: no check.
  std::vector<Dart> failed_from;
};

/// Folds κ(G, H) from dart `start` of G along <o>. `orbit` lists distinct
/// dimensions of the model (checked by the caller).
FoldResult fold(const KappaGraph& graph, const std::vector<Dim>& orbit, Dart start, const FoldOptions& options = {});
/// The same with tables kept across foldings of `graph`.
FoldResult fold(const KappaGraph& graph, const std::vector<Dim>& orbit, Dart start, const FoldOptions& options, FoldScratch& scratch);

/// The orbit G<o>(a) in the BFS order fold uses (a first, dimensions in
/// the order of `orbit`), by core's orbit walker.
std::vector<Dart> orbit_darts(const Map& g, const std::vector<Dim>& orbit, Dart start);
const std::vector<Dart>& orbit_darts(OrbitWalker& walker, const std::vector<Dim>& orbit, Dart start);

}  // namespace dartcheck::inference
