#include "querymodify/hex_queries.hpp"

namespace dartcheck::querymodify {

const std::vector<std::uint64_t>& labeled_hex_subdivisions() {
  static const std::vector<std::uint64_t> table{
#include "hex_subdivision_table.inc"
  };
  return table;
}

}  // namespace dartcheck::querymodify
