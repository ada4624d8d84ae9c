// Jerboa G-map files (.jba, "Jerboa JBA Generic Format"):
//
//   Jerboa JBA Generic Format
//   version 1
//   name <modeler class>
//   dimension 3
//   nbebd 2
//   ebdid 0 pos <a1, a2, a3> <value type>
//   ebdid 1 color <a0, a1> <value type>
//   <dart count> <an id bound, ignored>
//   <dart id> <alpha_0> ... <alpha_n>          (one line per dart)
//   <embedding name> <record count>           (one section per embedding)
//   <dart ids of one orbit>
//   <its value, kept as text>
//
// Loaded into a map of the n-G-map model (darts renumbered in file order)
// with each embedding's values per dart. Errors: InputError at file:line.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/map.hpp"
#include "core/map_embedding.hpp"
#include "rewriting/value.hpp"

namespace dartcheck {

struct JbaFile {
  std::string name;  // the modeler the file was written by
  Map map;
  std::vector<MapEmbedding> embeddings;
  std::vector<std::string> ids;  // the file's id of each dart
};

JbaFile read_jba(const std::string& file);

/// Writes `f` in the format above (dart ids 0..n-1, one record per value
/// of each orbit; unlabeled darts are left out of the records), so that
/// read_jba gives the same map and values back. Throws InputError naming
/// `path` if the map is not an n-G-map with every link set (a .jba holds
/// nothing else).
void write_jba(std::ostream& out, const JbaFile& f, const std::string& path);

/// A value as a .jba record holds it (coordinates separated by spaces, the
/// shortest text that reads back to the same double), as typed_embedding
/// reads it back.
std::string jba_value(const Value& v);

}  // namespace dartcheck
