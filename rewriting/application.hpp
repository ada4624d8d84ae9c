// The one way to apply the operation under test (GUIDE, "The pipeline"):
// a DPO rule (002 Sec. 2) matched from its hooks, or a rule scheme (002
// Sec. 6) instantiated on the hooks' pattern graph, give the same record:
// the match and comatch per (rule node, pattern position), the darts H
// renumbered, and from them the Renumbering of G's darts into H's. On an
// embedded map (003) the same application also evaluates the rule's terms
// between the match and the rewrite and writes their values: the engine
// with values, not a second engine. Every engine (run, apply, fuzz,
// events, inference, proofs' replays, ...) applies through an Applier, so
// no other place branches on scheme versus DPO. The one other application
// is graph_derivation.hpp's derive(), on D-graphs that are not maps.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/renumbering.hpp"
#include "rewriting/embedded_map.hpp"
#include "rewriting/match.hpp"
#include "rewriting/operation.hpp"
#include "rewriting/pattern_graphs.hpp"
#include "rewriting/term_facts.hpp"

namespace dartcheck {

struct Application {
  std::size_t g_size = 0;
  std::vector<std::vector<Dart>> match;    // [L node][p]: dart of G (a DPO rule has one position)
  std::vector<std::vector<Dart>> comatch;  // [R node][p]: dart of H (empty until rewritten)
  /// Darts of G that H renumbered to keep its darts dense: (old, new).
  std::vector<std::pair<Dart, Dart>> moved;
  /// The hooks' pattern P_v (schemes only).
  std::optional<PatternGraphs> pattern;

  /// G's darts against H's: matched darts through the rule (preserved ones
  /// by the comatch, deleted ones to nothing), unmatched ones by identity
  /// or their renumbering; R's added nodes are created darts. Costs
  /// O(|matched| + |moved|).
  Renumbering renumbering(const Rule& rule, std::size_t h_size) const;
};

/// How an Applier applies on embedded maps.
struct EvaluationOptions {
  /// How R's terms are evaluated under `extended` instantiation
  /// (term_facts.hpp).
  Evaluation evaluation = Evaluation::every_instance;
  /// The kept-label shortcut. Under one evaluation per orbit, for an
  /// embedding R closes, of a rule that deletes no node of L: a group of
  /// R's nodes whose terms all read one L node's stored value (`n0.pos`)
  /// is not walked for its classes when that value's pool index i(p) at
  /// each pattern copy p is defined and equals i(p·w) for each of the
  /// group's steps w; each copy is then its own class, valued i(p). The
  /// result is the walk's, index for index: a class is connected by those
  /// steps, so i is constant on it, and the walk gives every instance the
  /// index of the class's first instance, i(p) again. When the check fails
  /// (G not consistent along the group, equal values in distinct pool
  /// entries, a missing value) the group is walked.
  bool kept_label_shortcut = true;
};

struct WrittenValue {
  std::string embedding, node;  // node: "y" for a DPO rule, "y@d" for pattern dart d of a scheme
  Dart dart = no_dart;          // in H
  Value value;
};

/// An application on an embedded map: its topology and the values written.
struct EmbeddedApplication {
  /// The match, comatch (H's numbering) and renumbered darts. Without
  /// `record`, the match and comatch tables stay with the Applier for the
  /// next application: only g_size and moved are set.
  Application topology;
  std::size_t matched = 0, added = 0;  // darts of G matched, darts of H added
  std::vector<WrittenValue> written;   // in R's node order (with `record`)
  std::vector<std::string> conflicts;  // orbits given two values (Def. 13 undefined)
};

class EmbeddedRewriter;

/// Applies one operation again and again: what an application derives from
/// the rule alone (a scheme's generators and refusals, the terms' facts) is
/// computed once, and the tables of an application (pattern, match,
/// comatch, traversal marks, the evaluator) keep their memory for the next.
/// The operation must outlive the Applier.
class Applier {
 public:
  explicit Applier(const Operation& op, EvaluationOptions options = {});
  ~Applier();
  Applier(const Applier&) = delete;
  Applier& operator=(const Applier&) = delete;

  /// Rewrites g in place at `hooks` (the topology alone: a map has no
  /// values); on refusal g is unchanged and the outcome says why
  /// (no-match, dangling, not-representable, ...).
  Outcome<Application> apply(Map& g, std::span<const Dart> hooks);
  /// Rewrites g and writes the values of the operation's terms (none when
  /// it has no terms); refusals also label-mismatch, overlap, no-value.
  /// With `record`, the result holds the match, comatch and every value
  /// written. Applied again to the same map, the per-map tables are kept
  /// (the map may change in between); applied to another, made anew.
  Outcome<EmbeddedApplication> apply(EmbeddedMap& g, std::span<const Dart> hooks, bool record = true);

  /// The first half of apply(Map&): the match (g_size, match, pattern),
  /// every refusal a scheme decides on G; g is not modified.
  Outcome<Application> match(const Map& g, std::span<const Dart> hooks);
  /// The second half: rewrites g along a match this Applier made on g (a
  /// DPO rule may still refuse: dangling, not-representable).
  Outcome<Application> rewrite(Map& g, Application&& matched);
  /// Hands an application's tables back for the next one.
  void recycle(Application&& a);

  /// How often the kept-label shortcut's check held, and failed (the walk
  /// ran), over this Applier's embedded applications.
  struct ShortcutCounts {
    std::size_t taken = 0, refused = 0;
  };
  ShortcutCounts kept_label_shortcuts() const;

 private:
  const Operation& op_;
  EvaluationOptions options_;
  struct Topology;
  std::unique_ptr<Topology> topology_;
  std::unique_ptr<EmbeddedRewriter> embedded_;  // bound to embedded_map_
  const EmbeddedMap* embedded_map_ = nullptr;
  ShortcutCounts earlier_shortcuts_;  // of rewriters bound to earlier maps
};

}  // namespace dartcheck
