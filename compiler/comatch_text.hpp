// The comatch (002 Def. 4: where each node of R lands in H) as generated
// C++, shared by the rewrite's emitter and the labels' emitter.
#pragma once

#include <string>
#include <string_view>

#include <fmt/format.h>

#include "rewriting/rule.hpp"

namespace dartcheck::compiler {

/// The dart of R's node y at pattern position `p`, as an expression: the
/// table ws.comatch when the rule deletes a node of L (added nodes reuse
/// its darts, the holes). When no node of L is deleted it is arithmetic
/// and no table is written: a preserved node is on its matched dart (in an
/// everywhere function the match is the identity, so on dart p), an added
/// node on the new darts, np per added node in R's node order, as
/// emit_rewrite numbers them.
inline std::string comatch_dart(const Rule& r, NodeId y, std::string_view p, bool positions_are_darts) {
  if (r.deletes_nodes()) return fmt::format("comatch[{} * np + {}]", y, p);
  if (const NodeId x = r.to_left(y); x != no_node)
    return positions_are_darts ? fmt::format("static_cast<Dart>({})", p) : fmt::format("match[{} * np + {}]", x, p);
  std::size_t rank = 0;
  for (NodeId z = 0; z < y; ++z) rank += r.to_left(z) == no_node;
  return fmt::format("static_cast<Dart>(first_new + {} * np + {})", rank, p);
}

/// The declaration of `match`, the darts of L's nodes per position: the
/// table ws.match, or in an everywhere function of a rule that deletes no
/// node (no pointer into the match is taken) the identity as a type, since
/// product node (p, hook) is dart p, so that its reads fold away.
inline std::string match_declaration(const Rule& r, bool positions_are_darts) {
  return positions_are_darts && !r.deletes_nodes() ? "[[maybe_unused]] constexpr dartcheck::compiled::IdentityMatch match{};"
                                                  : "[[maybe_unused]] const Dart* const match = ws.match.data();";
}

}  // namespace dartcheck::compiler
