// What an application G => H leaves for event detection (004 Sec. 1, 5):
// the match and comatch per (rule node, pattern position), the darts that
// H renumbered, and from them the correspondence between G's and H's
// darts. Built without touching the unmatched part of the map.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "events/dart_index.hpp"
#include "rewriting/operation.hpp"
#include "rewriting/scheme_application.hpp"

namespace dartcheck::events {

struct ApplicationTrace {
  std::size_t g_size = 0;
  std::vector<std::vector<Dart>> match;    // [L node][p]: dart of G
  std::vector<std::vector<Dart>> comatch;  // [R node][p]: dart of H
  std::vector<std::pair<Dart, Dart>> moved;
  /// The hook's pattern (schemes); a DPO rule has one position.
  std::optional<PatternGraphs> pattern;
};

/// Applies `op` at `hooks` to g in place (a DPO rule by apply_rule's steps,
/// a scheme by match_scheme then rewrite_scheme) and records the trace.
/// Refuses as the engines do, leaving g unchanged.
Outcome<ApplicationTrace> apply_traced(const Operation& op, Map& g, std::span<const Dart> hooks);

/// G's darts against H's: preserved darts by the comatch, unmatched ones by
/// identity or their renumbering. Costs O(|matched| + |moved|).
class Correspondence {
 public:
  Correspondence(const Rule& rule, const ApplicationTrace& t);
  /// The dart of H that g became; no_dart if g was deleted.
  Dart to_h(Dart g) const { return decode(g2h_.get(g), g); }
  /// The dart of G that h was; no_dart if h was created.
  Dart to_g(Dart h) const { return decode(h2g_.get(h), h); }
  bool matched(Dart g) const { return matched_.get(g) != DartIndex::none; }

 private:
  // Stored values: a dart, or `gone` for deleted / created darts; absent
  // darts map to themselves.
  static constexpr std::uint32_t gone = DartIndex::none - 1;
  static Dart decode(std::uint32_t v, Dart self) { return v == DartIndex::none ? self : v == gone ? no_dart : v; }
  DartIndex g2h_, h2g_, matched_;
};

}  // namespace dartcheck::events
