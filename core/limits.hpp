// Sizes dartcheck accepts from its input, checked before anything is
// allocated for them, so a hostile or mistaken file gets a message at its
// position instead of an allocation failure or a stack overflow. The
// defaults hold every map, term and rule of the seed papers and the
// benchmarks with room to spare; the command line raises them
// (--limit-darts, --limit-term-length, ...), for the whole process.
#pragma once

#include <cstddef>
#include <string>

namespace dartcheck {

struct Limits {
  /// Darts of one map read from a file or built from a mesh or shape.
  std::size_t darts = std::size_t{1} << 25;  // 33,554,432
  /// Bytes of one input file (maps, meshes, catalogs, modelers, shards).
  std::size_t file_bytes = std::size_t{1} << 31;  // 2 GiB
  /// Characters of one embedding term.
  std::size_t term_length = std::size_t{1} << 16;
  /// Nesting of one term: parentheses, calls, unary signs, operators.
  std::size_t term_depth = 256;
  /// Letters of one conjugate word (scheme arc labels, `dartcheck words`).
  std::size_t word_length = 4096;
  /// Nodes of one side of a rule or scheme.
  std::size_t rule_nodes = 4096;
  /// Words met while rewriting one word in a non-confluent R_{N,E} (models
  /// with two exchangeable oriented dimensions), memoized: about 100 MB.
  std::size_t rewrite_words = 1'000'000;
};

/// The process-wide limits (set once by the command line, before input is
/// read).
Limits& limits();

/// "darts: 2147483648 is over the limit of 33554432 (raise it with
/// --limit-darts)"
std::string over_limit(const char* what, std::size_t value, std::size_t limit, const char* option);

}  // namespace dartcheck
