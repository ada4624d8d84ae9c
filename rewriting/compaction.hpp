// Keeping a map dense after a rewrite deleted darts: what the Applier, the
// generated code (compiled_runtime.hpp) and query-modify share.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "core/map.hpp"

namespace dartcheck {

/// Keeps a map dense after deleting darts: the `holes` (darts with no arc
/// left) are filled with the last darts, which are renumbered, and the map
/// is truncated. Returns the renumberings (old, new).
/// `sources` are the darts a rule gave new arcs (in g's numbering before
/// the call): a rule that breaks O may leave a non-oriented arc without its
/// reverse, which Map::relocate cannot find, so their arcs into moved darts
/// are redirected here.
std::vector<std::pair<Dart, Dart>> compact(Map& g, std::vector<Dart> holes, std::span<const Dart> sources = {});

}  // namespace dartcheck
