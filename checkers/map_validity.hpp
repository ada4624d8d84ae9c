// Dynamic validity of a dense map against its model (002 Def. 9-10):
// I(D), O(N), C(E), and the variants' relaxed I and loop ban.
#pragma once

#include <string>
#include <string_view>

#include "checkers/violation.hpp"
#include "core/map.hpp"

namespace dartcheck {

/// Checks every dart of `map` and lists every violation.
///
/// The i-arcs of the map are the pairs (d, link_i(d)); for an oriented
/// dimension the recorded predecessors must be the sources of those arcs,
/// and a dart whose record disagrees breaks I(i) as stored.
///
/// One pass reads, for each dart, the records of its neighbours and decides
/// all constraints with identities that hold when every link array is a
/// bijection (C(i,j) at v  <=>  s_j(s_i(v)) = p_i(p_j(v))). If some dart
/// breaks I or O, those identities no longer describe the graph, and an
/// exact pass (degree counts, explicit ijij-paths) recomputes every
/// violation.
///
/// `threads` splits the darts into that many ranges checked at once (the
/// report is the same); 0 chooses validity_threads(map.size()).
ValidityReport check_map(const Map& map, unsigned threads = 0);

/// Maps of at least this many darts are checked by several threads by
/// default: below it, starting a thread costs more than it saves.
inline constexpr std::size_t parallel_validity_darts = std::size_t{1} << 20;
/// The default thread count of check_map: 1 below parallel_validity_darts,
/// else the hardware's concurrency (at most 8).
unsigned validity_threads(std::size_t darts);

/// The exact pass alone (used by the fast pass, and by tests as a second
/// implementation of the definition to compare against).
ValidityReport check_map_exact(const Map& map);

/// For a map given as input to an analysis that is defined on maps only
/// (inference, events, fuzz hosts): throws InputError on the command line,
/// "`subject`: not a valid 2-gmap (7 violations: the first five): `why`",
/// unless `map` is a valid map of its model.
void require_valid_map(const Map& map, std::string_view subject, std::string_view why);

}  // namespace dartcheck
