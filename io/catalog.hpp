// YAML rule catalogs (format: docs/catalog-format.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "core/map.hpp"
#include "rewriting/operation.hpp"

namespace dartcheck {

/// Where a map comes from. Shapes and meshes are built by the caller (the
/// builders live in generators/, a layer above io).
struct MapSource {
  std::string name;
  Model model;
  std::optional<Map> map;  // explicit darts and links
  std::string shape;       // e.g. "grid:3x4"
  std::string mesh;        // path, resolved against the catalog's folder
  SourceLocation location;
};

/// A rule of an imported file that dartcheck does not represent, and why.
struct SkippedRule {
  std::string name, why;
  SourceLocation location;
};

/// A worked application: rule at `hooks` on `map`, and what must happen.
struct Example {
  std::string map;
  std::vector<Dart> hooks;
  std::string expect;                             // "valid", "invalid", or a refusal name (no-match, dangling, ...)
  std::optional<std::vector<std::size_t>> cells;  // expected cell counts of H
  /// A catalog map H must be isomorphic to (an inferred rule's example:
  /// applied to the before map it gives the after map), or empty.
  std::string isomorphic_to;
  SourceLocation location;
};

/// An operation of a catalog (rewriting/operation.hpp) with what the
/// catalog says about it: its note, worked examples and recorded verdict.
struct CatalogRule : Operation {
  std::string note;
  std::vector<Example> examples;
  SourceLocation location;
  /// The recorded static verdict: the names of the conditions that fail
  /// ("I(0)", "C(0,2)", ...), empty for "consistent"; unset if none.
  std::optional<std::vector<std::string>> expected_failures;
  SourceLocation verdict_location;
  /// The solver's recorded class per embedding (a baseline's `solver`
  /// section, io/baseline.hpp); unset if none.
  std::optional<std::vector<std::pair<std::string, std::string>>> expected_solver;
  SourceLocation solver_location;
};

struct Catalog {
  std::string file;
  std::string modeler;  // the Jerboa modeler's name, for imported files
  std::vector<EmbeddingDecl> embeddings;
  /// `embeddings` with their value types, for catalogs whose rules carry
  /// terms (a declared type dartcheck does not know is an error there).
  std::vector<EmbeddingSignature> signatures;
  std::vector<SkippedRule> skipped;
  std::vector<MapSource> maps;
  std::vector<CatalogRule> rules;
  const MapSource* find_map(const std::string& name) const;
  const CatalogRule* find_rule(const std::string& name) const;
};

/// Reads a catalog; every error is an InputError with file:line:column.
/// A file ending in .jme is read as a Jerboa modeler (io/jerboa_modeler).
Catalog read_catalog(const std::string& file);

}  // namespace dartcheck
