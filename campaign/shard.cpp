#include "campaign/shard.hpp"

#include <algorithm>
#include <charconv>

#include <fmt/format.h>

#include "core/input_error.hpp"
#include "io/input_file.hpp"

namespace dartcheck::campaign {

std::string Shard::text() const { return fmt::format("{}/{}", index, count); }

Shard parse_shard(std::string_view text, std::string_view option) {
  const auto bad = [&] {
    return UsageError(fmt::format("{}: expected K/N with 0 <= K < N (shard K of N, e.g. 0/4), got '{}'", option, printable(text)));
  };
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) throw bad();
  Shard s;
  const auto number = [&](std::string_view part, std::size_t& out) {
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
    if (part.empty() || ec != std::errc() || end != part.data() + part.size()) throw bad();
  };
  number(text.substr(0, slash), s.index);
  number(text.substr(slash + 1), s.count);
  if (s.count == 0 || s.count > 1'000'000 || s.index >= s.count) throw bad();
  return s;
}

std::uint64_t stable_hash(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ULL;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ULL;
  return h;
}

bool in_shard(std::string_view name, const Shard& shard) { return stable_hash(name) % shard.count == shard.index; }

void keep_shard(Catalog& catalog, const Shard& shard) {
  if (shard.whole()) return;
  std::erase_if(catalog.rules, [&](const CatalogRule& e) { return !in_shard(e.rule.name(), shard); });
}

std::string file_digest(const std::string& path) { return fmt::format("fnv1a64:{:016x}", stable_hash(read_input(path))); }

}  // namespace dartcheck::campaign
