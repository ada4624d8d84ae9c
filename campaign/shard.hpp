// Shards of a campaign (docs/scale.md): `--shard K/N` runs the rules whose
// stable key falls in shard K of N. The key is a hash of the rule's name,
// not its position in the file, so a rule stays in its shard when rules
// are added or moved, and a shard replays alone with the same seed (every
// rule's seed derives from the run's seed and the rule's name).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/catalog.hpp"

namespace dartcheck::campaign {

struct Shard {
  std::size_t index = 0, count = 1;  // shard `index` of `count` (0-based)
  bool whole() const { return count == 1; }
  /// "K/N"
  std::string text() const;
  friend bool operator==(const Shard&, const Shard&) = default;
};

/// Parses "K/N" with 0 <= K < N <= 1,000,000; InputError naming `option`
/// otherwise.
Shard parse_shard(std::string_view text, std::string_view option = "--shard");

/// --shard as a command takes it: the whole run when `text` is empty.
inline Shard shard_option(const std::string& text) { return text.empty() ? Shard{} : parse_shard(text); }

/// FNV-1a (64 bits) of `bytes`: fixed on every platform and compiler,
/// unlike std::hash.
std::uint64_t stable_hash(std::string_view bytes);

/// Whether the rule named `name` belongs to `shard`.
bool in_shard(std::string_view name, const Shard& shard);

/// Removes the rules of `catalog` that are not in `shard`; the rules not
/// checked (Catalog::skipped) stay, as every shard reports them.
void keep_shard(Catalog& catalog, const Shard& shard);

/// "fnv1a64:<16 hex digits>" of a file's bytes: merge refuses shards of a
/// catalog (or baseline) that changed between them. InputError if the
/// file cannot be read.
std::string file_digest(const std::string& path);

}  // namespace dartcheck::campaign
