// YAML rule catalogs (format: docs/catalog-format.md).
#pragma once

#include <optional>
#include <string>
#include <vector>
#include <yaml-cpp/yaml.h>

#include "core/jerboa_scheme.hpp"
#include "core/map.hpp"
#include "core/rule.hpp"
#include "core/rule_terms.hpp"

namespace dartcheck {

struct SourceLocation {
  std::string file;
  int line = 0, column = 0;
  std::string str() const;
};

/// Where a map comes from. Shapes and meshes are built by the caller (the
/// builders live in generators/, a layer below core).
struct MapSource {
  std::string name;
  Model model;
  std::optional<Map> map;  // explicit darts and links
  std::string shape;       // e.g. "grid:3x4"
  std::string mesh;        // path, resolved against the catalog's folder
  SourceLocation location;
};

/// An embedding operation pi : <o> -> tau (003 Sec. 5.1). The value type
/// is kept as the text the file gives (a Jerboa Java class, "point3", ...).
struct EmbeddingDecl {
  std::string name, type;
  std::vector<Dim> orbit;
  SourceLocation location;
};

/// An embedding expression carried by a node of R (Jerboa's
/// <expr ebd="pos">code</expr>): opaque code, never evaluated; what matters
/// to the presence checks is that it is there.
struct NodeExpression {
  std::string node, embedding, code;
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
  std::string expect;  // "valid", "invalid", or a refusal name (no-match, dangling, ...)
  std::optional<std::vector<std::size_t>> cells;  // expected cell counts of H
  SourceLocation location;
};

struct CatalogRule {
  Rule rule;
  std::string note;
  std::vector<Example> examples;
  SourceLocation location;
  /// The recorded static verdict: the names of the conditions that fail
  /// ("I(0)", "C(0,2)", ...), empty for "consistent"; unset if none.
  std::optional<std::vector<std::string>> expected_failures;
  SourceLocation verdict_location;
  /// The W-labels of a rule scheme (002 Sec. 6); `words.scheme` is false
  /// for a DPO rule.
  ArcWords words;
  /// The orbit types of a Jerboa-style scheme's nodes (000 Sec. 4.3),
  /// already translated into `words`' loops; unset in the (W,D) notation.
  std::optional<JerboaLabels> jerboa;
  /// Embedding expressions on R's nodes (Jerboa modelers).
  std::vector<NodeExpression> expressions;
  /// What an import left out of this rule while keeping it (an ignored
  /// precondition, embedding parameters...), one sentence each.
  std::vector<std::string> caveats;
  /// Embedding terms on L's and R's nodes (003 Sec. 6); unset for a
  /// purely topological rule.
  std::optional<RuleTerms> terms;
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
/// A file ending in .jme is read as a Jerboa modeler (core/jerboa_modeler).
Catalog read_catalog(const std::string& file);

/// Reads one side of a rule: {nodes: [...], arcs: ["a -0- b", ...]}.
/// Arc notation: "a -i- b" is the non-oriented pair a -i-> b, b -i-> a
/// (one loop arc when a == b); "a -i-> b" and "a <-i- b" one oriented arc.
/// With `model` and `words`, arcs may carry scheme labels "(w,i)": `words`
/// receives one word per arc (ε for plain labels) and `has_words` is set if
/// any arc has one. With `jerboa` (the parameter orbit type), nodes are a
/// mapping from names to generalized orbit types and are translated to
/// (W,D) loops (core/jerboa_scheme.hpp).
TopoGraph read_side(const std::string& file, const YAML::Node& side, const char* which, const Model* model = nullptr,
                    std::vector<ConjWord>* words = nullptr, bool* has_words = nullptr, const OrbitType* jerboa = nullptr,
                    std::vector<OrbitType>* orbit_types = nullptr);

/// Reads a model: a preset name, or {dims, non_oriented, exchangeable,
/// partial, loop_free} for a custom one.
Model read_model(const std::string& file, const YAML::Node& node, const std::vector<Model>& custom);

}  // namespace dartcheck
