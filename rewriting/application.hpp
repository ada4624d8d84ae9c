// The one way to apply the operation under test (GUIDE, "The pipeline"):
// a DPO rule (002 Sec. 2) matched from its hooks, or a rule scheme (002
// Sec. 6) instantiated on the hooks' pattern graph, give the same record:
// the match and comatch per (rule node, pattern position), the darts H
// renumbered, and from them the Renumbering of G's darts into H's. Every
// engine (run, apply, fuzz, events, ...) applies through here, so no other
// place branches on scheme versus DPO.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/renumbering.hpp"
#include "rewriting/match.hpp"
#include "rewriting/operation.hpp"
#include "rewriting/scheme_application.hpp"

namespace dartcheck {

struct Application {
  std::size_t g_size = 0;
  std::vector<std::vector<Dart>> match;    // [L node][p]: dart of G (a DPO rule has one position)
  std::vector<std::vector<Dart>> comatch;  // [R node][p]: dart of H
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

/// Applies one operation again and again; a scheme's tables (SchemeRewriter)
/// are kept from one application to the next.
class Applier {
 public:
  explicit Applier(const Operation& op);
  ~Applier();
  Applier(const Applier&) = delete;
  Applier& operator=(const Applier&) = delete;

  /// Rewrites g in place at `hooks`; on refusal g is unchanged and the
  /// outcome says why (no-match, dangling, not-representable, ...).
  Outcome<Application> apply(Map& g, std::span<const Dart> hooks);
  /// The match alone, [L node][p]; g is not modified.
  Outcome<std::vector<std::vector<Dart>>> match(const Map& g, std::span<const Dart> hooks);
  /// Hands an application's tables back for the next one.
  void recycle(Application&& a);

 private:
  const Operation& op_;
  std::unique_ptr<SchemeRewriter> scheme_;
  Application spare_;  // a DPO rule's recycled tables (one vector per node)
};

/// One application with a fresh Applier.
Outcome<Application> apply(const Operation& op, Map& g, std::span<const Dart> hooks);

}  // namespace dartcheck
